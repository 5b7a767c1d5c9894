//! The graphical route: force plans group by group, as the course draws
//! them, from the last Assur group attached back to the input link.
//!
//! A group is cut out of the mechanism with the known loads on its links
//! and the reactions of the groups already solved (the later ones); the
//! reactions of its outer pairs are the unknowns. Each class II group has
//! a scheme (the tangential components from the moments of one link about
//! the middle joint, a projection on a guide where the middle pair is
//! prismatic), after which the force polygon of the whole group is laid
//! off at a scale μ_F and closed by the intersection of two lines of known
//! direction; the middle pair's reaction is the segment from the end of
//! the first link's loads to the closing point, and a prismatic pair's
//! couple (the place of its normal force) comes from a moment equation.
//! A cylinder (a driving slider between two moving links) is one side of
//! its group, its rod and barrel together (the moments of a set of bodies
//! in equilibrium balance whether it is rigid or not); its inner pair and
//! the drive force come from the barrel's (or rod's) own equilibrium. The
//! input link last: its balancing moment (force) and the frame's reaction.
//!
//! Every plan point carries a drafting error radius (δ per vector laid
//! off, amplified by 1/sin θ where two lines meet), as the kinematic plans
//! do; the reactions are measured off the plan. Class III groups have no
//! scheme here: their reactions come from the links' equilibrium only.

use super::loads::Load;
use super::newton_euler::guide_frame;
use crate::accuracy::ACCURACY;
use crate::error::{Error, Result};
use crate::geom::{Line, LineCut, intersect_lines, perp};
use crate::kinematics::construction::Field;
use crate::kinematics::positions::describe_input;
use crate::kinematics::solve::{Analysis, Solved};
use crate::model::scene::InputSpec;
use crate::model::structure::{AssurGroup, Conn, Dyad, InputRole, Joint, Stage};
use kurbo::{Point, Vec2};

/// Which force a vector of a plan is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Force {
    /// A known load (index into the position's loads).
    Load(usize),
    /// The reaction of link `from` on link `to` in the pair `joint`, or its
    /// component.
    Reaction {
        from: usize,
        to: usize,
        joint: Joint,
        part: Part,
    },
    /// The drive force of input `input` (a driving slider) on link `on`.
    Drive { input: usize, on: usize },
}

/// A reaction whole, or its component found first.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Part {
    Whole,
    /// Perpendicular to the link's line (from a moment equation).
    Tangential,
    /// Along the link's line (closing the polygon).
    Normal,
    /// Along the guide of the middle prismatic pair (from a projection).
    AlongGuide,
    /// Perpendicular to that guide (closing the polygon).
    AcrossGuide,
}

/// A vector of the plan: from plan point `from` to `to`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Drawn {
    pub from: usize,
    pub to: usize,
    pub force: Force,
    /// The real force, N (measured off the plan for the unknowns).
    pub value: Vec2,
}

/// A line drawn to close the polygon: through plan point `through`, in
/// direction `dir`, the line of `force`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DrawnLine {
    pub through: usize,
    pub dir: Vec2,
    pub force: Force,
}

/// One step of a force plan, for the steps in words.
#[derive(Clone, Debug, PartialEq)]
pub enum ForceStep {
    /// ΣM about point `about` of `links` = 0 gives `force` (a scalar along
    /// its known direction), N; or a couple (`force` a prismatic pair's).
    Moment {
        links: Vec<usize>,
        about: Point,
        about_name: Option<usize>,
        force: Force,
        value: f64,
    },
    /// The projection of `links`' equilibrium on a guide gives `force`.
    Projection {
        links: Vec<usize>,
        force: Force,
        value: f64,
    },
    /// Vector `Drawn` number `.0` laid off.
    LayOff(usize),
    /// Line number `.0` drawn.
    Line(usize),
    /// Lines `a`, `b` meet at plan point `out`, at sine `sin`.
    Intersect {
        lines: [usize; 2],
        out: usize,
        sin: f64,
    },
    /// The closing vector: the reaction read off the polygon.
    Measure(usize),
    /// The couple of a prismatic pair (the place of its normal force) from
    /// the moments of `links`: `value`, N·m; the force acts at `at`.
    Couple {
        links: Vec<usize>,
        force: Force,
        value: f64,
        at: Option<Point>,
    },
    /// The balancing moment (force) of input `input` from the input link's
    /// equilibrium.
    Balancing { input: usize, value: f64 },
}

