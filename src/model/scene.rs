//! The scene file (contract: `shared/spec/scene-format.md`, extensions in
//! `docs/scene-format.md`): reading and validating it completely, every
//! problem reported with its JSON pointer. All numbers are converted to SI
//! (m, rad) here, so nothing downstream knows about units.

use crate::error::{Error, Issue, Result};
use crate::json::{escape, parse_strict};
use kurbo::Point;
use serde_json::{Map, Value};

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

/// The driving link and its motion.
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
    /// (rate, rate of rate): (ω, ε) or (v, a).
    pub fn rates(&self) -> (f64, f64) {
        match self {
            InputSpec::Crank { omega, epsilon, .. } => (*omega, *epsilon),
            InputSpec::Slider { v, a, .. } => (*v, *a),
        }
    }
}

#[derive(Clone, Debug)]
pub enum PositionsSpec {
    /// The single input value of `input`.
    Single,
    /// Explicit input values (rad for a crank, m for a slider).
    List(Vec<f64>),
    /// Equal steps over a revolution from the extreme position of `output`.
    Count { count: usize, output: Option<usize> },
}

#[derive(Clone, Debug, Default)]
pub struct Scales {
    pub mu_l: Option<f64>,
    pub mu_v: Option<f64>,
    pub mu_a: Option<f64>,
}

#[derive(Clone, Debug)]
pub struct Want {
    pub velocity: bool,
    pub acceleration: bool,
    /// `None`: every point.
    pub points: Option<Vec<usize>>,
    pub drawings: Vec<String>,
    pub scales: Scales,
    pub lang: String,
}

impl Default for Want {
    fn default() -> Self {
        Want {
            velocity: true,
            acceleration: true,
            points: None,
            drawings: Vec::new(),
            scales: Scales::default(),
            lang: "en".into(),
        }
    }
}

#[derive(Clone, Debug)]
pub struct Scene {
    pub title: String,
    pub points: Vec<NamedPoint>,
    pub links: Vec<LinkSpec>,
    /// Index of link "0".
    pub frame: usize,
    pub sliders: Vec<SliderSpec>,
    pub lengths: Vec<LengthSpec>,
    pub input: InputSpec,
    pub positions: PositionsSpec,
    pub want: Want,
    /// Length unit of the file (m per unit), to echo inputs in their units.
    pub length_unit: f64,
    /// Angle unit of the file (rad per unit).
    pub angle_unit: f64,
    /// The rounding of each listed input value as the file writes it (rad
    /// or m; one value for the single `input` position, none for `count`):
    /// a few units of it move the input in the data check, as the data's
    /// own rounding does (an angle of a million turns in radians is known
    /// only to about 1e-9 rad).
    pub input_rounding: Vec<f64>,
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

impl Scene {
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
            .map_err(|e| Error::Json(locate_bad_numbers(text).unwrap_or(e)))?;
        let mut r = Reader::default();
        let scene = r.scene(&value);
        match scene {
            Some(s) if r.issues.is_empty() => Ok(s),
            _ => Err(Error::Scene(r.issues)),
        }
    }

    /// Read a scene file from disk.
    pub fn from_path(path: &std::path::Path) -> Result<Scene> {
        let text = std::fs::read_to_string(path).map_err(|source| Error::Io {
            path: path.display().to_string(),
            source,
        })?;
        Scene::from_json(&text)
    }
}

/// Accumulates issues while reading; every getter returns `None` after
/// recording what is wrong, so reading goes on and reports everything.
#[derive(Default)]
struct Reader {
    issues: Vec<Issue>,
    len: f64,
    ang: f64,
    /// [`Scene::input_rounding`], as the positions are read.
    rounding: Vec<f64>,
}

fn ptr(base: &str, key: &str) -> String {
    format!("{base}/{}", escape(key))
}

impl Reader {
    fn err(&mut self, pointer: impl Into<String>, message: impl Into<String>) {
        self.issues.push(Issue {
            pointer: pointer.into(),
            message: message.into(),
        });
    }

