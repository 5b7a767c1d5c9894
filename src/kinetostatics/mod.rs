//! Kinetostatics, the force analysis (issue #17), after the kinematics in
//! the data flow: at each solved position the known loads ([`loads`]:
//! inertia by d'Alembert, weights, the scene's external loads), the
//! reactions in every pair and the balancing moment (force) of every input
//! by the equilibrium of all links at once ([`newton_euler`]), checked
//! against the balancing moment by virtual power ([`power`]).
//! docs/kinetostatics.md gives the conventions and a worked example.

pub mod force_plan;
pub mod lever;
pub mod loads;
pub mod newton_euler;
pub mod power;
mod reactions;

use crate::accuracy::ACCURACY;
use crate::error::{Error, Result};
use crate::kinematics::positions::describe_input;
use crate::kinematics::solve::{Analysis, Position};
pub use loads::{Inertia, Load, Origin};
pub use reactions::{Balancing, GuideReaction, RevoluteReaction};

/// The force analysis of one position.
#[derive(Clone, Debug, PartialEq)]
pub struct Dynamics {
    /// Every known load: inertia, then weights, then the external loads
    /// in the order written ([`loads::loads`]), found once here for every
    /// reader (the force plans' words, sheets and checks).
    pub loads: Vec<Load>,
    /// Every link with mass, in the scene's order.
    pub inertia: Vec<Inertia>,
    /// Every revolute pair, in `Mechanism::revolutes`' order.
    pub revolutes: Vec<RevoluteReaction>,
    /// Every prismatic pair, in the scene's order of `sliders`.
    pub prismatics: Vec<GuideReaction>,
    /// Per input, in the scene's order: by the equilibrium of the links.
    pub balancing: Vec<Balancing>,
    /// Per input: the same by virtual power.
    pub virtual_power: Vec<f64>,
    /// The largest disagreement of the two, relative to the magnitudes of
    /// the virtual power's terms.
    pub balancing_diff: f64,
    /// Per input: the same by Zhukovsky's lever ([`lever`]), on the
    /// drafted velocity plan.
    pub lever: Vec<f64>,
    /// The equilibrium system's reciprocal condition number.
    pub rcond: f64,
    /// The largest force at the position (N; a couple counted over the
    /// mechanism's size): the scale of its residuals.
    pub force_scale: f64,
    /// The force plans, group by group (class III groups by Assur's
    /// point), and their largest disagreement with the links'
    /// equilibrium, relative to `force_scale`.
    pub force_plans: Option<force_plan::ForcePlans>,
    pub force_plans_diff: Option<f64>,
}

/// The force analysis of solved position `s`, the `k`-th (from 0) of the
/// scene; `None` when the scene has no `dynamics`. Refused (an error
/// naming the position) where the equilibrium equations are singular or
/// ill-conditioned, or the two routes disagree.
pub fn analyse(an: &Analysis, s: &Position, k: usize) -> Result<Option<Dynamics>> {
    let Some(inertia) = loads::inertia(an, s) else {
        return Ok(None);
    };
    let m = &an.mech;
    if let Some((at, x, lo, hi)) = loads::tables_cover(an, s) {
        return Err(Error::scene(
            at,
            format!(
                "at {} the force's point is {x} m from the table's `from`, outside its displacements {lo} … {hi} m: extend the table",
                describe_input(m, &s.drives.coords())
            ),
        ));
    }
    let loads = loads::loads(an, s, k);
    let x = newton_euler::solve(an, s, &loads)?;
    let vp = power::balancing(an, s, &loads);
    let size = m.size;
    let revolutes = revolute_reactions(an, s, &x);
    let balancing: Vec<Balancing> = m
        .scene
        .inputs()
        .zip(&x.drives)
        .map(|(i, &b)| {
            if i.is_crank() {
                Balancing::Moment(b)
            } else {
                Balancing::Force(b)
            }
        })
        .collect();
    let scale = force_scale(size, &loads, &revolutes, &balancing, &x);
    let prismatics = guide_reactions(an, s, &x, scale);
    // Each balancing value's disagreements are measured against the size
    // of the terms it is summed from, but never against less than a
    // ten-billionth of the position's largest force (times the
    // mechanism's size for a moment): at a dead centre without gravity
    // the terms vanish and rounding alone would read as a disagreement.
    let floors: Vec<f64> = m
        .scene
        .inputs()
        .map(|i| 1e-10 * scale * if i.is_crank() { size } else { 1.0 })
        .collect();
    let diff = balancing_diff(&balancing, &vp, &floors);
    if diff.is_nan() || diff > ACCURACY.max_balancing_diff {
        return Err(Error::singular(
            describe_input(m, &s.drives.coords()),
            format!(
                "the balancing moments (forces) of the inputs by the links' equilibrium {:?} and by virtual power {:?} differ by {diff:.1e} of the power's terms (more than {:.0e})",
                balancing.iter().map(Balancing::value).collect::<Vec<_>>(),
                vp.balancing,
                ACCURACY.max_balancing_diff
            ),
        ));
    }
    let (p, d) = plans(an, s, &loads, &x, scale)?;
    let (force_plans, force_plans_diff) = (Some(p), Some(d));
    let lever = lever::check(an, s, &loads, &balancing, &floors)?;
    Ok(Some(Dynamics {
        loads,
        force_plans,
        force_plans_diff,
        inertia,
        revolutes,
        prismatics,
        balancing,
        virtual_power: vp.balancing,
        lever,
        balancing_diff: diff,
        rcond: x.rcond,
        force_scale: scale,
    }))
}

