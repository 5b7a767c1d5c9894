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
//! do; the reactions are measured off the plan. A class III group
//! (`triad`): each leash's tangential component from its moments about
//! its joint on the base, the third leash's normal component from the
//! group's moments about Assur's point (where two leashes' axes meet),
//! the polygon closed along those two axes, the inner reactions read off.

mod draft;
mod dyad;
mod input;
mod known;
mod plan;
mod triad;

use known::Applied;
#[cfg(feature = "internals")]
pub use plan::{Drawn, DrawnLine};
pub use plan::{Force, ForcePlan, ForcePlans, ForceStep, Part, Slip};

use super::loads::Load;
use crate::error::Result;
use crate::kinematics::construction::Field;
use crate::kinematics::positions::describe_input;
use crate::kinematics::solve::{Analysis, Position};
use crate::model::structure::{AssurGroup, InputRole, Stage};
use kurbo::{Point, Vec2};

/// The force plans of every group and input at solved position `s`
/// under `loads`, from the last group attached back to the inputs.
pub fn solve(an: &Analysis, s: &Position, loads: &[Load], delta: f64) -> Result<ForcePlans> {
    solve_at(an, s, loads, delta, None)
}

/// Which plan: a group's (index into `Structure::groups`) or an input
/// link's (the scene's order of inputs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Which {
    Group(usize),
    Input(usize),
}

/// Where a force polygon at a scale left open must fit, mm: beside its
/// group's free body in a panel of a force sheet, whose polygon box holds
/// it as built (its μ_F is the one its steps, the result file and the
/// sheet state). Its longest vector 40–80 mm, the whole within 100 × 90.
const POLYGON: Field = Field {
    longest: 80.0,
    width: 100.0,
    height: 90.0,
};

/// [`solve`] with one plan drawn at a given scale `fixed` (a student's
/// μ_F, to check their plan at it); the others at the standard scale that
/// fits the default field.
pub fn solve_at(
    an: &Analysis,
    s: &Position,
    loads: &[Load],
    delta: f64,
    fixed: Option<(Which, f64)>,
) -> Result<ForcePlans> {
    solve_slipped(an, s, loads, delta, fixed, None)
}

/// [`solve_at`] with the plan `fixed` names drawn with a student's `slip`
/// (the others as the course draws them): the plans `check` compares a
/// wrong answer with to name its mistake.
pub fn solve_slipped(
    an: &Analysis,
    s: &Position,
    loads: &[Load],
    delta: f64,
    fixed: Option<(Which, f64)>,
    slip: Option<Slip>,
) -> Result<ForcePlans> {
    let slip_in = |w: Which| slip.filter(|_| fixed.is_some_and(|(f, _)| f == w));
    let scale_of = |w: Which, pts: &[Vec2]| match fixed {
        Some((f, mu)) if f == w => mu,
        _ => POLYGON.scale(pts.iter().copied()),
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
                let mu = |pts: &[Vec2]| scale_of(Which::Group(g), pts);
                let slip = slip_in(Which::Group(g));
                neighbours_slipped(&mut known, slip);
                let sheet = (&mut known, &mut out);
                // (τ's slips are drawn for a dyad's scheme only)
                let plan = match &st.groups[g] {
                    AssurGroup::Dyad(d) => {
                        dyad::group_plan(an, s, d, sheet, (delta, &mu, slip), &at)?
                    }
                    AssurGroup::Triad(t) => triad::group_plan(an, s, t, sheet, (delta, &mu), &at)?,
                };
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
                let slip = slip_in(Which::Input(i));
                neighbours_slipped(&mut known, slip);
                let plan =
                    input::input_plan(an, s, i, (&mut known, &mut out), (delta, &mu, slip))?;
                out.plans.push(ForcePlan {
                    input: Some(i),
                    ..plan
                });
            }
        }
    }
    Ok(out)
}


/// The slip of taking the reactions of the groups solved before with the
/// wrong sign: every reaction known so far reversed (only those on the
/// plan's own links enter it).
fn neighbours_slipped(known: &mut [Applied], slip: Option<Slip>) {
    if slip != Some(Slip::NeighbourSign) {
        return;
    }
    for a in known
        .iter_mut()
        .filter(|a| matches!(a.force, Force::Reaction { .. }))
    {
        a.f = -a.f;
        a.couple = -a.couple;
    }
}
