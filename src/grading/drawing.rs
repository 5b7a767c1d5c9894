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
}

/// The scale a drawing states in a text such as "μ_v = 0.01 (m/s)/mm",
/// "μ_F = 2 N/mm" (`prefix`: "" for any μ, "_F" for a force plan's).
pub(crate) fn stated_mu(labels: &[(String, Point)], prefix: &str) -> Option<f64> {
    labels.iter().find_map(|(s, _)| {
        let s = s.replace(' ', "");
        // The Greek letter, the micro sign (a code page's μ) or "mu".
        let rest = s
            .strip_prefix('μ')
            .or_else(|| s.strip_prefix('µ'))
            .or_else(|| s.strip_prefix("mu"))?;
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
    })
}

/// The names of the pole a drawing may have.
const POLE_NAMES: [&str; 5] = ["p_v", "pv", "p", "p_a", "pa"];

fn is_pole(name: &str) -> bool {
    POLE_NAMES.contains(&name.to_lowercase().as_str())
}

/// A problem of the drawing as a whole: no pointer ("svg" would be read as
/// the option --svg); the file is named by the caller.
pub(super) fn whole(message: &str) -> Error {
    Error::fields(vec![Issue {
        pointer: String::new(),
        message: message.into(),
    }])
}

/// The pole's label (p_v, p_a …) and where it is.
fn pole_label(labels: &[(String, Point)]) -> Result<(String, Point)> {
    labels
        .iter()
        .find(|(s, _)| is_pole(s))
        .cloned()
        .ok_or_else(|| whole("no pole: label the pole p_v (or p_a)"))
}

/// The line end the pole's label at `at` names.
fn pole_end(ends: &Ends, at: Point) -> Result<Point> {
    ends.snap(at)
        .ok_or_else(|| whole("the pole's label is not next to any line's end"))
}

/// Where a drawing's pole is (its coordinates, mm): the line end its
/// label names, as [`answer_of`] finds it.
pub(super) fn pole_of(drawing: &Drawing) -> Result<Point> {
    let (_, at) = pole_label(&drawing.labels)?;
    let ends = Ends::new(drawing.lines.iter().flatten().copied().collect());
    pole_end(&ends, at)
}

