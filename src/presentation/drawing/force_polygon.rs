//! A force polygon drawn from its plan (`kinetostatics::force_plan`): the
//! known vectors laid off head to tail, the two lines of known direction
//! that close it (dashed, a little past where they meet), the components
//! along them, and the reactions read off, bold; every vector named. The
//! plan's points are drawn as they are, `k` times enlarged (a drawing at
//! μ_F shows the plan built at its own μ: k = μ_plan / μ_F), so that what
//! is drawn is the construction itself.

use super::canvas::{Canvas, Class, FONT, Line};
use crate::kinetostatics::force_plan::{Force, ForcePlan, ForceStep, Part};
use crate::presentation::drawing::canvas::Label;
use kurbo::Point;

/// How far a closing line runs past the meeting point, and before the
/// point it is drawn through (mm).
const OVERSHOOT: f64 = 6.0;
const LEAD: f64 = 3.0;

/// The drawn place of plan point `i` at `k` mm per plan mm (the start at
/// the drawing's origin).
pub fn at(plan: &ForcePlan, i: usize, k: f64) -> Option<Point> {
    plan.points.get(i).map(|p| (*p * k).to_point())
}

/// Draw `plan` at `k` times its size, naming each force by `name`; ids
/// start with `tag`: `{tag}-vec-{from}-{to}` for the vectors (the plan's
/// point numbers), `{tag}-pt-{i}` for the points. Its details (local
/// enlargements) beside it in a row, or with `column` (a box taller than
/// wide) one above the other.
pub fn draw(
    plan: &ForcePlan,
    name: &dyn Fn(Force) -> Option<Label>,
    c: &mut Canvas,
    (k, column): (f64, bool),
    tag: &str,
) {
    let pt = |i: usize| at(plan, i, k);
    let mut used = vec![false; plan.points.len()];
    // The closing lines under the vectors.
    let mut components: Vec<(usize, usize, Force)> = Vec::new();
    for st in &plan.steps {
        let ForceStep::Intersect { lines, out, .. } = st else {
            continue;
        };
        for (j, &li) in lines.iter().enumerate() {
            let Some(l) = plan.lines.get(li) else {
                continue;
            };
            let (Some(a), Some(x)) = (pt(l.through), pt(*out)) else {
                continue;
            };
            let d = if (x - a).hypot() > 1e-9 {
                (x - a).normalize()
            } else {
                l.dir
            };
            c.path(vec![a - d * LEAD, x + d * OVERSHOOT], Line::Dashed);
            used[l.through] = true;
            used[*out] = true;
            // The component along the line: from the meeting point back to
            // the start (the first line's), or on to it (the second's).
            if let Force::Reaction {
                part: Part::Normal | Part::AcrossGuide,
                ..
            } = l.force
            {
                let (from, to) = if j == 0 {
                    (*out, l.through)
                } else {
                    (l.through, *out)
                };
                components.push((from, to, l.force));
            }
        }
    }
    let found = |vi: usize| plan.steps.contains(&ForceStep::Measure(vi));
    // Each segment once: a reaction laid off and read off again (RPR) is
    // drawn bold.
    let mut segs: Vec<(usize, usize, Force, Class)> = Vec::new();
    for (vi, v) in plan.vectors.iter().enumerate() {
        let class = if found(vi) {
            Class::Bold
        } else {
            Class::Vector
        };
        match segs
            .iter_mut()
            .find(|s| (s.0, s.1) == (v.from, v.to) && s.2 == v.force)
        {
            Some(s) => {
                if class == Class::Bold {
                    s.3 = class;
                }
            }
            None => segs.push((v.from, v.to, v.force, class)),
        }
    }
    for (from, to, force) in components {
        segs.push((from, to, force, Class::Vector));
    }
    // Vectors too short to carry their names where they are drawn stand
    // again in a local enlargement beside the polygon (ГОСТ 2.305's
    // detail, "I (5:1)"), named there and not on the polygon.
    let details = details(&segs, &pt);
    let in_detail = |from: usize, to: usize| details.iter().any(|d| d.segs.contains(&(from, to)));
    for &(from, to, force, class) in &segs {
        let (Some(a), Some(b)) = (pt(from), pt(to)) else {
            continue;
        };
        used[from] = true;
        used[to] = true;
        let id = format!("{tag}-vec-{from}-{to}");
        c.vector(a, b, class, Some(id.clone()));
        if in_detail(from, to) {
            continue;
        }
        if let Some(label) = name(force) {
            c.label_later(a.midpoint(b), label, FONT, Some(format!("{id}-label")));
        }
    }
    for (i, u) in used.iter().enumerate() {
        if let (true, Some(p)) = (*u, pt(i)) {
            c.dot(p, format!("{tag}-pt-{i}"));
        }
    }
    c.place_pending();
    draw_details(&details, &segs, &pt, name, c, (tag, column));
}

