//! The typical mistakes of a force plan, each as the whole plan it draws
//! at the student's scale: wrong loads (inertia not reversed, weights left
//! out, the polygon at another scale than the stated μ_F), a slip in one
//! step of the construction (τ's sign, τ along the link, the neighbouring
//! group's reactions reversed, the balancing moment's arms from the wrong
//! point), or a wrong reading of the finished plan (a reaction read the
//! wrong way round, the balancing moment's sign).

use crate::error::Result;
use crate::kinematics::solve::Analysis;
use crate::kinetostatics::force_plan::{self, ForcePlan, ForceStep, Slip, Which};
use crate::kinetostatics::loads::{Load, Origin};
use crate::pipeline::Solved;
use crate::words::construction::Lang;
use crate::words::{check, numbers};

/// A typical mistake of a force plan.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ForceMistake {
    /// The inertia forces and couples not reversed (m·a_S, J·ε).
    NotReversed,
    /// The weights left out.
    WeightsLeftOut,
    /// The polygon drawn at `drawn` × the stated μ_F (its segments
    /// 1/`drawn` of what the stated scale gives).
    Scale {
        /// The scale drawn at, as a multiple of the stated μ_F.
        drawn: f64,
    },
    /// The tangential components with the wrong sign.
    TangentialSign,
    /// The tangential components laid along the link.
    TangentialAlong,
    /// The reactions of the group solved before taken reversed.
    NeighbourSign,
    /// The balancing moment's arms from the crank's other joint.
    BalancingArm,
    /// Reactions read the wrong way round (R_12 for R_21).
    ActionForReaction,
    /// The balancing moment (force) with its sign reversed.
    BalancingSign,
}

impl ForceMistake {
    /// Every mistake the check tries, in the order it names them.
    pub const ALL: [ForceMistake; 10] = [
        ForceMistake::NotReversed,
        ForceMistake::WeightsLeftOut,
        ForceMistake::TangentialSign,
        ForceMistake::TangentialAlong,
        ForceMistake::ActionForReaction,
        ForceMistake::NeighbourSign,
        ForceMistake::Scale { drawn: 2.0 },
        ForceMistake::Scale { drawn: 0.5 },
        ForceMistake::BalancingSign,
        ForceMistake::BalancingArm,
    ];

    /// The mistake in words, to follow "the plan was drawn with".
    pub fn words(self, lang: Lang) -> String {
        let w = check::phrases(lang);
        match self {
            ForceMistake::NotReversed => w.force_not_reversed.clone(),
            ForceMistake::WeightsLeftOut => w.force_weights_left_out.clone(),
            ForceMistake::Scale { drawn } => {
                let k = numbers::decimals(&crate::format::num(drawn), lang);
                check::fill(&w.force_scale, &[("k", &k)])
            }
            ForceMistake::TangentialSign => w.force_tau_sign.clone(),
            ForceMistake::TangentialAlong => w.force_tau_along.clone(),
            ForceMistake::NeighbourSign => w.force_neighbour_sign.clone(),
            ForceMistake::BalancingArm => w.force_mb_arm.clone(),
            ForceMistake::ActionForReaction => w.force_action_for_reaction.clone(),
            ForceMistake::BalancingSign => w.force_mb_sign.clone(),
        }
    }
}

/// Where the plans are drawn: the position, the right loads, δ, and the
/// checked plan with the student's μ_F.
pub(super) struct At<'a> {
    pub an: &'a Analysis,
    pub s: &'a Solved,
    pub loads: &'a [Load],
    pub delta: f64,
    pub which: Which,
    pub mu: f64,
    pub links: &'a [String],
}

