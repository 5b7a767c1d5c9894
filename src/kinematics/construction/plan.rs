//! What the kernel hands out: a plan (its points, steps, measured values
//! and rates), what it needs to build one ([`Setup`], [`Drafting`]) and
//! the ways to build it besides the standard one ([`Variant`], [`Mistake`]).

pub use super::variant::{Mistake, Variant};
use crate::model::mechanism::Mechanism;
use crate::model::structure::Structure;
use kurbo::Vec2;

/// A plan of velocities or of accelerations: the same idea as the order of
/// the motion a route computes ([`crate::kinematics::analytic::Order`]),
/// one type under its two names.
pub use crate::kinematics::analytic::Order as PlanKind;

/// What a plan point is, by the indices of the mechanism: the kernel finds
/// and builds points by their ids; the names (`b`, `n_2`, `b_3` …) are
/// given at the end, from the ids and the mechanism's names.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PointId {
    /// The pole (plan point 0): p_v, p_a.
    Pole,
    /// A named point of the mechanism (its index): b, s2.
    Named(usize),
    /// A named point as a point of another link: b_3 is B of link 3.
    Coincident {
        /// The named point.
        point: usize,
        /// The link it is taken as a point of.
        link: usize,
    },
    /// The end of a normal component ω²·l of a link: n_2.
    Normal {
        /// The link.
        link: usize,
    },
    /// The end of a Coriolis acceleration of a link's sliding: k_3.
    Coriolis {
        /// The sliding link.
        link: usize,
    },
    /// The end of the given relative velocity (relative acceleration) of
    /// a link in a driving pair, laid off first on a cylinder's side: r_3.
    Relative {
        /// The link.
        link: usize,
    },
    /// The special point of a class III group on its base link: s_4.
    Special {
        /// The group's base link.
        base: usize,
    },
}

impl PointId {
    /// A point of the construction only (the pole, the ends of normal and
    /// Coriolis components): it has no name on the mechanism's figure.
    pub fn is_construction(self) -> bool {
        matches!(
            self,
            PointId::Pole
                | PointId::Normal { .. }
                | PointId::Coriolis { .. }
                | PointId::Relative { .. }
        )
    }
}

/// A point of a plan: `key` is its name in result files (`b`, `s2`, and
/// for construction points `n_2`, `k_3`, `b_3` …), `label` its letters and
/// subscript for drawings. Numbers-only builds leave the names empty.
#[derive(Clone, Debug)]
pub struct PlanPoint {
    /// Which point it is.
    pub id: PointId,
    /// Its name in result files (`b`, `n_2`); empty in numbers-only builds.
    pub key: String,
    /// Its letters and subscript for drawings.
    pub label: (String, String),
    /// Millimetres from the pole.
    pub at: Vec2,
    /// First-order drafting error radius, mm.
    pub err: f64,
}

/// The letters the construction gives its own points on the plans: the
/// pole p (p_v, p_a), the normals' ends n₂, the Coriolis points k₃, the
/// relative points r₃. A scene point with one of these letters is primed
/// on the plans (p′, k′), so that it never reads as a construction point.
pub(crate) const CONSTRUCTION_LETTERS: [&str; 4] = ["p", "n", "k", "r"];

impl PlanPoint {
    /// The point's name on the mechanism's figure (`B`, `S2`, `B3` for B
    /// as a point of link 3), from its label; empty for construction
    /// points. (Not a field: a numbers-only build moves every plan point
    /// once, and a smaller point moves cheaper.)
    pub fn figure(&self) -> String {
        if self.id.is_construction() {
            String::new()
        } else {
            self.scene_name().to_uppercase()
        }
    }
    /// The lower-case name of the mechanism's point it stands for ("k" for
    /// the ram's K, whose plan label is k′; "b3"), for the quantities'
    /// names (a^n_KC), which are the scene's; else as [`Self::name`].
    pub fn scene_name(&self) -> String {
        if self.id.is_construction() || self.id == PointId::Pole {
            return self.name();
        }
        format!("{}{}", self.scene_letter(), self.label.1)
    }
    /// The letter of [`Self::scene_name`]: the label's, without the prime
    /// that keeps it apart from a construction letter.
    pub fn scene_letter(&self) -> &str {
        let letter = self.label.0.as_str();
        if self.id.is_construction() {
            return letter;
        }
        letter
            .strip_suffix('′')
            .filter(|l| CONSTRUCTION_LETTERS.contains(l))
            .unwrap_or(letter)
    }
    /// "b", "s2", "n2" …: letters and subscript run together, for text.
    pub fn name(&self) -> String {
        if self.id == PointId::Pole {
            // The pole keeps its subscript visible: p_v, p_a.
            return self.key.clone();
        }
        format!("{}{}", self.label.0, self.label.1)
    }
}

