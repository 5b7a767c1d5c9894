//! A plan of velocities or accelerations drawn from its construction
//! steps: the pole, absolute vectors from the pole, relative vectors and
//! laid-off components between plan points (the relative slide along a
//! guide too), the construction lines (thin, a little past their
//! intersection, as a draftsman draws them), similar figures shaded and
//! outlined, every plan point labelled.

use super::canvas::{Canvas, Class, FONT, Label, Line};
use crate::kinematics::construction::{Dir, Op, Plan};
use kurbo::Point;

/// How far a construction line runs past its intersection (mm).
const OVERSHOOT: f64 = 6.0;

/// Draw `plan` with its pole at the drawing origin.
pub fn draw(plan: &Plan, c: &mut Canvas, reported: &[usize]) {
    draw_steps(plan, c, reported);
}

/// The step (index into `plan.steps`) that puts each plan point on the
/// plan: the pole, a laid-off vector's end, an intersection, a point of a
/// similar figure, a divided segment, a coinciding point.
pub fn made_at(plan: &Plan) -> Vec<Option<usize>> {
    let mut made = vec![None; plan.points.len()];
    for (k, step) in plan.steps.iter().enumerate() {
        let out = match &step.op {
            Op::Pole { .. } => 0,
            Op::LayOff { to, .. } => *to,
            Op::Intersect { out, .. }
            | Op::Similar { out, .. }
            | Op::Divide { out, .. }
            | Op::Coincide { out, .. } => *out,
            _ => continue,
        };
        made[out].get_or_insert(k);
    }
    made
}

/// [`draw`], telling which step drew what: for each primitive added to
/// `c`, in order, the index of its step in `plan.steps` (a point's dot and
/// label: the step that made the point, the first made of a shared
/// label's points). For drawing a plan step by step (the HTML handout).
pub fn draw_steps(plan: &Plan, c: &mut Canvas, reported: &[usize]) -> Vec<usize> {
    let start = c.prims.len();
    let mut steps: Vec<usize> = Vec::new();
    let mut tag = |c: &Canvas, k: usize| steps.resize(c.prims.len() - start, k);
    let made = made_at(plan);
    let made_of = |members: &[usize]| members.iter().filter_map(|&i| made[i]).min().unwrap_or(0);
    let at = |i: usize| plan.points[i].at.to_point();
    let mut used = vec![false; plan.points.len()];
    used[0] = true;
    // Construction lines and shaded figures first (under the vectors).
    for (k, step) in plan.steps.iter().enumerate() {
        match &step.op {
            Op::Intersect { lines, out, .. } => {
                for l in lines {
                    let (a, x) = (at(l.through), at(*out));
                    let d = if (x - a).hypot() > 1e-9 {
                        (x - a).normalize()
                    } else {
                        l.unit
                    };
                    c.path(vec![a - d * 3.0, x + d * OVERSHOOT], Line::Dashed);
                    used[l.through] = true;
                }
                used[*out] = true;
            }
            Op::Similar { a, b, out, .. } => {
                c.prims.push(super::canvas::Prim::Poly {
                    pts: vec![at(*a), at(*b), at(*out)],
                    fill: "#e3e3e3",
                    stroke: 0.25,
                });
                used[*out] = true;
            }
            _ => {}
        }
        tag(c, k);
    }
    // Vectors: laid-off components, relative segments (of rotation and of
    // sliding along a guide), absolute vectors; each drawn once.
    let mut drawn: Vec<(usize, usize)> = Vec::new();
    let mut vector =
        |c: &mut Canvas, from: usize, to: usize, class: Class, used: &mut Vec<bool>| {
            if drawn.contains(&(from, to)) {
                return;
            }
            drawn.push((from, to));
            c.vector(
                at(from),
                at(to),
                class,
                Some(format!(
                    "vec-{}-{}",
                    plan.points[from].key, plan.points[to].key
                )),
            );
            used[from] = true;
            used[to] = true;
        };
    for (k, step) in plan.steps.iter().enumerate() {
        match &step.op {
            Op::LayOff { from, to, .. } => vector(
                c,
                *from,
                *to,
                if *from == 0 {
                    Class::Main
                } else {
                    Class::Vector
                },
                &mut used,
            ),
            Op::Intersect { lines, out, .. } => {
                for l in lines {
                    if matches!(l.dir, Dir::Guide(_)) {
                        vector(c, l.through, *out, Class::Vector, &mut used);
                    }
                }
            }
            Op::Measure {
                from,
                to,
                rate: Some(_),
                ..
            } => vector(c, *from, *to, Class::Vector, &mut used),
            Op::Measure {
                from: 0,
                to,
                rate: None,
                ..
            } => vector(c, 0, *to, Class::Main, &mut used),
            Op::Divide { out, .. } | Op::Coincide { out, .. } => used[*out] = true,
            _ => {}
        }
        tag(c, k);
    }
    // The segments divided by similarity (ab for s₂ on AB): on an
    // acceleration plan no vector joins a and b, and s₂ would float.
    for (k, step) in plan.steps.iter().enumerate() {
        if let Op::Divide { a, b, .. } = step.op {
            let joined = drawn.contains(&(a, b)) || drawn.contains(&(b, a));
            if !joined && (at(a) - at(b)).hypot() > 1e-6 {
                c.seg(at(a), at(b), Class::Thin);
                drawn.push((a, b));
                used[a] = true;
                used[b] = true;
            }
        }
        tag(c, k);
    }
    for &p in reported {
        if let Some(i) = plan.of_point[p] {
            used[i] = true;
        }
    }
    // Labels: points at one place share one label ("p_v, o₁, o₂").
    let mut groups: Vec<(Point, Vec<usize>)> = Vec::new();
    for (i, u) in used.iter().enumerate() {
        if !u {
            continue;
        }
        let p = at(i);
        match groups.iter_mut().find(|g| (g.0 - p).hypot() < 0.05) {
            Some(g) => g.1.push(i),
            None => groups.push((p, vec![i])),
        }
    }
    for (p, members) in &groups {
        c.dot(*p, format!("pt-{}", plan.points[members[0]].key));
        tag(c, made_of(members));
    }
    for (p, members) in groups {
        let first = &plan.points[members[0]];
        let mut label = Label::new(first.label.0.clone(), first.label.1.clone());
        for &i in &members[1..] {
            let q = &plan.points[i];
            label = label.and(q.label.0.clone(), q.label.1.clone());
        }
        c.label(p, label, FONT, Some(format!("label-{}", first.key)));
        tag(c, made_of(&members));
    }
    steps
}
