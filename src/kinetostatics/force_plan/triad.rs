//! A class III group's force plan (a base link with three leashes, all
//! pairs revolute: the structure refuses a class III group with a
//! prismatic pair).
//!
//! Each leash n (outer joint E_n on a known link, inner joint J_n on the
//! base) has its outer reaction split into a tangential component, ⊥ the
//! leash's axis E_nJ_n, from the leash's moments about J_n, and a normal
//! component along the axis. Of the three normal components, the third
//! leash's (k) comes from the moments of the whole group about Assur's
//! point S, where the axes of the other two (i, j) meet: their normal
//! components pass through S. The polygon of the whole group (every known
//! load, the three tangential components, R^n_k) is then closed by two
//! lines along the axes of i and j, meeting at a point whose drafting
//! error is amplified by 1/sin θ of the axes' angle. The inner reactions
//! (leash–base) are read off the polygon, as a dyad's middle one.
//!
//! Which pair (i, j): the one whose axes meet at the largest angle (the
//! smallest amplification); where two leashes' axes are parallel (their
//! S at infinity) another pair is taken. Refused only where no pair
//! meets (all three axes parallel) or where S lies on the third axis (the
//! three axes meet in one point: the group's dead point, the reactions
//! not determined).

use super::draft::Draft;
use super::dyad::reaction;
use super::known::{Applied, ScaleOf, Side, record};
use super::plan::{ForcePlan, ForcePlans, ForceStep, Part};
use crate::accuracy::ACCURACY;
use crate::error::{Error, Result};
use crate::geom::{Line, LineCut, intersect_lines, perp};
use crate::kinematics::solve::{Analysis, Position};
use crate::model::structure::{Joint, Triad};
use kurbo::{Point, Vec2};

/// A leash of the group at the position: its outer joint E (point id),
/// its inner joint J on the base (point id), the known link across E.
#[derive(Clone, Copy)]
struct Leash {
    link: usize,
    known: usize,
    e: Point,
    e_id: usize,
    j: Point,
    j_id: usize,
}

impl Leash {
    /// The axis E → J.
    fn axis(&self) -> Vec2 {
        self.j - self.e
    }
    /// Its outer reaction (on the leash from the known link), `part`.
    fn outer(&self, part: Part) -> super::plan::Force {
        reaction(self.known, self.link, Joint::R(self.e_id), part)
    }
}

/// The leashes of `t` at position `s`.
fn leashes(an: &Analysis, s: &Position, t: &Triad) -> [Leash; 3] {
    let m = &an.mech;
    let point = |j: Joint| match j {
        Joint::R(p) => p,
        Joint::P(_) => unreachable!("the structure refuses a class III group with a prismatic pair"),
    };
    std::array::from_fn(|n| {
        let (e_id, j_id) = (point(t.ext[n].joint), point(t.int[n].joint));
        Leash {
            link: t.leashes[n],
            known: t.ext[n].from,
            e: s.config.point(m, t.leashes[n], e_id),
            e_id,
            j: s.config.point(m, t.base, j_id),
            j_id,
        }
    })
}

/// The pair of leashes (i, j) whose axes meet at the largest angle, the
/// third k, and their point S; refused where none meets or S is on the
/// third axis.
fn assur_point(
    an: &Analysis,
    t: &Triad,
    l: &[Leash; 3],
    at: &dyn Fn() -> String,
) -> Result<((usize, usize, usize), Point)> {
    let line = |n: usize| Line::new(l[n].e, l[n].axis());
    let sine = |a: usize, b: usize| l[a].axis().normalize().cross(l[b].axis().normalize()).abs();
    let (i, j, k) = [(0, 1, 2), (0, 2, 1), (1, 2, 0)]
        .into_iter()
        .max_by(|a, b| sine(a.0, a.1).total_cmp(&sine(b.0, b.1)))
        .expect("three pairs");
    let LineCut::Point { at: sp, .. } = intersect_lines(&line(i), &line(j), ACCURACY.min_line_sine)
    else {
        return Err(Error::singular(
            at(),
            "on the force plan of the class III group the axes of all three leashes are parallel: no Assur point, the group's reactions are not determined",
        ));
    };
    let m = &an.mech;
    let size = t
        .leashes
        .iter()
        .chain([&t.base])
        .map(|&x| m.link_scale(x))
        .fold(0.0, f64::max);
    let arm = (l[k].e - sp).cross(l[k].axis().normalize());
    if arm.abs() <= ACCURACY.same_point * size {
        return Err(Error::singular(
            at(),
            "on the force plan of the class III group the three leashes' axes meet in one point: a dead point, the group's reactions are not determined",
        ));
    }
    Ok(((i, j, k), sp))
}

/// What the group's polygon gives: per leash its outer reaction and the
/// base's reaction on it.
struct Solution {
    outer: [Vec2; 3],
    inner: [Vec2; 3],
}