/// A direction as the method describes it.
#[derive(Clone, Debug, PartialEq)]
pub enum Dir {
    /// Perpendicular to the segment of the mechanism (`"BC"`).
    Perp(String),
    /// Parallel to a segment of the mechanism.
    Along(String),
    /// Parallel to a segment, from its first point toward its second.
    Toward(String, String),
    /// Parallel to the guide of a link.
    Guide(String),
    /// A vector turned by 90° in the sense of an angular velocity.
    Turned(String, String),
    /// Perpendicular to a segment in the sense of an angular rate.
    PerpSense(String, String),
}

/// A line drawn on the plan: through a plan point, in a direction.
#[derive(Clone, Debug)]
pub struct PlanLine {
    /// The plan point it is drawn through (an index into the plan's points).
    pub through: usize,
    /// Its direction, a unit vector.
    pub unit: Vec2,
    /// What the direction is, in words.
    pub dir: Dir,
    /// Offset error of the drawn line, mm.
    pub err: f64,
    /// Where the pencil actually drew it: shifted by this much to the left
    /// of `unit` (zero unless the plan emulates hand drafting).
    pub shift: f64,
}

/// Why a plan point coincides with another.
#[derive(Clone, Debug, PartialEq)]
pub enum Why {
    /// A point of the frame: at the pole.
    Fixed,
    /// A point of a translating link (its id).
    Translates(String),
}

/// One drafting operation.
#[derive(Clone, Debug)]
pub enum Op {
    /// The pole (plan point 0) and the frame points that lie there.
    Pole {
        /// The names of the frame points at the pole.
        fixed: Vec<String>,
    },
    /// Lay off a known vector `what` (real value `value`) from `from`.
    LayOff {
        /// The plan point laid off from.
        from: usize,
        /// The plan point it ends at.
        to: usize,
        /// The vector's name.
        what: String,
        /// Its real magnitude.
        value: f64,
        /// Its direction, in words.
        dir: Dir,
    },
    /// Two lines and their intersection.
    Intersect {
        /// The two lines.
        lines: [PlanLine; 2],
        /// The plan point at their intersection.
        out: usize,
        /// The sine of the angle between them.
        sin_angle: f64,
    },
    /// The similarity theorem: a triangle on `a b` similar to the link's.
    Similar {
        /// The first known plan point.
        a: usize,
        /// The second known plan point.
        b: usize,
        /// The plan point found.
        out: usize,
        /// The three points' names, as on the link.
        figure: [String; 3],
        /// The link's name.
        link: String,
    },
    /// A point of a link on the line of two others: divide the segment.
    Divide {
        /// The first known plan point.
        a: usize,
        /// The second known plan point.
        b: usize,
        /// The plan point found.
        out: usize,
        /// The three points' names, as on the link.
        figure: [String; 3],
        /// The ratio the segment `a b` is divided in.
        ratio: f64,
    },
    /// A point coinciding with another (a translating link, or the pole).
    Coincide {
        /// The plan point placed.
        out: usize,
        /// The plan point it coincides with.
        with: usize,
        /// Why.
        why: Why,
    },
    /// Measure a segment: `quantity` = length × μ; for a relative segment
    /// also the link's angular rate (name, signed value, link segment).
    Measure {
        /// The segment's first plan point.
        from: usize,
        /// The segment's second plan point.
        to: usize,
        /// The quantity's name.
        quantity: String,
        /// Its value, real units.
        value: f64,
        /// The link length the rate is measured over, m, where it is one.
        length: Option<f64>,
        /// The link's angular rate: its name, signed value and link segment.
        rate: Option<(String, f64, (String, String))>,
    },
    /// Links in a prismatic pair share ω (ε).
    Same {
        /// The link whose rate is given.
        link: String,
        /// The link it shares the rate with.
        from_link: String,
        /// The rate's name.
        what: String,
    },
    /// The vector equations of a group, as the lecture writes them.
    Equation {
        /// The equations' text.
        text: String,
    },
}