/// The force plan of one Assur group (or of an input link).
#[derive(Clone, Debug, PartialEq)]
pub struct ForcePlan {
    /// The group (index into `Structure::groups`); `None`: an input link.
    pub group: Option<usize>,
    /// The input (scene order) when `group` is `None`.
    pub input: Option<usize>,
    /// The links cut out.
    pub links: Vec<usize>,
    /// Scale, N per mm.
    pub mu: f64,
    /// Pencil precision δ, mm.
    pub delta: f64,
    /// Plan points, mm from the first (the start of the polygon).
    pub points: Vec<Vec2>,
    /// Their drafting error radii, mm.
    pub err: Vec<f64>,
    pub vectors: Vec<Drawn>,
    pub lines: Vec<DrawnLine>,
    pub steps: Vec<ForceStep>,
    /// The smallest sine of the lines' meeting (1: none).
    pub worst_sin: f64,
}

/// Every pair's reaction as the force plans find it (the conventions of
/// [`super::newton_euler::Unknowns`]), and the plans.
#[derive(Clone, Debug, PartialEq)]
pub struct ForcePlans {
    pub plans: Vec<ForcePlan>,
    /// Per revolute pair: the force of its first link on its second, N.
    pub revolute: Vec<Option<Vec2>>,
    /// Per prismatic pair: the guide's normal force on the slider along
    /// the guide's left normal, N, and its couple about the pair's point.
    pub prismatic: Vec<Option<(f64, f64)>>,
    /// Per input: the balancing moment (force).
    pub drives: Vec<Option<f64>>,
}

/// A force known on a link: a load, or a reaction found (of a later group
/// on this link).
#[derive(Clone, Copy, Debug)]
struct Applied {
    link: usize,
    at: Point,
    f: Vec2,
    couple: f64,
    force: Force,
}

impl Applied {
    fn moment_about(&self, p: Point) -> f64 {
        (self.at - p).cross(self.f) + self.couple
    }
}

/// What acts on a set of links: its forces (the polygon's vectors, in
/// order) and its moment about any point.
struct Side<'a> {
    links: Vec<usize>,
    known: &'a [Applied],
}

impl Side<'_> {
    fn has(&self, l: usize) -> bool {
        self.links.contains(&l)
    }
    fn forces(&self) -> impl Iterator<Item = &Applied> {
        self.known.iter().filter(|a| self.has(a.link))
    }
    fn sum(&self) -> Vec2 {
        self.forces().fold(Vec2::ZERO, |s, a| s + a.f)
    }
    fn moment_about(&self, p: Point) -> f64 {
        self.forces().map(|a| a.moment_about(p)).sum()
    }
}

/// A plan being drawn at scale `mu`.
struct Draft {
    plan: ForcePlan,
}

impl Draft {
    fn new(mu: f64, delta: f64) -> Draft {
        Draft {
            plan: ForcePlan {
                group: None,
                input: None,
                links: Vec::new(),
                mu,
                delta,
                points: vec![Vec2::ZERO],
                err: vec![0.0],
                vectors: Vec::new(),
                lines: Vec::new(),
                steps: Vec::new(),
                worst_sin: 1.0,
            },
        }
    }
    fn last(&self) -> usize {
        self.plan.points.len() - 1
    }
    /// Lay off `f` from the last point (a zero force is not drawn).
    fn lay_off(&mut self, f: Vec2, force: Force) {
        if f == Vec2::ZERO {
            return;
        }
        let p = &mut self.plan;
        let from = p.points.len() - 1;
        p.points.push(p.points[from] + f / p.mu);
        p.err.push(p.err[from] + p.delta);
        p.vectors.push(Drawn {
            from,
            to: from + 1,
            force,
            value: f,
        });
        p.steps.push(ForceStep::LayOff(p.vectors.len() - 1));
    }
    fn line(&mut self, through: usize, dir: Vec2, force: Force) -> usize {
        let p = &mut self.plan;
        p.lines.push(DrawnLine {
            through,
            dir: dir.normalize(),
            force,
        });
        p.steps.push(ForceStep::Line(p.lines.len() - 1));
        p.lines.len() - 1
    }
    /// Where lines `a` and `b` meet: a new plan point.
    fn meet(&mut self, a: usize, b: usize, at: &dyn Fn() -> String) -> Result<usize> {
        let p = &mut self.plan;
        let line = |i: usize| Line {
            point: p.points[p.lines[i].through].to_point(),
            dir: p.lines[i].dir,
        };
        let LineCut::Point { at: x, sin_angle } =
            intersect_lines(&line(a), &line(b), ACCURACY.min_line_sine)
        else {
            return Err(Error::singular(
                at(),
                "on the force plan the lines of the two unknown reactions are parallel: the group's reactions are not determined",
            ));
        };
        let err = (p.err[p.lines[a].through] + p.delta).hypot(p.err[p.lines[b].through] + p.delta)
            / sin_angle;
        p.points.push(x.to_vec2());
        p.err.push(err);
        p.worst_sin = p.worst_sin.min(sin_angle);
        let out = p.points.len() - 1;
        p.steps.push(ForceStep::Intersect {
            lines: [a, b],
            out,
            sin: sin_angle,
        });
        Ok(out)
    }
    /// The vector from plan point `from` to `to`, measured: `force`.
    fn measure(&mut self, from: usize, to: usize, force: Force) -> Vec2 {
        let p = &mut self.plan;
        let value = (p.points[to] - p.points[from]) * p.mu;
        p.vectors.push(Drawn {
            from,
            to,
            force,
            value,
        });
        p.steps.push(ForceStep::Measure(p.vectors.len() - 1));
        value
    }
}

