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

/// [`draw`] with the points' labels left waiting ([`Canvas::label_later`]):
/// a drawing that adds marks over the plan (a check's overlay) places
/// them once everything is drawn, clear of those marks too.
pub fn draw_labels_later(plan: &Plan, c: &mut Canvas, reported: &[usize]) {
    steps_drawn(plan, c, reported, true);
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
    steps_drawn(plan, c, reported, false)
}

/// [`draw_steps`], its labels placed at once or left waiting (`later`).
fn steps_drawn(plan: &Plan, c: &mut Canvas, reported: &[usize], later: bool) -> Vec<usize> {
    let mut d = Steps {
        later,
        plan,
        start: c.prims.len(),
        steps: Vec::new(),
        used: vec![false; plan.points.len()],
        drawn: Vec::new(),
    };
    d.used[0] = true;
    // Construction lines and shaded figures first (under the vectors).
    d.construction(c);
    d.vectors(c);
    d.divided(c);
    for &p in reported {
        if let Some(i) = plan.of_point[p] {
            d.used[i] = true;
        }
    }
    d.labels(c);
    d.steps
}

/// A plan being drawn: the step of each primitive added since `start`,
/// the plan points shown (`used`) and the vectors drawn.
struct Steps<'a> {
    /// The labels left waiting for [`Canvas::place_pending`].
    later: bool,
    plan: &'a Plan,
    start: usize,
    steps: Vec<usize>,
    used: Vec<bool>,
    drawn: Vec<(usize, usize)>,
}

