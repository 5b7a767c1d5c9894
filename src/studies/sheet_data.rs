//! What the sheets draw that takes solving beyond the solved positions,
//! solved here for the sheets a request draws and read by presentation:
//! the positions' trajectories and the output's extreme positions (the
//! positions sheet, the course sheet), the positions the course singles
//! out (found from the working stroke), the kinematic diagrams (the
//! diagrams sheet, the course sheet; each sheet scales them to its room
//! with [`Diagrams::at_length`]).

use crate::error::Result;
use crate::kinematics::solve::Analysis;
use crate::studies::chosen::Chosen;
use crate::studies::diagrams::Diagrams;
use crate::studies::stroke::Stroke;
use crate::studies::trajectories::{Placed, Trajectories, trajectories};

/// The kinematic diagrams' intervals per revolution, as the lecture draws
/// them (N = 12).
pub const DIAGRAM_INTERVALS: usize = 12;

/// The abscissa the diagrams are sampled at, mm (each sheet rescales).
const SAMPLED_LENGTH: f64 = 180.0;

/// Which of [`SheetData`] the sheets of a request draw (the drawing layer
/// says: `drawing::sheet_needs`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SheetNeeds {
    /// The positions sheet or the course sheet: trajectories, extreme
    /// positions and the chosen positions.
    pub trajectories: bool,
    /// The diagrams sheet, whose diagrams must be drawn (a failure to
    /// build them fails the request).
    pub diagrams: bool,
    /// The course sheet, which draws the diagrams where they can be built.
    pub course: bool,
}

/// The data of the sheets [`SheetNeeds`] names, solved.
#[derive(Clone, Debug, Default)]
pub struct SheetData {
    /// The trajectories and the extreme positions, where drawn.
    pub trajectories: Option<Trajectories>,
    /// The positions whose plans the course sheet shows and the one it
    /// analyses (the bold one of the positions drawing).
    pub chosen: Chosen,
    /// The diagrams of the mechanism's output, N = 12, where drawn and
    /// built.
    pub diagrams: Option<Diagrams>,
    /// The output's stroke H, the working and idle strokes' crank angles
    /// and K, for the course sheet (none for an output that turns fully).
    pub stroke: Option<Stroke>,
}

impl SheetData {
    /// Solve what `needs` names for the positions `solved`. Errors: the
    /// diagrams the diagrams sheet needs cannot be built (an output that
    /// turns fully, one that does not move).
    pub fn solve<S: Placed>(
        an: &Analysis,
        solved: &[S],
        needs: SheetNeeds,
    ) -> Result<SheetData> {
        let build = || {
            let out = crate::studies::invariants::default_output(an);
            Diagrams::build(an, out, DIAGRAM_INTERVALS, SAMPLED_LENGTH)
        };
        let diagrams = if needs.diagrams {
            Some(build()?)
        } else if needs.course {
            build().ok()
        } else {
            None
        };
        Ok(SheetData {
            trajectories: needs.trajectories.then(|| trajectories(an, solved)),
            chosen: match needs.trajectories || needs.course {
                true => Chosen::of(an, solved.len()),
                false => Chosen::default(),
            },
            diagrams,
            stroke: if needs.course { Stroke::of(an) } else { None },
        })
    }
}
