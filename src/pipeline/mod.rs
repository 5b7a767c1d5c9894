//! The pipeline above the stages: every position asked for, solved in
//! order ([`run`]): the kinematics (both routes, the plans), their
//! cross-check, then the forces. A [`Solved`] position is the kinematic
//! [`Position`] with its [`CrossCheck`] and, with the scene's `dynamics`,
//! its force analysis; it reads as its position (`Deref`).

mod held;
mod inputs;
mod rescaled;
mod run;
mod switches;

pub use inputs::{InputPosition, InputPositions};

pub use crate::kinematics::solve::{Analysis, Position};
pub use crate::verification::crosscheck::CrossCheck;

use crate::kinetostatics::Dynamics;

/// Positions found and finished at a time by [`Analysis::run_each`]:
/// enough to keep both cores busy, few enough that a sweep of the largest
/// count allowed needs no more memory than a short one.
pub const RUN_CHUNK: usize = 512;

/// One solved position: the kinematics, its cross-check, the forces.
#[derive(Clone, Debug)]
pub struct Solved {
    /// What the kinematics gives at the position.
    pub position: Position,
    /// The routes and the plans compared, with the printed bounds.
    pub check: Option<CrossCheck>,
    /// The force analysis (with the scene's `dynamics`), after the
    /// cross-check has passed the motion it starts from.
    pub dynamics: Option<Box<Dynamics>>,
}

impl From<Position> for Solved {
    /// A position not yet checked, without forces.
    fn from(position: Position) -> Solved {
        Solved {
            position,
            check: None,
            dynamics: None,
        }
    }
}

impl std::ops::Deref for Solved {
    type Target = Position;
    fn deref(&self) -> &Position {
        &self.position
    }
}

impl std::ops::DerefMut for Solved {
    fn deref_mut(&mut self) -> &mut Position {
        &mut self.position
    }
}
