//! What a scene says, as types: its points, links, lengths, sliders, inputs,
//! positions, what is wanted and the sheet's data, and the limits a scene
//! is read within.

use kurbo::{Point, Vec2};

/// A named point of the sketch.
#[derive(Clone, Debug)]
pub struct NamedPoint {
    pub name: String,
    pub sketch: Point,
}

/// A link: its id as written, an optional name, and its points (indices into
/// `Scene::points`) in the order listed: the first two form its base.
#[derive(Clone, Debug)]
pub struct LinkSpec {
    pub id: String,
    pub name: Option<String>,
    pub points: Vec<usize>,
}

/// Where a guide line passes.
#[derive(Clone, Debug)]
pub enum Through {
    Point(usize),
    Coords(Point),
}

/// The direction of a guide line.
#[derive(Clone, Debug)]
pub enum Direction {
    /// A direction in the sketch frame, radians.
    Angle(f64),
    /// Parallel to the ray from the first point to the second.
    Along(usize, usize),
}

#[derive(Clone, Debug)]
pub struct GuideLine {
    pub through: Through,
    pub direction: Direction,
    /// Signed shift, positive to the left of the direction (m).
    pub offset: f64,
}

/// A prismatic pair: `slider` slides along a line fixed to `guide`.
#[derive(Clone, Debug)]
pub struct SliderSpec {
    pub slider: usize,
    pub guide: usize,
    pub point: usize,
    pub line: GuideLine,
}

#[derive(Clone, Debug)]
pub struct LengthSpec {
    pub key: String,
    pub a: usize,
    pub b: usize,
    pub value: f64,
}

/// A driving link and its motion: a crank about a frame point, or a
/// driving slider in a prismatic pair whose guide is the frame or any
/// moving link (a hydraulic cylinder: the rod's slide relative to the
/// cylinder is given).
#[derive(Clone, Debug)]
pub enum InputSpec {
    Crank {
        link: usize,
        pivot: usize,
        angle: f64,
        omega: f64,
        epsilon: f64,
    },
    Slider {
        link: usize,
        /// Index into `Scene::sliders`.
        pair: usize,
        s: f64,
        v: f64,
        a: f64,
    },
}

impl InputSpec {
    pub fn link(&self) -> usize {
        match self {
            InputSpec::Crank { link, .. } | InputSpec::Slider { link, .. } => *link,
        }
    }
    /// The generalised coordinate of the scene's own input value.
    pub fn coordinate(&self) -> f64 {
        match self {
            InputSpec::Crank { angle, .. } => *angle,
            InputSpec::Slider { s, .. } => *s,
        }
    }
    /// Is it a crank (an angle), not a slider (a slide)?
    pub fn is_crank(&self) -> bool {
        matches!(self, InputSpec::Crank { .. })
    }
    /// (rate, rate of rate): (ω, ε) or (v, a).
    pub fn rates(&self) -> (f64, f64) {
        match self {
            InputSpec::Crank { omega, epsilon, .. } => (*omega, *epsilon),
            InputSpec::Slider { v, a, .. } => (*v, *a),
        }
    }
    /// The sense of the input's motion: +1 counter-clockwise (a slider:
    /// along its guide), −1 against; a standing input counts as +1.
    pub fn sense(&self) -> f64 {
        if self.rates().0 < 0.0 { -1.0 } else { 1.0 }
    }
}

#[derive(Clone, Debug)]
pub enum PositionsSpec {
    /// The single input value of `input`.
    Single,
    /// Explicit input values (rad for a crank, m for a slider).
    List(Vec<f64>),
    /// Explicit values of several inputs: one list per position, one value
    /// per input in the order of `input` (rad for a crank, m for a slider).
    Values(Vec<Vec<f64>>),
    /// Equal steps over a revolution from the extreme position of `output`.
    Count { count: usize, output: Option<usize> },
}

impl PositionsSpec {
    /// How many positions are asked for.
    pub fn count(&self) -> usize {
        match self {
            PositionsSpec::Single => 1,
            PositionsSpec::List(v) => v.len(),
            PositionsSpec::Values(v) => v.len(),
            PositionsSpec::Count { count, .. } => *count,
        }
    }

