//! Positions made lean as they are finished, where only the sheets read
//! them (`draw` of a sweep no sheet reads all at once, whose runs hold a
//! chunk of positions in flight): the sheets that share scales (the
//! mechanism's μ_l and box) read of a position's plans only the rates
//! (the plan of the mechanism marks ω); each position's own sheets get
//! its plans built again when its turn comes. A lean position is some
//! 3 kB where a whole one with its plans is 20 to 35 kB.

use super::{Analysis, Solved};
use crate::error::Result;
use crate::kinematics::construction::{Plan, Plans, build_plans};

impl Solved {
    /// The position without what only its own sheets read: its plans
    /// reduced to their rates (each plan's construction, points and
    /// measures dropped; [`Analysis::plans_again`] builds them again),
    /// and the transfer functions (drawn on no sheet). The cross-check
    /// stays: the run's checks of the assembly between positions read it.
    pub fn lean(mut self) -> Solved {
        if let Some(p) = self.position.plans.as_mut() {
            rates_only(&mut p.velocity);
            if let Some(a) = p.acceleration.as_mut() {
                rates_only(a);
            }
        }
        self.position.analogue = Vec::new();
        self.position.more_analogues = Vec::new();
        self.position.mixed = Vec::new();
        self
    }
}

/// `plan` reduced to its rates and their senses.
fn rates_only(plan: &mut Plan) {
    plan.points = Vec::new();
    plan.steps = Vec::new();
    plan.measured = Vec::new();
    plan.body = Vec::new();
    plan.of_point = Vec::new();
}

impl Analysis {
    /// The plans of position `index` (from 0) built again from its
    /// places and drives, as its run built them (the same build, the same
    /// scales: the same plans to the bit); `None` where the run builds
    /// none.
    pub fn plans_again(&self, index: usize, s: &Solved) -> Result<Option<Plans>> {
        match (self.plans, self.order) {
            (true, Some(order)) => {
                let d = self.drafting_at(index);
                build_plans(&self.setup(), &s.config, s.drives, order, d).map(Some)
            }
            _ => Ok(None),
        }
    }
}
