//! The inputs of a position in short, as the steps, the handout and the
//! sheets head a position: the symbols are the lecture's in every
//! language (φ1, s, ω1, ε1), the numbers as a student writes them.

use crate::format::num;
use crate::kinematics::analytic::Drive;
use crate::kinematics::solve::{Analysis, Position};
use crate::model::scene::InputSpec;

/// Each input's words by `f` (its spec, its drive, its subscript: the
/// link's id with several inputs, else `crank` for a crank and nothing for
/// a slider), joined by `sep`.
fn each_input(
    an: &Analysis,
    s: &Position,
    sep: &str,
    f: impl Fn(&InputSpec, &Drive, &str) -> String,
) -> String {
    let m = &an.mech;
    let several = m.scene.several_inputs();
    m.scene
        .inputs()
        .zip(s.drives.iter())
        .map(|(spec, d)| {
            let id = m.link_id(spec.link());
            let k = match spec {
                _ if several => id,
                InputSpec::Crank { .. } => "1",
                InputSpec::Slider { .. } => "",
            };
            f(spec, d, k)
        })
        .collect::<Vec<_>>()
        .join(sep)
}

/// The inputs of a position in short: "φ1 = 30°", "s = 0.1 m"; several
/// with their links' ids: "φ1 = 30°, φ4 = 120°", "s3 = 0.1 m, s6 = 0 m".
pub fn input_words(an: &Analysis, s: &Position) -> String {
    each_input(an, s, ", ", |spec, d, k| match spec {
        InputSpec::Crank { .. } => format!("φ{k} = {}°", num(d.q.to_degrees().rem_euclid(360.0))),
        InputSpec::Slider { .. } => format!("s{k} = {} m", num(d.q)),
    })
}

/// The inputs' rates of a position in short: "ω1 = 10 rad/s, ε1 = 0
/// rad/s²", several with their links' ids.
pub fn drive_words(an: &Analysis, s: &Position) -> String {
    each_input(an, s, "; ", |spec, d, k| match spec {
        InputSpec::Crank { .. } => format!(
            "ω{k} = {} rad/s, ε{k} = {} rad/s²",
            num(d.rate),
            num(d.rate2)
        ),
        InputSpec::Slider { .. } => format!("v{k} = {} m/s, a{k} = {} m/s²", num(d.rate), num(d.rate2)),
    })
}