    /// How the scene's positions are numbered: a `count` sweep from 0
    /// (position 0 is the extreme position that starts the working stroke,
    /// as the lecture numbers them), every other sweep (the input values
    /// given: `angles`, `s`, `values`, or the one position) from 1.
    pub fn numbering(&self) -> Numbering {
        match self {
            PositionsSpec::Count { .. } => Numbering::FROM_0,
            _ => Numbering::FROM_1,
        }
    }
}

/// How positions are numbered: the number of the first, 0 or 1. One
/// numbering serves every number a person reads or types and a program
/// reads (the sheets and their files, `--position`, the result files, a
/// checked answer's `position`, its report, the gradebook, the handout):
/// the scene's (a `count` sweep from 0, given input values from 1),
/// unless a study is numbered otherwise (`--positions-from`,
/// `Study::numbered`); an answer may state its own (`"positions_from"`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Numbering {
    first: usize,
}

impl Numbering {
    /// From 0: a `count` sweep's own numbering.
    pub const FROM_0: Numbering = Numbering { first: 0 };
    /// From 1: the numbering of given input values, and the older one of
    /// every sweep.
    pub const FROM_1: Numbering = Numbering { first: 1 };

    /// The numbering whose first position is `first`; `None` unless it is
    /// 0 or 1.
    pub fn from_first(first: u64) -> Option<Numbering> {
        match first {
            0 => Some(Numbering::FROM_0),
            1 => Some(Numbering::FROM_1),
            _ => None,
        }
    }

    /// The number of the first position: 0 or 1.
    pub fn first(self) -> usize {
        self.first
    }

    /// The number of the position at `index` (from 0, in the sweep's order).
    pub fn number(self, index: usize) -> usize {
        index + self.first
    }

    /// The index (from 0) of position `number` among `count` positions;
    /// `None` if there is no such position.
    pub fn index(self, number: usize, count: usize) -> Option<usize> {
        number.checked_sub(self.first).filter(|&k| k < count)
    }

    /// The numbers of `count` positions, for a message: "from 0 to 11".
    pub fn range_text(self, count: usize) -> String {
        format!(
            "from {} to {}",
            self.first,
            (count + self.first).saturating_sub(1)
        )
    }
}

/// The text for `lang` among `by` (a title given in several languages),
/// else `default`.
pub fn in_lang<'a>(
    default: &'a str,
    by: &'a [(crate::lang::Lang, String)],
    lang: crate::lang::Lang,
) -> &'a str {
    by.iter()
        .find(|(l, _)| *l == lang)
        .map_or(default, |(_, t)| t.as_str())
}

impl Scene {
    /// The scene's title in `lang` (its own text where the scene gives
    /// one, else its default).
    pub fn title_in(&self, lang: crate::lang::Lang) -> &str {
        in_lang(&self.title, &self.titles, lang)
    }
}

impl SheetInfo {
    /// The drawing's name in `lang`, where the scene gives one.
    pub fn title_in(&self, lang: crate::lang::Lang) -> Option<&str> {
        let d = self.title.as_deref()?;
        Some(in_lang(d, &self.titles, lang))
    }
}

/// What the main title block says (the scene's `sheet` object); every
/// field optional, an absent one left blank on the sheet.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SheetInfo {
    /// The document's designation (ГОСТ 2.104 field 2), e.g. "ТММ.КП.01.00.001".
    pub designation: Option<String>,
    /// The name of the drawing (field 1); else the scene's title.
    pub title: Option<String>,
    /// The name in each language it is given in (see [`Scene::titles`]).
    pub titles: Vec<(crate::lang::Lang, String)>,
    /// The document's letter (ГОСТ 2.104 field 4; ГОСТ 2.103), up to three
    /// letters, one a cell; else the language's default ("У").
    pub letter: Option<String>,
    /// Who drew it ("Разраб.").
    pub author: Option<String>,
    /// Who checked it ("Пров.").
    pub checker: Option<String>,
    /// The organisation, group (field 9).
    pub organisation: Option<String>,
    /// The scale field (6); else a dash, the figures stating their μ.
    pub scale: Option<String>,
}