/// An outer pair of a group: where it is and which link is across it.
#[derive(Clone, Copy)]
enum Outer {
    /// A revolute pair at `at` (point `point`).
    Pin { point: usize, at: Point },
    /// A prismatic pair: its point `q`, the guide's direction `u`.
    Guide { q: Point, u: Vec2 },
}

fn outer(an: &Analysis, s: &Solved, c: &Conn, link: usize) -> Outer {
    match c.joint {
        Joint::R(p) => Outer::Pin {
            point: p,
            at: s.config.point(&an.mech, link, p),
        },
        Joint::P(k) => {
            let (q, u, _) = guide_frame(an, s, k);
            Outer::Guide { q, u }
        }
    }
}

/// The force plans of every group and input at solved position `s`
/// under `loads`, from the last group attached back to the inputs.
pub fn solve(an: &Analysis, s: &Solved, loads: &[Load], delta: f64) -> Result<ForcePlans> {
    solve_at(an, s, loads, delta, None)
}

/// The scale a plan is drawn at, from its points at unit scale.
type ScaleOf<'a> = &'a dyn Fn(&[Vec2]) -> f64;

/// Which plan: a group's (index into `Structure::groups`) or an input
/// link's (the scene's order of inputs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Which {
    Group(usize),
    Input(usize),
}

/// [`solve`] with one plan drawn at a given scale `fixed` (a student's
/// μ_F, to check their plan at it); the others at the standard scale that
/// fits the default field.
pub fn solve_at(
    an: &Analysis,
    s: &Solved,
    loads: &[Load],
    delta: f64,
    fixed: Option<(Which, f64)>,
) -> Result<ForcePlans> {
    let scale_of = |w: Which, pts: &[Vec2]| match fixed {
        Some((f, mu)) if f == w => mu,
        _ => Field::default().scale(pts.iter().copied()),
    };
    let m = &an.mech;
    let st = &an.structure;
    let at = || describe_input(m, &s.drives.coords());
    let mut known: Vec<Applied> = Vec::new();
    for (i, l) in loads.iter().enumerate() {
        let (link, at, f, couple) = match *l {
            Load::Force { link, at, f, .. } => (link, at, f, 0.0),
            Load::Couple { link, m, .. } => (link, Point::ORIGIN, Vec2::ZERO, m),
        };
        if f != Vec2::ZERO || couple != 0.0 {
            known.push(Applied {
                link,
                at,
                f,
                couple,
                force: Force::Load(i),
            });
        }
    }
    let mut out = ForcePlans {
        plans: Vec::new(),
        revolute: vec![None; m.revolutes.len()],
        prismatic: vec![None; m.prismatics.len()],
        drives: vec![None; m.scene.input_count()],
    };
    for stage in st.stages.iter().rev() {
        match *stage {
            Stage::Group(g) => {
                let AssurGroup::Dyad(d) = &st.groups[g] else {
                    return Err(Error::structure(
                        "mechplan draws no force plan of a class III group (its reactions come from the links' equilibrium only)",
                    ));
                };
                let mu = |pts: &[Vec2]| scale_of(Which::Group(g), pts);
                let plan = group_plan(an, s, d, (&mut known, &mut out), (delta, &mu), &at)?;
                out.plans.push(ForcePlan {
                    group: Some(g),
                    ..plan
                });
            }
            Stage::Input(i) => {
                if let InputRole::InGroup { .. } = st.roles[i] {
                    continue;
                }
                let mu = |pts: &[Vec2]| scale_of(Which::Input(i), pts);
                let plan = input_plan(an, s, i, (&mut known, &mut out), (delta, &mu))?;
                out.plans.push(ForcePlan {
                    input: Some(i),
                    ..plan
                });
            }
        }
    }
    Ok(out)
}

