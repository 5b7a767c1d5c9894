//! The construction kernel: plans of velocities and accelerations drawn as
//! a draftsman draws them, group by group in the order of attachment.
//!
//! The primitives are drafting operations on the sheet (millimetres, the
//! pole at the origin): lay off a vector at scale μ; draw a line through a
//! plan point perpendicular or parallel to a link or guide; intersect two
//! lines; divide a segment; build the figure similar to a link's figure
//! (same order of letters, so never a mirror image); turn a relative
//! velocity by 90° in the sense of ω (Coriolis); measure a segment and
//! multiply by μ. Directions come from the plan of the mechanism (the
//! solved positions); magnitudes laid off come from the data (ω1, ε1) or
//! from quantities measured earlier on the plans. Every step is recorded
//! with the items it used, so a plan is a replayable list of steps.
//!
//! Every plan point carries a first-order drafting-error radius: a pencil
//! error δ (mm) for each line drawn or vector laid off, amplified by
//! 1/sin θ at an intersection of lines meeting at θ.
//!
//! The kernel works in ids: plan points by their [`PointId`] and index,
//! the mechanism's points and links by index, each step recorded as such
//! (`record`). A full build then names everything (the plan points' keys,
//! labels and figures, the steps); a numbers-only build does not.
//!
//! The files follow the method: [`plan`] (what the kernel hands out),
//! `builder` (the drafting operations and the order of the construction),
//! `point` (a point of a link from what the plan knows of it), `input`,
//! `dyad`, `triad` (the groups), `record` (the steps in ids, and their
//! naming), [`text`] (the steps in words), [`scale`].

mod builder;
mod dyad;
mod input;
pub mod plan;
mod point;
mod record;
pub mod scale;
pub mod text;
mod triad;

pub use plan::{
    Dir, Drafting, Known, Measured, Mistake, Op, Plan, PlanKind, PlanLine, PlanPoint, Plans,
    PointId, Quantity, Setup, Step, Variant, Why, non_rotating,
};
pub use scale::Field;

use crate::error::Result;
use crate::kinematics::analytic::{Drives, Order};
use crate::kinematics::positions::Configuration;
use builder::Builder;
use record::Act;

/// Build the plan of `kind` (on the velocity plan `vel` for the
/// acceleration plan): its numbers, and the record of its steps. A scale
/// `d` leaves open is the standard one at which the plan fits `field`,
/// found by a first construction at unit scale.
#[allow(clippy::too_many_arguments)]
fn construct(
    st: &Setup,
    c: &Configuration,
    drive: Drives,
    kind: PlanKind,
    vel: Option<&Plan>,
    d: &Drafting,
    field: &Field,
    naming: Naming,
) -> Result<(Plan, Vec<Act>)> {
    use rand::SeedableRng;
    let rng = |k: u64| {
        d.variant
            .jitter
            .map(|s| rand::rngs::StdRng::seed_from_u64(s ^ k))
    };
    let plan = Plan::empty(kind, 1.0, d.delta, st.m);
    let mut b = Builder::new(st, c, drive, plan, vel, d.variant, rng(1));
    let mu = match d.mu(kind) {
        Some(mu) => mu,
        None => {
            b.run()?;
            field.scale(b.plan.points.iter().map(|p| p.at))
        }
    };
    // The real construction at that scale (the steps' numbers are in mm),
    // in the first one's buffers.
    b.again(mu, rng(2));
    b.record = naming == Naming::Full;
    b.run()?;
    Ok((b.plan, b.acts))
}

/// What a build gives besides the numbers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Naming {
    /// The plan points' keys, labels and figures, the measured
    /// quantities' names and the steps: a plan to draw and narrate.
    Full,
    /// Numbers only: every plan point, rate, measured value and error
    /// bound, but no names, labels or steps. For sweeps that read numbers.
    NumbersOnly,
}

/// Both plans (the acceleration plan when `order` asks: it needs the
/// velocity plan's ω and relative velocities), a scale `d` leaves open the
/// standard one at which the plan fits `field`.
pub fn build_plans_in(
    st: &Setup,
    c: &Configuration,
    (drive, order): (Drives, Order),
    d: Drafting,
    field: &Field,
    naming: Naming,
) -> Result<Plans> {
    let build = |kind, vel| -> Result<Plan> {
        let (mut plan, acts) = construct(st, c, drive, kind, vel, &d, field, naming)?;
        if naming == Naming::Full {
            record::narrate(&mut plan, &acts, st);
        }
        Ok(plan)
    };
    let velocity = build(PlanKind::Velocity, None)?;
    let acceleration = match order {
        Order::Acceleration => Some(build(PlanKind::Acceleration, Some(&velocity))?),
        Order::Velocity => None,
    };
    Ok(Plans {
        velocity,
        acceleration,
    })
}

/// Build the velocity plan, and the acceleration plan when `order` asks;
/// a scale left open fits the default [`Field`].
pub fn build_plans(
    st: &Setup,
    c: &Configuration,
    drive: impl Into<Drives>,
    order: Order,
    d: Drafting,
) -> Result<Plans> {
    let drive = drive.into();
    build_plans_in(st, c, (drive, order), d, &Field::default(), Naming::Full)
}

/// The acceleration plan built on a given velocity plan (its ω and
/// relative velocities): a student's own velocity plan, at their scale,
/// with the ω they measured.
pub fn build_acceleration(
    st: &Setup,
    c: &Configuration,
    drive: impl Into<Drives>,
    vel: &Plan,
    d: Drafting,
) -> Result<Plan> {
    let drive = drive.into();
    let field = Field::default();
    let kind = PlanKind::Acceleration;
    let (mut plan, acts) = construct(st, c, drive, kind, Some(vel), &d, &field, Naming::Full)?;
    record::narrate(&mut plan, &acts, st);
    Ok(plan)
}

/// The same constructions as [`build_plans`], numbers only
/// ([`Naming::NumbersOnly`]): the precision report, the speed bench.
pub fn build_plans_numbers(
    st: &Setup,
    c: &Configuration,
    drive: impl Into<Drives>,
    order: Order,
    d: Drafting,
) -> Result<Plans> {
    let drive = drive.into();
    let field = Field::default();
    build_plans_in(st, c, (drive, order), d, &field, Naming::NumbersOnly)
}