/// Which positions' plans the course sheet shows (`want.plans_at`, read
/// in the scene's numbering), as the k-th positions (from 1, in the
/// sweep's order); `None`: the default.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PlansAt {
    pub velocity: Option<Vec<usize>>,
    pub acceleration: Option<Vec<usize>>,
}

#[derive(Clone, Debug, Default)]
pub struct Scales {
    pub mu_l: Option<f64>,
    pub mu_v: Option<f64>,
    pub mu_a: Option<f64>,
}

#[derive(Clone, Debug)]
pub struct Want {
    /// The rates computed (`want.rates`, else `want.plans`): velocities,
    /// and accelerations with them.
    pub velocity: bool,
    pub acceleration: bool,
    /// Whether the plans are built (`want.plans` not empty, rates
    /// wanted); without them every position is checked by route (b)'s
    /// residuals at route (a)'s answer (docs/sweeps.md).
    pub plans: bool,
    /// `None`: every point.
    pub points: Option<Vec<usize>>,
    pub drawings: Vec<String>,
    pub scales: Scales,
    pub lang: String,
    /// The positions whose plans the course sheet shows.
    pub plans_at: PlansAt,
}

impl Default for Want {
    fn default() -> Self {
        Want {
            velocity: true,
            acceleration: true,
            plans: true,
            points: None,
            drawings: Vec::new(),
            scales: Scales::default(),
            lang: "en".into(),
            plans_at: PlansAt::default(),
        }
    }
}

#[derive(Clone, Debug)]
pub struct Scene {
    /// The scene's title (its English text where `title` gives several).
    pub title: String,
    /// The title in each language it is given in (`"title": { "en": …,
    /// "uk": … }`); empty for a plain string. [`Scene::title_in`] reads it.
    pub titles: Vec<(crate::lang::Lang, String)>,
    /// What the title block says (`sheet`).
    pub sheet: SheetInfo,
    pub points: Vec<NamedPoint>,
    pub links: Vec<LinkSpec>,
    /// Index of link "0".
    pub frame: usize,
    pub sliders: Vec<SliderSpec>,
    pub lengths: Vec<LengthSpec>,
    /// The driving link (the first, when `input` lists several).
    pub input: InputSpec,
    /// The further inputs, in the order `input` lists them (empty for one
    /// input): [`Scene::inputs`] gives them all.
    pub more_inputs: Vec<InputSpec>,
    pub positions: PositionsSpec,
    pub want: Want,
    /// Length unit of the file (m per unit), to echo inputs in their units.
    pub length_unit: f64,
    /// Whether the file states its length unit (`units.length`): without
    /// it the lengths are metres, and a sketch larger than
    /// [`MILLIMETRES_LIKELY_M`] draws a note that they may be millimetres.
    pub length_stated: bool,
    /// Angle unit of the file (rad per unit).
    pub angle_unit: f64,
    /// The rounding of each listed input value as the file writes it (rad
    /// or m; one value per input for the single `input` position and for
    /// `count` (the input's own, where the steps start at it); with
    /// several inputs position after position, one value per input):
    /// a few units of it move the input in the data check, as the data's
    /// own rounding does (an angle of a million turns in radians is known
    /// only to about 1e-9 rad).
    pub input_rounding: Vec<f64>,
    /// Masses and external loads for the force analysis (`dynamics`);
    /// `None`: kinematics only.
    pub dynamics: Option<DynamicsSpec>,
}

/// Unit roundoff of f64: half an ulp, relative.
pub(super) const U: f64 = f64::EPSILON / 2.0;

/// The size of a sketch (the diagonal of its bounding box, m) beyond
/// which a scene that states no `units.length` draws a note that its
/// lengths, read as metres, may be millimetres: no machine drawn in a
/// course is 20 m across, while a mechanism of a few hundred millimetres
/// read as metres is hundreds of metres.
pub const MILLIMETRES_LIKELY_M: f64 = 20.0;

/// Upper limits that keep a hostile file from exhausting the machine.
pub const MAX_FILE_BYTES: usize = 4 << 20;

pub const MAX_POINTS: usize = 10_000;

pub const MAX_LINKS: usize = 5_000;