/// The local enlargements `details` of a polygon drawn in `c` (its
/// segments `segs`, its points at `pt`): a numbered ring round each on the
/// polygon, and beside the polygon the vectors again, enlarged and named,
/// under their designation "I (5:1)".
fn draw_details(
    details: &[Detail],
    segs: &[(usize, usize, Force, Class)],
    pt: &dyn Fn(usize) -> Option<Point>,
    name: &dyn Fn(Force) -> Option<Label>,
    c: &mut Canvas,
    (tag, column): (&str, bool),
) {
    let mut x = c.bounds().x1 + DETAIL_GAP;
    let mut top = c.bounds().y0;
    for (n, d) in details.iter().enumerate() {
        let numeral = ["I", "II", "III", "IV"][n];
        // On the polygon: a thin circle round the short vectors, numbered.
        let centre = d.area.center();
        let r = (0.5 * d.area.width().hypot(d.area.height()) + 1.5).max(2.5);
        c.ring(centre, r, format!("{tag}-d{}", n + 1));
        c.label_later(
            centre + kurbo::Vec2::new(r, -r) * std::f64::consts::FRAC_1_SQRT_2,
            Label::new(numeral, ""),
            FONT,
            Some(format!("{tag}-d{}-mark", n + 1)),
        );
        c.place_pending();
        // Beside it: the same vectors `m` times larger, named.
        let m = d.scale;
        let o = Point::new(x + d.area.width() * m / 2.0 + 2.0, top + d.area.height() * m / 2.0 + 8.0);
        let place = |p: Point| o + (p - centre) * m;
        // Its designation over it, as ГОСТ 2.305 writes a detail's.
        c.text(
            Point::new(o.x - d.area.width() * m / 2.0, o.y + d.area.height() * m / 2.0 + 6.0),
            Label::new(format!("{numeral} ({}:1)", m), ""),
            FONT,
            "caption",
        );
        for &(from, to, force, class) in segs.iter().filter(|s| d.segs.contains(&(s.0, s.1))) {
            let (Some(a), Some(b)) = (pt(from), pt(to)) else {
                continue;
            };
            let id = format!("{tag}-d{}-vec-{from}-{to}", n + 1);
            c.vector(place(a), place(b), class, Some(id.clone()));
            if let Some(label) = name(force) {
                c.label_later(place(a).midpoint(place(b)), label, FONT, Some(format!("{id}-label")));
            }
        }
        c.place_pending();
        if column {
            // The next above this one's designation.
            top = o.y + d.area.height() * m / 2.0 + 6.0 + FONT;
        } else {
            x = c.bounds().x1 + DETAIL_GAP;
        }
    }
}

/// Below this length (mm) a polygon's vector is too short for its name.
const SHORT: f64 = 5.0;
/// The enlargements of ГОСТ 2.302, smallest first.
const ENLARGE: [f64; 8] = [2.0, 4.0, 5.0, 10.0, 20.0, 40.0, 50.0, 100.0];
/// The largest side of a detail (mm), and its distance from the polygon.
const DETAIL_SIDE: f64 = 45.0;
const DETAIL_GAP: f64 = 8.0;

/// A local enlargement: the short vectors `segs` (from, to) within `area`
/// of the polygon, drawn `scale` times larger.
struct Detail {
    segs: Vec<(usize, usize)>,
    area: kurbo::Rect,
    scale: f64,
}

