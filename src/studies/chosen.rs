//! The positions a course project's sheets single out: the ones whose
//! plans the course sheet shows, and the one it analyses (its acceleration
//! plan, its force sheet, the bold position of the positions drawing).
//! Chosen here, where the working stroke may be solved for (the middle of
//! the working stroke by default), and read by the drawings.

use crate::kinematics::solve::Analysis;
use crate::model::scene::PositionsSpec;

/// Which positions' plans the sheets show (the k-th, from 1: ordinals, not
/// the positions' numbers, which `position_number` gives).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Chosen {
    /// The velocity plans shown: every position (every k-th beyond 24
    /// positions) unless `want.plans_at` says.
    pub velocity: Vec<usize>,
    /// The acceleration plans shown: `want.plans_at`'s; by default, in a
    /// sweep (`count`), the positions in the middle of the working stroke
    /// and in the middle of the idle stroke (not its start, an extreme
    /// position: a dead centre), else the first and the middle one.
    pub acceleration: Vec<usize>,
}

impl Chosen {
    /// The positions of `n` whose plans the sheets show (which only their
    /// number decides, so known before any is solved).
    pub fn of(an: &Analysis, n: usize) -> Chosen {
        let at = &an.mech.scene.want.plans_at;
        let velocity = at.velocity.clone().unwrap_or_else(|| {
            let step = if n <= 24 { 1 } else { n.div_ceil(12) };
            (1..=n).step_by(step).collect()
        });
        let acceleration = at.acceleration.clone().unwrap_or_else(|| {
            let middles = match &an.mech.scene.positions {
                // A sweep starts at the working stroke's start, an extreme
                // position (a dead centre of a slider-crank): the plans of
                // the middle of the working stroke and of the idle stroke
                // instead, as a course draws them.
                PositionsSpec::Count { count, output } => {
                    let out = output.unwrap_or_else(|| an.default_output());
                    an.working_stroke(out).ok().map(|(_, stroke)| {
                        let step = std::f64::consts::TAU / *count as f64;
                        let at = |phi: f64| 1 + (phi / step).round() as usize;
                        let idle = std::f64::consts::TAU - stroke;
                        vec![at(stroke / 2.0), at(stroke + idle / 2.0)]
                    })
                }
                _ => Some(vec![1, n / 2 + 1]),
            };
            let mut v: Vec<usize> = Vec::new();
            for k in middles.unwrap_or_default() {
                if (1..=n).contains(&k) && !v.contains(&k) {
                    v.push(k);
                }
            }
            if v.is_empty() {
                v.push(1);
            }
            v
        });
        Chosen {
            velocity,
            acceleration,
        }
    }

    /// The position (from 0) of `n` that the force analysis sheet
    /// analyses: the first with an acceleration plan after the first
    /// position, else the first with one.
    pub fn analysed(&self, n: usize) -> usize {
        self.acceleration
            .iter()
            .copied()
            .find(|&k| k > 1)
            .or(self.acceleration.first().copied())
            .unwrap_or(1)
            .clamp(1, n.max(1))
            - 1
    }

    /// Every position (from 0) whose plan is shown, velocity or
    /// acceleration, once each in order: the ones whose scales the course
    /// sheet fixes.
    pub fn shown(&self) -> Vec<usize> {
        let mut at: Vec<usize> = (self.velocity.iter().chain(&self.acceleration))
            .filter(|&&k| k >= 1)
            .map(|k| k - 1)
            .collect();
        at.sort_unstable();
        at.dedup();
        at
    }
}