/// Record the reaction `r` (with couple `c`) of link `from` on link `to`
/// in pair `joint` in the mechanism's conventions.
#[allow(clippy::too_many_arguments)]
fn record(
    (an, s): (&Analysis, &Solved),
    out: &mut ForcePlans,
    joint: Joint,
    from: usize,
    to: usize,
    r: Vec2,
    c: f64,
) {
    let m = &an.mech;
    match joint {
        Joint::R(p) => {
            if let Some(k) = m
                .revolutes
                .iter()
                .position(|rv| rv.point == p && (rv.a, rv.b) == (from, to))
            {
                out.revolute[k] = Some(r);
            } else if let Some(k) = m
                .revolutes
                .iter()
                .position(|rv| rv.point == p && (rv.a, rv.b) == (to, from))
            {
                out.revolute[k] = Some(-r);
            }
        }
        Joint::P(k) => {
            // The guide's force on the slider, along the guide's left normal.
            let (_, _, n) = guide_frame(an, s, k);
            let (r, c) = if m.prismatics[k].slider == to {
                (r, c)
            } else {
                (-r, -c)
            };
            out.prismatic[k] = Some((r.dot(n), c));
        }
    }
}

/// The plan of dyad `d`: its outer reactions (pushed on the links across
/// them), its middle reaction, a cylinder's inner pair and drive.
#[allow(clippy::too_many_arguments)]
fn group_plan(
    an: &Analysis,
    s: &Solved,
    d: &Dyad,
    (known, out): (&mut Vec<Applied>, &mut ForcePlans),
    (delta, scale): (f64, ScaleOf),
    at: &dyn Fn() -> String,
) -> Result<ForcePlan> {
    let mut sides = [vec![d.links[0]], vec![d.links[1]]];
    if let Some(c) = d.cylinder {
        sides[c.slot].push(c.other);
    }
    let (e1, mid, e2) = (d.ext1, d.mid, d.ext2);
    // The forces on the group: its links' loads and later reactions.
    let o1 = outer(an, s, &e1, e1.to);
    let o2 = outer(an, s, &e2, e2.from);
    let draw = |mu: f64| -> Result<(ForcePlan, Solution)> {
        let mut dr = Draft::new(mu, delta);
        dr.plan.links = sides.concat();
        let sol = dyad_polygon(an, s, d, &sides, known, (o1, o2), &mut dr, at)?;
        Ok((dr.plan, sol))
    };
    let (trial, _) = draw(1.0)?;
    let mu = scale(&trial.points);
    let (mut plan, sol) = draw(mu)?;
    // Record, and hand the outer reactions to the links across them.
    record((an, s), out, e1.joint, e1.from, e1.to, sol.r1, sol.c1);
    record((an, s), out, e2.joint, e2.to, e2.from, sol.r2, sol.c2);
    record((an, s), out, mid.joint, mid.to, mid.from, sol.rm, sol.cm);
    let point_of = |o: Outer| match o {
        Outer::Pin { at, .. } => at,
        Outer::Guide { q, .. } => q,
    };
    known.push(Applied {
        link: e1.from,
        at: point_of(o1),
        f: -sol.r1,
        couple: -sol.c1,
        force: Force::Reaction {
            from: e1.to,
            to: e1.from,
            joint: e1.joint,
            part: Part::Whole,
        },
    });
    known.push(Applied {
        link: e2.to,
        at: point_of(o2),
        f: -sol.r2,
        couple: -sol.c2,
        force: Force::Reaction {
            from: e2.from,
            to: e2.to,
            joint: e2.joint,
            part: Part::Whole,
        },
    });
    if let Some(c) = d.cylinder {
        cylinder_pair(an, s, d, c, known, out, &mut plan, sol)?;
    }
    Ok(plan)
}

