//! The positions a course project's sheets single out: the ones whose
//! plans the course sheet shows, and the one it analyses (its acceleration
//! plan, its force sheet, the bold position of the positions drawing).

use crate::kinematics::solve::Analysis;
use crate::model::scene::PositionsSpec;
use crate::pipeline::Solved;

/// Which positions' plans the sheet shows (the k-th, from 1: ordinals, not
/// the positions' numbers, which `position_number` gives): the velocity
/// plans of every position (of every k-th beyond 24 positions) unless
/// `want.plans_at` says; the acceleration plans of `want.plans_at`, by
/// default the first position (the start of the working stroke) and the
/// one in the middle of the working stroke.
pub fn chosen(an: &Analysis, solved: &[Solved]) -> (Vec<usize>, Vec<usize>) {
    chosen_of(an, solved.len())
}

/// [`chosen`] of `n` positions (which only their number decides).
pub fn chosen_of(an: &Analysis, n: usize) -> (Vec<usize>, Vec<usize>) {
    let at = &an.mech.scene.want.plans_at;
    let velocity = at.velocity.clone().unwrap_or_else(|| {
        let step = if n <= 24 { 1 } else { n.div_ceil(12) };
        (1..=n).step_by(step).collect()
    });
    let acceleration = at.acceleration.clone().unwrap_or_else(|| {
        let middle = match &an.mech.scene.positions {
            PositionsSpec::Count { count, output } => {
                let out = output.unwrap_or_else(|| an.default_output());
                an.working_stroke(out).ok().map(|(_, stroke)| {
                    let step = std::f64::consts::TAU / *count as f64;
                    1 + ((stroke / 2.0) / step).round() as usize
                })
            }
            _ => Some(n / 2 + 1),
        };
        let mut v = vec![1];
        if let Some(k) = middle.filter(|&k| k > 1 && k <= n) {
            v.push(k);
        }
        v
    });
    (velocity, acceleration)
}

/// The position the force analysis sheet analyses (from 0): the first
/// position with an acceleration plan after the first, else the first.
pub fn position(an: &Analysis, solved: &[Solved]) -> usize {
    let (_, acc) = chosen(an, solved);
    acc.iter()
        .copied()
        .find(|&k| k > 1)
        .or(acc.first().copied())
        .unwrap_or(1)
        .clamp(1, solved.len().max(1))
        - 1
}