///A step of the construction: one drafting operation.
#[derive(Clone, Debug)]
pub struct Step {
    /// What is drawn.
    pub op: Op,
}

/// What a measured value is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Quantity {
    /// The angular rate of a link (ω on the velocity plan, ε on the
    /// acceleration plan).
    Rate(usize),
    /// The velocity (acceleration) of a named point.
    Point(usize),
}

/// A measured quantity with its drafting-error bound.
#[derive(Clone, Debug)]
pub struct Measured {
    /// What it is.
    pub of: Quantity,
    /// Its name (`ω2`, `v_B`); empty in numbers-only builds.
    pub quantity: String,
    /// The segment's first plan point.
    pub from: usize,
    /// The segment's second plan point.
    pub to: usize,
    /// The segment's length on the plan, mm.
    pub mm: f64,
    /// The value, real units (length × μ).
    pub value: f64,
    /// First-order bound of the drafting error of `value` (real units).
    pub bound: f64,
}

/// A plan point known on a link: the link, the point's local coordinates
/// on it, and the plan point (one flat list for the whole plan).
#[derive(Clone, Copy, Debug)]
pub struct Known {
    /// The link.
    pub link: usize,
    /// The point's local coordinates on the link.
    pub local: Vec2,
    /// The plan point.
    pub point: usize,
}

/// A plan: the replayable list of steps and the named plan points.
#[derive(Clone, Debug)]
pub struct Plan {
    /// Velocities or accelerations.
    pub kind: PlanKind,
    /// Scale coefficient: real value per mm.
    pub mu: f64,
    /// Pencil precision δ used for the error model, mm.
    pub delta: f64,
    /// The plan points, the pole first.
    pub points: Vec<PlanPoint>,
    /// The steps in words (empty in numbers-only builds).
    pub steps: Vec<Step>,
    /// Angular velocity (velocity plan) or acceleration (acceleration plan)
    /// of every constructed link, as measured; and its error bound.
    pub rates: Vec<Option<(f64, f64)>>,
    /// The length each rate was measured over (the relative segment's
    /// link length, m; 0 where a rate is taken over from another link).
    pub rate_len: Vec<f64>,
    /// Whether the sense of each rate can be read off the plan: the end of
    /// its relative segment clear of the link's line by more than its
    /// drafting error (a plan drawn wrong has it on the line, and so has
    /// one of a link that hardly turns; then the rate is known in
    /// magnitude only).
    pub rate_sense: Vec<bool>,
    /// Every quantity measured on the plan.
    pub measured: Vec<Measured>,
    /// Smallest sine of an intersection angle (1 when none).
    pub worst_sin: f64,
    /// The plan points known on the links, in the order they were found.
    pub body: Vec<Known>,
    /// The plan point of each named point of the mechanism.
    pub of_point: Vec<Option<usize>>,
    /// With a deliberate mistake: the step where it was made.
    pub mistake_step: Option<usize>,
    /// With a deliberate mistake: how many decisions of its kind the
    /// construction took (whether made wrong or not).
    pub decisions: usize,
    /// A replay of a student's drawing (the construction's `replay`): each point the
    /// student drew, judged at the step that draws it from the student's
    /// own earlier points.
    pub judged: Vec<Judged>,
    /// The pair of leashes each class III group took its special point
    /// on, in the order of the construction.
    pub triads: Vec<(usize, usize, usize)>,
    /// The plan points a deliberate mistake left out (a normal component
    /// forgotten): counted with the points of their id, so that a later
    /// point of the same id keeps its place in the order (a replay matches
    /// the student's points by id and that place).
    pub skipped: Vec<PointId>,
}

