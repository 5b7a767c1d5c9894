//! The run's switches for the project's own tests and benches (feature
//! `internals`): the reference twins instead of the compiled route, the
//! sweep's construction kernel, a deliberate error put into route (a) to
//! see the cross-check catch it. Without `internals` each is off and
//! costs nothing.

use super::Analysis;
use crate::kinematics::analytic::{Coords, Order};
#[cfg(feature = "internals")]
pub(super) use crate::kinematics::construction::Kernel;
use crate::kinematics::construction::Plans;
use crate::kinematics::positions::Configuration;
#[cfg(feature = "internals")]
use crate::kinematics::solve::Corruption;
#[cfg(feature = "internals")]
use std::time::Instant as Clock;

/// Without `internals` no sweep's kernel is ever asked for
/// (`Analysis::sweep_kernel` is the tests' and benches' switch): a
/// kernel that cannot be made, so the run's route carries none.
#[cfg(not(feature = "internals"))]
pub(super) type Kernel = std::convert::Infallible;

impl Analysis {
    /// Whether the run takes the twins kept as references
    /// (`Analysis::reference`, tests and benches only).
    pub(super) fn reference(&self) -> bool {
        #[cfg(feature = "internals")]
        return self.reference;
        #[cfg(not(feature = "internals"))]
        false
    }

    /// The sweep's kernel where plans are only checked and it is asked
    /// for (`Analysis::sweep_kernel`, tests and benches only).
    #[cfg(feature = "internals")]
    pub(super) fn kernel(&self) -> Option<Kernel> {
        (self.plans && !self.keep_plans && !self.reference && self.sweep_kernel).then(Kernel::new)
    }

    /// No sweep's kernel without `internals`.
    #[cfg(not(feature = "internals"))]
    pub(super) fn kernel(&self) -> Option<Kernel> {
        None
    }

    /// Without `internals` there is no kernel to build with.
    #[cfg(not(feature = "internals"))]
    pub(super) fn kernel_plans(
        &self,
        k: &mut Kernel,
        _: &Configuration,
        _: (Coords, usize),
        _: Order,
    ) -> (Option<Plans>, f64) {
        match *k {}
    }

    /// The plans of a position by the sweep's kernel `k`, numbers only (as
    /// the one-position build's, [`Kernel`]), and their time; `None` where
    /// it refuses.
    #[cfg(feature = "internals")]
    pub(super) fn kernel_plans(
        &self,
        k: &mut Kernel,
        config: &Configuration,
        (q, index): (Coords, usize),
        order: Order,
    ) -> (Option<Plans>, f64) {
        let t = Clock::now();
        let drives = self.drives_at(&q);
        let plans = k
            .build(&self.setup(), config, drives, order, self.drafting_at(index))
            .ok()
            .map(|(v, a)| Plans {
                velocity: v.clone(),
                acceleration: a.cloned(),
            });
        (plans, t.elapsed().as_secs_f64())
    }

    /// Put the deliberate error of [`Analysis::corrupt`] (tests only) into
    /// route (a)'s answer: into the link that reports the last point on a
    /// moving link (so that reported numbers change).
    #[cfg(feature = "internals")]
    pub(super) fn corrupt(
        &self,
        config: &mut Configuration,
        motion: &mut [Option<crate::kinematics::analytic::Motion>],
    ) {
        use crate::geom::Pose;
        use kurbo::Vec2;
        let Some(c) = self.corrupt else { return };
        let m = &self.mech;
        // The link that reports the last reported point on a moving link.
        let Some(l) = self
            .points
            .iter()
            .rev()
            .map(|&p| self.carrier(p))
            .find(|&l| l != m.frame())
        else {
            return;
        };
        // The largest velocity and acceleration of a reported point.
        let (mut sv, mut sa) = (f64::MIN_POSITIVE, f64::MIN_POSITIVE);
        for &p in &self.points {
            let k = self.carrier(p);
            if let Some(mo) = motion[k] {
                let at = config.point(m, k, p);
                sv = sv.max(mo.velocity(at).hypot());
                sa = sa.max(mo.acceleration(at).hypot());
            }
        }
        let pose = config.pose(l);
        match c {
            Corruption::Position(x) => {
                let moved = pose.origin + Vec2::new(x * m.size, 0.0);
                config.poses[l] = Some(Pose::new(moved, pose.angle));
            }
            Corruption::Velocity(x) => {
                if let Some(mo) = motion[l].as_mut() {
                    mo.v_at += Vec2::new(x * sv, 0.0);
                }
            }
            Corruption::Acceleration(x) => {
                if let Some(mo) = motion[l].as_mut() {
                    mo.a_at += Vec2::new(x * sa, 0.0);
                }
            }
        }
    }
}