/// What a dyad's polygon gives: the outer reactions on the group's links
/// (with the couples of prismatic pairs), and the middle reaction on the
/// first side's link from the second's.
#[derive(Clone, Copy, Debug)]
struct Solution {
    r1: Vec2,
    c1: f64,
    r2: Vec2,
    c2: f64,
    rm: Vec2,
    cm: f64,
}

/// The dyad's scheme and polygon (see the module's comment).
#[allow(clippy::too_many_arguments)]
fn dyad_polygon(
    an: &Analysis,
    s: &Solved,
    d: &Dyad,
    sides: &[Vec<usize>; 2],
    known: &[Applied],
    (o1, o2): (Outer, Outer),
    dr: &mut Draft,
    at: &dyn Fn() -> String,
) -> Result<Solution> {
    let side = |i: usize| Side {
        links: sides[i].clone(),
        known,
    };
    let (s0, s1) = (side(0), side(1));
    let (e1, mid, e2) = (d.ext1, d.mid, d.ext2);
    let r1_force = |part| Force::Reaction {
        from: e1.from,
        to: e1.to,
        joint: e1.joint,
        part,
    };
    let r2_force = |part| Force::Reaction {
        from: e2.to,
        to: e2.from,
        joint: e2.joint,
        part,
    };
    // The middle pair: its point (B) or its guide.
    let (b, mid_guide) = match mid.joint {
        Joint::R(p) => (s.config.point(&an.mech, mid.to, p), None),
        Joint::P(k) => {
            let (q, u, _) = guide_frame(an, s, k);
            (q, Some(u))
        }
    };
    // Step 1: the first side's known component of its outer reaction.
    let mut pre = Vec2::ZERO;
    let mut pre_force = r1_force(Part::Tangential);
    match (o1, mid_guide) {
        (Outer::Pin { at: a, .. }, None) => {
            // ΣM_B(side 0) = 0: R^τ ⊥ AB.
            let e = perp((b - a).normalize());
            let t = -s0.moment_about(b) / (a - b).cross(e);
            pre = e * t;
            dr.plan.steps.push(ForceStep::Moment {
                links: s0.links.clone(),
                about: b,
                about_name: mid_point(&mid),
                force: pre_force,
                value: t,
            });
        }
        (Outer::Pin { at: a, .. }, Some(u)) => {
            // Along the middle guide: the guide's force on side 0 is across
            // it, so (R + ΣF₀)·u = 0.
            let along = -s0.sum().dot(u);
            pre_force = r1_force(Part::AlongGuide);
            dr.plan.steps.push(ForceStep::Projection {
                links: s0.links.clone(),
                force: pre_force,
                value: along,
            });
            if let Outer::Pin { at: c, .. } = o2 {
                // RPR: ΣM_C(both sides) = 0 gives the rest of R.
                let n = perp(u);
                let both = s0.moment_about(c) + s1.moment_about(c);
                let across = -((a - c).cross(u * along) + both) / (a - c).cross(n);
                pre = u * along + n * across;
                pre_force = r1_force(Part::Whole);
                dr.plan.steps.push(ForceStep::Moment {
                    links: [s0.links.clone(), s1.links.clone()].concat(),
                    about: c,
                    about_name: outer_point(&o2),
                    force: r1_force(Part::AcrossGuide),
                    value: across,
                });
            } else {
                pre = u * along;
            }
        }
        (Outer::Guide { .. }, _) => {}
    }
    dr.lay_off(pre, pre_force);
    let after_pre = dr.last();
    for a in s0.forces().filter(|a| a.f != Vec2::ZERO) {
        dr.lay_off(a.f, a.force);
    }
    let end0 = dr.last();
    for a in s1.forces().filter(|a| a.f != Vec2::ZERO) {
        dr.lay_off(a.f, a.force);
    }
    let end1 = dr.last();
    // The second side's tangential component (RRR).
    if let (Outer::Pin { at: c, .. }, None) = (o2, mid_guide) {
        let e = perp((b - c).normalize());
        let t = -s1.moment_about(b) / (c - b).cross(e);
        dr.plan.steps.push(ForceStep::Moment {
            links: s1.links.clone(),
            about: b,
            about_name: mid_point(&mid),
            force: r2_force(Part::Tangential),
            value: t,
        });
        dr.lay_off(e * t, r2_force(Part::Tangential));
    }
    let end = dr.last();
    // Close the polygon: where two lines of known direction meet, or (RPR)
    // the vector back to the start.
    let closing = match (o1, o2, mid_guide) {
        (Outer::Pin { .. }, Outer::Pin { .. }, Some(_)) => 0,
        _ => {
            let first_dir = match (o1, mid_guide) {
                (Outer::Pin { at: a, .. }, None) => (b - a, Part::Normal),
                (Outer::Pin { .. }, Some(u)) => (perp(u), Part::AcrossGuide),
                (Outer::Guide { u, .. }, _) => (perp(u), Part::Whole),
            };
            let second_dir = match o2 {
                Outer::Pin { at: c, .. } => (b - c, Part::Normal),
                Outer::Guide { u, .. } => (perp(u), Part::Whole),
            };
            let l1 = dr.line(0, first_dir.0, r1_force(first_dir.1));
            let l2 = dr.line(end, second_dir.0, r2_force(second_dir.1));
            dr.meet(l1, l2, at)?
        }
    };
    let r1 = dr.measure(closing, after_pre, r1_force(Part::Whole));
    let r2 = dr.measure(end1, closing, r2_force(Part::Whole));
    let mid_force = Force::Reaction {
        from: mid.to,
        to: mid.from,
        joint: mid.joint,
        part: Part::Whole,
    };
    let rm = dr.measure(end0, closing, mid_force);
    // The couples of prismatic pairs (where their normal forces act), side
    // 0 first: each side has at most one unknown couple.
    let point_of = |o: Outer| match o {
        Outer::Pin { at, .. } => at,
        Outer::Guide { q, .. } => q,
    };
    let (p1, p2) = (point_of(o1), point_of(o2));
    let mut sol = Solution {
        r1,
        c1: 0.0,
        r2,
        c2: 0.0,
        rm,
        cm: 0.0,
    };
    let m0 = s0.moment_about(p1) + (b - p1).cross(rm);
    if mid_guide.is_some() {
        sol.cm = -m0;
        couple_step(dr, &s0.links, mid_force, sol.cm, rm, b);
    } else if let Outer::Guide { .. } = o1 {
        sol.c1 = -m0;
        couple_step(dr, &s0.links, r1_force(Part::Whole), sol.c1, r1, p1);
    }
    if let Outer::Guide { .. } = o2 {
        let m1 = s1.moment_about(p2) + (b - p2).cross(-rm) - sol.cm;
        sol.c2 = -m1;
        couple_step(dr, &s1.links, r2_force(Part::Whole), sol.c2, r2, p2);
    }
    Ok(sol)
}

