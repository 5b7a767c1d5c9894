//! A class II group's force plan: the scheme of its kind (the tangential
//! components by moments about the middle joint, a projection on a middle
//! guide), its polygon closed by two lines, the middle reaction and the
//! guides' couples read off; a cylinder's inner pair and drive force.

use super::draft::Draft;
use super::plan::{Force, ForcePlan, ForcePlans, ForceStep, Part, Slip};
use super::known::{Applied, ScaleOf, Side, record};
use crate::error::Result;
use crate::geom::perp;
use crate::kinematics::solve::{Analysis, Position};
use crate::kinetostatics::newton_euler::guide_frame;
use crate::model::structure::{Conn, Dyad, Joint};
use kurbo::{Point, Vec2};

/// An outer pair of a group: where it is and which link is across it.
#[derive(Clone, Copy)]
enum Outer {
    /// A revolute pair at `at` (point `point`).
    Pin { point: usize, at: Point },
    /// A prismatic pair: its point `q`, the guide's direction `u`.
    Guide { q: Point, u: Vec2 },
}

impl Outer {
    /// Where the pair's reaction acts: the pin, the guide's point.
    fn point(self) -> Point {
        match self {
            Outer::Pin { at, .. } => at,
            Outer::Guide { q, .. } => q,
        }
    }
}

