//! The independent check: the balancing moment (force) by the principle of
//! virtual power. Frictionless pairs do no work, so the drive's power
//! balances that of every known load: M_b·ω1 + Σ F·v_P + Σ M·ω = 0.
//!
//! Written with the transfer functions (route (a) at unit input rate):
//! M_b = −(Σ F·v_P' + Σ M·φ'), the same as dividing by ω1, and defined
//! also where the input stands (ω1 = 0). A slider input: per unit speed,
//! the drive's force along its guide. Several inputs: each input's
//! generalised force, its partial velocities.

use super::loads::Load;
use crate::kinematics::solve::{Analysis, Position};

/// The balancing moment (crank, N·m) or force (driving slider, N) of each
/// input by virtual power, with the sum of the magnitudes of its power's
/// terms: the scale of the cancellation it came from.
#[derive(Clone, Debug, PartialEq)]
pub struct VirtualPower {
    pub balancing: Vec<f64>,
    pub scale: Vec<f64>,
}

/// [`VirtualPower`] of `loads` at solved position `s`.
pub fn balancing(an: &Analysis, s: &Position, loads: &[Load]) -> VirtualPower {
    let w = an.mech.scene.input_count();
    let mut out = VirtualPower {
        balancing: Vec::with_capacity(w),
        scale: Vec::with_capacity(w),
    };
    for i in 0..w {
        let unit = s.analogue_of(i);
        let (mut sum, mut scale) = (0.0, 0.0);
        for load in loads {
            let Some(mo) = unit[load.link()] else {
                continue;
            };
            let p = match *load {
                Load::Force { at, f, .. } => f.dot(mo.velocity(at)),
                Load::Couple { m, .. } => m * mo.omega,
            };
            sum += p;
            scale += p.abs();
        }
        out.balancing.push(-sum);
        out.scale.push(scale);
    }
    out
}