/// What a replay takes from a student's drawing ([`super::replay`]).
#[derive(Clone, Debug, Default)]
pub struct Drawing {
    /// The `nth` plan point of an id, where the student drew it (mm from
    /// the pole), and how far the coordinates as typed may be from where
    /// it was read (their rounding, mm; 0 for a drawing).
    pub points: Vec<(PointId, usize, Vec2, f64)>,
    /// The pairs of leashes the right plan's class III groups took: where
    /// the student's points do not tell which pair they used, the same
    /// (so that a special point σ they measured is the same point).
    pub triads: Vec<(usize, usize, usize)>,
    /// Points known only by their distance from the pole (a table's
    /// segment without its direction, a value |v_X|): the `nth` plan
    /// point of an id on the circle of this radius about the pole (mm),
    /// and its rounding. A replay puts such a point where the circle is
    /// nearest the step's place: its step is judged by how far the circle
    /// passes from it, and every later step starts from there.
    pub circles: Vec<(PointId, usize, f64, f64)>,
}

/// A point a student drew, as the construction's step that draws it
/// predicts it from the student's own earlier points (a replay puts the
/// student's points in place of the constructed ones, so nothing of an
/// earlier step's error is carried into this one).
#[derive(Clone, Debug)]
pub struct Judged {
    /// Which point it is.
    pub id: PointId,
    /// Which plan point of that id (a link may have several normal points).
    pub nth: usize,
    /// Its index in the plan.
    pub point: usize,
    /// Where the step puts it, mm from the pole.
    pub predicted: Vec2,
    /// The step's own tolerance: the error radius of the prediction from
    /// the points it uses (each read to δ), the pencil's δ per operation,
    /// the error of a value that enters, and δ for reading the point.
    pub tol: f64,
    /// Where the student drew it.
    pub given: Vec2,
    /// The rounding of its coordinates as typed, mm: counted with the
    /// reading of the point in every tolerance of its step.
    pub rounding: f64,
    /// Known only by its distance from the pole (`Drawing::circles`):
    /// the student's point is where that circle is nearest the step's
    /// place, so the step judges its length, not its direction.
    pub on_circle: bool,
    /// The same point by another right construction (a similar figure on
    /// another pair of known points): place and tolerance.
    pub others: Vec<(Vec2, f64)>,
    /// For a point where two lines meet, the lines as drawn through the
    /// student's points (a point on it, its direction, and how far a point
    /// read off it may lie from it: the line's own error and δ for the
    /// reading): the point is judged by its distance from each, which the
    /// angle between them does not blow up.
    pub lines: Vec<(Vec2, Vec2, f64)>,
    /// The builder's step count when it was drawn (the step's index).
    pub step: usize,
}

impl Judged {
    /// How far the student's point is from what this step draws, over the
    /// step's tolerance (≤ 1: it fits): the larger of its distances from
    /// the two lines over theirs, or the least distance from a right
    /// construction's place over that construction's tolerance.
    pub fn misfit(&self) -> f64 {
        self.misfit_at(self.given)
    }
    /// [`Judged::misfit`] of a point at `at`.
    pub fn misfit_at(&self, at: Vec2) -> f64 {
        if !self.lines.is_empty() {
            return self
                .lines
                .iter()
                .map(|&(p, u, tol)| (at - p).cross(u).abs() / tol.max(1e-300))
                .fold(0.0, f64::max);
        }
        std::iter::once((self.predicted, self.tol))
            .chain(self.others.iter().copied())
            .map(|(p, tol)| (at - p).hypot() / tol.max(1e-300))
            .fold(f64::INFINITY, f64::min)
    }
    /// How far a point at `at` is from what this step draws, mm (from the
    /// farther of the two lines, or from the nearest right place), and
    /// that measure's tolerance.
    pub fn apart(&self, at: Vec2) -> (f64, f64) {
        if !self.lines.is_empty() {
            return self
                .lines
                .iter()
                .map(|&(p, u, tol)| ((at - p).cross(u).abs(), tol))
                .max_by(|a, b| (a.0 / a.1.max(1e-300)).total_cmp(&(b.0 / b.1.max(1e-300))))
                .expect("two lines");
        }
        let (p, tol) = self.judging(at);
        ((at - p).hypot(), tol)
    }
    /// The prediction of the right construction the student's point is
    /// judged by, with its tolerance ([`Judged::apart`]).
    pub fn nearest(&self) -> (Vec2, f64) {
        self.judging(self.given)
    }
    /// Of the right constructions, the one a point at `at` is judged by:
    /// the most precise of those it fits (the construction the plan draws
    /// where that one fits), else the one it misses least.
    fn judging(&self, at: Vec2) -> (Vec2, f64) {
        let all = || std::iter::once((self.predicted, self.tol)).chain(self.others.iter().copied());
        let ratio = |(p, tol): (Vec2, f64)| (at - p).hypot() / tol.max(1e-300);
        all()
            .filter(|&x| ratio(x) <= 1.0)
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .or_else(|| all().min_by(|&a, &b| ratio(a).total_cmp(&ratio(b))))
            .expect("one prediction")
    }
}