/// The details of a polygon: its vectors shorter than [`SHORT`] (and
/// longer than 0.05 mm: a vanishing force is a dot), grouped where their
/// boxes lie within 8 mm of each other, each group at the smallest
/// standard enlargement that draws its shortest vector 6 mm long; where
/// that would make the detail larger than [`DETAIL_SIDE`], its longest
/// vectors go to a detail of their own at a smaller enlargement. At most
/// four.
fn details(
    segs: &[(usize, usize, Force, Class)],
    pt: &dyn Fn(usize) -> Option<Point>,
) -> Vec<Detail> {
    type Seg = ((usize, usize), Point, Point, f64);
    let mut groups: Vec<Vec<Seg>> = Vec::new();
    for &(from, to, _, _) in segs {
        let (Some(a), Some(b)) = (pt(from), pt(to)) else {
            continue;
        };
        let len = (b - a).hypot();
        if !(0.05..SHORT).contains(&len) {
            continue;
        }
        let near = |g: &Vec<Seg>| {
            let r = g
                .iter()
                .fold(kurbo::Rect::from_points(g[0].1, g[0].2), |r, s| {
                    r.union(kurbo::Rect::from_points(s.1, s.2))
                })
                .inflate(8.0, 8.0);
            r.contains(a) || r.contains(b)
        };
        match groups.iter_mut().find(|g| near(g)) {
            Some(g) => g.push(((from, to), a, b, len)),
            None => groups.push(vec![((from, to), a, b, len)]),
        }
    }
    let area = |g: &[Seg]| {
        g.iter().fold(kurbo::Rect::from_points(g[0].1, g[0].2), |r, s| {
            r.union(kurbo::Rect::from_points(s.1, s.2))
        })
    };
    let mut out = Vec::new();
    while let Some(mut g) = groups.pop() {
        if out.len() == 4 {
            break;
        }
        g.sort_by(|x, y| x.3.total_cmp(&y.3));
        let shortest = g[0].3;
        let scale = ENLARGE
            .iter()
            .copied()
            .find(|&m| shortest * m >= 6.0)
            .unwrap_or(ENLARGE[ENLARGE.len() - 1]);
        // The shortest vectors that fit at that enlargement; the rest on.
        let mut n = g.len();
        while n > 1 && {
            let r = area(&g[..n]);
            r.width().max(r.height()) * scale > DETAIL_SIDE
        } {
            n -= 1;
        }
        let rest = g.split_off(n);
        let r = area(&g);
        if r.width().max(r.height()) * scale <= DETAIL_SIDE {
            out.push(Detail {
                segs: g.iter().map(|s| s.0).collect(),
                area: r,
                scale,
            });
        }
        if !rest.is_empty() {
            groups.push(rest);
        }
    }
    out
}

/// The forces of `plan`'s vector equation in the order they are laid off
/// round the polygon from its start: the vectors laid off, then the
/// closing ones — the second line's component from the last vector's end
/// to the meeting point and the first line's back to the start (or the
/// one reaction read off from the end back to the start).
pub fn equation_terms(plan: &ForcePlan) -> Vec<Force> {
    let mut out: Vec<Force> = Vec::new();
    let mut end = 0;
    for st in &plan.steps {
        if let ForceStep::LayOff(vi) = st
            && let Some(v) = plan.vectors.get(*vi)
        {
            out.push(v.force);
            end = v.to;
        }
    }
    let meet = plan.steps.iter().find_map(|st| match st {
        ForceStep::Intersect { lines, .. } => Some(*lines),
        _ => None,
    });
    match meet {
        Some([a, b]) => {
            out.extend(
                [b, a]
                    .iter()
                    .filter_map(|&l| plan.lines.get(l).map(|l| l.force)),
            );
        }
        None => {
            if let Some(v) = plan.vectors.iter().enumerate().find(|(vi, v)| {
                v.from == end && v.to == 0 && plan.steps.contains(&ForceStep::Measure(*vi))
            }) {
                out.push(v.1.force);
            }
        }
    }
    out
}

/// The width the equation is wrapped to at least, mm.
const EQUATION_WIDTH: f64 = 60.0;

/// The vector equation of `plan` under what `c` holds (its polygon), in
/// the order of laying off and with the polygon's names ("R^τ_34 + Φ_4 +
/// … + R^n_34 = 0"), wrapped to the polygon's width or `room` mm (the
/// width of the box it is drawn in), whichever is wider, and at least
/// [`EQUATION_WIDTH`]; its lines' ids `{tag}-equation-{j}`.
pub fn equation(
    plan: &ForcePlan,
    name: &dyn Fn(Force) -> Option<Label>,
    c: &mut Canvas,
    (tag, room): (&str, f64),
) {
    use super::canvas::{lettering, runs_width};
    use crate::words::notation::runs;
    let terms: Vec<String> = equation_terms(plan)
        .into_iter()
        .filter_map(|f| name(f).map(|l| crate::words::forces::plain(&l)))
        .collect();
    if terms.is_empty() {
        return;
    }
    let size = FONT * lettering();
    let b = c.bounds();
    let width = b.width().max(room).max(EQUATION_WIDTH);
    let wide = |s: &str| runs_width(&runs(s), size);
    let mut lines: Vec<String> = vec![String::new()];
    let n = terms.len();
    for (i, t) in terms.iter().enumerate() {
        let piece = if i + 1 == n {
            format!("{t} = 0")
        } else {
            format!("{t} +")
        };
        let last = lines.last_mut().expect("a line");
        let joined = if last.is_empty() {
            piece.clone()
        } else {
            format!("{last} {piece}")
        };
        if last.is_empty() || wide(&joined) <= width {
            *last = joined;
        } else {
            lines.push(piece);
        }
    }
    let step = 2.0 * size;
    for (j, line) in lines.iter().enumerate() {
        let at = Point::new(b.x0, b.y0 - 1.5 - 1.6 * size - j as f64 * step);
        c.rich_id(
            at,
            line,
            FONT,
            ("equation", "start"),
            format!("{tag}-equation-{j}"),
        );
    }
}
