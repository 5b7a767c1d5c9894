//! What a plan drawn in a program (a vector editor's SVG, a CAD's DXF)
//! holds, and how it is read as an answer — the same rules for every
//! format: text labels placed next to points (p_v, a, b …) and line
//! segments between them; each label names the segment end nearest to it
//! (within [`SNAP_MM`]); coordinates are taken relative to the pole's
//! point, y up, in millimetres; μ stated as a text ("μ_v = 0.01 (m/s)/mm")
//! or given; the plan named by its pole's label or given. The formats'
//! readers ([`super::svg`], [`super::dxf`]) only turn a file into a
//! [`Drawing`].
//!
//! The line end nearest to a label is found in a grid of cells of the
//! snapping distance, so that reading is linear in the drawing's size.

use super::answer::{Answer, Given, Item};
use crate::error::{Error, Issue, Result};
use crate::kinematics::construction::PlanKind;
use super::letters::{is_pole, plan_letter, scale_statement};
use super::touching::plan_lines;
use kurbo::Point;
use std::collections::{HashMap, HashSet};

/// How far from a line's end its label may be, mm.
pub(super) const SNAP_MM: f64 = 8.0;

/// The line ends in cells of [`SNAP_MM`]: the nearest end within that
/// distance of a label is in the label's cell or one of its eight
/// neighbours.
struct Ends {
    ends: Vec<Point>,
    cells: HashMap<(i64, i64), Vec<usize>>,
}

impl Ends {
    fn cell(p: Point) -> (i64, i64) {
        // `as` saturates: far-off coordinates share the outermost cells.
        (
            (p.x / SNAP_MM).floor() as i64,
            (p.y / SNAP_MM).floor() as i64,
        )
    }

    fn new(ends: Vec<Point>) -> Ends {
        let mut cells: HashMap<(i64, i64), Vec<usize>> = HashMap::new();
        for (k, p) in ends.iter().enumerate() {
            if p.x.is_finite() && p.y.is_finite() {
                cells.entry(Ends::cell(*p)).or_default().push(k);
            }
        }
        Ends { ends, cells }
    }

    /// The end nearest to `at` if it is within [`SNAP_MM`] (of equally
    /// near ends, the first drawn).
    fn snap(&self, at: Point) -> Option<Point> {
        if !(at.x.is_finite() && at.y.is_finite()) {
            return None;
        }
        let (cx, cy) = Ends::cell(at);
        let mut best: Option<(f64, usize)> = None;
        for dx in -1..=1i64 {
            for dy in -1..=1i64 {
                let key = (cx.saturating_add(dx), cy.saturating_add(dy));
                for &k in self.cells.get(&key).into_iter().flatten() {
                    let d = (self.ends[k] - at).hypot();
                    if d <= SNAP_MM && best.is_none_or(|(bd, bk)| d < bd || (d == bd && k < bk)) {
                        best = Some((d, k));
                    }
                }
            }
        }
        best.map(|(_, k)| self.ends[k])
    }
}

/// What a drawing holds: its text labels (their text and where they are,
/// mm, y down as drawn: a CAD's y up is turned over by its reader) and its
/// lines (each path, line or polyline's points in order, mm); `kind` is
/// the format's name ("svg", "dxf") that its problems' pointers start
/// with.
pub(crate) struct Drawing {
    pub labels: Vec<(String, Point)>,
    pub lines: Vec<Vec<Point>>,
    pub kind: &'static str,
    /// Its arrowheads (a force plan's vectors' senses).
    pub heads: Vec<super::arrows::Head>,
}

/// The scale a drawing states in a text such as "μ_v = 0.01 (m/s)/mm",
/// "Масштаб μv = 0,01 (м/с)/мм", "μ_F = 2 N/mm" (`prefix`: "" for any
/// μ, "_F" for a force plan's).
pub(crate) fn stated_mu(labels: &[(String, Point)], prefix: &str) -> Option<f64> {
    labels.iter().find_map(|(s, _)| mu_of(s, prefix))
}