impl At<'_> {
    /// The checked plan drawn with `loads` and `slip`.
    pub(super) fn plan(&self, loads: &[Load], slip: Option<Slip>) -> Result<ForcePlan> {
        let fp = force_plan::solve_slipped(
            self.an,
            self.s,
            loads,
            self.delta,
            Some((self.which, self.mu)),
            slip,
        )?;
        let (_, i) = super::place::which(self.an, &fp.plans, self.links).expect("the same structure");
        Ok(fp.plans[i].clone())
    }

    /// The plans of mistake `m`, given the right plan `right` (τ's sign:
    /// the first side's, the second's, both); none where a mistaken plan
    /// cannot be drawn (its lines parallel, say).
    pub(super) fn mistaken(&self, m: ForceMistake, right: &ForcePlan) -> Vec<ForcePlan> {
        if m == ForceMistake::TangentialSign {
            return [(true, false), (false, true), (true, true)]
                .into_iter()
                .filter_map(|(first, second)| {
                    let slip = Slip::TangentialSign { first, second };
                    self.plan(self.loads, Some(slip)).ok()
                })
                .collect();
        }
        self.one_mistaken(m, right).into_iter().collect()
    }

    /// The plan of a mistake drawn one way.
    fn one_mistaken(&self, m: ForceMistake, right: &ForcePlan) -> Option<ForcePlan> {
        let loads = self.loads;
        match m {
            ForceMistake::NotReversed => self.plan(&not_reversed(loads), None).ok(),
            ForceMistake::WeightsLeftOut => self.plan(&without_weights(loads), None).ok(),
            // Every load ×k: the linear equilibrium scales every force ×k,
            // so the segments are those of a polygon at μ_F / k.
            ForceMistake::Scale { drawn } => self.plan(&scaled(loads, 1.0 / drawn), None).ok(),
            ForceMistake::TangentialSign => None,
            ForceMistake::TangentialAlong => self.plan(loads, Some(Slip::TangentialAlong)).ok(),
            ForceMistake::NeighbourSign => self.plan(loads, Some(Slip::NeighbourSign)).ok(),
            ForceMistake::BalancingArm => self.plan(loads, Some(Slip::BalancingAbout)).ok(),
            ForceMistake::ActionForReaction => {
                // The reactions read off the plan, each the wrong way round.
                let mut p = right.clone();
                for step in &right.steps {
                    if let ForceStep::Measure(i) = step {
                        let v = &mut p.vectors[*i];
                        std::mem::swap(&mut v.from, &mut v.to);
                        v.value = -v.value;
                    }
                }
                Some(p)
            }
            ForceMistake::BalancingSign => {
                let mut p = right.clone();
                for step in &mut p.steps {
                    if let ForceStep::Balancing { value, .. } = step {
                        *value = -*value;
                    }
                }
                Some(p)
            }
        }
    }
}

/// The loads with the inertia forces and couples not reversed.
fn not_reversed(loads: &[Load]) -> Vec<Load> {
    loads
        .iter()
        .map(|l| match *l {
            Load::Force {
                f,
                origin: Origin::Inertia,
                link,
                point,
                at,
            } => Load::Force {
                f: -f,
                origin: Origin::Inertia,
                link,
                point,
                at,
            },
            Load::Couple {
                m,
                origin: Origin::Inertia,
                link,
            } => Load::Couple {
                m: -m,
                origin: Origin::Inertia,
                link,
            },
            other => other,
        })
        .collect()
}

/// The loads with the weights zeroed in place (a zero force is not drawn),
/// so that every other load keeps its index and its name.
fn without_weights(loads: &[Load]) -> Vec<Load> {
    loads
        .iter()
        .map(|l| match *l {
            Load::Force {
                origin: Origin::Gravity,
                link,
                point,
                at,
                ..
            } => Load::Force {
                f: kurbo::Vec2::ZERO,
                origin: Origin::Gravity,
                link,
                point,
                at,
            },
            other => other,
        })
        .collect()
}

/// Every load ×`k`.
fn scaled(loads: &[Load], k: f64) -> Vec<Load> {
    loads
        .iter()
        .map(|l| match *l {
            Load::Force {
                f,
                origin,
                link,
                point,
                at,
            } => Load::Force {
                f: f * k,
                origin,
                link,
                point,
                at,
            },
            Load::Couple { m, origin, link } => Load::Couple {
                m: m * k,
                origin,
                link,
            },
        })
        .collect()
}