fn outer(an: &Analysis, s: &Position, c: &Conn, link: usize) -> Outer {
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

/// The plan of dyad `d`: its outer reactions (pushed on the links across
/// them), its middle reaction, a cylinder's inner pair and drive.
#[allow(clippy::too_many_arguments)]
pub(super) fn group_plan(
    an: &Analysis,
    s: &Position,
    d: &Dyad,
    (known, out): (&mut Vec<Applied>, &mut ForcePlans),
    (delta, scale, slip): (f64, ScaleOf, Option<Slip>),
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
        let sol = dyad_polygon(an, s, (d, slip), &sides, known, (o1, o2), &mut dr, at)?;
        Ok((dr.plan, sol))
    };
    let (trial, _) = draw(1.0)?;
    let mu = scale(&trial.points);
    let (mut plan, sol) = draw(mu)?;
    // Record, and hand the outer reactions to the links across them.
    record((an, s), out, e1.joint, e1.from, e1.to, sol.r1, sol.c1);
    record((an, s), out, e2.joint, e2.to, e2.from, sol.r2, sol.c2);
    record((an, s), out, mid.joint, mid.to, mid.from, sol.rm, sol.cm);
    known.push(Applied {
        link: e1.from,
        at: o1.point(),
        f: -sol.r1,
        couple: -sol.c1,
        force: reaction(e1.to, e1.from, e1.joint, Part::Whole),
    });
    known.push(Applied {
        link: e2.to,
        at: o2.point(),
        f: -sol.r2,
        couple: -sol.c2,
        force: reaction(e2.from, e2.to, e2.joint, Part::Whole),
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

/// A dyad's polygon under way: its two sides' forces, its pairs, the
/// middle pair's point (B) or its guide.
struct Polygon<'k> {
    s0: Side<'k>,
    s1: Side<'k>,
    e1: Conn,
    mid: Conn,
    e2: Conn,
    o1: Outer,
    o2: Outer,
    b: Point,
    mid_guide: Option<Vec2>,
    slip: Option<Slip>,
}

impl Polygon<'_> {
    /// A tangential component `e·t` (`e` ⊥ the link `along`; the second
    /// side's when `second`) as the plan lays it off: with a student's
    /// slip, reversed or along the link.
    fn tangential(&self, e: Vec2, along: Vec2, t: f64, second: bool) -> Vec2 {
        match self.slip {
            Some(Slip::TangentialSign { first, second: other })
                if (second && other) || (!second && first) =>
            {
                e * -t
            }
            Some(Slip::TangentialAlong) => along.normalize() * t,
            _ => e * t,
        }
    }

    /// The reaction in the first outer pair, on the group (`part` of it).
    fn r1_force(&self, part: Part) -> Force {
        reaction(self.e1.from, self.e1.to, self.e1.joint, part)
    }

    /// The reaction in the second outer pair, on the group.
    fn r2_force(&self, part: Part) -> Force {
        reaction(self.e2.to, self.e2.from, self.e2.joint, part)
    }

    /// Step 1: the first side's known component of its outer reaction
    /// and what it is of that reaction.
    fn first_component(&self, dr: &mut Draft) -> (Vec2, Force) {
        let (s0, s1, b) = (&self.s0, &self.s1, self.b);
        let mut pre = Vec2::ZERO;
        let mut pre_force = self.r1_force(Part::Tangential);
        match (self.o1, self.mid_guide) {
            (Outer::Pin { at: a, .. }, None) => {
                // ΣM_B(side 0) = 0: R^τ ⊥ AB.
                let e = perp((b - a).normalize());
                let t = -s0.moment_about(b) / (a - b).cross(e);
                pre = self.tangential(e, b - a, t, false);
                dr.plan.steps.push(ForceStep::Moment {
                    links: s0.links.clone(),
                    about: b,
                    about_name: mid_point(&self.mid),
                    force: pre_force,
                    value: t,
                });
            }
            (Outer::Pin { at: a, .. }, Some(u)) => {
                // Along the middle guide: the guide's force on side 0 is across
                // it, so (R + ΣF₀)·u = 0.
                let along = -s0.sum().dot(u);
                pre_force = self.r1_force(Part::AlongGuide);
                dr.plan.steps.push(ForceStep::Projection {
                    links: s0.links.clone(),
                    force: pre_force,
                    value: along,
                });
                if let Outer::Pin { at: c, .. } = self.o2 {
                    // RPR: ΣM_C(both sides) = 0 gives the rest of R.
                    let n = perp(u);
                    let both = s0.moment_about(c) + s1.moment_about(c);
                    let across = -((a - c).cross(u * along) + both) / (a - c).cross(n);
                    pre = u * along + n * across;
                    pre_force = self.r1_force(Part::Whole);
                    dr.plan.steps.push(ForceStep::Moment {
                        links: [s0.links.clone(), s1.links.clone()].concat(),
                        about: c,
                        about_name: outer_point(&self.o2),
                        force: self.r1_force(Part::AcrossGuide),
                        value: across,
                    });
                } else {
                    pre = u * along;
                }
            }
            (Outer::Guide { .. }, _) => {}
        }
        (pre, pre_force)
    }

    /// The second side's tangential component (RRR).
    fn second_component(&self, dr: &mut Draft) {
        let (s1, b) = (&self.s1, self.b);
        if let (Outer::Pin { at: c, .. }, None) = (self.o2, self.mid_guide) {
            let e = perp((b - c).normalize());
            let t = -s1.moment_about(b) / (c - b).cross(e);
            dr.plan.steps.push(ForceStep::Moment {
                links: s1.links.clone(),
                about: b,
                about_name: mid_point(&self.mid),
                force: self.r2_force(Part::Tangential),
                value: t,
            });
            dr.lay_off(self.tangential(e, b - c, t, true), self.r2_force(Part::Tangential));
        }
    }

    /// Close the polygon ending at point `end`: where two lines of known
    /// direction meet, or (RPR) the vector back to the start.
    fn close(&self, dr: &mut Draft, end: usize, at: &dyn Fn() -> String) -> Result<usize> {
        let b = self.b;
        Ok(match (self.o1, self.o2, self.mid_guide) {
            (Outer::Pin { .. }, Outer::Pin { .. }, Some(_)) => 0,
            _ => {
                let first_dir = match (self.o1, self.mid_guide) {
                    (Outer::Pin { at: a, .. }, None) => (b - a, Part::Normal),
                    (Outer::Pin { .. }, Some(u)) => (perp(u), Part::AcrossGuide),
                    (Outer::Guide { u, .. }, _) => (perp(u), Part::Whole),
                };
                let second_dir = match self.o2 {
                    Outer::Pin { at: c, .. } => (b - c, Part::Normal),
                    Outer::Guide { u, .. } => (perp(u), Part::Whole),
                };
                let l1 = dr.line(0, first_dir.0, self.r1_force(first_dir.1));
                let l2 = dr.line(end, second_dir.0, self.r2_force(second_dir.1));
                dr.meet(l1, l2, at)?
            }
        })
    }

    /// The couples of prismatic pairs (where their normal forces act), side
    /// 0 first: each side has at most one unknown couple.
    fn couples(&self, dr: &mut Draft, sol: &mut Solution, mid_force: Force) {
        let (s0, s1, b) = (&self.s0, &self.s1, self.b);
        let (r1, r2, rm) = (sol.r1, sol.r2, sol.rm);
        let (p1, p2) = (self.o1.point(), self.o2.point());
        let m0 = s0.moment_about(p1) + (b - p1).cross(rm);
        if self.mid_guide.is_some() {
            sol.cm = -m0;
            couple_step(dr, &s0.links, mid_force, sol.cm, rm, b);
        } else if let Outer::Guide { .. } = self.o1 {
            sol.c1 = -m0;
            couple_step(dr, &s0.links, self.r1_force(Part::Whole), sol.c1, r1, p1);
        }
        if let Outer::Guide { .. } = self.o2 {
            let m1 = s1.moment_about(p2) + (b - p2).cross(-rm) - sol.cm;
            sol.c2 = -m1;
            couple_step(dr, &s1.links, self.r2_force(Part::Whole), sol.c2, r2, p2);
        }
    }
}

/// The reaction in pair `joint` on link `to` from link `from` (`part` of it).
pub(super) fn reaction(from: usize, to: usize, joint: Joint, part: Part) -> Force {
    Force::Reaction {
        from,
        to,
        joint,
        part,
    }
}

/// The dyad's scheme and polygon (see the module's comment).
#[allow(clippy::too_many_arguments)]
fn dyad_polygon(
    an: &Analysis,
    s: &Position,
    (d, slip): (&Dyad, Option<Slip>),
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
    let (e1, mid, e2) = (d.ext1, d.mid, d.ext2);
    // The middle pair: its point (B) or its guide.
    let (b, mid_guide) = match mid.joint {
        Joint::R(p) => (s.config.point(&an.mech, mid.to, p), None),
        Joint::P(k) => {
            let (q, u, _) = guide_frame(an, s, k);
            (q, Some(u))
        }
    };
    let pg = Polygon {
        s0: side(0),
        s1: side(1),
        e1,
        mid,
        e2,
        o1,
        o2,
        b,
        mid_guide,
        slip,
    };
    let (pre, pre_force) = pg.first_component(dr);
    dr.lay_off(pre, pre_force);
    let after_pre = dr.last();
    for a in pg.s0.forces().filter(|a| a.f != Vec2::ZERO) {
        dr.lay_off(a.f, a.force);
    }
    let end0 = dr.last();
    for a in pg.s1.forces().filter(|a| a.f != Vec2::ZERO) {
        dr.lay_off(a.f, a.force);
    }
    let end1 = dr.last();
    pg.second_component(dr);
    let end = dr.last();
    let closing = pg.close(dr, end, at)?;
    let r1 = dr.measure(closing, after_pre, pg.r1_force(Part::Whole));
    let r2 = dr.measure(end1, closing, pg.r2_force(Part::Whole));
    let mid_force = reaction(mid.to, mid.from, mid.joint, Part::Whole);
    let rm = dr.measure(end0, closing, mid_force);
    let mut sol = Solution {
        r1,
        c1: 0.0,
        r2,
        c2: 0.0,
        rm,
        cm: 0.0,
    };
    pg.couples(dr, &mut sol, mid_force);
    Ok(sol)
}

/// A prismatic pair's couple `c` with its normal force `n` at the pair's
/// point `q`: the step, with the point the force acts at.
pub(super) fn couple_step(
    dr: &mut Draft,
    links: &[usize],
    force: Force,
    c: f64,
    n: Vec2,
    q: Point,
) {
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
    s: &Position,
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