/// The scale one text states ([`stated_mu`]).
fn mu_of(s: &str, prefix: &str) -> Option<f64> {
    // What follows the Greek letter, the micro sign (a code page's μ) or
    // "mu", anywhere in the text.
    let rest = scale_statement(s)?.replace(' ', "");
    let rest = rest.strip_prefix(prefix)?;
    // A decimal point or comma ("0,01" as written in uk/ru).
    let num: String = rest
        .split('=')
        .nth(1)?
        .chars()
        .take_while(|c| c.is_ascii_digit() || matches!(c, '.' | ',' | 'e' | '-'))
        .map(|c| if c == ',' { '.' } else { c })
        .collect();
    num.trim_end_matches('.').parse().ok()
}

/// A problem of the drawing as a whole: no pointer ("svg" would be read as
/// the option --svg); the file is named by the caller.
pub(super) fn whole(message: &str) -> Error {
    Error::fields(vec![Issue {
        pointer: String::new(),
        message: message.into(),
    }])
}

/// What a text of a drawing is read as.
#[derive(Clone, Debug, PartialEq)]
enum Text {
    /// A scale ("μv = 0.01 (m/s)/mm"), read by [`stated_mu`].
    Scale,
    /// A title naming the plan ("Velocity plan"), read by [`stated_plan`].
    Title,
    /// A plan's letter, by its name ([`plan_letter`]).
    Letter(String),
    /// Anything else — a title block's words, a sheet number, a caption,
    /// given data: no point's name, left out and noted.
    Other,
}

/// What a text is read as: a scale before a letter (a "μv = …" is never
/// a point), a letter before a title, and everything else left out.
fn text_kind(s: &str) -> Text {
    if s.trim().is_empty() {
        Text::Other
    } else if scale_statement(s).is_some() {
        Text::Scale
    } else if let Some(name) = plan_letter(s) {
        Text::Letter(name)
    } else if plan_named(s).is_some() {
        Text::Title
    } else {
        Text::Other
    }
}

/// The pole's name a text is read as, if it is one.
fn pole_name(t: &Text) -> Option<&str> {
    match t {
        Text::Letter(n) if is_pole(n) => Some(n),
        _ => None,
    }
}

/// The drawing's pole: the first text read as the pole's letter that
/// stands next to a line's end (`all`: every line's), its index and that
/// end — of the poles of the plan `prefer` (the plan asked or named by
/// the texts) first, so that of a velocity and an acceleration plan drawn
/// on one sheet the one asked is read. No such text, or none next to an
/// end, is refused saying what to change.
fn find_pole(
    labels: &[(String, Point)],
    texts: &[Text],
    all: &Ends,
    prefer: Option<PlanKind>,
) -> Result<(usize, Point)> {
    let other_plans = |t: &Text| {
        let kind = pole_name(t).and_then(labelled_plan);
        prefer.is_some() && kind.is_some() && kind != prefer
    };
    let mut order: Vec<usize> = (0..texts.len())
        .filter(|&k| pole_name(&texts[k]).is_some())
        .collect();
    order.sort_by_key(|&k| other_plans(&texts[k]));
    let mut poles = order.into_iter().map(|k| (k, &texts[k])).peekable();
    if poles.peek().is_none() {
        let others = quoted(
            labels
                .iter()
                .zip(texts)
                .filter(|(_, t)| **t == Text::Other)
                .map(|((s, _), _)| s.as_str()),
        );
        let seen = if others.is_empty() {
            String::new()
        } else {
            format!(" (texts read as no plan letter: {others})")
        };
        return Err(whole(&format!(
            "no pole: no text reads as the pole's letter (p, p_v, pv, p_a, pa, π){seen}; label the pole beside the point its vectors start from"
        )));
    }
    let first = poles.peek().map(|(k, _)| *k).unwrap_or_default();
    poles
        .find_map(|(k, _)| all.snap(labels[k].1).map(|e| (k, e)))
        .ok_or_else(|| {
            whole(&format!(
                "the pole's label \"{}\" is not next to any line's end: put it within {SNAP_MM} mm of the point the plan's vectors start from",
                labels[first].0
            ))
        })
}