impl Plan {
    /// An empty plan for `m` at scale `mu`.
    pub(super) fn empty(kind: PlanKind, mu: f64, delta: f64, m: &Mechanism) -> Plan {
        // Room for a plan's usual size: its points and what it finds on
        // each link, without growing (and copying) on the way.
        let room = 2 * (m.scene.points.len() + m.links.len());
        Plan {
            kind,
            mu,
            delta,
            points: Vec::with_capacity(room),
            steps: Vec::new(),
            rates: vec![None; m.links.len()],
            rate_len: vec![0.0; m.links.len()],
            rate_sense: vec![true; m.links.len()],
            measured: Vec::with_capacity(m.scene.points.len() + m.links.len()),
            worst_sin: 1.0,
            body: Vec::with_capacity(room),
            of_point: vec![None; m.scene.points.len()],
            mistake_step: None,
            decisions: 0,
            judged: Vec::new(),
            triads: Vec::new(),
            skipped: Vec::new(),
        }
    }
    /// Empty the plan, at scale `mu` (its buffers kept).
    pub(super) fn clear(&mut self, mu: f64) {
        self.mu = mu;
        self.points.clear();
        self.steps.clear();
        self.measured.clear();
        self.body.clear();
        self.rates.fill(None);
        self.rate_len.fill(0.0);
        self.rate_sense.fill(true);
        self.of_point.fill(None);
        self.worst_sin = 1.0;
        self.mistake_step = None;
        self.decisions = 0;
        self.judged.clear();
        self.triads.clear();
        self.skipped.clear();
    }
    /// The plan point of the material point of `link` at `local`.
    pub fn known_at(&self, link: usize, local: Vec2, tol: f64) -> Option<usize> {
        self.body
            .iter()
            .find(|k| k.link == link && (k.local - local).hypot2() <= tol * tol)
            .map(|k| k.point)
    }
    /// The step that draws plan point `idx` (its index in `steps`).
    pub fn step_of(&self, idx: usize) -> Option<usize> {
        self.steps.iter().position(|s| match &s.op {
            Op::LayOff { to, .. } => *to == idx,
            Op::Intersect { out, .. }
            | Op::Similar { out, .. }
            | Op::Divide { out, .. }
            | Op::Coincide { out, .. } => *out == idx,
            Op::Pole { .. } => idx == 0,
            _ => false,
        })
    }
    /// Where the construction puts plan point `i`: its place, or in a
    /// replay, for a point the student drew, where the step predicts it.
    pub fn place(&self, i: usize) -> Vec2 {
        self.judged
            .iter()
            .find(|j| j.point == i)
            .map_or(self.points[i].at, |j| j.predicted)
    }
    /// The first step where `other` (the same construction with a
    /// mistake) draws something else than this plan: another operation,
    /// or a point put elsewhere (by more than a millionth of the plan's
    /// size, or a measured value off by a millionth of it). The step
    /// where the mistake enters, found from the two drawings alone.
    pub fn first_difference(&self, other: &Plan) -> Option<usize> {
        let size = self.points.iter().map(|p| p.at.hypot()).fold(1.0, f64::max);
        let out = |op: &Op| match op {
            Op::LayOff { to, .. } => Some(*to),
            Op::Intersect { out, .. }
            | Op::Similar { out, .. }
            | Op::Divide { out, .. }
            | Op::Coincide { out, .. } => Some(*out),
            _ => None,
        };
        for (k, (a, b)) in self.steps.iter().zip(&other.steps).enumerate() {
            if std::mem::discriminant(&a.op) != std::mem::discriminant(&b.op) {
                return Some(k);
            }
            if let (Some(i), Some(j)) = (out(&a.op), out(&b.op))
                && (self.place(i) - other.place(j)).hypot() > 1e-6 * size
            {
                return Some(k);
            }
            if let (Op::Measure { value: x, .. }, Op::Measure { value: y, .. }) = (&a.op, &b.op)
                && (x - y).abs() > 1e-6 * (x.abs() + y.abs()).max(1e-300)
            {
                return Some(k);
            }
        }
        (self.steps.len() != other.steps.len()).then_some(self.steps.len().min(other.steps.len()))
    }
    /// The plan point named `key` (`b`, `n_2`), if the plan has it.
    pub fn point(&self, key: &str) -> Option<&PlanPoint> {
        self.points.iter().find(|p| p.key == key)
    }
    /// The real vector of a named point (velocity or acceleration).
    pub fn value_of(&self, point: usize) -> Option<Vec2> {
        self.of_point[point].map(|i| self.points[i].at * self.mu)
    }
    /// Worst intersection angle, degrees.
    pub fn worst_angle_deg(&self) -> f64 {
        self.worst_sin.clamp(0.0, 1.0).asin().to_degrees()
    }
}

