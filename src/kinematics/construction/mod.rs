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
//! naming), [`scale`]. The steps in words are `crate::words::construction`.

mod builder;
mod dyad;
mod input;
pub mod plan;
mod point;
mod record;
pub mod scale;
mod settle;
mod triad;
mod variant;

pub use plan::{
    Dir, Drafting, Drawing, Judged, Measured, Mistake, Op, Plan, PlanKind, PlanLine, PlanPoint, Plans,
    PointId, Setup, Variant, Why, non_rotating,
};
pub use scale::Field;

use crate::error::Result;
use crate::kinematics::analytic::{Drives, Order};
use crate::kinematics::positions::Configuration;
use builder::{Builder, Tools};

/// Build the plan of `kind` (on the velocity plan `vel` for the
/// acceleration plan) into `plan` with the buffers `tools`: its numbers,
/// and in `tools.acts` the record of its steps. A scale `d` leaves open
/// is the standard one at which the plan fits `field`, found by a first
/// construction at unit scale; or, given a `guess` (the scale of the
/// sweep's last position and its [`scale::band`]), by the construction at
/// that scale itself when the plan it draws settles on it
/// ([`Plan::settles_in`]), the same plan to the bit without the first
/// construction. Whether it settled, with the buffers.
#[allow(clippy::too_many_arguments)]
fn construct(
    st: &Setup,
    c: &Configuration,
    drive: Drives,
    (kind, vel): (PlanKind, Option<&Plan>),
    d: &Drafting,
    naming: Naming,
    (plan, tools): (&mut Plan, &mut Tools),
    guess: Option<(f64, (f64, f64))>,
) -> Result<bool> {
    use rand::SeedableRng;
    let rng = |k: u64| {
        d.variant
            .jitter
            .map(|s| rand::rngs::StdRng::seed_from_u64(s ^ k))
    };
    let field = &d.field;
    plan.kind = kind;
    plan.delta = d.delta;
    let mut b = Builder::new(st, c, drive, plan, vel, d.variant, rng(1), tools);
    let record = naming == Naming::Full;
    let mu = match d.mu(kind) {
        Some(mu) => mu,
        None => {
            // The pencil's noise and deliberate mistakes act at unit scale
            // in the first construction: only a plain one can skip it.
            let plain = d.variant.jitter.is_none()
                && d.variant.mistake.is_none()
                && d.variant.also.is_none();
            if let Some((mu, band)) = guess.filter(|_| plain) {
                b.again(mu, rng(2));
                b.record = record;
                if b.run().is_ok() && b.plan.settles_in(field, band) {
                    return Ok(true);
                }
            }
            b.again(1.0, rng(1));
            b.record = false;
            b.run()?;
            field.scale(b.plan.points.iter().map(|p| p.at))
        }
    };
    // The real construction at that scale (the steps' numbers are in mm),
    // in the first one's buffers.
    b.again(mu, rng(2));
    b.record = record;
    b.run()?;
    Ok(false)
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
    naming: Naming,
) -> Result<Plans> {
    let build = |kind, vel| -> Result<Plan> {
        let mut plan = Plan::empty(kind, 1.0, d.delta, st.m);
        let mut tools = Tools::new(st);
        let fresh = (&mut plan, &mut tools);
        construct(st, c, drive, (kind, vel), &d, naming, fresh, None)?;
        if naming == Naming::Full {
            record::narrate(&mut plan, &tools.acts, st);
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
/// a scale left open fits `d.field`.
pub fn build_plans(
    st: &Setup,
    c: &Configuration,
    drive: impl Into<Drives>,
    order: Order,
    d: Drafting,
) -> Result<Plans> {
    let drive = drive.into();
    build_plans_in(st, c, (drive, order), d, Naming::Full)
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
    let kind = PlanKind::Acceleration;
    let mut plan = Plan::empty(kind, 1.0, d.delta, st.m);
    let mut tools = Tools::new(st);
    let fresh = (&mut plan, &mut tools);
    let naming = Naming::Full;
    construct(
        st,
        c,
        drive,
        (kind, Some(vel)),
        &d,
        naming,
        fresh,
        None,
    )?;
    record::narrate(&mut plan, &tools.acts, st);
    Ok(plan)
}

/// A student's drawing replayed: the plan of `kind` (on the velocity plan
/// `vel` for an acceleration plan) at the scale `d` fixes, each point the
/// student drew (`given`) judged at the step that draws it from their own
/// earlier points ([`Plan::judged`]) and then taken where they drew it,
/// so that no earlier step's error is carried into a later one.
pub fn replay(
    st: &Setup,
    c: &Configuration,
    drive: impl Into<Drives>,
    (kind, vel): (PlanKind, Option<&Plan>),
    d: Drafting,
    given: Drawing,
) -> Result<Plan> {
    let drive = drive.into();
    debug_assert!(d.mu(kind).is_some(), "a replay is at the student's scale");
    let mut plan = Plan::empty(kind, 1.0, d.delta, st.m);
    let mut tools = Tools::new(st);
    tools.given = given;
    let fresh = (&mut plan, &mut tools);
    construct(st, c, drive, (kind, vel), &d, Naming::Full, fresh, None)?;
    record::narrate(&mut plan, &tools.acts, st);
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
    build_plans_in(st, c, (drive, order), d, Naming::NumbersOnly)
}

/// Numbers-only builds over a sweep ([`Naming::NumbersOnly`]): the plans
/// and the builder's buffers kept from one position to the next, and each
/// plan's last scale tried first: a plan drawn at it whose own extent
/// picks it ([`Plan::settles_in`]) is kept, without the first construction
/// at unit scale; else that construction is made. So a position's plans
/// equal, bit for bit, what [`build_plans_numbers`] gives for it alone,
/// but where the first construction at unit scale takes other
/// scale-dependent choices (which pair of a class III group, a similar
/// figure by division or by arcs) than the drawing does and its extent
/// falls a standard step apart (none of 5574 over the fixtures'
/// sweeps, `tests/plans.rs`): then the plan is at the neighbouring scale,
/// settled there, with the same values. The build of
/// `Analysis::sweep_kernel` (tests and benches only).
#[cfg(feature = "internals")]
pub struct Kernel {
    /// The last position's plans, their buffers for the next (empty
    /// until the first build).
    velocity: Option<Plan>,
    acceleration: Option<Plan>,
    /// The builder's buffers (made at the first build).
    tools: Option<Tools>,
    /// The last scales of the velocity and acceleration plans, with their
    /// bands ([`scale::band`]).
    last: [Option<(f64, (f64, f64))>; 2],
    /// Plans drawn at once at the last scale (no first construction).
    pub settled: usize,
}

#[cfg(feature = "internals")]
impl Kernel {
    pub fn new() -> Kernel {
        Kernel {
            velocity: None,
            acceleration: None,
            tools: None,
            last: [None; 2],
            settled: 0,
        }
    }

    /// The velocity plan of one position and, when `order` asks, its
    /// acceleration plan; a scale `d` leaves open fits the default
    /// [`Field`]. The mechanism must be the same at every call.
    pub fn build(
        &mut self,
        st: &Setup,
        c: &Configuration,
        drive: impl Into<Drives>,
        order: Order,
        d: Drafting,
    ) -> Result<(&Plan, Option<&Plan>)> {
        let drive = drive.into();
        let m = st.m;
        let velocity = self
            .velocity
            .get_or_insert_with(|| Plan::empty(PlanKind::Velocity, 1.0, d.delta, m));
        // (A construction empties what it uses first: an error mid-way
        // leaves nothing the next one reads.)
        let tools = self.tools.get_or_insert_with(|| Tools::new(st));
        let at = (st, c, drive, &d);
        let kind = (PlanKind::Velocity, None);
        self.settled += usize::from(sweep_plan(at, kind, velocity, tools, &mut self.last[0])?);
        if order == Order::Velocity {
            return Ok((velocity, None));
        }
        let acceleration = self
            .acceleration
            .get_or_insert_with(|| Plan::empty(PlanKind::Acceleration, 1.0, d.delta, m));
        let kind = (PlanKind::Acceleration, Some(&*velocity));
        self.settled += usize::from(sweep_plan(
            at,
            kind,
            acceleration,
            tools,
            &mut self.last[1],
        )?);
        Ok((velocity, Some(acceleration)))
    }
}

/// One plan of a sweep's position, numbers only, tried first at the
/// scale it was last drawn at (`last`, with its band), which it then
/// keeps: whether it settled there at once.
#[cfg(feature = "internals")]
fn sweep_plan(
    (st, c, drive, d): (&Setup, &Configuration, Drives, &Drafting),
    kind: (PlanKind, Option<&Plan>),
    plan: &mut Plan,
    tools: &mut Tools,
    last: &mut Option<(f64, (f64, f64))>,
) -> Result<bool> {
    let naming = Naming::NumbersOnly;
    let settled = construct(st, c, drive, kind, d, naming, (plan, tools), *last)?;
    // The scale the plan was drawn at, and its band when it changed.
    if last.is_none_or(|l| l.0 != plan.mu) {
        *last = scale::band(plan.mu).map(|b| (plan.mu, b));
    }
    Ok(settled)
}

#[cfg(feature = "internals")]
impl Default for Kernel {
    fn default() -> Self {
        Kernel::new()
    }
}