/// Texts quoted in a note or message: each once, the first twenty, then how
/// many more.
fn quoted<'a>(texts: impl Iterator<Item = &'a str>) -> String {
    let mut seen: Vec<&str> = Vec::new();
    for t in texts {
        let t = t.trim();
        if !t.is_empty() && !seen.contains(&t) {
            seen.push(t);
        }
    }
    let mut out: Vec<String> = seen.iter().take(20).map(|t| format!("\"{t}\"")).collect();
    if seen.len() > 20 {
        out.push(format!("and {} more", seen.len() - 20));
    }
    out.join(", ")
}

/// The ends of the plan's lines ([`plan_lines`]), where its labels snap.
fn plan_ends(lines: &[Vec<Point>], pole: Point) -> Result<Ends> {
    let on = plan_lines(lines, pole)?;
    Ok(Ends::new(
        lines
            .iter()
            .zip(on)
            .filter(|(_, on)| *on)
            .flat_map(|(l, _)| l.iter().copied())
            .collect(),
    ))
}

/// Where a drawing's pole is (its coordinates, mm): the line end its
/// label names, as [`answer_and_notes`] finds it.
/// `plan`: the plan the answer was read as.
pub(super) fn pole_of(drawing: &Drawing, plan: Option<PlanKind>) -> Result<Point> {
    let texts: Vec<Text> = drawing.labels.iter().map(|(s, _)| text_kind(s)).collect();
    let all = Ends::new(drawing.lines.iter().flatten().copied().collect());
    find_pole(&drawing.labels, &texts, &all, plan).map(|(_, e)| e)
}

/// A drawing read as an answer ([`answer_and_notes`] without its notes).
#[cfg(feature = "internals")]
pub(super) fn answer_of(
    drawing: Drawing,
    mu: Option<f64>,
    plan: Option<PlanKind>,
    delta: f64,
    position: super::position::StatedPosition,
) -> Result<Answer> {
    answer_and_notes(drawing, mu, plan, delta, position).map(|(a, _)| a)
}