impl Steps<'_> {
    /// The primitives added since the last tag are step `k`'s.
    fn tag(&mut self, c: &Canvas, k: usize) {
        self.steps.resize(c.prims.len() - self.start, k);
    }

    fn at(&self, i: usize) -> Point {
        self.plan.points[i].at.to_point()
    }

    /// The construction lines (thin, a little past their intersection)
    /// and the similar figures, shaded.
    fn construction(&mut self, c: &mut Canvas) {
        for (k, step) in self.plan.steps.iter().enumerate() {
            match &step.op {
                Op::Intersect { lines, out, .. } => {
                    for l in lines {
                        let (a, x) = (self.at(l.through), self.at(*out));
                        let d = if (x - a).hypot() > 1e-9 {
                            (x - a).normalize()
                        } else {
                            l.unit
                        };
                        c.path(vec![a - d * 3.0, x + d * OVERSHOOT], Line::Dashed);
                        self.used[l.through] = true;
                    }
                    self.used[*out] = true;
                }
                Op::Similar { a, b, out, .. } => {
                    c.prims.push(super::canvas::Prim::Poly {
                        pts: vec![self.at(*a), self.at(*b), self.at(*out)],
                        fill: "#e3e3e3",
                        stroke: 0.25,
                        id: None,
                    });
                    self.used[*out] = true;
                }
                _ => {}
            }
            self.tag(c, k);
        }
    }

    /// The vector `from` → `to`, once: once too where other plan points
    /// at the same two places drew it already (the shaper's p_v → k′, m, t
    /// of the translating ram lie on d₀ → d₅: one arrow, not four).
    fn vector(&mut self, c: &mut Canvas, from: usize, to: usize, class: Class) {
        let same = |p: Point, q: Point| (p - q).hypot() < 0.05;
        let (a, b) = (self.at(from), self.at(to));
        let twice = self
            .drawn
            .iter()
            .any(|&(f, t)| same(self.at(f), a) && same(self.at(t), b));
        self.drawn.push((from, to));
        if twice {
            self.used[from] = true;
            self.used[to] = true;
            return;
        }
        let p = &self.plan.points;
        c.vector(
            self.at(from),
            self.at(to),
            class,
            Some(format!("vec-{}-{}", p[from].key, p[to].key)),
        );
        self.used[from] = true;
        self.used[to] = true;
    }

    /// Vectors: laid-off components, relative segments (of rotation and
    /// of sliding along a guide), absolute vectors; each drawn once.
    fn vectors(&mut self, c: &mut Canvas) {
        for (k, step) in self.plan.steps.iter().enumerate() {
            match &step.op {
                Op::LayOff { from, to, .. } => {
                    let class = if *from == 0 {
                        Class::Main
                    } else {
                        Class::Vector
                    };
                    self.vector(c, *from, *to, class);
                }
                Op::Intersect { lines, out, .. } => {
                    for l in lines {
                        if matches!(l.dir, Dir::Guide(_)) {
                            self.vector(c, l.through, *out, Class::Vector);
                        }
                    }
                }
                Op::Measure {
                    from,
                    to,
                    rate: Some(_),
                    ..
                } => self.vector(c, *from, *to, Class::Vector),
                Op::Measure {
                    from: 0,
                    to,
                    rate: None,
                    ..
                } => self.vector(c, 0, *to, Class::Main),
                Op::Divide { out, .. } | Op::Coincide { out, .. } => self.used[*out] = true,
                _ => {}
            }
            self.tag(c, k);
        }
    }

    /// The segments divided by similarity (ab for s₂ on AB): on an
    /// acceleration plan no vector joins a and b, and s₂ would float.
    fn divided(&mut self, c: &mut Canvas) {
        for (k, step) in self.plan.steps.iter().enumerate() {
            if let Op::Divide { a, b, .. } = step.op {
                let joined = self.drawn.contains(&(a, b)) || self.drawn.contains(&(b, a));
                if !joined && (self.at(a) - self.at(b)).hypot() > 1e-6 {
                    c.seg(self.at(a), self.at(b), Class::Thin);
                    self.drawn.push((a, b));
                    self.used[a] = true;
                    self.used[b] = true;
                }
            }
            self.tag(c, k);
        }
    }

    /// The shown points' dots and labels: points at one place share one
    /// label ("p_v, o₁, o₂"), of the step that made the first of them. A
    /// point that only coincides with another by a step of its own (a
    /// point of the frame at the pole, a point of a translating link at
    /// the point that link's motion was found at) is not named again: the
    /// lecture's plan of Fig. 2.11 shows d₅ alone for the ram, not "d₅, k′,
    /// m, t", and p_v alone, never the frame's d₀ (steps and tables still
    /// name them, "point k′ coincides with d₅").
    fn labels(&mut self, c: &mut Canvas) {
        let plan = self.plan;
        let made = made_at(plan);
        let made_of =
            |members: &[usize]| members.iter().filter_map(|&i| made[i]).min().unwrap_or(0);
        let mut groups: Vec<(Point, Vec<usize>)> = Vec::new();
        for (i, u) in self.used.iter().enumerate() {
            if !u {
                continue;
            }
            let p = self.at(i);
            match groups.iter_mut().find(|g| (g.0 - p).hypot() < 0.05) {
                Some(g) => g.1.push(i),
                None => groups.push((p, vec![i])),
            }
        }
        for (_, members) in groups.iter_mut() {
            *members = named(plan, members);
        }
        for (p, members) in &groups {
            c.dot(*p, format!("pt-{}", plan.points[members[0]].key));
            self.tag(c, made_of(members));
        }
        for (p, members) in groups {
            let first = &plan.points[members[0]];
            let mut label = Label::new(first.label.0.clone(), first.label.1.clone());
            for &i in &members[1..] {
                let q = &plan.points[i];
                label = label.and(q.label.0.clone(), q.label.1.clone());
            }
            let id = Some(format!("label-{}", first.key));
            if self.later {
                c.label_later(p, label, FONT, id);
            } else {
                c.label(p, label, FONT, id);
            }
            self.tag(c, made_of(&members));
        }
    }
}

/// Of the plan points `members` at one place, those its label names: not
/// a point that only coincides with another of them by a step of its own
/// (the frame's d₀ at the pole, a translating ram's k′, m, t at d₅), as
/// the lecture names them; all of them where that would name none.
pub(super) fn named(plan: &Plan, members: &[usize]) -> Vec<usize> {
    let echo = |i: usize| {
        plan.steps.iter().any(|s| {
            matches!(s.op, Op::Coincide { out, with, .. } if out == i && members.contains(&with))
        })
    };
    let shown: Vec<usize> = members.iter().copied().filter(|&i| !echo(i)).collect();
    if shown.is_empty() {
        members.to_vec()
    } else {
        shown
    }
}