/// A drawing read as an answer. `mu`, `plan` come from the command line
/// when the drawing does not state them (a "μ = 0.01" text, and the pole's
/// label p_v / p_a); a plan asked that the pole's label contradicts is
/// refused.
pub(super) fn answer_of(
    drawing: Drawing,
    mu: Option<f64>,
    plan: Option<PlanKind>,
    delta: f64,
    position: super::position::StatedPosition,
) -> Result<Answer> {
    let Drawing { labels, lines, kind } = drawing;
    let ends: Vec<Point> = lines.into_iter().flatten().collect();
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
    let (pole_name, pole_at) = pole_label(&labels)?;
    let plan = plan_of(&pole_name, plan, stated_plan(&labels))?;
    let ends = Ends::new(ends);
    let pole = pole_end(&ends, pole_at)?;
    // The pole labelled again at another line end: which is the pole?
    let other_pole = labels
        .iter()
        .filter(|(s, _)| is_pole(s))
        .find_map(|(s, at)| ends.snap(*at).filter(|e| *e != pole).map(|e| (s, e)));
    if let Some((s, e)) = other_pole {
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
    Ok(Answer {
        plan,
        position,
        mu,
        delta,
        items: points(&labels, &ends, pole, kind)?,
        mu_v: None,
        stated: Vec::new(),
    })
}

/// The plan a drawing's texts name, when they name one only: the scale's
/// subscript (`μv = …`, `μ_a = …`, `mu_v = …`) or a title ("Velocity
/// plan", "План швидкостей", "План ускорений" …).
pub(crate) fn stated_plan(labels: &[(String, Point)]) -> Option<PlanKind> {
    let mut named = labels.iter().filter_map(|(s, _)| {
        let t = s.to_lowercase().replace([' ', '_', '{', '}'], "");
        let scale = t
            .strip_prefix('μ')
            .or_else(|| t.strip_prefix('µ'))
            .or_else(|| t.strip_prefix("mu"))
            .filter(|r| r.contains('='));
        if let Some(r) = scale {
            // MTEXT's stacked subscript read as its letters: "μ\\s^v;".
            let r = r.trim_start_matches("\\s^");
            return match r.chars().next() {
                Some('v') => Some(PlanKind::Velocity),
                Some('a') => Some(PlanKind::Acceleration),
                _ => None,
            };
        }
        // A title: a text about a plan. Velocities named elsewhere (given
        // data beside an acceleration plan: "angular velocity ω1 = 10
        // 1/s", "угловые скорости") name no plan.
        // The word itself ("plan", "plans", "план", "плани"), not a
        // part of another ("explanation").
        let about_a_plan = s
            .to_lowercase()
            .split(|c: char| !c.is_alphanumeric())
            .any(|w| w.starts_with("plan") || w.starts_with("план"));
        if !about_a_plan {
            return None;
        }
        let velocity = ["velocit", "швидкост", "скорост"].iter().any(|w| t.contains(w));
        let acceleration = ["accelera", "прискорен", "ускорен"].iter().any(|w| t.contains(w));
        match (velocity, acceleration) {
            (true, false) => Some(PlanKind::Velocity),
            (false, true) => Some(PlanKind::Acceleration),
            _ => None,
        }
    });
    let first = named.next()?;
    named.all(|k| k == first).then_some(first)
}

/// The plan a drawing is of: `asked` (--plan), else the one the pole's
/// label `pole` names, else the one the drawing's texts name (`stated`);
/// --plan and the pole's label must agree (a velocity plan's pole is p_v,
/// an acceleration plan's p_a).
fn plan_of(pole: &str, asked: Option<PlanKind>, stated: Option<PlanKind>) -> Result<PlanKind> {
    let labelled = match pole.to_lowercase().as_str() {
        "p_v" | "pv" => Some(PlanKind::Velocity),
        "p_a" | "pa" => Some(PlanKind::Acceleration),
        _ => None,
    };
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
                "the plan asked is the {} plan, but the drawing's pole is labelled \"{pole}\", the {} plan's pole: give --plan {} or label the pole {}",
                name(p),
                name(l),
                name(l),
                if p == PlanKind::Velocity { "p_v" } else { "p_a" }
            ),
        )),
        (Some(p), _) | (None, Some(p)) => Ok(p),
        (None, None) => stated.ok_or_else(|| {
            whole(
                "which plan is it? label the pole p_v or p_a, write the scale as μ_v = … or μ_a = …, or give --plan",
            )
        }),
    }
}

/// The labelled points of a drawing: each label (but the pole's and
/// texts with "=") at the line end nearest to it, mm from the `pole`'s
/// end, y up; a place off any sheet is refused.
fn points(
    labels: &[(String, Point)],
    ends: &Ends,
    pole: Point,
    kind: &str,
) -> Result<Vec<Item>> {
    let mut items: Vec<Item> = Vec::new();
    let mut issues = Vec::new();
    // The labels read so far: (name in lower case, place's bits).
    let mut read: HashSet<(String, [u64; 2])> = HashSet::new();
    for (name, at) in labels {
        if name.is_empty() || is_pole(name) || name.contains('=') {
            continue;
        }
        let Some(e) = ends.snap(*at) else { continue };
        let rel = e - pole;
        // One label at the same line end twice (a copied text) is one
        // point labelled twice; at another end it gives a second place,
        // refused when the names are resolved (`items::given_twice`).
        if !read.insert((name.to_lowercase(), [rel.x.to_bits(), (-rel.y).to_bits()])) {
            continue;
        }
        let pointer = format!("{kind}: label {name}");
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
        return Err(whole("no labelled points next to line ends were found"));
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