/// Every revolute pair's reaction (of its first link on its second) at
/// position `s`, from the links' equilibrium `x`.
fn revolute_reactions(
    an: &Analysis,
    s: &Position,
    x: &newton_euler::Unknowns,
) -> Vec<RevoluteReaction> {
    let m = &an.mech;
    m.revolutes
        .iter()
        .zip(&x.revolute)
        .enumerate()
        .map(|(pair, (rv, &r))| RevoluteReaction {
            pair,
            point: rv.point,
            first: rv.a,
            second: rv.b,
            at: s.config.point(m, rv.b, rv.point),
            r,
        })
        .collect()
}

/// The largest force at the position (N; a couple over the mechanism's
/// `size`): the loads, the reactions, the balancing values.
fn force_scale(
    size: f64,
    loads: &[Load],
    revolutes: &[RevoluteReaction],
    balancing: &[Balancing],
    x: &newton_euler::Unknowns,
) -> f64 {
    let mut scale = loads
        .iter()
        .map(|l| match *l {
            Load::Force { f, .. } => f.hypot(),
            Load::Couple { m, .. } => m.abs() / size,
        })
        .fold(0.0, f64::max);
    for r in revolutes {
        scale = scale.max(r.r.hypot());
    }
    for b in balancing {
        scale = scale.max(match *b {
            Balancing::Moment(x) => x.abs() / size,
            Balancing::Force(x) => x.abs(),
        });
    }
    for &(n, c) in &x.prismatic {
        scale = scale.max(n.abs()).max(c.abs() / size);
    }
    scale
}

/// Every prismatic pair's reaction (the guide's on the slider) at
/// position `s`, from the links' equilibrium `x`; its line of action
/// where its normal force is not null against `scale`.
fn guide_reactions(
    an: &Analysis,
    s: &Position,
    x: &newton_euler::Unknowns,
    scale: f64,
) -> Vec<GuideReaction> {
    an.mech
        .prismatics
        .iter()
        .zip(&x.prismatic)
        .enumerate()
        .map(|(pair, (pr, &(n, c)))| {
            let (q, u, nrm) = newton_euler::guide_frame(an, s, pair);
            // One force n through q + t·u has the moment t·n about q.
            let at = (n.abs() > ACCURACY.null_normal_force * scale).then(|| q + u * (c / n));
            GuideReaction {
                pair,
                slider: pr.slider,
                guide: pr.guide,
                point: pr.point,
                q,
                u,
                n: nrm * n,
                m: c,
                at,
            }
        })
        .collect()
}

/// The largest disagreement of the balancing values by the links'
/// equilibrium and by virtual power `vp`, each relative to its terms'
/// size (never below its floor).
fn balancing_diff(balancing: &[Balancing], vp: &power::VirtualPower, floors: &[f64]) -> f64 {
    let mut diff: f64 = 0.0;
    for (((b, &v), &sc), &floor) in balancing
        .iter()
        .zip(&vp.balancing)
        .zip(&vp.scale)
        .zip(floors)
    {
        let d = (b.value() - v).abs();
        let rel = if d == 0.0 {
            0.0
        } else {
            d / sc.max(floor).max(f64::MIN_POSITIVE)
        };
        diff = diff.max(rel);
    }
    diff
}

/// The force plans at position `s` and their largest disagreement with the
/// links' equilibrium `x` (relative to `scale`). Refused where they
/// disagree by more than
/// `accuracy::max_balancing_diff`.
fn plans(
    an: &Analysis,
    s: &Position,
    loads: &[Load],
    x: &newton_euler::Unknowns,
    scale: f64,
) -> Result<(force_plan::ForcePlans, f64)> {
    let m = &an.mech;
    let fp = force_plan::solve(an, s, loads, an.drafting.delta)?;
    let size = m.size;
    let mut diff: f64 = 0.0;
    let mut worst = |a: f64, b: Option<f64>| {
        let d = b.map_or(f64::INFINITY, |b| {
            (a - b).abs() / scale.max(f64::MIN_POSITIVE)
        });
        diff = diff.max(if d.is_nan() { f64::INFINITY } else { d });
    };
    for (r, p) in x.revolute.iter().zip(&fp.revolute) {
        worst(r.x, p.map(|p| p.x));
        worst(r.y, p.map(|p| p.y));
    }
    for (r, p) in x.prismatic.iter().zip(&fp.prismatic) {
        worst(r.0, p.map(|p| p.0));
        worst(r.1 / size, p.map(|p| p.1 / size));
    }
    for (i, (r, p)) in x.drives.iter().zip(&fp.drives).enumerate() {
        let l = if m.scene.input_at(i).is_crank() {
            size
        } else {
            1.0
        };
        worst(r / l, p.map(|p| p / l));
    }
    if diff > ACCURACY.max_balancing_diff {
        return Err(Error::singular(
            describe_input(m, &s.drives.coords()),
            format!(
                "the force plans and the links' equilibrium give reactions that differ by {diff:.1e} of the largest force (more than {:.0e})",
                ACCURACY.max_balancing_diff
            ),
        ));
    }
    Ok((fp, diff))
}
