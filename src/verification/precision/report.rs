//! What the work-precision report is: the settings of a run, and its
//! rows of errors and run times per method.



/// What to run.
#[derive(Clone, Debug)]
pub struct Settings {
    /// Newton tolerances of route (b).
    pub newton_tols: Vec<f64>,
    /// Positions per revolution of the kinematic diagrams.
    pub diagram_ns: Vec<usize>,
    /// Monte Carlo seeds of the emulated hand drafting.
    pub seeds: u64,
    /// Pencil precision, mm.
    pub delta: f64,
    /// Positions compared: `None` the scene's own (36 of a revolution
    /// when it gives one), `Some(k)` k of a revolution from its input.
    pub positions: Option<usize>,
    /// Least wall time of one timing batch, seconds (three batches, the
    /// fastest counts).
    pub min_time: f64,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            newton_tols: vec![1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14],
            diagram_ns: vec![12, 24, 48, 96, 180, 360, 720, 1800, 3600],
            seeds: 200,
            delta: 0.5,
            positions: None,
            min_time: 0.1,
        }
    }
}

/// Maximum and median of one kind of error.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stat {
    pub max: f64,
    pub median: f64,
}

/// The kinds of output quantity, in the order of [`Row::err`] (named by
/// the tests).
#[cfg(feature = "internals")]
pub const KINDS: [&str; 5] = ["place", "v", "a", "ω", "ε"];

/// One method at one setting.
#[derive(Clone, Debug)]
pub struct Row {
    /// "kernel", "contour", "newton", "chords", "central", "hand".
    pub method: String,
    /// "tol 1e-8", "N = 360", "δ = 0.5 mm, 200 seeds", or "".
    pub setting: String,
    /// Run time per position, seconds.
    pub time: f64,
    /// Per kind of quantity (place, v, a, ω, ε); `None` where the method does not give it.
    pub err: [Option<Stat>; 5],
    /// Positions (× seeds) compared (read by the tests).
    #[cfg(feature = "internals")]
    pub compared: usize,
}

impl Row {
    /// The largest of the row's maximum errors.
    #[cfg(feature = "internals")]
    pub fn worst(&self) -> f64 {
        self.err.iter().flatten().map(|s| s.max).fold(0.0, f64::max)
    }
    /// The worst error among the rates (v, a, ω, ε), the plot's ordinate.
    pub fn worst_rates(&self) -> f64 {
        self.err[1..]
            .iter()
            .flatten()
            .map(|s| s.max)
            .fold(0.0, f64::max)
    }
}

/// The whole report of one scene.
#[derive(Clone, Debug)]
pub struct Report {
    pub positions: usize,
    pub rows: Vec<Row>,
}