/// A drawing read as an answer, and the notes on what of it was left
/// out (for the report: a teacher sees what was not read, and the
/// student is not refused for a title block). `mu`, `plan` come from the
/// command line when the drawing does not state them (a "μ = 0.01" text,
/// and the pole's label p_v / p_a); a plan asked that the pole's label
/// contradicts is refused.
///
/// Read as a teacher reads a sheet: the pole is the first text read as
/// its letter next to a line's end; the plan is the lines joined to it
/// ([`plan_lines`]); every other text that is a plan's letter names the
/// end of the plan's lines nearest to it. Texts that are no plan letter
/// (a title block, a caption) and letters next to no end of the plan
/// (a mechanism's A, B, a title block's format A3) are left out, each
/// named in a note.
pub(crate) fn answer_and_notes(
    drawing: Drawing,
    mu: Option<f64>,
    plan: Option<PlanKind>,
    delta: f64,
    position: super::position::StatedPosition,
) -> Result<(Answer, Vec<String>)> {
    let Drawing {
        labels, lines, kind, ..
    } = drawing;
    let texts: Vec<Text> = labels.iter().map(|(s, _)| text_kind(s)).collect();
    // μ from a text such as "μ_v = 0.01 (m/s)/mm" when not given: a
    // scale no plan has is refused where it is said (the option, or the
    // drawing).
    let (mu, said) = match mu {
        Some(m) => (Some(m), "mu".to_string()),
        None => (stated_mu(&labels, ""), format!("{kind}: label μ")),
    };
    let Some(mu) = mu else {
        return Err(whole(
            "no scale: give --mu or write \"μ = …\" on the drawing",
        ));
    };
    if let Some(i) = super::answer::mu_issue(mu, &said) {
        return Err(Error::fields(vec![i]));
    }
    let all = Ends::new(lines.iter().flatten().copied().collect());
    let stated = stated_plan(&labels);
    let (pole_k, pole) = find_pole(&labels, &texts, &all, plan.or(stated))?;
    let pole_label = pole_name(&texts[pole_k]).unwrap_or("p");
    let plan = plan_of(pole_label, labels[pole_k].0.trim(), plan, stated)?;
    let ends = plan_ends(&lines, pole)?;
    let mut astray: Vec<&str> = Vec::new();
    // The pole labelled again at another end of the plan: which is the
    // pole? One beside no end of the plan (a second plan's) is left out.
    for (k, ((s, at), t)) in labels.iter().zip(&texts).enumerate() {
        if k == pole_k || pole_name(t).is_none() {
            continue;
        }
        match ends.snap(*at) {
            Some(e) if e != pole => {
                let rel = e - pole;
                return Err(Error::scene(
                    format!("{kind}: label {s}"),
                    format!(
                        "the pole is given twice, by labels at different line ends: (0, 0) and ({}, {}) mm from the first; label the pole once",
                        crate::format::num(rel.x),
                        crate::format::num(-rel.y)
                    ),
                ));
            }
            Some(_) => {}
            None => astray.push(s),
        }
    }
    let items = points(&labels, &texts, &ends, pole, kind, &mut astray)?;
    let mut notes = Vec::new();
    let others = quoted(
        labels
            .iter()
            .zip(&texts)
            .filter(|(_, t)| **t == Text::Other)
            .map(|((s, _), _)| s.as_str()),
    );
    if !others.is_empty() {
        notes.push(format!(
            "texts read as no plan letter, left out: {others}"
        ));
    }
    let astray = quoted(astray.into_iter());
    if !astray.is_empty() {
        notes.push(format!(
            "letters next to no end of the plan's lines (those joined to the pole), left out: {astray}"
        ));
    }
    Ok((
        Answer {
            plan,
            position,
            mu,
            delta,
            items,
            mu_v: None,
            stated: Vec::new(),
        },
        notes,
    ))
}

/// The plan a drawing's texts name, when they name one only: the scale's
/// subscript (`μv = …`, `μ_a = …`, `mu_v = …`) or a title ("Velocity
/// plan", "План швидкостей", "План ускорений" …).
pub(crate) fn stated_plan(labels: &[(String, Point)]) -> Option<PlanKind> {
    let mut named = labels.iter().filter_map(|(s, _)| plan_named(s));
    let first = named.next()?;
    named.all(|k| k == first).then_some(first)
}

/// The plan one text names ([`stated_plan`]).
fn plan_named(s: &str) -> Option<PlanKind> {
    if let Some(r) = scale_statement(s) {
        let r = r.to_lowercase().replace([' ', '_', '{', '}'], "");
        // MTEXT's stacked subscript read as its letters: "μ\\s^v;".
        let r = r.trim_start_matches("\\s^");
        return match r.chars().next() {
            Some('v') => Some(PlanKind::Velocity),
            Some('a') => Some(PlanKind::Acceleration),
            _ => None,
        };
    }
    let t = s.to_lowercase().replace([' ', '_', '{', '}'], "");
    // A title: a text about a plan. Velocities named elsewhere (given
    // data beside an acceleration plan: "angular velocity ω1 = 10
    // 1/s", "угловые скорости") name no plan.
    // The word itself ("plan", "plans", "план", "плани"), not a
    // part of another ("explanation"); in any language's words
    // (`reading` of the catalogues).
    let lower = s.to_lowercase();
    let words: Vec<&str> = lower.split(|c: char| !c.is_alphanumeric()).collect();
    let every = || crate::words::catalogue::every_reading();
    let about_a_plan = every().any(|r| {
        r.plan_words
            .iter()
            .any(|p| words.iter().any(|w| w.starts_with(p.as_str())))
    });
    if !about_a_plan {
        return None;
    }
    let velocity = every().any(|r| r.velocity_stems.iter().any(|w| t.contains(w.as_str())));
    let acceleration = every().any(|r| r.acceleration_stems.iter().any(|w| t.contains(w.as_str())));
    match (velocity, acceleration) {
        (true, false) => Some(PlanKind::Velocity),
        (false, true) => Some(PlanKind::Acceleration),
        _ => None,
    }
}

