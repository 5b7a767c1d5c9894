//! The sheets' words: their headings per language, "position 1, φ1 =
//! 30°", and scales as the sheets write them ("μ_v = 0.01 (m/s)/mm").

use super::canvas::Label;
use super::table::{self, number};
use crate::kinematics::solve::Analysis;
use crate::model::scene::InputSpec;
use crate::presentation::position_number;
use crate::pipeline::Solved;
use crate::words::construction::Lang;
use crate::words::catalogue::SheetPhrases;

/// The sheets' words in `lang` (its catalogue's).
pub(crate) fn words(lang: Lang) -> &'static SheetPhrases {
    &crate::words::catalogue(lang).sheets
}
/// "position 0, φ1 = 30°" (the input link's own number), localised.
pub(crate) fn position_text(an: &Analysis, s: &Solved, k: usize, lang: Lang) -> String {
    let w = words(lang);
    let m = &an.mech;
    if m.scene.several_inputs() {
        // Every input with its link's id: "φ1 = 60°, φ4 = 120°", "s3 = 0,1 м".
        let inputs: Vec<String> = m
            .scene
            .inputs()
            .zip(s.drives.iter())
            .map(|(spec, d)| {
                let id = m.link_id(spec.link());
                match spec {
                    InputSpec::Crank { .. } => format!(
                        "φ{id} = {}°",
                        number(d.q.to_degrees().rem_euclid(360.0), lang)
                    ),
                    InputSpec::Slider { .. } => {
                        format!("s{id} = {} {}", number(d.q, lang), table::unit("m", lang))
                    }
                }
            })
            .collect();
        return format!("{} {}, {}", w.position, position_number(an, k), inputs.join(", "));
    }
    match m.scene.input {
        InputSpec::Crank { link, .. } => format!(
            "{} {}, φ{} = {}°",
            w.position,
            position_number(an, k),
            m.link_id(link),
            number(s.q.to_degrees().rem_euclid(360.0), lang)
        ),
        InputSpec::Slider { .. } => format!(
            "{} {}, s = {} {}",
            w.position,
            position_number(an, k),
            number(s.q, lang),
            table::unit("m", lang)
        ),
    }
}
/// "μ_v = 0.01 (m/s)/mm" in the notation of the sheets, localised.
pub(crate) fn scale_text(sym: &str, mu: f64, unit: &str, lang: Lang) -> String {
    let u = table::unit(unit, lang);
    let u = if u.contains('/') { format!("({u})") } else { u };
    format!(
        "μ_{sym} = {} {u}/{}",
        number(mu, lang),
        table::unit("mm", lang)
    )
}
/// "μ_v = 0.01 (m/s)/mm", localised, as a label (the handout's).
pub(crate) fn scale_label(sym: &str, mu: f64, unit: &str, lang: Lang) -> Label {
    let t = scale_text(sym, mu, unit, lang);
    let tail = t.split_once(' ').map(|x| x.1).unwrap_or("");
    Label::new("μ", sym).with_tail(format!(" {tail}"))
}