/// A prismatic pair's couple `c` with its normal force `n` at the pair's
/// point `q`: the step, with the point the force acts at.
fn couple_step(dr: &mut Draft, links: &[usize], force: Force, c: f64, n: Vec2, q: Point) {
    // One force n through q + t·u has the moment t·(u × n) about q.
    let at = (n.hypot() > 0.0).then(|| {
        let u = perp(n).normalize() * -1.0;
        q + u * (c / u.cross(n))
    });
    dr.plan.steps.push(ForceStep::Couple {
        links: links.to_vec(),
        force,
        value: c,
        at,
    });
}

fn mid_point(c: &Conn) -> Option<usize> {
    match c.joint {
        Joint::R(p) => Some(p),
        Joint::P(_) => None,
    }
}

fn outer_point(o: &Outer) -> Option<usize> {
    match *o {
        Outer::Pin { point, .. } => Some(point),
        Outer::Guide { .. } => None,
    }
}

/// A cylinder's inner pair and drive force, from the equilibrium of its
/// link that does not carry the group's outer pair (all else on it known).
#[allow(clippy::too_many_arguments)]
fn cylinder_pair(
    an: &Analysis,
    s: &Solved,
    d: &Dyad,
    c: crate::model::structure::Cylinder,
    known: &[Applied],
    out: &mut ForcePlans,
    plan: &mut ForcePlan,
    sol: Solution,
) -> Result<()> {
    let m = &an.mech;
    let body = c.other;
    let (q, u, n) = guide_frame(an, s, c.pair);
    let mut f = Vec2::ZERO;
    let mut mq = 0.0;
    for a in known.iter().filter(|a| a.link == body) {
        f += a.f;
        mq += a.moment_about(q);
    }
    // The middle pair's reaction, if it is on this link.
    if d.mid.from == body || d.mid.to == body {
        let b = match d.mid.joint {
            Joint::R(p) => s.config.point(m, body, p),
            Joint::P(k) => guide_frame(an, s, k).0,
        };
        // `rm` acts on side 0's link from side 1's.
        let on_body = if c.slot == 0 { sol.rm } else { -sol.rm };
        let cm = if c.slot == 0 { sol.cm } else { -sol.cm };
        f += on_body;
        mq += (b - q).cross(on_body) + cm;
    }
    let pr = &m.prismatics[c.pair];
    // On `body` from its partner: N·n + sign·F_b·u (the drive pushes the
    // slider along u and the guide back) and a couple.
    let sign = if pr.slider == body { 1.0 } else { -1.0 };
    let drive = -f.dot(u) * sign;
    let normal = -f.dot(n);
    let couple = -mq;
    plan.steps.push(ForceStep::Projection {
        links: vec![body],
        force: Force::Drive {
            input: c.input,
            on: body,
        },
        value: drive,
    });
    plan.steps.push(ForceStep::Balancing {
        input: c.input,
        value: drive,
    });
    out.drives[c.input] = Some(drive);
    let partner = if pr.slider == body {
        pr.guide
    } else {
        pr.slider
    };
    record(
        (an, s),
        out,
        Joint::P(c.pair),
        partner,
        body,
        n * normal,
        couple,
    );
    Ok(())
}