/// The plan a pole's name (as [`plan_letter`] reads it) says by its
/// subscript: p_v the velocity plan's, p_a the acceleration plan's; `p`,
/// `π` alone none.
fn labelled_plan(pole: &str) -> Option<PlanKind> {
    match pole.to_lowercase().as_str() {
        "pv" | "πv" => Some(PlanKind::Velocity),
        "pa" | "πa" => Some(PlanKind::Acceleration),
        _ => None,
    }
}

/// The plan a drawing is of: `asked` (--plan), else the one the pole's
/// label `pole` (a name as [`plan_letter`] reads it; `shown`: the label
/// as written, for a message) names, else the one
/// the drawing's texts name (`stated`), else, for a pole labelled `π`
/// alone, the acceleration plan (Russian and Ukrainian books letter the
/// velocity plan's pole p and the acceleration plan's π); --plan and the
/// pole's label must agree (a velocity plan's pole is p_v, an
/// acceleration plan's p_a).
fn plan_of(
    pole: &str,
    shown: &str,
    asked: Option<PlanKind>,
    stated: Option<PlanKind>,
) -> Result<PlanKind> {
    let labelled = labelled_plan(pole);
    let name = |k: PlanKind| {
        if k == PlanKind::Velocity {
            "velocity"
        } else {
            "acceleration"
        }
    };
    match (asked, labelled) {
        (Some(p), Some(l)) if p != l => Err(Error::scene(
            "plan",
            format!(
                "the plan asked is the {} plan, but the drawing's pole is labelled \"{shown}\", the {} plan's pole: give --plan {} or label the pole {}",
                name(p),
                name(l),
                name(l),
                if p == PlanKind::Velocity { "p_v" } else { "p_a" }
            ),
        )),
        (Some(p), _) | (None, Some(p)) => Ok(p),
        (None, None) => stated
            .or((pole == "π").then_some(PlanKind::Acceleration))
            .ok_or_else(|| {
                whole(
                    "which plan is it? label the pole p_v or p_a, write the scale as μ_v = … or μ_a = …, or give --plan",
                )
            }),
    }
}

/// The labelled points of a drawing: each plan letter (but the pole's)
/// at the end of the plan's lines nearest to it, mm from the `pole`'s
/// end, y up; a letter next to none goes to `astray`; a place off any
/// sheet is refused, and so is a drawing with no point labelled.
fn points<'a>(
    labels: &'a [(String, Point)],
    texts: &[Text],
    ends: &Ends,
    pole: Point,
    kind: &str,
    astray: &mut Vec<&'a str>,
) -> Result<Vec<Item>> {
    let mut items: Vec<Item> = Vec::new();
    let mut issues = Vec::new();
    // The labels read so far: (name in lower case, place's bits).
    let mut read: HashSet<(String, [u64; 2])> = HashSet::new();
    for ((text, at), t) in labels.iter().zip(texts) {
        let Text::Letter(name) = t else { continue };
        if is_pole(name) {
            continue;
        }
        let Some(e) = ends.snap(*at) else {
            astray.push(text);
            continue;
        };
        let rel = e - pole;
        // One label at the same line end twice (a copied text) is one
        // point labelled twice; at another end it gives a second place,
        // refused when the names are resolved (`items::given_twice`).
        if !read.insert((name.to_lowercase(), [rel.x.to_bits(), (-rel.y).to_bits()])) {
            continue;
        }
        let pointer = format!("{kind}: label {}", text.trim());
        let far = [rel.x, rel.y]
            .iter()
            .find_map(|&x| super::answer::coordinate_issue(x, &pointer));
        issues.extend(far);
        items.push(Item {
            pointer,
            key: name.clone(),
            given: Given::Point {
                name: name.clone(),
                at: [rel.x, -rel.y],
            },
            rounding: 0.0,
        });
    }
    if !issues.is_empty() {
        return Err(Error::fields(issues));
    }
    if items.is_empty() {
        let astray = quoted(astray.iter().copied());
        let seen = if astray.is_empty() {
            String::new()
        } else {
            format!(" (letters elsewhere: {astray})")
        };
        return Err(whole(&format!(
            "no point of the plan is labelled: no letter (a, b, s2 …) stands within {SNAP_MM} mm of an end of the lines joined to the pole{seen}; draw the vectors from the pole and label each point beside its vector's end"
        )));
    }
    Ok(items)
}


