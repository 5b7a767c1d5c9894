//! The construction kernel: plans of velocities and accelerations drawn as
//! a draftsman draws them, group by group in the order of attachment.
//!
//! The primitives are drafting operations on the sheet (millimetres, the
//! pole at the origin): lay off a vector at scale μ; draw a line through a
//! plan point perpendicular or parallel to a link or guide; intersect two
//! lines; divide a segment; build the figure similar to a link's figure
//! (same order of letters, so never a mirror image); turn a relative
//! velocity by 90° in the sense of ω (Coriolis); measure a segment and
//! multiply by μ. Directions come from the plan of the mechanism (the
//! solved positions); magnitudes laid off come from the data (ω1, ε1) or
//! from quantities measured earlier on the plans. Every step is recorded
//! with the items it used, so a plan is a replayable list of steps.
//!
//! Every plan point carries a first-order drafting-error radius: a pencil
//! error δ (mm) for each line drawn or vector laid off, amplified by
//! 1/sin θ at an intersection of lines meeting at θ.

pub mod scale;
pub mod text;

use crate::error::{Error, Result};
use crate::geom::{Line, LineCut, perp};
use crate::kinematics::analytic::{Drive, Order};
use crate::kinematics::positions::{Configuration, describe_input};
use crate::model::mechanism::Mechanism;
use crate::model::scene::InputSpec;
use crate::model::structure::{AssurGroup, Conn, Dyad, DyadKind, Joint, Structure, Triad};
use kurbo::{Point, Vec2};