/// The input link `i` (a crank, a driving slider on the frame or a chained
/// slider): its balancing moment (force) and the reaction of the link it
/// turns or slides on.
fn input_plan(
    an: &Analysis,
    s: &Solved,
    i: usize,
    (known, out): (&mut Vec<Applied>, &mut ForcePlans),
    (delta, scale): (f64, ScaleOf),
) -> Result<ForcePlan> {
    let m = &an.mech;
    let spec = m.scene.input_at(i);
    let link = spec.link();
    let side = Side {
        links: vec![link],
        known,
    };
    let sum = side.sum();
    let draw = |mu: f64| {
        let mut dr = Draft::new(mu, delta);
        dr.plan.links = vec![link];
        for a in side.forces().filter(|a| a.f != Vec2::ZERO) {
            dr.lay_off(a.f, a.force);
        }
        dr
    };
    let trial = draw(1.0);
    let mu = scale(&trial.plan.points);
    let mut dr = draw(mu);
    let end = dr.last();
    match *spec {
        InputSpec::Crank { pivot, .. } => {
            let o = s.config.point(m, link, pivot);
            let mb = -side.moment_about(o);
            dr.plan.steps.push(ForceStep::Balancing {
                input: i,
                value: mb,
            });
            out.drives[i] = Some(mb);
            let frame = m.frame();
            let joint = Joint::R(pivot);
            let force = Force::Reaction {
                from: frame,
                to: link,
                joint,
                part: Part::Whole,
            };
            let r = dr.measure(end, 0, force);
            record((an, s), out, joint, frame, link, r, 0.0);
        }
        InputSpec::Slider { pair, .. } => {
            let pr = &m.prismatics[pair];
            let other = if pr.slider == link {
                pr.guide
            } else {
                pr.slider
            };
            let (q, u, n) = guide_frame(an, s, pair);
            let sign = if pr.slider == link { 1.0 } else { -1.0 };
            let fb = -sum.dot(u) * sign;
            dr.plan.steps.push(ForceStep::Balancing {
                input: i,
                value: fb,
            });
            out.drives[i] = Some(fb);
            let normal = -sum.dot(n);
            let couple = -side.moment_about(q);
            let joint = Joint::P(pair);
            let force = Force::Reaction {
                from: other,
                to: link,
                joint,
                part: Part::Whole,
            };
            dr.lay_off(u * (fb * sign), Force::Drive { input: i, on: link });
            let r = dr.measure(dr.last(), 0, force);
            couple_step(&mut dr, &[link], force, couple, r, q);
            record((an, s), out, joint, other, link, n * normal, couple);
            // The chained slider's guide link feels the opposite.
            known.push(Applied {
                link: other,
                at: q,
                f: -(n * normal) - u * (fb * sign),
                couple: -couple,
                force: Force::Reaction {
                    from: link,
                    to: other,
                    joint,
                    part: Part::Whole,
                },
            });
        }
    }
    Ok(dr.plan)
}