    fn object<'a>(&mut self, v: &'a Value, at: &str) -> Option<&'a Map<String, Value>> {
        let o = v.as_object();
        if o.is_none() {
            self.err(at, "expected an object");
        }
        o
    }

    fn only_keys(&mut self, o: &Map<String, Value>, at: &str, allowed: &[&str]) {
        for k in o.keys() {
            if !allowed.contains(&k.as_str()) {
                self.err(
                    ptr(at, k),
                    format!(
                        "unknown field \"{k}\" (allowed here: {})",
                        allowed.join(", ")
                    ),
                );
            }
        }
    }

    fn number(&mut self, v: &Value, at: &str) -> Option<f64> {
        match v.as_f64() {
            Some(x) if x.is_finite() && x.abs() <= MAX_MAGNITUDE => Some(x),
            Some(x) if x.is_finite() => {
                self.err(at, format!("{x:e} is too large (|x| ≤ {MAX_MAGNITUDE:e}): its square would not be a finite number"));
                None
            }
            Some(_) => {
                self.err(at, "non-finite number");
                None
            }
            None => {
                self.err(at, format!("expected a number, found {}", kind(v)));
                None
            }
        }
    }

    fn string<'a>(&mut self, v: &'a Value, at: &str) -> Option<&'a str> {
        let s = v.as_str();
        if s.is_none() {
            self.err(at, format!("expected a string, found {}", kind(v)));
        }
        s
    }

    /// A link id may be written as a string ("2") or an integer (2).
    fn link_ref(&mut self, v: &Value, at: &str, links: &[LinkSpec]) -> Option<usize> {
        let id = match v {
            Value::String(s) => s.clone(),
            Value::Number(n) if n.is_u64() => n.to_string(),
            _ => {
                self.err(at, format!("expected a link id, found {}", kind(v)));
                return None;
            }
        };
        let i = links.iter().position(|l| l.id == id);
        if i.is_none() {
            self.err(at, format!("unknown link \"{id}\""));
        }
        i
    }

    fn point_ref(&mut self, v: &Value, at: &str, points: &[NamedPoint]) -> Option<usize> {
        let name = self.string(v, at)?;
        let i = points.iter().position(|p| p.name == name);
        if i.is_none() {
            self.err(at, format!("unknown point \"{name}\""));
        }
        i
    }

    fn coords(&mut self, v: &Value, at: &str) -> Option<Point> {
        match v.as_array() {
            Some(a) if a.len() == 2 => {
                let x = self.number(&a[0], &format!("{at}/0"));
                let y = self.number(&a[1], &format!("{at}/1"));
                Some(Point::new(x? * self.len, y? * self.len))
            }
            _ => {
                self.err(at, "expected coordinates [x, y]");
                None
            }
        }
    }

    fn scene(&mut self, v: &Value) -> Option<Scene> {
        let top = self.object(v, "")?;
        self.only_keys(
            top,
            "",
            &[
                "mechplan",
                "title",
                "source",
                "notes",
                "units",
                "points",
                "links",
                "sliders",
                "lengths",
                "input",
                "positions",
                "want",
            ],
        );
        match top.get("mechplan") {
            None => self.err("/mechplan", "missing: the format version, 1"),
            Some(v) if v.as_u64() == Some(1) => {}
            Some(v) => self.err(
                "/mechplan",
                format!("unsupported format version {v}; this mechplan reads version 1"),
            ),
        }
        let title = match top.get("title") {
            Some(t) => self.string(t, "/title").unwrap_or("").to_owned(),
            None => String::new(),
        };
        for k in ["source", "notes"] {
            if let Some(t) = top.get(k) {
                self.string(t, &format!("/{k}"));
            }
        }
        self.units(top.get("units"));
        let points = self.points(top.get("points"));
        let links = self.links(top.get("links"), &points);
        let frame = links.iter().position(|l| l.id == "0");
        if frame.is_none() && top.get("links").is_some_and(|l| l.is_object()) {
            self.err("/links", "the frame, link \"0\", is missing");
        }
        self.orphans(&points, &links);
        let sliders = self.sliders(top.get("sliders"), &points, &links, frame);
        let lengths = self.lengths(top.get("lengths"), &points, &links);
        let input = self.input(top.get("input"), &points, &links, &sliders, frame);
        let positions = self.positions(top.get("positions"), &links, input.as_ref());
        let want = self.want(top.get("want"), &points);
        Some(Scene {
            title,
            points,
            links,
            frame: frame?,
            sliders,
            lengths,
            input: input?,
            positions: positions?,
            want: want?,
            length_unit: self.len,
            angle_unit: self.ang,
            input_rounding: std::mem::take(&mut self.rounding),
        })
    }

    /// An angle of the file in radians, reduced once, exactly, in the unit
    /// it was written in (whole turns off: `x % 360` is exact in degrees),
    /// before any route sees it: 1e6 turns plus 30° is 30°, for both.
    fn angle(&self, x: f64) -> f64 {
        if self.ang == 1.0 {
            x % std::f64::consts::TAU
        } else {
            (x % 360.0) * self.ang
        }
    }

    /// The rounding of an angle written `x` in the file's unit, in rad:
    /// the decimal's own (half an ulp of what is written: of all its turns
    /// in radians, of the reduced angle in degrees, whose reduction is
    /// exact), and the conversion's.
    fn angle_rounding(&self, x: f64) -> f64 {
        let written = if self.ang == 1.0 { x } else { x % 360.0 };
        2.0 * U * written.abs() * self.ang + U * self.angle(x).abs()
    }

    fn units(&mut self, v: Option<&Value>) {
        self.len = 1.0;
        self.ang = std::f64::consts::PI / 180.0;
        let Some(v) = v else { return };
        let Some(o) = self.object(v, "/units") else {
            return;
        };
        self.only_keys(o, "/units", &["length", "angle"]);
        if let Some(l) = o.get("length") {
            match l.as_str() {
                Some("m") => self.len = 1.0,
                Some("mm") => self.len = 1e-3,
                _ => self.err("/units/length", "expected \"m\" or \"mm\""),
            }
        }
        if let Some(a) = o.get("angle") {
            match a.as_str() {
                Some("deg") => {}
                Some("rad") => self.ang = 1.0,
                _ => self.err("/units/angle", "expected \"deg\" or \"rad\""),
            }
        }
    }

    fn points(&mut self, v: Option<&Value>) -> Vec<NamedPoint> {
        let mut out = Vec::new();
        let Some(v) = v else {
            self.err("/points", "missing: the named points of the sketch");
            return out;
        };
        let Some(o) = self.object(v, "/points") else {
            return out;
        };
        if o.len() > MAX_POINTS {
            self.err(
                "/points",
                format!("{} points; at most {MAX_POINTS}", o.len()),
            );
            return out;
        }
        for (name, c) in o {
            let at = ptr("/points", name);
            if name.is_empty()
                || !name
                    .chars()
                    .all(|ch| ch.is_ascii_alphanumeric() || ch == '_')
            {
                self.err(
                    &at,
                    format!("bad point name \"{name}\": use letters, digits and _"),
                );
            }
            if let Some(p) = self.coords(c, &at) {
                out.push(NamedPoint {
                    name: name.clone(),
                    sketch: p,
                });
            } else {
                // Keep the name so later references to it do not cascade.
                out.push(NamedPoint {
                    name: name.clone(),
                    sketch: Point::new(f64::NAN, f64::NAN),
                });
            }
        }
        if out.is_empty() {
            self.err("/points", "no points");
        }
        out
    }

    fn links(&mut self, v: Option<&Value>, points: &[NamedPoint]) -> Vec<LinkSpec> {
        let mut out = Vec::new();
        let Some(v) = v else {
            self.err("/links", "missing: the links and their points");
            return out;
        };
        let Some(o) = self.object(v, "/links") else {
            return out;
        };
        if o.len() > MAX_LINKS {
            self.err("/links", format!("{} links; at most {MAX_LINKS}", o.len()));
            return out;
        }
        for (id, l) in o {
            let at = ptr("/links", id);
            let mut spec = LinkSpec {
                id: id.clone(),
                name: None,
                points: Vec::new(),
            };
            if let Some(lo) = self.object(l, &at) {
                self.only_keys(lo, &at, &["points", "name"]);
                if let Some(n) = lo.get("name") {
                    spec.name = self.string(n, &format!("{at}/name")).map(str::to_owned);
                }
                match lo.get("points").and_then(Value::as_array) {
                    None => self.err(format!("{at}/points"), "missing: a list of point names"),
                    Some(a) if a.is_empty() => {
                        self.err(format!("{at}/points"), "a link needs at least one point")
                    }
                    Some(a) => {
                        for (k, p) in a.iter().enumerate() {
                            let pat = format!("{at}/points/{k}");
                            if let Some(i) = self.point_ref(p, &pat, points) {
                                if spec.points.contains(&i) {
                                    self.err(
                                        pat,
                                        format!("point \"{}\" is listed twice", points[i].name),
                                    );
                                } else {
                                    spec.points.push(i);
                                }
                            }
                        }
                    }
                }
            }
            out.push(spec);
        }
        out
    }

    fn orphans(&mut self, points: &[NamedPoint], links: &[LinkSpec]) {
        for (i, p) in points.iter().enumerate() {
            if !links.iter().any(|l| l.points.contains(&i)) {
                self.err(
                    ptr("/points", &p.name),
                    format!("point \"{}\" belongs to no link", p.name),
                );
            }
        }
    }

    fn sliders(
        &mut self,
        v: Option<&Value>,
        points: &[NamedPoint],
        links: &[LinkSpec],
        frame: Option<usize>,
    ) -> Vec<SliderSpec> {
        let mut out = Vec::new();
        let Some(v) = v else { return out };
        let Some(a) = v.as_array() else {
            self.err("/sliders", "expected a list of prismatic pairs");
            return out;
        };
        for (k, s) in a.iter().enumerate() {
            let at = format!("/sliders/{k}");
            let Some(o) = self.object(s, &at) else {
                continue;
            };
            self.only_keys(o, &at, &["slider", "guide", "point", "line"]);
            let get = |r: &mut Self, key: &str| {
                let g = o.get(key);
                if g.is_none() {
                    r.err(format!("{at}/{key}"), "missing");
                }
                g
            };
            let slider =
                get(self, "slider").and_then(|x| self.link_ref(x, &format!("{at}/slider"), links));
            let guide =
                get(self, "guide").and_then(|x| self.link_ref(x, &format!("{at}/guide"), links));
            let point =
                get(self, "point").and_then(|x| self.point_ref(x, &format!("{at}/point"), points));
            if let (Some(s), Some(g)) = (slider, guide)
                && s == g
            {
                self.err(format!("{at}/guide"), "a link cannot slide on itself");
            }
            if let (Some(s), Some(p)) = (slider, point)
                && !links[s].points.contains(&p)
            {
                self.err(
                    format!("{at}/point"),
                    format!(
                        "point \"{}\" is not a point of the slider, link \"{}\"",
                        points[p].name, links[s].id
                    ),
                );
            }
            let line = get(self, "line").and_then(|l| {
                self.guide_line(l, &format!("{at}/line"), points, links, guide, frame)
            });
            if let (Some(slider), Some(guide), Some(point), Some(line)) =
                (slider, guide, point, line)
            {
                out.push(SliderSpec {
                    slider,
                    guide,
                    point,
                    line,
                });
            }
        }
        out
    }

    fn guide_line(
        &mut self,
        v: &Value,
        at: &str,
        points: &[NamedPoint],
        links: &[LinkSpec],
        guide: Option<usize>,
        frame: Option<usize>,
    ) -> Option<GuideLine> {
        let o = self.object(v, at)?;
        self.only_keys(o, at, &["through", "angle", "along", "offset"]);
        let on_guide = |r: &mut Self, p: usize, pat: String| {
            if let Some(g) = guide
                && !links[g].points.contains(&p)
            {
                r.err(
                    pat,
                    format!(
                        "point \"{}\" is not a point of the guide, link \"{}\"",
                        points[p].name, links[g].id
                    ),
                );
            }
        };
        let through = match o.get("through") {
            None => {
                self.err(
                    format!("{at}/through"),
                    "missing: a point of the guide link, or coordinates on the frame",
                );
                None
            }
            Some(Value::String(_)) => {
                let p = self.point_ref(&o["through"], &format!("{at}/through"), points);
                if let Some(p) = p {
                    on_guide(self, p, format!("{at}/through"));
                }
                p.map(Through::Point)
            }
            Some(c) => {
                if guide.is_some() && guide != frame {
                    self.err(
                        format!("{at}/through"),
                        "coordinates are allowed only for a guide on the frame; name a point of the guide link",
                    );
                }
                self.coords(c, &format!("{at}/through"))
                    .map(Through::Coords)
            }
        };
        let direction = match (o.get("angle"), o.get("along")) {
            (Some(a), None) => self
                .number(a, &format!("{at}/angle"))
                .map(|x| Direction::Angle(self.angle(x))),
            (None, Some(al)) => {
                let pat = format!("{at}/along");
                match al.as_array() {
                    Some(a) if a.len() == 2 => {
                        let q = self.point_ref(&a[0], &format!("{pat}/0"), points);
                        let r = self.point_ref(&a[1], &format!("{pat}/1"), points);
                        if let Some(q) = q {
                            on_guide(self, q, format!("{pat}/0"));
                        }
                        if let Some(r) = r {
                            on_guide(self, r, format!("{pat}/1"));
                        }
                        match (q, r) {
                            (Some(q), Some(r)) if q == r => {
                                self.err(pat, "two different points are needed");
                                None
                            }
                            (Some(q), Some(r)) => Some(Direction::Along(q, r)),
                            _ => None,
                        }
                    }
                    _ => {
                        self.err(pat, "expected two point names [Q, R]");
                        None
                    }
                }
            }
            (Some(_), Some(_)) => {
                self.err(
                    at.to_string(),
                    "give either \"angle\" or \"along\", not both",
                );
                None
            }
            (None, None) => {
                self.err(
                    at.to_string(),
                    "missing: the direction, \"angle\" or \"along\"",
                );
                None
            }
        };
        let offset = match o.get("offset") {
            Some(x) => self
                .number(x, &format!("{at}/offset"))
                .map(|x| x * self.len),
            None => Some(0.0),
        };
        Some(GuideLine {
            through: through?,
            direction: direction?,
            offset: offset?,
        })
    }

    fn lengths(
        &mut self,
        v: Option<&Value>,
        points: &[NamedPoint],
        links: &[LinkSpec],
    ) -> Vec<LengthSpec> {
        let mut out: Vec<LengthSpec> = Vec::new();
        let Some(v) = v else { return out };
        let Some(o) = self.object(v, "/lengths") else {
            return out;
        };
        for (key, val) in o {
            let at = ptr("/lengths", key);
            let names: Vec<&str> = key.split('-').collect();
            let value = self.number(val, &at);
            if names.len() != 2 {
                self.err(&at, "expected a key \"P-Q\" naming two points");
                continue;
            }
            let find = |n: &str| points.iter().position(|p| p.name == n);
            let (a, b) = match (find(names[0]), find(names[1])) {
                (Some(a), Some(b)) => (a, b),
                (pa, pb) => {
                    for (n, p) in names.iter().zip([pa, pb]) {
                        if p.is_none() {
                            self.err(&at, format!("unknown point \"{n}\""));
                        }
                    }
                    continue;
                }
            };
            if a == b {
                self.err(&at, "the two points are the same");
                continue;
            }
            if !links
                .iter()
                .any(|l| l.points.contains(&a) && l.points.contains(&b))
            {
                self.err(
                    &at,
                    format!("points \"{}\" and \"{}\" share no link", names[0], names[1]),
                );
                continue;
            }
            if out
                .iter()
                .any(|l| (l.a == a && l.b == b) || (l.a == b && l.b == a))
            {
                self.err(
                    &at,
                    "this distance is already given (keys \"P-Q\" and \"Q-P\" are the same)",
                );
                continue;
            }
            let Some(value) = value else { continue };
            if value <= 0.0 {
                self.err(&at, format!("a length must be positive, found {value}"));
                continue;
            }
            out.push(LengthSpec {
                key: key.clone(),
                a,
                b,
                value: value * self.len,
            });
        }
        out
    }

    fn input(
        &mut self,
        v: Option<&Value>,
        points: &[NamedPoint],
        links: &[LinkSpec],
        sliders: &[SliderSpec],
        frame: Option<usize>,
    ) -> Option<InputSpec> {
        let Some(v) = v else {
            self.err("/input", "missing: the driving link and its motion");
            return None;
        };
        let o = self.object(v, "/input")?;
        let is_slider = match o.get("slider") {
            None => false,
            Some(Value::Bool(b)) => *b,
            Some(x) => {
                self.err(
                    "/input/slider",
                    format!("expected true or false, found {}", kind(x)),
                );
                return None;
            }
        };
        let link = match o.get("link") {
            Some(l) => self.link_ref(l, "/input/link", links),
            None => {
                self.err("/input/link", "missing: the id of the driving link");
                None
            }
        };
        if link.is_some() && link == frame {
            self.err("/input/link", "the frame cannot be the driving link");
            return None;
        }
        let opt = |r: &mut Self, key: &str, default: Option<f64>| -> Option<f64> {
            match o.get(key) {
                Some(x) => r.number(x, &format!("/input/{key}")),
                None => {
                    if default.is_none() {
                        r.err(format!("/input/{key}"), "missing");
                    }
                    default
                }
            }
        };
        if is_slider {
            self.only_keys(o, "/input", &["link", "slider", "s", "v", "a"]);
            let s = opt(self, "s", Some(0.0)).map(|x| x * self.len);
            self.rounding = s.map(|x| vec![2.0 * U * x.abs()]).unwrap_or_default();
            let vv = opt(self, "v", None).map(|x| x * self.len);
            let a = opt(self, "a", Some(0.0)).map(|x| x * self.len);
            let link = link?;
            let pair = sliders
                .iter()
                .position(|s| s.slider == link && Some(s.guide) == frame);
            if pair.is_none() {
                self.err(
                    "/input/link",
                    format!(
                        "a driving slider must slide on a guide of the frame; link \"{}\" has no such entry in /sliders",
                        links[link].id
                    ),
                );
            }
            return Some(InputSpec::Slider {
                link,
                pair: pair?,
                s: s?,
                v: vv?,
                a: a?,
            });
        }
        self.only_keys(
            o,
            "/input",
            &[
                "link", "slider", "pivot", "angle", "omega", "rpm", "epsilon",
            ],
        );
        let pivot = match o.get("pivot") {
            Some(p) => self.point_ref(p, "/input/pivot", points),
            None => {
                self.err(
                    "/input/pivot",
                    "missing: the frame point the crank turns about",
                );
                None
            }
        };
        let raw = opt(self, "angle", None);
        self.rounding = raw
            .map(|x| vec![self.angle_rounding(x)])
            .unwrap_or_default();
        let angle = raw.map(|x| self.angle(x));
        let omega = match (o.get("omega"), o.get("rpm")) {
            (Some(w), None) => self.number(w, "/input/omega"),
            (None, Some(n)) => self
                .number(n, "/input/rpm")
                .map(|n| n * std::f64::consts::TAU / 60.0),
            (Some(_), Some(_)) => {
                self.err("/input", "give either \"omega\" or \"rpm\", not both");
                None
            }
            (None, None) => {
                self.err(
                    "/input/omega",
                    "missing: the crank's angular velocity (omega, rad/s, or rpm)",
                );
                None
            }
        };
        let epsilon = opt(self, "epsilon", Some(0.0));
        let (link, pivot) = (link?, pivot?);
        if let Some(f) = frame
            && !links[f].points.contains(&pivot)
        {
            self.err(
                "/input/pivot",
                format!(
                    "pivot \"{}\" is not a point of the frame",
                    points[pivot].name
                ),
            );
        }
        let base = &links[link].points;
        if base.len() < 2 || !base[..2].contains(&pivot) {
            self.err(
                "/input/pivot",
                format!(
                    "a crank's first two points must be its pivot \"{}\" and the point whose ray gives the angle; link \"{}\" lists {:?}",
                    points[pivot].name,
                    links[link].id,
                    base.iter().map(|&p| points[p].name.as_str()).collect::<Vec<_>>()
                ),
            );
        }
        Some(InputSpec::Crank {
            link,
            pivot,
            angle: angle?,
            omega: omega?,
            epsilon: epsilon?,
        })
    }

    fn positions(
        &mut self,
        v: Option<&Value>,
        links: &[LinkSpec],
        input: Option<&InputSpec>,
    ) -> Option<PositionsSpec> {
        let Some(v) = v else {
            return Some(PositionsSpec::Single);
        };
        let o = self.object(v, "/positions")?;
        self.only_keys(o, "/positions", &["angles", "s", "count", "output"]);
        let crank = matches!(input, Some(InputSpec::Crank { .. }));
        let slider = matches!(input, Some(InputSpec::Slider { .. }));
        let list = |r: &mut Self, key: &str, unit: f64| -> Option<Vec<f64>> {
            let at = format!("/positions/{key}");
            let a = o[key].as_array();
            match a {
                Some(a) if !a.is_empty() && a.len() <= MAX_POSITIONS => {
                    let mut out = Vec::new();
                    for (k, x) in a.iter().enumerate() {
                        out.push(r.number(x, &format!("{at}/{k}"))? * unit);
                    }
                    Some(out)
                }
                Some(a) if a.len() > MAX_POSITIONS => {
                    r.err(
                        at,
                        format!("{} positions; at most {MAX_POSITIONS}", a.len()),
                    );
                    None
                }
                _ => {
                    r.err(at, "expected a non-empty list of numbers");
                    None
                }
            }
        };
        let n = ["angles", "s", "count"]
            .iter()
            .filter(|k| o.contains_key(**k))
            .count();
        if n != 1 {
            self.err(
                "/positions",
                "give exactly one of \"angles\", \"s\" or \"count\"",
            );
            return None;
        }
        if o.contains_key("angles") {
            if slider {
                self.err(
                    "/positions/angles",
                    "the input is a slider: give \"s\", not \"angles\"",
                );
                return None;
            }
            return list(self, "angles", 1.0).map(|v| {
                self.rounding = v.iter().map(|&x| self.angle_rounding(x)).collect();
                PositionsSpec::List(v.into_iter().map(|x| self.angle(x)).collect())
            });
        }
        if o.contains_key("s") {
            if crank {
                self.err(
                    "/positions/s",
                    "the input is a crank: give \"angles\", not \"s\"",
                );
                return None;
            }
            return list(self, "s", self.len).map(|v| {
                self.rounding = v.iter().map(|&x| 2.0 * U * x.abs()).collect();
                PositionsSpec::List(v)
            });
        }
        let count = match o["count"].as_u64() {
            Some(c) if (1..=MAX_POSITIONS as u64).contains(&c) => c as usize,
            _ => {
                self.err(
                    "/positions/count",
                    format!("expected a whole number from 1 to {MAX_POSITIONS}"),
                );
                return None;
            }
        };
        if slider {
            self.err(
                "/positions/count",
                "equal steps over a revolution need a crank input; give \"s\" for a driving slider",
            );
            return None;
        }
        let output = match o.get("output") {
            Some(x) => {
                let l = self.link_ref(x, "/positions/output", links)?;
                if links[l].id == "0" {
                    self.err(
                        "/positions/output",
                        "the frame does not move: name a moving link",
                    );
                    return None;
                }
                Some(l)
            }
            None => None,
        };
        self.rounding.clear();
        Some(PositionsSpec::Count { count, output })
    }

    fn want(&mut self, v: Option<&Value>, points: &[NamedPoint]) -> Option<Want> {
        let mut w = Want::default();
        let Some(v) = v else { return Some(w) };
        let o = self.object(v, "/want")?;
        self.only_keys(
            o,
            "/want",
            &["plans", "points", "drawings", "scales", "lang"],
        );
        let names = |r: &mut Self, key: &str, allowed: &[&str]| -> Vec<String> {
            let at = format!("/want/{key}");
            let mut out = Vec::new();
            match o[key].as_array() {
                Some(a) => {
                    for (k, x) in a.iter().enumerate() {
                        match x.as_str() {
                            Some(s) if allowed.is_empty() || allowed.contains(&s) => {
                                out.push(s.to_owned())
                            }
                            _ => r.err(
                                format!("{at}/{k}"),
                                format!("expected one of {}", allowed.join(", ")),
                            ),
                        }
                    }
                }
                None => r.err(at, "expected a list"),
            }
            out
        };
        if o.contains_key("plans") {
            let p = names(self, "plans", &["velocity", "acceleration"]);
            w.velocity = p.iter().any(|x| x == "velocity");
            w.acceleration = p.iter().any(|x| x == "acceleration");
        }
        if o.contains_key("drawings") {
            w.drawings = names(
                self,
                "drawings",
                &[
                    "mechanism",
                    "velocity",
                    "acceleration",
                    "positions",
                    "diagrams",
                ],
            );
        }
        if let Some(pv) = o.get("points") {
            let mut out = Vec::new();
            match pv.as_array() {
                Some(a) => {
                    for (k, x) in a.iter().enumerate() {
                        if let Some(i) = self.point_ref(x, &format!("/want/points/{k}"), points)
                            && !out.contains(&i)
                        {
                            out.push(i);
                        }
                    }
                }
                None => self.err("/want/points", "expected a list of point names"),
            }
            w.points = Some(out);
        }
        if let Some(s) = o.get("scales")
            && let Some(so) = self.object(s, "/want/scales")
        {
            self.only_keys(so, "/want/scales", &["mu_l", "mu_v", "mu_a"]);
            let mut get = |key: &str| -> Option<f64> {
                let x = self.number(so.get(key)?, &format!("/want/scales/{key}"))?;
                if x <= 0.0 {
                    self.err(format!("/want/scales/{key}"), "a scale must be positive");
                    return None;
                }
                Some(x)
            };
            w.scales = Scales {
                mu_l: get("mu_l"),
                mu_v: get("mu_v"),
                mu_a: get("mu_a"),
            };
        }
        if let Some(l) = o.get("lang") {
            match l.as_str() {
                Some(s @ ("en" | "uk" | "ru")) => w.lang = s.to_owned(),
                _ => self.err("/want/lang", "expected \"en\", \"uk\" or \"ru\""),
            }
        }
        Some(w)
    }
}