/// The text of a name, a label or a step: formatted as `format!` does, or
/// left empty (no allocation) when the builder is lean.
macro_rules! txt {
    ($b:expr, $($arg:tt)*) => {
        if $b.lean {
            String::new()
        } else {
            format!($($arg)*)
        }
    };
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PlanKind {
    Velocity,
    Acceleration,
}

/// A point of a plan: `key` is its name in result files (`b`, `s2`, and
/// for construction points `n_2`, `k_3`, `b_3` …), `label` its letters and
/// subscript for drawings.
#[derive(Clone, Debug)]
pub struct PlanPoint {
    pub key: String,
    pub label: (String, String),
    /// Millimetres from the pole.
    pub at: Vec2,
    /// First-order drafting error radius, mm.
    pub err: f64,
    /// The point's name on the mechanism's figure (`B`, `S2`, `B3` for B
    /// as a point of link 3); empty for construction points.
    pub figure: String,
}

impl PlanPoint {
    /// "b", "s2", "n2" …: letters and subscript run together, for text.
    pub fn name(&self) -> String {
        if self.key.starts_with("p_") {
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
    pub through: usize,
    pub unit: Vec2,
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
    Pole { fixed: Vec<String> },
    /// Lay off a known vector `what` (real value `value`) from `from`.
    LayOff {
        from: usize,
        to: usize,
        what: String,
        value: f64,
        dir: Dir,
    },
    /// Two lines and their intersection.
    Intersect {
        lines: [PlanLine; 2],
        out: usize,
        sin_angle: f64,
    },
    /// The similarity theorem: a triangle on `a b` similar to the link's.
    Similar {
        a: usize,
        b: usize,
        out: usize,
        figure: [String; 3],
        link: String,
    },
    /// A point of a link on the line of two others: divide the segment.
    Divide {
        a: usize,
        b: usize,
        out: usize,
        figure: [String; 3],
        ratio: f64,
    },
    /// A point coinciding with another (a translating link, or the pole).
    Coincide { out: usize, with: usize, why: Why },
    /// Measure a segment: `quantity` = length × μ; for a relative segment
    /// also the link's angular rate (name, signed value, link segment).
    Measure {
        from: usize,
        to: usize,
        quantity: String,
        value: f64,
        length: Option<f64>,
        rate: Option<(String, f64, (String, String))>,
    },
    /// Links in a prismatic pair share ω (ε).
    Same {
        link: String,
        from_link: String,
        what: String,
    },
    /// The vector equations of a group, as the lecture writes them.
    Equation { text: String },
}

#[derive(Clone, Debug)]
pub struct Step {
    pub op: Op,
}

/// A measured quantity with its drafting-error bound.
#[derive(Clone, Debug)]
pub struct Measured {
    pub quantity: String,
    pub from: usize,
    pub to: usize,
    pub mm: f64,
    pub value: f64,
    /// First-order bound of the drafting error of `value` (real units).
    pub bound: f64,
}

/// A plan point known on a link: the link, the point's local coordinates
/// on it, and the plan point (one flat list for the whole plan).
#[derive(Clone, Copy, Debug)]
pub struct Known {
    pub link: usize,
    pub local: Vec2,
    pub point: usize,
}

impl Plan {
    /// The plan point of the material point of `link` at `local`.
    fn known_at(&self, link: usize, local: Vec2, tol: f64) -> Option<usize> {
        self.body
            .iter()
            .find(|k| k.link == link && (k.local - local).hypot() <= tol)
            .map(|k| k.point)
    }
}

/// A plan: the replayable list of steps and the named plan points.
#[derive(Clone, Debug)]
pub struct Plan {
    pub kind: PlanKind,
    /// Scale coefficient: real value per mm.
    pub mu: f64,
    /// Pencil precision δ used for the error model, mm.
    pub delta: f64,
    pub points: Vec<PlanPoint>,
    pub steps: Vec<Step>,
    /// Angular velocity (velocity plan) or acceleration (acceleration plan)
    /// of every constructed link, as measured; and its error bound.
    pub rates: Vec<Option<(f64, f64)>>,
    /// The length each rate was measured over (the relative segment's
    /// link length, m; 0 where a rate is taken over from another link).
    pub rate_len: Vec<f64>,
    /// Whether the sense of each rate can be read off the plan: the end of
    /// its relative segment clear of the link's line by more than its
    /// drafting error (only a plan drawn wrong has it on the line; then
    /// the rate is known in magnitude only).
    pub rate_sense: Vec<bool>,
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
}

impl Plan {
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

/// A vector known in magnitude and direction, doubly underlined as the
/// lecture marks it.
fn known(s: &str) -> String {
    s.chars().flat_map(|c| [c, '\u{0333}']).collect()
}

/// A vector known in direction only, singly underlined.
fn direction_known(s: &str) -> String {
    s.chars().flat_map(|c| [c, '\u{0332}']).collect()
}

fn lower_label(name: &str) -> (String, String) {
    let lower = name.to_lowercase();
    let split = lower
        .find(|c: char| c.is_ascii_digit() || c == '_')
        .unwrap_or(lower.len());
    let (a, b) = lower.split_at(split);
    (a.to_string(), b.trim_start_matches('_').to_string())
}

/// A typical student's mistake, built into the construction on purpose so
/// that a hand-drawn plan can be diagnosed by the mistake that explains it.
/// Each kind is a decision the construction takes at certain steps (every
/// normal component, every similar figure …); [`Variant::at`] makes it at
/// one of them only.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Mistake {
    /// The Coriolis acceleration turned the wrong way (against ω).
    CoriolisReversed,
    /// The Coriolis acceleration left out on a rotating guide.
    CoriolisForgotten,
    /// The Coriolis acceleration as ω·v_rel, without the factor 2.
    CoriolisFactorOne,
    /// A normal component laid off from the centre instead of toward it.
    NormalFromCentre,
    /// A normal component ω²·l left out.
    NormalForgotten,
    /// A similar figure built mirrored (letters in the wrong order).
    MirroredFigure,
    /// In an RRR group, each line drawn ⊥ the other link of the group.
    WrongPerpendicular,
    /// A relative (tangential) component drawn ∥ the link instead of ⊥ it.
    TangentialParallel,
    /// A point taken on the wrong link: on a rocking guide, the guide's
    /// coincident point b₃ taken as the slider's point b₂ (the relative
    /// sliding ignored).
    WrongLink,
    /// ε1 ≠ 0 but the tangential component of the crank's point left out.
    Epsilon1Forgotten,
    /// ε1 = 0 but a tangential component ε1·l added, taking ε1 = ω1².
    Epsilon1Added,
    /// Normal components computed with the input's ω1 instead of the link's ω.
    OmegaWrongLink,
    /// The crank's velocity laid off against the sense of ω1.
    OmegaWrongSense,
    /// One vector laid off with a wrong length (an arithmetic or measuring
    /// slip): its length times [`Variant::factor`].
    Slip,
}

/// How to build a plan besides the standard way: with a mistake, or with
/// every drafting operation perturbed by the pencil (a hand drawing).
#[derive(Clone, Copy, Debug)]
pub struct Variant {
    pub mistake: Option<Mistake>,
    /// Which of the mistake's decisions is taken wrong, counted from 0 in
    /// the order of the construction ([`Plan::decisions`] counts them);
    /// `None`: every one (the mistake repeated wherever it can be made).
    pub at: Option<usize>,
    /// The plan the mistake is made on (`None`: both).
    pub on: Option<PlanKind>,
    /// For [`Mistake::Slip`]: the wrong length over the right one.
    pub factor: f64,
    /// A second mistake made together with the first, everywhere it can
    /// be (students combine some: a Coriolis acceleration reversed and the
    /// normals from the centre).
    pub also: Option<Mistake>,
    /// Seed of the pencil noise: each laid-off point, each line and each
    /// constructed point moves by at most δ.
    pub jitter: Option<u64>,
}

impl Default for Variant {
    fn default() -> Self {
        Variant {
            mistake: None,
            at: None,
            on: None,
            factor: 1.0,
            also: None,
            jitter: None,
        }
    }
}

impl Variant {
    /// The mistake `m` at every decision of its kind, on both plans.
    pub fn everywhere(m: Mistake) -> Variant {
        Variant {
            mistake: Some(m),
            ..Variant::default()
        }
    }
}

/// How a point of a link is placed ([`Builder::best_construction`]).
#[derive(Clone, Copy, Debug)]
enum Construction {
    /// The figure similar to the link's on known points `a`, `b` (indices
    /// in the list of the link's known points), the new point at
    /// a + ρ·(b − a) with the complex ratio ρ.
    Figure {
        a: usize,
        b: usize,
        ratio: Vec2,
        err: FigureErr,
    },
    /// From known point `a` by the relative vector of the link's rates.
    Relation { a: usize },
}

/// The way a similar figure is drawn, and the new point's error radius.
#[derive(Clone, Copy, Debug)]
enum FigureErr {
    /// Proportional division of the segment (the point on or a hair off
    /// the line of the two).
    Divide(f64),
    /// Two arcs meeting at an angle of sine `.1`.
    Arcs(f64, f64),
}

/// A prismatic pair seen from a group: the link being found, the known
/// link it slides on (or that slides on it), and which of them is the guide.
#[derive(Clone, Copy)]
struct Slide {
    unknown: usize,
    known: usize,
    guide: usize,
}

struct Builder<'a> {
    variant: Variant,
    rng: Option<rand::rngs::StdRng>,
    st: &'a Setup<'a>,
    c: &'a Configuration,
    plan: Plan,
    /// The velocity plan, when building the acceleration plan.
    vel: Option<&'a Plan>,
    nr: Vec<bool>,
    q: f64,
    /// Numbers only: no names, labels, steps or sentences (the scale
    /// probe, and sweeps that read numbers only).
    lean: bool,
    /// The first normal-component point laid off for each link (n₂ …),
    /// found by index, not by its name.
    normal_of: Vec<Option<usize>>,
}

/// Build the velocity plan (`vel` = None) or the acceleration plan.
pub fn build(
    st: &Setup,
    c: &Configuration,
    drive: Drive,
    kind: PlanKind,
    vel: Option<&Plan>,
    d: &Drafting,
    lean: bool,
) -> Result<Plan> {
    use rand::SeedableRng;
    let (delta, variant) = (d.delta, d.variant);
    let mu = match kind {
        PlanKind::Velocity => d.mu_v,
        PlanKind::Acceleration => d.mu_a,
    };
    let m = st.m;
    let (q, rates) = (drive.q, (drive.rate, drive.rate2));
    let rng = |k: u64| {
        variant
            .jitter
            .map(|s| rand::rngs::StdRng::seed_from_u64(s ^ k))
    };
    let mut b = Builder {
        variant,
        rng: rng(1),
        st,
        c,
        plan: Plan {
            kind,
            mu: 1.0,
            delta,
            points: Vec::new(),
            steps: Vec::new(),
            rates: vec![None; m.links.len()],
            rate_len: vec![0.0; m.links.len()],
            rate_sense: vec![true; m.links.len()],
            measured: Vec::new(),
            worst_sin: 1.0,
            body: Vec::new(),
            of_point: vec![None; m.scene.points.len()],
            mistake_step: None,
            decisions: 0,
        },
        vel,
        nr: non_rotating(m),
        q,
        // The probe only needs where the points fall.
        lean: true,
        normal_of: vec![None; m.links.len()],
    };
    // First pass at unit scale, then the standard scale that fits, then the
    // real construction at that scale (the steps' numbers are in mm).
    let mu = match mu {
        Some(mu) => mu,
        None => {
            b.run(rates)?;
            // The largest vector at most 150 mm, and the whole plan within
            // 240 × 130 mm, the free area of an A4 landscape sheet.
            let pts = &b.plan.points;
            let largest = pts.iter().map(|p| p.at.hypot()).fold(0.0, f64::max);
            let span = |f: fn(&PlanPoint) -> f64| {
                let (lo, hi) = pts
                    .iter()
                    .map(f)
                    .fold((f64::MAX, f64::MIN), |(lo, hi), x| (lo.min(x), hi.max(x)));
                hi - lo
            };
            let (w, h) = (span(|p| p.at.x), span(|p| p.at.y));
            let mu = scale::standard_scale(largest, 150.0)
                .max(scale::standard_scale(w, 240.0))
                .max(scale::standard_scale(h, 130.0));
            // A plan all at the pole (everything at rest): any scale draws it.
            if mu > 0.0 { mu } else { 1.0 }
        }
    };
    // The real construction reuses the probe's buffers, emptied.
    let mut probe = b.plan;
    probe.points.clear();
    probe.measured.clear();
    probe.body.clear();
    probe.rates.fill(None);
    probe.rate_len.fill(0.0);
    probe.rate_sense.fill(true);
    probe.of_point.fill(None);
    let mut normal_of = b.normal_of;
    normal_of.fill(None);
    let mut b = Builder {
        variant,
        rng: rng(2),
        st,
        c,
        plan: Plan {
            mu,
            mistake_step: None,
            decisions: 0,
            worst_sin: 1.0,
            ..probe
        },
        vel,
        nr: b.nr,
        q,
        lean,
        normal_of,
    };
    b.run(rates)?;
    Ok(b.plan)
}

impl<'a> Builder<'a> {
    fn m(&self) -> &'a Mechanism {
        self.st.m
    }
    fn vel_kind(&self) -> bool {
        self.plan.kind == PlanKind::Velocity
    }
    fn step(&mut self, op: Op) {
        if !self.lean {
            self.plan.steps.push(Step { op });
        }
    }
    fn world(&self, link: usize, p: usize) -> Point {
        self.c.point(self.m(), link, p)
    }
    fn local(&self, link: usize, x: Point) -> Vec2 {
        self.c.pose(link).local(x)
    }
    fn name(&self, p: usize) -> String {
        txt!(self, "{}", self.m().point_name(p))
    }
    fn link(&self, l: usize) -> String {
        txt!(self, "{}", self.m().link_id(l))
    }
    fn label(&self, name: &str) -> (String, String) {
        if self.lean {
            (String::new(), String::new())
        } else {
            lower_label(name)
        }
    }
    /// Remember the first normal-component point of `link`.
    fn note_normal(&mut self, link: usize, idx: usize) {
        self.normal_of[link].get_or_insert(idx);
    }
    fn rate_sym(&self) -> &'static str {
        if self.vel_kind() { "ω" } else { "ε" }
    }
    /// ω of a link from the velocity plan (for the acceleration plan).
    fn omega(&self, l: usize) -> f64 {
        match self.vel {
            Some(v) => v.rates[l].map(|r| r.0).unwrap_or(0.0),
            None => self.plan.rates[l].map(|r| r.0).unwrap_or(0.0),
        }
    }
    fn omega_err(&self, l: usize) -> f64 {
        self.vel
            .and_then(|v| v.rates[l].map(|r| r.1))
            .unwrap_or(0.0)
    }

    fn add_point(&mut self, key: String, label: (String, String), at: Vec2, err: f64) -> usize {
        if self.lean {
            self.plan.points.push(PlanPoint {
                key,
                label,
                at,
                err,
                figure: String::new(),
            });
            return self.plan.points.len() - 1;
        }
        let (mut key, mut label) = (key, label);
        while self.plan.points.iter().any(|p| p.key == key) {
            // A second n₂ on one plan is n₂′ (then n₂″).
            key.push('\'');
            label.1.push('′');
        }
        let construction = key.starts_with("n_") || key.starts_with("k_") || key.starts_with("p_");
        let figure = if construction {
            String::new()
        } else {
            txt!(self, "{}{}", label.0, label.1).to_uppercase()
        };
        self.plan.points.push(PlanPoint {
            key,
            label,
            at,
            err,
            figure,
        });
        self.plan.points.len() - 1
    }

    /// How close two places of one link are the same material point: a
    /// billionth of the link's own size, above the rounding of the
    /// coordinates (never a fraction of the whole sketch).
    fn same_point(&self, link: usize, x: Point) -> f64 {
        1e-9 * self.m().link_scale(link) + 64.0 * f64::EPSILON * x.to_vec2().hypot()
    }

    fn register(&mut self, link: usize, x: Point, idx: usize) {
        let local = self.local(link, x);
        let tol = self.same_point(link, x);
        if self.plan.known_at(link, local, tol).is_none() {
            self.plan.body.push(Known {
                link,
                local,
                point: idx,
            });
        }
    }

    fn find(&self, link: usize, x: Point) -> Option<usize> {
        let local = self.local(link, x);
        let tol = self.same_point(link, x);
        self.plan.known_at(link, local, tol)
    }

    /// Lay off the real vector `v` from plan point `from`.
    fn lay_off(
        &mut self,
        from: usize,
        v: Vec2,
        what: String,
        dir: Dir,
        (key, label): (String, (String, String)),
        value_err: f64,
    ) -> usize {
        let v = if self.making(Mistake::Slip) {
            v * self.variant.factor
        } else {
            v
        };
        let at = self.plan.points[from].at + v / self.plan.mu + self.pencil();
        let err = self.plan.points[from].err + self.plan.delta + value_err / self.plan.mu;
        let to = self.add_point(key, label, at, err);
        self.step(Op::LayOff {
            from,
            to,
            what,
            value: v.hypot(),
            dir,
        });
        to
    }

    fn line(&mut self, through: usize, unit: Vec2, dir: Dir) -> PlanLine {
        let shift = self.pencil().x;
        PlanLine {
            through,
            unit: unit.normalize(),
            dir,
            err: self.plan.points[through].err + self.plan.delta,
            shift,
        }
    }

    /// The pencil's error of one operation: a random displacement within δ
    /// when emulating hand drafting, else zero.
    fn pencil(&mut self) -> Vec2 {
        use rand::Rng;
        let delta = self.plan.delta;
        match &mut self.rng {
            None => Vec2::ZERO,
            Some(r) => loop {
                let v = Vec2::new(r.random_range(-1.0..=1.0), r.random_range(-1.0..=1.0));
                if v.hypot2() <= 1.0 {
                    break v * delta;
                }
            },
        }
    }

    /// Is this mistake being made at this decision? Counts the decisions
    /// of its kind and records the first step where it is made.
    fn making(&mut self, m: Mistake) -> bool {
        if self.variant.on.is_some_and(|k| k != self.plan.kind) {
            return false;
        }
        if self.variant.also == Some(m) && self.variant.mistake != Some(m) {
            // A second mistake combined with the first, made everywhere.
            if self.plan.mistake_step.is_none() {
                self.plan.mistake_step = Some(self.plan.steps.len());
            }
            return true;
        }
        if self.variant.mistake != Some(m) {
            return false;
        }
        let n = self.plan.decisions;
        self.plan.decisions += 1;
        if self.variant.at.is_some_and(|at| at != n) {
            return false;
        }
        if self.plan.mistake_step.is_none() {
            self.plan.mistake_step = Some(self.plan.steps.len());
        }
        true
    }

    fn intersect(
        &mut self,
        a: PlanLine,
        b: PlanLine,
        key: String,
        label: (String, String),
    ) -> Result<usize> {
        let la = Line {
            point: self.plan.points[a.through].at.to_point() + perp(a.unit) * a.shift,
            dir: a.unit,
        };
        let lb = Line {
            point: self.plan.points[b.through].at.to_point() + perp(b.unit) * b.shift,
            dir: b.unit,
        };
        let LineCut::Point { at, sin_angle } = crate::geom::intersect_lines(&la, &lb, 1e-12) else {
            return Err(Error::Singular {
                at: describe_input(self.m(), self.q),
                why: format!(
                    "on the {} plan the lines for {} are parallel: the position is a dead point of the group",
                    self.kind_word(),
                    label.0.clone() + &label.1
                ),
            });
        };
        let err = a.err.hypot(b.err) / sin_angle;
        let out = self.add_point(key, label, at.to_vec2(), err);
        self.plan.worst_sin = self.plan.worst_sin.min(sin_angle);
        self.step(Op::Intersect {
            lines: [a, b],
            out,
            sin_angle,
        });
        Ok(out)
    }

    fn kind_word(&self) -> &'static str {
        if self.vel_kind() {
            "velocity"
        } else {
            "acceleration"
        }
    }

    /// The plan point of the material point of `link` now at `x`, built
    /// from what the plan knows of that link: the pole for the frame, the
    /// same point for a translating link, the similarity theorem from two
    /// known points, or, from one known point, the relative vector of the
    /// link's measured rates.
    fn point_on(
        &mut self,
        link: usize,
        x: Point,
        key: String,
        label: (String, String),
        figure_name: String,
    ) -> usize {
        if let Some(i) = self.find(link, x) {
            return i;
        }
        let m = self.m();
        let known: Vec<(Vec2, usize)> = self
            .plan
            .body
            .iter()
            .filter(|k| k.link == link)
            .map(|k| (k.local, k.point))
            .collect();
        if link == m.frame() {
            let out = self.add_point(key, label, Vec2::ZERO, 0.0);
            self.step(Op::Coincide {
                out,
                with: 0,
                why: Why::Fixed,
            });
            self.register(link, x, out);
            return out;
        }
        let local = self.local(link, x);
        if let (true, Some(&(_, with))) = (self.nr[link], known.first()) {
            // A translating link: all its points share one plan point.
            let out = self.add_point(
                key,
                label,
                self.plan.points[with].at,
                self.plan.points[with].err,
            );
            let why = Why::Translates(self.link(link));
            self.step(Op::Coincide { out, with, why });
            self.register(link, x, out);
            return out;
        }
        assert!(
            !known.is_empty(),
            "a link is constructed only after one of its points"
        );
        let names = |b: &Builder, (l, idx): (Vec2, usize)| -> String {
            // The mechanism's name for a known point of this link: its own
            // point there, else the name of the coincident plan point (B3).
            if b.lean {
                return String::new();
            }
            let m = b.m();
            m.links[link]
                .points
                .iter()
                .find(|&&p| (m.local(link, p) - l).hypot() <= 1e-9 * m.link_scale(link))
                .map(|&p| m.point_name(p).to_string())
                .unwrap_or_else(|| b.plan.points[idx].figure.clone())
        };
        match self.best_construction(link, local, x, &known) {
            Construction::Figure { a, b, ratio, err } => {
                let ((la, pa), (lb, pb)) = (known[a], known[b]);
                let mut ratio = ratio;
                let collinear = matches!(err, FigureErr::Divide(_));
                if !collinear && ratio.y != 0.0 && self.making(Mistake::MirroredFigure) {
                    ratio.y = -ratio.y;
                }
                let (a_at, b_at) = (self.plan.points[pa].at, self.plan.points[pb].at);
                let at = a_at + (b_at - a_at).rotate_scale(ratio) + self.pencil();
                let fig = [names(self, (la, pa)), names(self, (lb, pb)), figure_name];
                let (e, op_is_divide, s) = match err {
                    FigureErr::Divide(e) => (e, true, 1.0),
                    FigureErr::Arcs(e, s) => (e, false, s),
                };
                let out = self.add_point(key, label, at, e);
                if op_is_divide {
                    self.step(Op::Divide {
                        a: pa,
                        b: pb,
                        out,
                        figure: fig,
                        ratio: ratio.x,
                    });
                } else {
                    if s < 1.0 {
                        self.plan.worst_sin = self.plan.worst_sin.min(s.max(0.0));
                    }
                    let link_id = self.link(link);
                    self.step(Op::Similar {
                        a: pa,
                        b: pb,
                        out,
                        figure: fig,
                        link: link_id,
                    });
                }
                self.register(link, x, out);
                out
            }
            Construction::Relation { a } => {
                // One known point A and the link's rates: v_X = v_A + ω×AX,
                // a_X = a_A + ε×AX − ω²·AX.
                let (la, pa) = known[a];
                let a_world = self.c.pose(link).apply(la);
                let r = x - a_world;
                let an = names(self, known[a]);
                let w = self.omega(link);
                let seg = txt!(self, "{}{}", an, figure_name);
                if self.vel_kind() {
                    let werr = self.plan.rates[link].map(|r| r.1).unwrap_or(0.0);
                    let out = self.lay_off(
                        pa,
                        perp(r) * w,
                        txt!(self, "ω{}·l_{seg}", self.link(link)),
                        Dir::PerpSense(seg.clone(), txt!(self, "ω{}", self.link(link))),
                        (key, label),
                        werr * r.hypot(),
                    );
                    self.register(link, x, out);
                    out
                } else {
                    let eps = self.plan.rates[link].map(|r| r.0).unwrap_or(0.0);
                    let eerr = self.plan.rates[link].map(|r| r.1).unwrap_or(0.0);
                    let n_key = txt!(self, "n_{}", self.link(link));
                    let mut from = pa;
                    if w != 0.0 && !self.making(Mistake::NormalForgotten) {
                        from = self.lay_off(
                            pa,
                            -r * (w * w),
                            txt!(self, "ω{}²·l_{seg}", self.link(link)),
                            Dir::Toward(figure_name.clone(), an.clone()),
                            (n_key, (txt!(self, "n"), self.link(link))),
                            2.0 * w.abs() * self.omega_err(link) * r.hypot(),
                        );
                        self.note_normal(link, from);
                    }
                    let out = self.lay_off(
                        from,
                        perp(r) * eps,
                        txt!(self, "ε{}·l_{seg}", self.link(link)),
                        Dir::PerpSense(seg, txt!(self, "ε{}", self.link(link))),
                        (key, label),
                        eerr * r.hypot(),
                    );
                    self.register(link, x, out);
                    out
                }
            }
        }
    }

    /// The best-conditioned way a careful draftsman places the material
    /// point of `link` at `local` (world `x`) from what the plan knows of
    /// the link (`known`: local place and plan point): the similar figure
    /// on any pair of its known points — by proportional division when the
    /// point is (nearly) on their line, by two arcs otherwise — or, from
    /// one known point, the relative vector of the link's measured rates.
    /// Each way's first-order error radius: the similar figure moves with
    /// its base as a + ρ·(b − a) does (|1 − ρ|·e_a + |ρ|·e_b: an extension
    /// beyond b grows it by its ratio), plus the pencil's δ for a division
    /// and the point's offset from the line the division ignores, or √2·δ
    /// over the sine of the arcs' angle; the relative vector adds δ per
    /// vector laid off and the rate's error times the distance. The least
    /// wins, so a point a hair off a rod is divided, not found by two
    /// nearly tangent arcs.
    fn best_construction(
        &self,
        link: usize,
        local: Vec2,
        x: Point,
        known: &[(Vec2, usize)],
    ) -> Construction {
        let delta = self.plan.delta;
        let mu = self.plan.mu;
        let pts = &self.plan.points;
        let mut best: Option<(f64, Construction)> = None;
        let consider = |e: f64, c: Construction, best: &mut Option<(f64, Construction)>| {
            if best.as_ref().is_none_or(|b| e < b.0) {
                *best = Some((e, c));
            }
        };
        for a in 0..known.len() {
            for b in a + 1..known.len() {
                let ((la, pa), (lb, pb)) = (known[a], known[b]);
                let ab = lb - la;
                if ab.hypot2() == 0.0 {
                    continue;
                }
                let ratio = (local - la).rotate_scale(Vec2::new(ab.x, -ab.y)) / ab.hypot2();
                let (ea, eb) = (pts[pa].err, pts[pb].err);
                let moved = (Vec2::new(1.0, 0.0) - ratio).hypot() * ea + ratio.hypot() * eb;
                let (a_at, b_at) = (pts[pa].at, pts[pb].at);
                let plan_ab = (b_at - a_at).hypot();
                // Division: the offset from the line is not drawn.
                let divide = moved + delta + ratio.y.abs() * plan_ab;
                let by_division = Construction::Figure {
                    a,
                    b,
                    ratio,
                    err: FigureErr::Divide(divide),
                };
                if ratio.y.abs() <= 1e-12 * ratio.hypot().max(1.0) {
                    consider(divide, by_division, &mut best);
                } else {
                    // Two arcs from a and b, meeting at the angle of the
                    // figure's sides at the new point.
                    let at = a_at + (b_at - a_at).rotate_scale(ratio);
                    let (ca, cb) = (at - a_at, at - b_at);
                    let s = if ca.hypot() * cb.hypot() > 0.0 {
                        (ca.cross(cb) / (ca.hypot() * cb.hypot())).abs()
                    } else {
                        1.0
                    };
                    let arcs = moved + std::f64::consts::SQRT_2 * delta / s.max(1e-300);
                    // A triangle is drawn by arcs (the lecture's way); a
                    // point a hair off the line by division, where the
                    // arcs would meet at too small an angle.
                    if 2.0 * divide < arcs {
                        consider(divide, by_division, &mut best);
                    } else {
                        consider(
                            arcs,
                            Construction::Figure {
                                a,
                                b,
                                ratio,
                                err: FigureErr::Arcs(arcs, s),
                            },
                            &mut best,
                        );
                    }
                }
            }
        }
        if let Some((rate, rate_err)) = self.plan.rates[link] {
            for (a, &(la, pa)) in known.iter().enumerate() {
                let r = (x - self.c.pose(link).apply(la)).hypot();
                let e = if self.vel_kind() {
                    pts[pa].err + delta + rate_err * r / mu
                } else {
                    let w = self.omega(link);
                    let normal = if w != 0.0 {
                        delta + 2.0 * w.abs() * self.omega_err(link) * r / mu
                    } else {
                        0.0
                    };
                    pts[pa].err + normal + delta + rate_err * r / mu
                };
                let _ = rate;
                // The similar figure is the lecture's way: the relative
                // vector takes over only where it is clearly better.
                consider(e * 2.0, Construction::Relation { a }, &mut best);
            }
        }
        best.map(|b| b.1).unwrap_or(Construction::Relation { a: 0 })
    }

    /// The named point `p` carried by `link` (registering it on every link
    /// carrying it that the plan knows).
    fn named(&mut self, link: usize, p: usize) -> usize {
        let x = self.world(link, p);
        // A point the plan already has needs no name.
        let i = match self.find(link, x) {
            Some(i) => i,
            None => {
                let name = self.name(p);
                let (key, label) = (name.to_lowercase(), self.label(&name));
                self.point_on(link, x, key, label, name)
            }
        };
        if self.plan.of_point[p].is_none() {
            self.plan.of_point[p] = Some(i);
        }
        i
    }

    /// The coincident point of `link` at world `x` (named after point `p`
    /// with the link's number as subscript: b₃ is B as a point of link 3).
    fn coincident(&mut self, link: usize, x: Point, p: usize) -> usize {
        if let Some(i) = self.find(link, x) {
            return i;
        }
        let name = self.name(p);
        let (mut key, mut label) = (name.to_lowercase(), self.label(&name));
        key = txt!(self, "{key}_{}", self.link(link));
        label.1 = self.link(link);
        self.point_on(
            link,
            x,
            key,
            label,
            txt!(self, "{}{}", self.name(p), self.link(link)),
        )
    }

    /// The line of a rigid relation X ∈ link with known point J:
    /// v_X = v_J + v_XJ (⊥ JX); a_X = a_J + a^n_XJ (toward J) + a^t_XJ (⊥ JX).
    /// Returns the line and the plan point the relative (tangential) part
    /// starts from.
    fn rigid(
        &mut self,
        link: usize,
        j: usize,
        jw: Point,
        jname: &str,
        x: Point,
        xname: &str,
    ) -> (PlanLine, usize) {
        let seg = txt!(self, "{jname}{xname}");
        let u = if self.making(Mistake::TangentialParallel) {
            x - jw
        } else {
            perp(x - jw)
        };
        if self.vel_kind() {
            (self.line(j, u, Dir::Perp(seg)), j)
        } else {
            let mut w = self.omega(link);
            if self.nr[link] || w == 0.0 || self.making(Mistake::NormalForgotten) {
                return (self.line(j, u, Dir::Perp(seg)), j);
            }
            let input = self.m().scene.input.link();
            // (A driving slider has no ω1 to take by mistake.)
            if link != input && self.omega(input) != 0.0 && self.making(Mistake::OmegaWrongLink) {
                w = self.omega(input);
            }
            let r = x - jw;
            let toward = if self.making(Mistake::NormalFromCentre) {
                1.0
            } else {
                -1.0
            };
            let n = self.lay_off(
                j,
                r * (toward * w * w),
                txt!(self, "a^n_{xname}{jname} = ω{}²·l_{seg}", self.link(link)),
                Dir::Toward(xname.to_string(), jname.to_string()),
                (
                    txt!(self, "n_{}", self.link(link)),
                    (txt!(self, "n"), self.link(link)),
                ),
                2.0 * w.abs() * self.omega_err(link) * r.hypot(),
            );
            self.note_normal(link, n);
            (self.line(n, u, Dir::Perp(seg)), n)
        }
    }

    /// The line of a slide of `unknown` along `u` relative to `known`, the
    /// point of `known` at x being plan point `kx`:
    /// v_X = v_Xk + v_rel (∥ guide); a_X = a_Xk + a^k + a^r (∥ guide),
    /// a^k = 2·ω×v_rel turned by 90° in the sense of ω (on a rotating guide).
    fn slide(
        &mut self,
        kx: usize,
        u: Vec2,
        Slide {
            unknown,
            known,
            guide,
        }: Slide,
        x: Point,
        xname: &str,
    ) -> Result<PlanLine> {
        let dir = Dir::Guide(self.link(guide));
        if self.vel_kind() || self.nr[known] {
            return Ok(self.line(kx, u, dir));
        }
        let w = self.omega(known);
        // v_rel of `unknown` relative to `known` at x, from the velocity plan.
        let vel = self.vel.expect("acceleration plan after the velocity plan");
        let local_u = self.local(unknown, x);
        let local_k = self.local(known, x);
        let (tol_u, tol_k) = (self.same_point(unknown, x), self.same_point(known, x));
        let find = |l: usize, loc: Vec2, tol: f64| vel.known_at(l, loc, tol);
        let (Some(iu), Some(ik)) = (find(unknown, local_u, tol_u), find(known, local_k, tol_k))
        else {
            unreachable!("the velocity plan has both coincident points");
        };
        let vrel = (vel.points[iu].at - vel.points[ik].at) * vel.mu;
        if self.making(Mistake::CoriolisForgotten) {
            return Ok(self.line(kx, u, dir));
        }
        let sense = if self.making(Mistake::CoriolisReversed) {
            -1.0
        } else {
            1.0
        };
        let factor = if self.making(Mistake::CoriolisFactorOne) {
            1.0
        } else {
            2.0
        };
        let k_vec = perp(vrel) * (factor * w * sense);
        let verr = (vel.points[iu].err + vel.points[ik].err) * vel.mu;
        let k = self.lay_off(
            kx,
            k_vec,
            txt!(
                self,
                "a^k_{xname}{u}{xname}{k} = 2·ω{k}·v_{xname}{u}{xname}{k}",
                u = self.link(unknown),
                k = self.link(known)
            ),
            Dir::Turned(
                txt!(
                    self,
                    "v_{xname}{}{xname}{}",
                    self.link(unknown),
                    self.link(known)
                ),
                txt!(self, "ω{}", self.link(known)),
            ),
            (
                txt!(self, "k_{}", self.link(unknown)),
                (txt!(self, "k"), self.link(unknown)),
            ),
            2.0 * (w.abs() * verr + self.omega_err(known) * vrel.hypot()),
        );
        Ok(self.line(k, u, dir))
    }

    /// Measure the relative segment from `from` to `to` (the tangential
    /// part for accelerations) of `link` between J and X: its rate.
    fn measure_rate(
        &mut self,
        link: usize,
        from: usize,
        to: usize,
        (jw, jname): (Point, &str),
        (x, xname): (Point, &str),
    ) {
        let mu = self.plan.mu;
        let rel = (self.plan.points[to].at - self.plan.points[from].at) * mu;
        let r = x - jw;
        let len = r.hypot();
        let sign = r.cross(rel).signum();
        let value = sign * rel.hypot() / len;
        let err_mm = self.plan.points[to].err + self.plan.points[from].err + self.plan.delta;
        let err = err_mm * mu / len;
        // The sense is read from the side of the link's line the relative
        // segment's end lies on: within the drafting error of that line it
        // cannot be read (only a plan drawn wrong has it there), and the
        // rate is known only in magnitude.
        let sense_known = !(len > 0.0 && (r.cross(rel) / len).abs() / mu <= err_mm);
        self.plan.rate_sense[link] = sense_known;
        self.plan.rates[link] = Some((value, err));
        self.plan.rate_len[link] = len;
        let quantity = if self.vel_kind() {
            txt!(self, "v_{xname}{jname}")
        } else {
            txt!(self, "a^t_{xname}{jname}")
        };
        let name = txt!(self, "{}{}", self.rate_sym(), self.link(link));
        self.plan.measured.push(Measured {
            quantity: name.clone(),
            from,
            to,
            mm: rel.hypot() / mu,
            value,
            bound: err,
        });
        self.step(Op::Measure {
            from,
            to,
            quantity,
            value: rel.hypot(),
            length: Some(len),
            rate: Some((name, value, (jname.to_string(), xname.to_string()))),
        });
    }

    /// One vector equation of a group: X from a known point `base` through
    /// a rigid link (normal + tangential parts) or a slide (Coriolis +
    /// relative parts), with the lecture's marks of what is known.
    fn relation(&self, x: &str, base: &str, rigid: bool, rotating: bool) -> String {
        if self.lean {
            return String::new();
        }
        if self.vel_kind() {
            return txt!(
                self,
                "v_{x} = {} + {}",
                known(&txt!(self, "v_{base}")),
                direction_known(&txt!(self, "v_{x}{base}"))
            );
        }
        let mut parts = vec![known(&txt!(self, "a_{base}"))];
        if rigid {
            if rotating {
                parts.push(known(&txt!(self, "a^n_{x}{base}")));
            }
            parts.push(direction_known(&txt!(self, "a^t_{x}{base}")));
        } else {
            if rotating {
                parts.push(known(&txt!(self, "a^k_{x}{base}")));
            }
            parts.push(direction_known(&txt!(self, "a^r_{x}{base}")));
        }
        txt!(self, "a_{x} = {}", parts.join(" + "))
    }

    fn equations(&mut self, a: String, b: String) {
        self.step(Op::Equation {
            text: txt!(self, "{a}; {b}"),
        });
    }

    fn same_rate(&mut self, link: usize, from: usize) {
        self.plan.rates[link] = self.plan.rates[from];
        self.plan.rate_sense[link] = self.plan.rate_sense[from];
        let (a, b, w) = (
            self.link(link),
            self.link(from),
            self.rate_sym().to_string(),
        );
        self.step(Op::Same {
            link: a,
            from_link: b,
            what: w,
        });
    }

    fn run(&mut self, rates: (f64, f64)) -> Result<()> {
        let m = self.m();
        let frame = m.frame();
        // The pole and the fixed points.
        let pole_label = if self.vel_kind() {
            ("p".to_string(), "v".to_string())
        } else {
            ("p".to_string(), "a".to_string())
        };
        self.add_point(
            if self.vel_kind() {
                "p_v".into()
            } else {
                "p_a".into()
            },
            pole_label,
            Vec2::ZERO,
            0.0,
        );
        let fixed: Vec<String> = if self.lean {
            Vec::new()
        } else {
            m.links[frame]
                .points
                .iter()
                .filter(|p| self.st.points.contains(p))
                .map(|&p| self.name(p).to_lowercase())
                .collect()
        };
        self.step(Op::Pole { fixed });
        for &p in &m.links[frame].points {
            let x = self.world(frame, p);
            self.register(frame, x, 0);
            if self.st.points.contains(&p) {
                self.plan.of_point[p] = Some(0);
            }
        }
        self.plan.rates[frame] = Some((0.0, 0.0));
        self.input(rates)?;
        for (gi, g) in self.st.s.groups.iter().enumerate() {
            if !self.st.need[gi] {
                continue;
            }
            match g {
                AssurGroup::Dyad(d) => self.dyad(d)?,
                AssurGroup::Triad(t) => self.triad(t)?,
            }
            // The reported points of the group's links.
            for l in g.links() {
                for &p in &m.links[l].points {
                    if self.st.points.contains(&p)
                        && self.plan.of_point[p].is_none()
                        && self.carrier(p) == l
                    {
                        self.named(l, p);
                    }
                }
            }
        }
        // Measured absolute values of the reported points.
        for &p in self.st.points {
            if let Some(i) = self.plan.of_point[p] {
                if i == 0 {
                    continue;
                }
                let mm = self.plan.points[i].at.hypot();
                let q = txt!(
                    self,
                    "{}_{}",
                    if self.vel_kind() { "v" } else { "a" },
                    self.name(p)
                );
                self.plan.measured.push(Measured {
                    quantity: q.clone(),
                    from: 0,
                    to: i,
                    mm,
                    value: mm * self.plan.mu,
                    bound: (self.plan.points[i].err + self.plan.delta) * self.plan.mu,
                });
                self.step(Op::Measure {
                    from: 0,
                    to: i,
                    quantity: q,
                    value: mm * self.plan.mu,
                    length: None,
                    rate: None,
                });
            }
        }
        Ok(())
    }

    /// The first included link carrying `p` (in scene order), else the frame.
    fn carrier(&self, p: usize) -> usize {
        let m = self.m();
        (0..m.links.len())
            .find(|&l| self.st.include[l] && m.links[l].points.contains(&p))
            .unwrap_or(m.frame())
    }

    fn input(&mut self, (rate, rate2): (f64, f64)) -> Result<()> {
        let m = self.m();
        match m.scene.input {
            InputSpec::Crank { link, pivot, .. } => {
                let pts = &m.links[link].points;
                let other = if pts[0] == pivot { pts[1] } else { pts[0] };
                let (o, a) = (self.world(link, pivot), self.world(link, other));
                self.register(link, o, 0);
                let (on, an) = (self.name(pivot), self.name(other));
                let seg = txt!(self, "{on}{an}");
                let key = an.to_lowercase();
                let label = self.label(&an);
                let r = a - o;
                let id = self.link(link);
                let idx = if self.vel_kind() {
                    self.plan.rates[link] = Some((rate, 0.0));
                    self.step(Op::Equation {
                        text: txt!(self, "v_{an} = ω{id}·l_{seg}, v_{an} ⊥ {seg}"),
                    });
                    let sense = if self.making(Mistake::OmegaWrongSense) {
                        -1.0
                    } else {
                        1.0
                    };
                    self.lay_off(
                        0,
                        perp(r) * (rate * sense),
                        txt!(self, "ω{id}·l_{seg}"),
                        Dir::PerpSense(seg.clone(), txt!(self, "ω{id}")),
                        (key, label),
                        0.0,
                    )
                } else {
                    self.plan.rates[link] = Some((rate2, 0.0));
                    let w = self.omega(link);
                    let mut rate2 = rate2;
                    if rate2 != 0.0 && self.making(Mistake::Epsilon1Forgotten) {
                        rate2 = 0.0;
                    } else if rate2 == 0.0 && self.making(Mistake::Epsilon1Added) {
                        rate2 = w * w;
                    }
                    if rate2 != 0.0 {
                        self.step(Op::Equation {
                            text: txt!(self, "a_{an} = a^n_{an}{on} + a^t_{an}{on}"),
                        });
                        let n = self.lay_off(
                            0,
                            -r * (w * w),
                            txt!(self, "a^n_{an}{on} = ω{id}²·l_{seg}"),
                            Dir::Toward(an.clone(), on.clone()),
                            (txt!(self, "n_{id}"), (txt!(self, "n"), id.clone())),
                            0.0,
                        );
                        self.note_normal(link, n);
                        self.lay_off(
                            n,
                            perp(r) * rate2,
                            txt!(self, "a^t_{an}{on} = ε{id}·l_{seg}"),
                            Dir::PerpSense(seg.clone(), txt!(self, "ε{id}")),
                            (key, label),
                            0.0,
                        )
                    } else {
                        self.step(Op::Equation {
                            text: txt!(self, "a_{an} = a^n_{an}{on} (ε{id} = 0)"),
                        });
                        self.lay_off(
                            0,
                            -r * (w * w),
                            txt!(self, "a^n_{an}{on} = ω{id}²·l_{seg}"),
                            Dir::Toward(an.clone(), on.clone()),
                            (key, label),
                            0.0,
                        )
                    }
                };
                self.register(link, a, idx);
                self.plan.of_point[other] = Some(idx);
            }
            InputSpec::Slider { link, pair, .. } => {
                let pr = &m.prismatics[pair];
                let x = self.world(link, pr.point);
                let u = self.c.pose(m.frame()).dir(pr.line_dir);
                let xn = self.name(pr.point);
                let v = if self.vel_kind() { rate } else { rate2 };
                self.plan.rates[link] = Some((0.0, 0.0));
                let sym = if self.vel_kind() { "v" } else { "a" };
                let idx = self.lay_off(
                    0,
                    u * v,
                    txt!(self, "{sym}_{xn}"),
                    Dir::Guide(self.link(m.frame())),
                    (xn.to_lowercase(), self.label(&xn)),
                    0.0,
                );
                self.register(link, x, idx);
                self.plan.of_point[pr.point] = Some(idx);
            }
        }
        Ok(())
    }

    /// Plan point of the joint of connection `cn` on its known side `k`.
    fn joint_on(&mut self, k: usize, cn: &Conn) -> (usize, Point, String) {
        let Joint::R(p) = cn.joint else {
            unreachable!("a revolute pair")
        };
        let i = self.named(k, p);
        (i, self.world(k, p), self.name(p))
    }

    fn dyad(&mut self, d: &Dyad) -> Result<()> {
        let m = self.m();
        let [l1, l2] = d.links;
        let (s1, s2) = (self.link(l1), self.link(l2));
        match d.kind {
            DyadKind::Rrr => {
                let (b, bw, bn) = self.joint_on(d.ext1.from, &d.ext1);
                let (dd, dw, dn) = self.joint_on(d.ext2.to, &d.ext2);
                let Joint::R(pc) = d.mid.joint else {
                    unreachable!()
                };
                let (cw, cn) = (self.world(l1, pc), self.name(pc));
                self.register(l1, bw, b);
                self.register(l2, dw, dd);
                self.equations(
                    self.relation(&cn, &bn, true, !self.nr[l1]),
                    self.relation(&cn, &dn, true, !self.nr[l2]),
                );
                let (mut la, ta) = self.rigid(l1, b, bw, &bn, cw, &cn);
                let (mut lb, tb) = self.rigid(l2, dd, dw, &dn, cw, &cn);
                if self.making(Mistake::WrongPerpendicular) {
                    // Each line ⊥ the other link of the group.
                    std::mem::swap(&mut la.unit, &mut lb.unit);
                    std::mem::swap(&mut la.dir, &mut lb.dir);
                }
                let c = self.intersect(la, lb, cn.to_lowercase(), self.label(&cn))?;
                self.register(l1, cw, c);
                self.register(l2, cw, c);
                self.plan.of_point[pc].get_or_insert(c);
                self.measure_rate(l1, ta, c, (bw, &bn), (cw, &cn));
                self.measure_rate(l2, tb, c, (dw, &dn), (cw, &cn));
            }
            DyadKind::Rrp => {
                let (b, bw, bn) = self.joint_on(d.ext1.from, &d.ext1);
                self.register(l1, bw, b);
                let Joint::R(pc) = d.mid.joint else {
                    unreachable!()
                };
                let Joint::P(k) = d.ext2.joint else {
                    unreachable!()
                };
                let k2 = d.ext2.to;
                let (cw, cn) = (self.world(l1, pc), self.name(pc));
                let pr = &m.prismatics[k];
                let u = self.c.pose(pr.guide).dir(pr.line_dir);
                let kc = self.coincident(k2, cw, pc);
                let kcn = txt!(self, "{cn}{}", self.link(k2));
                self.equations(
                    self.relation(&cn, &bn, true, !self.nr[l1]),
                    self.relation(&cn, &kcn, false, !self.nr[k2]),
                );
                let (la, ta) = self.rigid(l1, b, bw, &bn, cw, &cn);
                let lb = self.slide(
                    kc,
                    u,
                    Slide {
                        unknown: l2,
                        known: k2,
                        guide: pr.guide,
                    },
                    cw,
                    &cn,
                )?;
                let c = self.intersect(la, lb, cn.to_lowercase(), self.label(&cn))?;
                self.register(l1, cw, c);
                self.register(l2, cw, c);
                self.plan.of_point[pc].get_or_insert(c);
                self.measure_rate(l1, ta, c, (bw, &bn), (cw, &cn));
                self.same_rate(l2, k2);
                let _ = (s1, s2);
            }
            DyadKind::Rpr => {
                let Joint::P(k) = d.mid.joint else {
                    unreachable!()
                };
                let pr = &m.prismatics[k];
                let (g, s) = (pr.guide, pr.slider);
                let (cg, cs) = if g == l1 {
                    (d.ext1, d.ext2)
                } else {
                    (d.ext2, d.ext1)
                };
                let kg = if cg.to == g { cg.from } else { cg.to };
                let ks = if cs.to == s { cs.from } else { cs.to };
                let (jg, jgw, jgn) = self.joint_on(kg, &cg);
                let (js, jsw, jsn) = self.joint_on(ks, &cs);
                self.register(g, jgw, jg);
                self.register(s, jsw, js);
                let Joint::R(ps) = cs.joint else {
                    unreachable!()
                };
                let u = self.c.pose(g).dir(pr.line_dir);
                let xg = txt!(self, "{jsn}{}", self.link(g));
                self.equations(
                    self.relation(&xg, &jsn, false, !self.nr[s]),
                    self.relation(&xg, &jgn, true, !self.nr[g]),
                );
                let (la, ta) = self.rigid(g, jg, jgw, &jgn, jsw, &xg);
                let lb = self.slide(
                    js,
                    u,
                    Slide {
                        unknown: g,
                        known: s,
                        guide: g,
                    },
                    jsw,
                    &jsn,
                )?;
                let (mut key, mut label) = (jsn.to_lowercase(), self.label(&jsn));
                key = txt!(self, "{key}_{}", self.link(g));
                label.1 = self.link(g);
                let x = if self.making(Mistake::WrongLink) {
                    // b₃ taken as b₂: the relative sliding ignored.
                    js
                } else {
                    self.intersect(la, lb, key, label)?
                };
                self.register(g, jsw, x);
                let _ = ps;
                self.measure_rate(g, ta, x, (jgw, &jgn), (jsw, &xg));
                self.same_rate(s, g);
            }
            DyadKind::Prp => {
                let Joint::R(pc) = d.mid.joint else {
                    unreachable!()
                };
                let (Joint::P(k1), Joint::P(k2)) = (d.ext1.joint, d.ext2.joint) else {
                    unreachable!()
                };
                let (kk1, kk2) = (d.ext1.from, d.ext2.to);
                let cw = self.world(l1, pc);
                let cn = self.name(pc);
                let (p1, p2) = (&m.prismatics[k1], &m.prismatics[k2]);
                let (u1, u2) = (
                    self.c.pose(p1.guide).dir(p1.line_dir),
                    self.c.pose(p2.guide).dir(p2.line_dir),
                );
                let c1 = self.coincident(kk1, cw, pc);
                let c2 = self.coincident(kk2, cw, pc);
                let (n1, n2) = (
                    txt!(self, "{cn}{}", self.link(kk1)),
                    txt!(self, "{cn}{}", self.link(kk2)),
                );
                self.equations(
                    self.relation(&cn, &n1, false, !self.nr[kk1]),
                    self.relation(&cn, &n2, false, !self.nr[kk2]),
                );
                let la = self.slide(
                    c1,
                    u1,
                    Slide {
                        unknown: l1,
                        known: kk1,
                        guide: p1.guide,
                    },
                    cw,
                    &cn,
                )?;
                let lb = self.slide(
                    c2,
                    u2,
                    Slide {
                        unknown: l2,
                        known: kk2,
                        guide: p2.guide,
                    },
                    cw,
                    &cn,
                )?;
                let c = self.intersect(la, lb, cn.to_lowercase(), self.label(&cn))?;
                self.register(l1, cw, c);
                self.register(l2, cw, c);
                self.plan.of_point[pc].get_or_insert(c);
                self.same_rate(l1, kk1);
                self.same_rate(l2, kk2);
            }
            DyadKind::Rpp => {
                let (b, bw, bn) = self.joint_on(d.ext1.from, &d.ext1);
                self.register(l1, bw, b);
                let (Joint::P(km), Joint::P(ke)) = (d.mid.joint, d.ext2.joint) else {
                    unreachable!()
                };
                let k2 = d.ext2.to;
                let Joint::R(pb) = d.ext1.joint else {
                    unreachable!()
                };
                let (pm, pe) = (&m.prismatics[km], &m.prismatics[ke]);
                let (um, ue) = (
                    self.c.pose(pm.guide).dir(pm.line_dir),
                    self.c.pose(pe.guide).dir(pe.line_dir),
                );
                self.same_rate(l2, k2);
                self.same_rate(l1, k2);
                let bk = self.coincident(k2, bw, pb);
                let (x2, xk) = (
                    txt!(self, "{bn}{}", self.link(l2)),
                    txt!(self, "{bn}{}", self.link(k2)),
                );
                self.equations(
                    self.relation(&x2, &bn, false, !self.nr[l1]),
                    self.relation(&x2, &xk, false, !self.nr[k2]),
                );
                let la = self.slide(
                    b,
                    um,
                    Slide {
                        unknown: l2,
                        known: l1,
                        guide: pm.guide,
                    },
                    bw,
                    &bn,
                )?;
                let lb = self.slide(
                    bk,
                    ue,
                    Slide {
                        unknown: l2,
                        known: k2,
                        guide: pe.guide,
                    },
                    bw,
                    &bn,
                )?;
                let (mut key, mut label) = (bn.to_lowercase(), self.label(&bn));
                key = txt!(self, "{key}_{}", self.link(l2));
                label.1 = self.link(l2);
                let x = self.intersect(la, lb, key, label)?;
                self.register(l2, bw, x);
            }
        }
        Ok(())
    }

    /// A three-leash group by Assur's special point: the axes of two
    /// leashes meet at S, taken on the base link; v_S (a_S) is reached from
    /// both leashes' outer joints along lines ⊥ their axes. The pair of
    /// leashes
    /// whose construction is best conditioned: each of the three pairs is
    /// drawn in turn and the one whose points come out with the smallest
    /// largest error radius is kept (the largest angle between the axes
    /// is not enough: a special point far out on the base carries large
    /// normal components ω²·l of the base).
    fn triad(&mut self, t: &Triad) -> Result<()> {
        let pairs = [(0, 1, 2), (0, 2, 1), (1, 2, 0)];
        let saved = (self.plan.clone(), self.normal_of.clone(), self.rng.clone());
        let start = self.plan.points.len();
        let mut best: Option<(f64, (usize, usize, usize))> = None;
        let mut first_err = None;
        for pair in pairs {
            (self.plan, self.normal_of, self.rng) = saved.clone();
            match self.triad_by(t, Some(pair)) {
                Ok(()) => {
                    let worst = self.plan.points[start..]
                        .iter()
                        .map(|p| p.err)
                        .fold(0.0, f64::max);
                    if best.is_none_or(|b| worst < b.0) {
                        best = Some((worst, pair));
                    }
                }
                Err(e) => {
                    first_err.get_or_insert(e);
                }
            }
        }
        (self.plan, self.normal_of, self.rng) = saved;
        match best {
            Some((_, pair)) => self.triad_by(t, Some(pair)),
            // No pair constructs: the error of the best-angled one.
            None => self
                .triad_by(t, None)
                .and(Err(first_err.expect("three tries"))),
        }
    }

    /// The three-leash group by the special point of leashes (i, j), the
    /// third leash k found from it; `None`: the pair whose axes meet at the
    /// largest angle.
    fn triad_by(&mut self, t: &Triad, pair: Option<(usize, usize, usize)>) -> Result<()> {
        let m = self.m();
        let e: Vec<(usize, Point, String)> = (0..3)
            .map(|i| self.joint_on(t.ext[i].from, &t.ext[i]))
            .collect();
        let jp: Vec<usize> = t
            .int
            .iter()
            .map(|c| match c.joint {
                Joint::R(p) => p,
                Joint::P(_) => unreachable!(),
            })
            .collect();
        let jw: Vec<Point> = jp.iter().map(|&p| self.world(t.base, p)).collect();
        let jn: Vec<String> = jp.iter().map(|&p| self.name(p)).collect();
        for (leash, ei) in t.leashes.iter().zip(&e) {
            self.register(*leash, ei.1, ei.0);
        }
        let axis = |i: usize| Line::new(e[i].1, jw[i] - e[i].1);
        let pairs = [(0, 1, 2), (0, 2, 1), (1, 2, 0)];
        let (i, j, k) = pair.unwrap_or_else(|| {
            *pairs
                .iter()
                .max_by(|a, b| {
                    axis(a.0)
                        .dir
                        .cross(axis(a.1).dir)
                        .abs()
                        .total_cmp(&axis(b.0).dir.cross(axis(b.1).dir).abs())
                })
                .unwrap()
        });
        let LineCut::Point { at: sw, .. } = crate::geom::intersect_lines(&axis(i), &axis(j), 1e-12)
        else {
            return Err(Error::Singular {
                at: describe_input(m, self.q),
                why: "all three leashes of the class III group are parallel".into(),
            });
        };
        let group_size = t
            .leashes
            .iter()
            .chain([&t.base])
            .map(|&l| m.link_scale(l))
            .fold(0.0, f64::max);
        if (sw - jw[k]).hypot() <= 1e-9 * group_size {
            return Err(Error::Singular {
                at: describe_input(m, self.q),
                why:
                    "the three leashes' axes meet in one point: a dead point of the class III group"
                        .into(),
            });
        }
        let base = self.link(t.base);
        let v = if self.vel_kind() { "v" } else { "a" };
        let sname = txt!(self, "S{base}");
        self.step(Op::Equation {
            text: txt!(self,
                "special point {sname} = {}{} ∩ {}{} on link {base}: {v}_{sname} = {v}_{} + {v}_{}{} + {v}_{sname}{}; {v}_{sname} = {v}_{} + {v}_{}{} + {v}_{sname}{}",
                e[i].2, jn[i], e[j].2, jn[j], e[i].2, jn[i], e[i].2, jn[i], e[j].2, jn[j], e[j].2, jn[j]
            ),
        });
        // The line for S from leash n: through e_n (+ normals) ⊥ E_n J_n.
        let line_for_s = |b: &mut Builder, n: usize| -> PlanLine {
            let u = perp(jw[n] - e[n].1);
            let seg = txt!(b, "{}{}", e[n].2, jn[n]);
            if b.vel_kind() {
                return b.line(e[n].0, u, Dir::Perp(seg));
            }
            let mut from = e[n].0;
            let leash = t.leashes[n];
            let (wl, wb) = (b.omega(leash), b.omega(t.base));
            let r1 = jw[n] - e[n].1;
            if wl != 0.0 {
                from = b.lay_off(
                    from,
                    -r1 * (wl * wl),
                    txt!(b, "a^n_{}{} = ω{}²·l_{seg}", jn[n], e[n].2, b.link(leash)),
                    Dir::Toward(jn[n].clone(), e[n].2.clone()),
                    (
                        txt!(b, "n_{}", b.link(leash)),
                        (txt!(b, "n"), b.link(leash)),
                    ),
                    2.0 * wl.abs() * b.omega_err(leash) * r1.hypot(),
                );
                b.note_normal(leash, from);
            }
            let r2 = sw - jw[n];
            if wb != 0.0 && r2.hypot() > 0.0 {
                from = b.lay_off(
                    from,
                    -r2 * (wb * wb),
                    txt!(
                        b,
                        "a^n_{sname}{} = ω{}²·l_{sname}{}",
                        jn[n],
                        b.link(t.base),
                        jn[n]
                    ),
                    Dir::Toward(sname.clone(), jn[n].clone()),
                    (
                        txt!(b, "n_{}", b.link(t.base)),
                        (txt!(b, "n"), b.link(t.base)),
                    ),
                    2.0 * wb.abs() * b.omega_err(t.base) * r2.hypot(),
                );
                b.note_normal(t.base, from);
            }
            b.line(from, u, Dir::Perp(seg))
        };
        let la = line_for_s(self, i);
        let lb = line_for_s(self, j);
        let s_idx = self.intersect(
            la,
            lb,
            txt!(self, "s_{base}"),
            (txt!(self, "s"), base.clone()),
        )?;
        self.register(t.base, sw, s_idx);
        // Third leash: J_k from S on the base and from E_k on the leash.
        let (lbase, tbase) = self.rigid(t.base, s_idx, sw, &sname, jw[k], &jn[k]);
        let (lleash, tleash) = self.rigid(t.leashes[k], e[k].0, e[k].1, &e[k].2, jw[k], &jn[k]);
        let jk = self.intersect(lbase, lleash, jn[k].to_lowercase(), self.label(&jn[k]))?;
        self.register(t.base, jw[k], jk);
        self.register(t.leashes[k], jw[k], jk);
        self.plan.of_point[jp[k]].get_or_insert(jk);
        self.measure_rate(t.base, tbase, jk, (sw, &sname), (jw[k], &jn[k]));
        self.measure_rate(t.leashes[k], tleash, jk, (e[k].1, &e[k].2), (jw[k], &jn[k]));
        // The other joints by similarity on the base, then the leashes' rates.
        for n in [i, j] {
            let jn_idx = self.named(t.base, jp[n]);
            self.register(t.leashes[n], jw[n], jn_idx);
            let from = if self.vel_kind() || self.omega(t.leashes[n]) == 0.0 {
                e[n].0
            } else {
                self.normal_of[t.leashes[n]].unwrap_or(e[n].0)
            };
            self.measure_rate(
                t.leashes[n],
                from,
                jn_idx,
                (e[n].1, &e[n].2),
                (jw[n], &jn[n]),
            );
        }
        Ok(())
    }
}