#[cfg(test)]
mod tests {
    use super::*;

    /// The grid finds what a search of every end finds: the nearest end
    /// within the snapping distance, the first drawn of equally near ones.
    #[test]
    fn snapping_in_cells_agrees_with_a_search_of_every_end() {
        let mut r: u64 = 7;
        let mut next = || {
            r = r
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (r >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut ends: Vec<Point> = (0..2000)
            .map(|_| Point::new(300.0 * next() - 50.0, 300.0 * next() - 50.0))
            .collect();
        // Repeated ends, ends on cell borders, far-off and non-finite ones.
        ends.extend_from_slice(&[
            ends[3],
            Point::new(16.0, 24.0),
            Point::new(24.0, 24.0),
            Point::new(1e300, -1e300),
            Point::new(f64::NAN, 0.0),
        ]);
        let grid = Ends::new(ends.clone());
        let brute = |at: Point| {
            ends.iter()
                .copied()
                .min_by(|a, b| (*a - at).hypot().total_cmp(&(*b - at).hypot()))
                .filter(|e| (*e - at).hypot() <= SNAP_MM)
        };
        let mut probes: Vec<Point> = (0..5000)
            .map(|_| Point::new(320.0 * next() - 60.0, 320.0 * next() - 60.0))
            .collect();
        probes.extend_from_slice(&[
            Point::new(20.0, 24.0),
            Point::new(16.0 + SNAP_MM, 24.0),
            Point::new(1e300, -1e300),
        ]);
        for at in probes {
            assert_eq!(grid.snap(at), brute(at), "at {at:?}");
        }
    }


    /// The plan a drawing's texts name: the scale's subscript or a title
    /// naming one plan; none when they name both, or disagree.
    #[test]
    fn a_drawing_names_its_plan_by_its_texts() {
        let at = Point::ZERO;
        let of = |texts: &[&str]| {
            stated_plan(&texts.iter().map(|t| (t.to_string(), at)).collect::<Vec<_>>())
        };
        assert_eq!(of(&["p", "μv = 0.01 (m/s)/mm"]), Some(PlanKind::Velocity));
        assert_eq!(of(&["μ_a = 0,05"]), Some(PlanKind::Acceleration));
        assert_eq!(of(&["mu_v = 0.01"]), Some(PlanKind::Velocity));
        assert_eq!(of(&["План прискорень, положення 3"]), Some(PlanKind::Acceleration));
        assert_eq!(of(&["План скоростей"]), Some(PlanKind::Velocity));
        assert_eq!(of(&["Velocity plan", "μ = 0.01"]), Some(PlanKind::Velocity));
        assert_eq!(of(&["Plans of velocities and accelerations"]), None);
        assert_eq!(of(&["μv = 0.01", "Acceleration plan"]), None);
        assert_eq!(of(&["μ = 0.01", "a", "b"]), None);
        assert_eq!(of(&["Explanation of the velocity"]), None);
        assert_eq!(of(&["must = 3"]), None);
        // Given data beside an acceleration plan names no plan.
        assert_eq!(of(&["Angular velocity of the crank ω1 = 10 1/s"]), None);
        assert_eq!(of(&["Угловые скорости: ω2 = 1,5 1/с", "μ = 0,05"]), None);
        assert_eq!(
            of(&["Angular velocities: ω2 = 1.5 1/s", "Acceleration plan"]),
            Some(PlanKind::Acceleration)
        );
    }

}