/// Both plans at one position, as `want.plans` asks.
#[derive(Clone, Debug)]
pub struct Plans {
    pub velocity: Plan,
    pub acceleration: Option<Plan>,
}

/// What the kernel needs to know: the mechanism, its positions, the groups
/// to build and the points to report.
pub struct Setup<'a> {
    pub m: &'a Mechanism,
    pub s: &'a Structure,
    pub need: &'a [bool],
    pub points: &'a [usize],
    pub include: &'a [bool],
}

/// Links whose angle cannot change (the frame, and links joined to a
/// non-rotating link by a prismatic pair): no normal components, no
/// Coriolis acceleration on them.
pub fn non_rotating(m: &Mechanism) -> Vec<bool> {
    let mut nr = vec![false; m.links.len()];
    nr[m.frame()] = true;
    loop {
        let mut changed = false;
        for pr in &m.prismatics {
            if nr[pr.slider] != nr[pr.guide] {
                nr[pr.slider] = true;
                nr[pr.guide] = true;
                changed = true;
            }
        }
        if !changed {
            return nr;
        }
    }
}

/// Fixed scales, the pencil precision and the variant for
/// [`build_plans`](super::build_plans). A scale left `None` is the
/// standard one at which the plan fits `field`: the field of the sheet the
/// plans are drawn on (its plan once measured, its μ is the one every
/// output states: steps, result file, sheets, handout).
#[derive(Clone, Copy, Debug)]
pub struct Drafting {
    pub mu_v: Option<f64>,
    pub mu_a: Option<f64>,
    /// Where a plan at a scale left open must fit, mm.
    pub field: super::scale::Field,
    /// Pencil precision δ, mm.
    pub delta: f64,
    pub variant: Variant,
}

impl Default for Drafting {
    fn default() -> Self {
        Drafting {
            mu_v: None,
            mu_a: None,
            field: super::scale::Field::default(),
            delta: 0.5,
            variant: Variant::default(),
        }
    }
}

impl Drafting {
    /// The fixed scale of a plan of `kind`, if any.
    pub(super) fn mu(&self, kind: PlanKind) -> Option<f64> {
        match kind {
            PlanKind::Velocity => self.mu_v,
            PlanKind::Acceleration => self.mu_a,
        }
    }
}