/// The plan of class III group `t`: its outer reactions (pushed on the
/// links across them) and its inner ones.
pub(super) fn group_plan(
    an: &Analysis,
    s: &Position,
    t: &Triad,
    (known, out): (&mut Vec<Applied>, &mut ForcePlans),
    (delta, scale): (f64, ScaleOf),
    at: &dyn Fn() -> String,
) -> Result<ForcePlan> {
    let l = leashes(an, s, t);
    let (pair, sp) = assur_point(an, t, &l, at)?;
    // The group's links in the scene's order, as its label lists them.
    let mut links = vec![t.leashes[0], t.leashes[1], t.leashes[2], t.base];
    links.sort_unstable();
    let draw = |mu: f64| -> Result<(ForcePlan, Solution)> {
        let mut dr = Draft::new(mu, delta);
        dr.plan.links = links.clone();
        let sol = polygon(t, &l, known, (pair, sp), &mut dr, at)?;
        Ok((dr.plan, sol))
    };
    let (trial, _) = draw(1.0)?;
    let (plan, sol) = draw(scale(&trial.points))?;
    for (n, leash) in l.iter().enumerate() {
        let (outer, inner) = (sol.outer[n], sol.inner[n]);
        record((an, s), out, t.ext[n].joint, leash.known, leash.link, outer, 0.0);
        record((an, s), out, t.int[n].joint, t.base, leash.link, inner, 0.0);
        known.push(Applied {
            link: leash.known,
            at: leash.e,
            f: -outer,
            couple: 0.0,
            force: reaction(leash.link, leash.known, t.ext[n].joint, Part::Whole),
        });
    }
    Ok(plan)
}

/// Leash `n`'s tangential component from its moments about J: the step
/// and the vector.
fn tangential(dr: &mut Draft, leash: &Leash, known: &[Applied]) -> Vec2 {
    let side = Side {
        links: vec![leash.link],
        known,
    };
    let e = perp(leash.axis().normalize());
    let v = -side.moment_about(leash.j) / (leash.e - leash.j).cross(e);
    dr.plan.steps.push(ForceStep::Moment {
        links: vec![leash.link],
        about: leash.j,
        about_name: Some(leash.j_id),
        force: leash.outer(Part::Tangential),
        value: v,
    });
    e * v
}

/// Lay off the loads of `link` (a zero force is not drawn).
fn lay_loads(dr: &mut Draft, link: usize, known: &[Applied]) {
    for a in known.iter().filter(|a| a.link == link && a.f != Vec2::ZERO) {
        dr.lay_off(a.f, a.force);
    }
}

/// The group's scheme and polygon (see the module's comment): R^τ_i and
/// leash i's loads, the base's, R^τ_k, R^n_k and leash k's, leash j's and
/// R^τ_j; closed by the lines of R^n_i through the start and of R^n_j
/// through the end.
fn polygon(
    t: &Triad,
    l: &[Leash; 3],
    known: &[Applied],
    ((i, j, k), sp): ((usize, usize, usize), Point),
    dr: &mut Draft,
    at: &dyn Fn() -> String,
) -> Result<Solution> {
    let tau: [Vec2; 3] = std::array::from_fn(|n| tangential(dr, &l[n], known));
    // ΣM_S(group) = 0: R^n_i and R^n_j pass through S.
    let group = Side {
        links: vec![t.leashes[0], t.leashes[1], t.leashes[2], t.base],
        known,
    };
    let taus: f64 = (0..3).map(|n| (l[n].e - sp).cross(tau[n])).sum();
    let u = l[k].axis().normalize();
    let nk = -(group.moment_about(sp) + taus) / (l[k].e - sp).cross(u);
    dr.plan.steps.push(ForceStep::Moment {
        links: group.links.clone(),
        about: sp,
        about_name: None,
        force: l[k].outer(Part::Normal),
        value: nk,
    });
    dr.lay_off(tau[i], l[i].outer(Part::Tangential));
    let after_i = dr.last();
    lay_loads(dr, l[i].link, known);
    let end_i = dr.last();
    lay_loads(dr, t.base, known);
    let k0 = dr.last();
    dr.lay_off(tau[k], l[k].outer(Part::Tangential));
    dr.lay_off(u * nk, l[k].outer(Part::Normal));
    let kn = dr.last();
    lay_loads(dr, l[k].link, known);
    let k1 = dr.last();
    lay_loads(dr, l[j].link, known);
    let j1 = dr.last();
    dr.lay_off(tau[j], l[j].outer(Part::Tangential));
    let end = dr.last();
    let li = dr.line(0, l[i].axis(), l[i].outer(Part::Normal));
    let lj = dr.line(end, l[j].axis(), l[j].outer(Part::Normal));
    let c = dr.meet(li, lj, at)?;
    let inner_force = |n: usize| reaction(t.base, l[n].link, t.int[n].joint, Part::Whole);
    let mut sol = Solution {
        outer: [Vec2::ZERO; 3],
        inner: [Vec2::ZERO; 3],
    };
    sol.outer[i] = dr.measure(c, after_i, l[i].outer(Part::Whole));
    sol.outer[j] = dr.measure(j1, c, l[j].outer(Part::Whole));
    sol.outer[k] = dr.measure(k0, kn, l[k].outer(Part::Whole));
    // The base's reaction on each leash closes the leash's own polygon.
    sol.inner[i] = dr.measure(end_i, c, inner_force(i));
    sol.inner[k] = dr.measure(k1, k0, inner_force(k));
    sol.inner[j] = dr.measure(c, k1, inner_force(j));
    Ok(sol)
}
