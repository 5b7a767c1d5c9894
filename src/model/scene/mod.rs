//! The scene file (described completely in `docs/scene-format.md`):
//! reading and validating it completely, every
//! problem reported with its JSON pointer. All numbers are converted to SI
//! (m, rad) here, so nothing downstream knows about units.
//!
//! The types are here; the reader, by section of the file: `reader` (the
//! top level, the units and the getters every section uses), `numbers`
//! (numbers, angles and their rounding, non-finite numbers located),
//! `links` (points and links), `sliders` (prismatic pairs and their
//! guide lines), `lengths`, `input`, `positions`, `want`, `dynamics`.

mod dynamics;
mod input;
mod lengths;
mod links;
mod numbers;
mod positions;
mod reader;
mod sheet;
mod sliders;
mod want;

use crate::error::{Error, Result};
use crate::json::parse_strict;
use kurbo::Point;
use numbers::locate_bad_numbers;
use reader::Reader;

pub use dynamics::{
    DynamicsSpec, ForceSpec, ForceTable, LinkMass, MAX_MOVING_LINKS, MomentSpec, PerPosition,
};

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

/// What the main title block says (the scene's `sheet` object); every
/// field optional, an absent one left blank on the sheet.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SheetInfo {
    /// The document's designation (ГОСТ 2.104 field 2), e.g. "ТММ.КП.01.00.001".
    pub designation: Option<String>,
    /// The name of the drawing (field 1); else the scene's title.
    pub title: Option<String>,
    /// Who drew it ("Разраб.").
    pub author: Option<String>,
    /// Who checked it ("Пров.").
    pub checker: Option<String>,
    /// The organisation, group (field 9).
    pub organisation: Option<String>,
    /// The scale field (6); else a dash, the figures stating their μ.
    pub scale: Option<String>,
}

/// Which positions' plans the course sheet shows (`want.plans_at`, from
/// 1); `None`: the default.
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
    pub title: String,
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
    /// Angle unit of the file (rad per unit).
    pub angle_unit: f64,
    /// The rounding of each listed input value as the file writes it (rad
    /// or m; one value per input for the single `input` position, none for
    /// `count`; with several inputs position after position, one value per
    /// input):
    /// a few units of it move the input in the data check, as the data's
    /// own rounding does (an angle of a million turns in radians is known
    /// only to about 1e-9 rad).
    pub input_rounding: Vec<f64>,
    /// Masses and external loads for the force analysis (`dynamics`);
    /// `None`: kinematics only.
    pub dynamics: Option<DynamicsSpec>,
}

/// Unit roundoff of f64: half an ulp, relative.
const U: f64 = f64::EPSILON / 2.0;

/// Upper limits that keep a hostile file from exhausting the machine.
pub const MAX_FILE_BYTES: usize = 4 << 20;
pub const MAX_POINTS: usize = 10_000;
pub const MAX_LINKS: usize = 5_000;
pub const MAX_POSITIONS: usize = 100_000;
/// Largest magnitude of any number: accelerations square velocities, so
/// larger inputs would overflow to infinity.
pub const MAX_MAGNITUDE: f64 = 1e100;

/// The most inputs a scene may have.
pub const MAX_INPUTS: usize = 8;

impl Scene {
    /// Every input, in the order `input` lists them.
    pub fn inputs(&self) -> impl Iterator<Item = &InputSpec> {
        std::iter::once(&self.input).chain(&self.more_inputs)
    }
    /// Input `i` (0: the first).
    pub fn input_at(&self, i: usize) -> &InputSpec {
        if i == 0 {
            &self.input
        } else {
            &self.more_inputs[i - 1]
        }
    }
    /// How many inputs the scene has.
    pub fn input_count(&self) -> usize {
        1 + self.more_inputs.len()
    }
    /// Does the scene have several inputs?
    pub fn several_inputs(&self) -> bool {
        !self.more_inputs.is_empty()
    }
    pub fn point_index(&self, name: &str) -> Option<usize> {
        self.points.iter().position(|p| p.name == name)
    }
    pub fn link_index(&self, id: &str) -> Option<usize> {
        self.links.iter().position(|l| l.id == id)
    }
    /// Links (indices) that list point `p`, in scene order.
    pub fn links_of_point(&self, p: usize) -> Vec<usize> {
        (0..self.links.len())
            .filter(|&l| self.links[l].points.contains(&p))
            .collect()
    }

    /// Read a scene from JSON text.
    pub fn from_json(text: &str) -> Result<Scene> {
        if text.len() > MAX_FILE_BYTES {
            return Err(Error::scene(
                "",
                format!(
                    "the file has {} bytes; a scene may have at most {MAX_FILE_BYTES}",
                    text.len()
                ),
            ));
        }
        let value = parse_strict(text.strip_prefix('\u{feff}').unwrap_or(text))
            .map_err(|e| Error::json(locate_bad_numbers(text).unwrap_or(e)))?;
        let mut r = Reader::default();
        let scene = r.scene(&value);
        match scene {
            Some(s) if r.issues.is_empty() => Ok(s),
            _ => Err(Error::fields(r.issues)),
        }
    }
}