/// Both plans at one position, as `want.plans` asks.
#[derive(Clone, Debug)]
pub struct Plans {
    pub velocity: Plan,
    pub acceleration: Option<Plan>,
}

/// Fixed scales, the pencil precision and the variant for [`build_plans`].
#[derive(Clone, Copy, Debug)]
pub struct Drafting {
    pub mu_v: Option<f64>,
    pub mu_a: Option<f64>,
    /// Pencil precision δ, mm.
    pub delta: f64,
    pub variant: Variant,
}

impl Default for Drafting {
    fn default() -> Self {
        Drafting {
            mu_v: None,
            mu_a: None,
            delta: 0.5,
            variant: Variant::default(),
        }
    }
}

/// Build the velocity plan, and the acceleration plan when `order` asks
/// (it needs the velocity plan's ω and relative velocities).
pub fn build_plans(
    st: &Setup,
    c: &Configuration,
    drive: Drive,
    order: Order,
    d: Drafting,
) -> Result<Plans> {
    plans(st, c, drive, order, d, false)
}

/// The acceleration plan built on a given velocity plan (its ω and
/// relative velocities): a student's own velocity plan, at their scale,
/// with the ω they measured.
pub fn build_acceleration(
    st: &Setup,
    c: &Configuration,
    drive: Drive,
    vel: &Plan,
    d: Drafting,
) -> Result<Plan> {
    build(st, c, drive, PlanKind::Acceleration, Some(vel), &d, false)
}

/// The same constructions as [`build_plans`], numbers only: every plan
/// point, rate, measured value and error bound, but no names, labels or
/// steps (the plan cannot be drawn or narrated). For sweeps that read
/// numbers: the precision report, the speed bench.
pub fn build_plans_numbers(
    st: &Setup,
    c: &Configuration,
    drive: Drive,
    order: Order,
    d: Drafting,
) -> Result<Plans> {
    plans(st, c, drive, order, d, true)
}

fn plans(
    st: &Setup,
    c: &Configuration,
    drive: Drive,
    order: Order,
    d: Drafting,
    lean: bool,
) -> Result<Plans> {
    let velocity = build(st, c, drive, PlanKind::Velocity, None, &d, lean)?;
    let acceleration = match order {
        Order::Acceleration => Some(build(
            st,
            c,
            drive,
            PlanKind::Acceleration,
            Some(&velocity),
            &d,
            lean,
        )?),
        Order::Velocity => None,
    };
    Ok(Plans {
        velocity,
        acceleration,
    })
}
