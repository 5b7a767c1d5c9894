//! Every tolerance mechplan decides by, in one documented place.
//!
//! Two kinds. *Rounding multiples* say how many units of rounding (ε, the
//! machine epsilon, times the magnitude of the numbers involved) a result
//! may carry before it counts as different: they judge a part by its own
//! numbers, never by the size of the whole sketch. *Thresholds* are
//! dimensionless limits of a method (a sine, a ratio, a turn).

/// The tolerances (see [`ACCURACY`] for the values and why).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Accuracy {
    /// A slider's point may be drawn off its guide by this fraction of
    /// the links that carry it: the sketch is a drawing.
    pub sketch_off_guide: f64,
    /// A length between two frame points against their coordinates,
    /// relative (the contract's 1e-9: frame points are exact).
    pub frame_length: f64,
    /// The dead band of a group's orientation sign read off the sketch (a
    /// sine or cosine of the group's own lengths): within it the sketch
    /// shows a dead point and its branch cannot be read.
    pub branch_dead_band: f64,
    /// The smallest sine at which two lines are intersected (positions,
    /// plans, the special point of a class III group).
    pub min_line_sine: f64,
    /// A contour matrix with unit columns whose determinant is below this
    /// is singular (route (a)).
    pub min_contour_determinant: f64,
    /// Units of rounding a toggle (tangent circles, a circle touching a
    /// line, a rocking guide's pin at its reach) may miss by and still
    /// close: ε times the group's lengths and its joints' coordinates.
    pub tangency_roundings: f64,
    /// Route (b): the smallest σ_min/σ_max of the scaled Jacobian solved
    /// for rates; below it the position is singular.
    pub min_conditioning: f64,
    /// Route (b): the largest turn of the path over one step of the path
    /// follower, radians (at a neck of width δ the path's radius is about
    /// δ, so a step is a few hundredths of δ).
    pub max_path_turn: f64,
    /// Route (b): the largest step of a crank's angle, degrees (a driving
    /// slider: this many per cent of its link's size).
    pub max_path_step: f64,
    /// Two places of one link within this fraction of its size are one
    /// material point (the construction kernel's plan points).
    pub same_point: f64,
    /// A point of a link whose offset from the line of two known points is
    /// below this fraction of their distance is on that line (a division).
    pub collinear_ratio: f64,
    /// The relative vector from one known point replaces the similar
    /// figure only when its error radius is this many times smaller.
    pub relation_over_figure: f64,
    /// Two arcs are replaced by a division only when the division's error
    /// radius is this many times smaller.
    pub division_over_arcs: f64,
    /// The largest relative disagreement of the two routes, or change with
    /// the data moved by their rounding, before a position is refused.
    pub max_rel_diff: f64,
    /// Units of its own rounding every datum is moved by in the data check.
    pub data_roundings: f64,
    /// Without plans (the fast path), the data check is route (b)'s
    /// equations of the changed data linearized at route (a)'s answer
    /// where the scaled Jacobian's conditioning is at least this; below
    /// it (near a singular position, where the change is not linear in
    /// the data) route (a) is solved again on the changed data.
    pub linear_data_conditioning: f64,
    /// … and where the linearized sensitivity is below this: nearer the
    /// refusal (`max_rel_diff`) it is decided by the solve again.
    pub linear_data_sensitivity: f64,
    /// The constant c of the printed bound (c·ε·κ + 4·d + 4·σ)·S: the
    /// roundings per equation and their accumulation through the groups.
    pub bound_roundings: f64,
    /// An item of a hand-drawn plan whose tolerance exceeds this fraction
    /// of the plan's size cannot be judged.
    pub max_tolerance_of_plan: f64,
    /// Two explanations of a wrong answer are told apart only when one's
    /// misfit is this many times the other's.
    pub distinct_misfit: f64,
    /// Of two mistakes of different kinds that both put a wrong step's
    /// point within their tolerance, the better is named when the other's
    /// misfit (distance over tolerance) is more than this many times its
    /// own; else both are listed, not recognised.
    pub step_distinct_misfit: f64,
    /// How a student's point scatters within a step's tolerance, for
    /// weighing a right construction against a mistaken one that both
    /// put it there: the tolerance is the worst case of about three
    /// errors each within δ (the points used read, the pencil, the point
    /// read), so a point at misfit m (distance over tolerance) is
    /// (1 − m²)^k as likely as one at the construction's place — a
    /// density that vanishes at the worst case and, with k = 4, follows
    /// that of the sum of three such errors to within a tenth of its
    /// logarithm's range out to m = 0.97.
    pub step_scatter: f64,
    /// The force analysis: the smallest reciprocal condition number (1-norm)
    /// of the scaled equilibrium system; below it its rounding (ε/rcond)
    /// could exceed `max_rel_diff` and the position is refused.
    pub min_force_conditioning: f64,
    /// The force analysis: the two routes' balancing moments (forces) may
    /// differ by this fraction of the virtual power's terms (the sum of
    /// their magnitudes) before the position is refused, as the routes of
    /// the kinematics by `max_rel_diff`.
    pub max_balancing_diff: f64,
    /// A prismatic pair's normal force below this fraction of the largest
    /// force at the position has no point of application (`at` is null):
    /// the couple over it would be rounding magnified.
    pub null_normal_force: f64,
}

/// The values mechplan uses.
pub const ACCURACY: Accuracy = Accuracy {
    sketch_off_guide: 1e-3,
    frame_length: 1e-9,
    branch_dead_band: 1e-9,
    min_line_sine: 1e-12,
    min_contour_determinant: 1e-12,
    tangency_roundings: 64.0,
    min_conditioning: 1e-13,
    max_path_turn: 0.035,
    max_path_step: 5.0,
    same_point: 1e-9,
    collinear_ratio: 1e-12,
    relation_over_figure: 2.0,
    division_over_arcs: 2.0,
    max_rel_diff: 1e-6,
    data_roundings: 8.0,
    linear_data_conditioning: 1e-3,
    linear_data_sensitivity: 1e-9,
    bound_roundings: 256.0,
    max_tolerance_of_plan: 0.2,
    distinct_misfit: 2.0,
    step_distinct_misfit: 1.5,
    step_scatter: 4.0,
    min_force_conditioning: f64::EPSILON / 1e-6,
    max_balancing_diff: 1e-6,
    null_normal_force: 1e-9,
};