/// serde_json stops at `NaN`, `Infinity` or `1e999` with only a line and
/// column, but the contract names the field. Put a marker string in place of
/// each such number and read the text again: where a marker lands in the tree
/// is the field's JSON pointer. `None` when the text has no such number, more
/// than a few, or other syntax errors besides (the plain message then stands).
fn locate_bad_numbers(text: &str) -> Option<Vec<String>> {
    const MARK: &str = r"\u0001mechplan-bad-number-";
    let mut text = text.to_owned();
    let mut found = Vec::new();
    let value = loop {
        let e = match serde_json::from_str::<Value>(&text) {
            Ok(v) => break v,
            Err(e) if found.len() < 32 => e,
            Err(_) => return None,
        };
        // serde_json's column is 1-based, in bytes, and falls inside the token.
        let line_start: usize = text
            .split_inclusive('\n')
            .take(e.line().saturating_sub(1))
            .map(str::len)
            .sum();
        let at = line_start + e.column().saturating_sub(1);
        let b = text.as_bytes();
        let tok = |c: u8| c.is_ascii_alphanumeric() || matches!(c, b'+' | b'-' | b'.');
        if at >= b.len() || !tok(b[at]) {
            return None;
        }
        let start = (0..at).rev().find(|&i| !tok(b[i])).map_or(0, |i| i + 1);
        let end = (at..b.len()).find(|&i| !tok(b[i])).unwrap_or(b.len());
        let token = text[start..end].to_owned();
        if token.parse::<f64>().map_or(true, f64::is_finite) {
            return None;
        }
        text.replace_range(start..end, &format!("\"{MARK}{}\"", found.len()));
        found.push((token, e.line()));
    };
    fn walk(v: &Value, at: &str, out: &mut Vec<(usize, String)>) {
        match v {
            Value::String(s) => {
                if let Some(k) = s
                    .strip_prefix("\u{1}mechplan-bad-number-")
                    .and_then(|k| k.parse().ok())
                {
                    out.push((k, at.to_owned()));
                }
            }
            Value::Array(a) => a
                .iter()
                .enumerate()
                .for_each(|(i, x)| walk(x, &format!("{at}/{i}"), out)),
            Value::Object(o) => o.iter().for_each(|(k, x)| walk(x, &ptr(at, k), out)),
            _ => {}
        }
    }
    let mut at = Vec::new();
    walk(&value, "", &mut at);
    at.sort();
    let msgs: Vec<String> = at
        .into_iter()
        .filter_map(|(k, pointer)| {
            let (token, line) = found.get(k)?;
            Some(format!(
                "{pointer}: non-finite number {token} (line {line}); every number must be finite"
            ))
        })
        .collect();
    (!msgs.is_empty()).then_some(msgs)
}

fn kind(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "a list",
        Value::Object(_) => "an object",
    }
}
