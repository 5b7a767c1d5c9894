//! A plan of velocities or accelerations drawn from its construction
//! steps: the pole, absolute vectors from the pole, relative vectors and
//! laid-off components between plan points, the construction lines (thin,
//! a little past their intersection, as a draftsman draws them), similar
//! figures shaded, every plan point labelled.

use super::canvas::{Canvas, Class, FONT, Label};
use crate::construction::{Op, Plan};
use kurbo::Point;

/// How far a construction line runs past its intersection (mm).
const OVERSHOOT: f64 = 6.0;

/// Draw `plan` with its pole at the drawing origin.
pub fn draw(plan: &Plan, c: &mut Canvas, reported: &[usize]) {
    let at = |i: usize| plan.points[i].at.to_point();
    let mut used = vec![false; plan.points.len()];
    used[0] = true;
    // Construction lines and shaded figures first (under the vectors).
    for step in &plan.steps {
        match &step.op {
            Op::Intersect { lines, out, .. } => {
                for l in lines {
                    let (a, x) = (at(l.through), at(*out));
                    let d = if (x - a).hypot() > 1e-9 {
                        (x - a).normalize()
                    } else {
                        l.unit
                    };
                    c.seg(a - d * 3.0, x + d * OVERSHOOT, Class::Thin);
                    used[l.through] = true;
                }
                used[*out] = true;
            }
            Op::Similar { a, b, out, .. } => {
                c.prims.push(super::canvas::Prim::Poly {
                    pts: vec![at(*a), at(*b), at(*out)],
                    fill: "#e3e3e3",
                    stroke: 0.0,
                });
                used[*out] = true;
            }
            _ => {}
        }
    }
    // Vectors: laid-off components, relative segments, absolute vectors
    // (each drawn once: a relative segment from the pole is also absolute).
    let mut drawn: Vec<(usize, usize)> = Vec::new();
    for step in &plan.steps {
        if let Op::LayOff { from, to, .. } | Op::Measure { from, to, .. } = &step.op {
            if drawn.contains(&(*from, *to)) {
                continue;
            }
            drawn.push((*from, *to));
        }
        match &step.op {
            Op::LayOff { from, to, .. } => {
                c.vector(
                    at(*from),
                    at(*to),
                    if *from == 0 {
                        Class::Main
                    } else {
                        Class::Vector
                    },
                    Some(format!(
                        "vec-{}-{}",
                        plan.points[*from].key, plan.points[*to].key
                    )),
                );
                used[*from] = true;
                used[*to] = true;
            }
            Op::Measure {
                from,
                to,
                rate: Some(_),
                ..
            } => {
                c.vector(
                    at(*from),
                    at(*to),
                    Class::Vector,
                    Some(format!(
                        "vec-{}-{}",
                        plan.points[*from].key, plan.points[*to].key
                    )),
                );
                used[*to] = true;
            }
            Op::Measure {
                from: 0,
                to,
                rate: None,
                ..
            } => {
                c.vector(
                    at(0),
                    at(*to),
                    Class::Main,
                    Some(format!(
                        "vec-{}-{}",
                        plan.points[0].key, plan.points[*to].key
                    )),
                );
                used[*to] = true;
            }
            Op::Divide { out, .. } | Op::Coincide { out, .. } => used[*out] = true,
            _ => {}
        }
    }
    for &p in reported {
        if let Some(i) = plan.of_point[p] {
            used[i] = true;
        }
    }
    // Labels: points at one place share one label ("p_v, o1, o2").
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
    }
    for (p, members) in groups {
        let first = &plan.points[members[0]];
        let rest: Vec<String> = members[1..]
            .iter()
            .map(|&i| plan.points[i].name())
            .collect();
        // The first keeps its subscript; the others follow as plain names.
        let mut label = Label::new(first.label.0.clone(), first.label.1.clone());
        if !rest.is_empty() {
            label = label.with_tail(format!(", {}", rest.join(", ")));
        }
        c.label(p, label, FONT, Some(format!("label-{}", first.key)));
    }
}