/// The most positions a list (`angles`, `s`, `values`) may give, and
/// the most a command that holds every position at once (`draw`'s
/// handout, `check`, `serve`, [`crate::Study::solve`]) takes.
pub const MAX_POSITIONS: usize = 100_000;

/// The most positions `positions.count` may ask for. A count's steps are
/// made as the sweep reaches them and `solve` writes each position as it
/// is solved, so memory does not bound it; this refuses only what no run
/// would finish (a billion four-bar positions are some 40 minutes and
/// 480 GB of CSV).
pub const MAX_COUNT: usize = 1_000_000_000;

/// Largest magnitude of any number: accelerations square velocities, so
/// larger inputs would overflow to infinity.
pub const MAX_MAGNITUDE: f64 = 1e100;

/// The most inputs a scene may have.
pub const MAX_INPUTS: usize = 8;
/// The most moving links the force analysis takes: its equilibrium
/// system is dense, 3 equations a link (an LU of 600 × 600 at every
/// position).
pub const MAX_MOVING_LINKS: usize = 200;

/// The scene's `dynamics`: gravity, masses, external loads.
#[derive(Clone, Debug, PartialEq)]
pub struct DynamicsSpec {
    /// The acceleration of gravity, m/s² (absent: no gravity, [0, 0]).
    pub g: Vec2,
    /// The links with mass, in the order written.
    pub links: Vec<LinkMass>,
    pub forces: Vec<ForceSpec>,
    pub moments: Vec<MomentSpec>,
}

/// A link's mass `m` (kg), its moment of inertia `j` about its centre
/// (kg·m²) and the centre, a point of the link.
#[derive(Clone, Debug, PartialEq)]
pub struct LinkMass {
    pub link: usize,
    pub m: f64,
    pub j: f64,
    pub centre: usize,
}

/// A value the same at every position, or one per position (a working
/// resistance over the stroke, an indicator diagram's gas force).
#[derive(Clone, Debug, PartialEq)]
pub enum PerPosition<T> {
    Constant(T),
    List(Vec<T>),
}

impl<T: Copy> PerPosition<T> {
    /// The value at position `k` (from 0).
    pub fn at(&self, k: usize) -> T {
        match self {
            PerPosition::Constant(x) => *x,
            PerPosition::List(v) => v[k],
        }
    }
}

/// An external force `f` (N) on `link` at its point `point`: given (one
/// value, or one per position), or by a table against the displacement
/// of its point (`table`, when `Some`: then `f` is not read).
#[derive(Clone, Debug, PartialEq)]
pub struct ForceSpec {
    pub link: usize,
    pub point: usize,
    pub f: PerPosition<Vec2>,
    pub table: Option<ForceTable>,
}

/// A force against the displacement of its point, s = |P − `from`| (m):
/// a working resistance over the stroke, a gas force over the piston's
/// travel. `working` while the point moves away from `from`, `back` while
/// it moves toward it (zero when the table gives none), linear between
/// the rows; a position whose s falls outside the rows is refused.
#[derive(Clone, Debug, PartialEq)]
pub struct ForceTable {
    pub from: kurbo::Point,
    /// Increasing displacements, m.
    pub s: Vec<f64>,
    pub working: Vec<Vec2>,
    pub back: Vec<Vec2>,
}

impl ForceTable {
    /// The force at displacement `s` (clamped to the rows), on the
    /// working stroke or back.
    pub fn at(&self, s: f64, working: bool) -> Vec2 {
        let f = if working { &self.working } else { &self.back };
        if f.is_empty() {
            return Vec2::ZERO;
        }
        let n = self.s.len();
        if s <= self.s[0] {
            return f[0];
        }
        if s >= self.s[n - 1] {
            return f[n - 1];
        }
        let i = self.s.partition_point(|&x| x <= s).clamp(1, n - 1);
        let t = (s - self.s[i - 1]) / (self.s[i] - self.s[i - 1]);
        f[i - 1] + (f[i] - f[i - 1]) * t
    }
}

/// An external couple `m` (N·m, counter-clockwise positive) on `link`.
#[derive(Clone, Debug, PartialEq)]
pub struct MomentSpec {
    pub link: usize,
    pub m: PerPosition<f64>,
}
