//! The reader: the file's top level and units, and the getters every
//! section uses (objects, allowed keys, strings, references to points and
//! links, coordinates).

use crate::lang::Lang;
use super::{LinkSpec, NamedPoint, Numbering, PositionsSpec, Scene};
use crate::error::Issue;
use crate::json::escape;
use kurbo::Point;
use serde_json::{Map, Value};

/// Accumulates issues while reading; every getter returns `None` after
/// recording what is wrong, so reading goes on and reports everything.
#[derive(Default)]
pub(super) struct Reader {
    pub(super) issues: Vec<Issue>,
    pub(super) len: f64,
    /// Whether `units.length` is written.
    pub(super) len_stated: bool,
    pub(super) ang: f64,
    /// [`Scene::input_rounding`], as the positions are read.
    pub(super) rounding: Vec<f64>,
}

pub(super) fn ptr(base: &str, key: &str) -> String {
    format!("{base}/{}", escape(key))
}

impl Reader {
    pub(super) fn err(&mut self, pointer: impl Into<String>, message: impl Into<String>) {
        self.issues.push(Issue {
            pointer: pointer.into(),
            message: message.into(),
        });
    }

    pub(super) fn object<'a>(&mut self, v: &'a Value, at: &str) -> Option<&'a Map<String, Value>> {
        let o = v.as_object();
        if o.is_none() {
            self.err(at, "expected an object");
        }
        o
    }

    pub(super) fn only_keys(&mut self, o: &Map<String, Value>, at: &str, allowed: &[&str]) {
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

    pub(super) fn string<'a>(&mut self, v: &'a Value, at: &str) -> Option<&'a str> {
        let s = v.as_str();
        if s.is_none() {
            self.err(at, format!("expected a string, found {}", kind(v)));
        }
        s
    }

    /// A text in one language (a string) or in several (`{ "en": "…",
    /// "uk": "…", "ru": "…" }`, at least one): the default (English, else
    /// the first given of uk, ru) and every language's own.
    pub(super) fn localised(&mut self, v: &Value, at: &str) -> Option<(String, Vec<(Lang, String)>)> {
        let Some(o) = v.as_object() else {
            return self.string(v, at).map(|s| (s.to_owned(), Vec::new()));
        };
        let mut by = Vec::new();
        for (k, t) in o {
            let at = format!("{at}/{k}");
            let Some(l) = Lang::parse(k) else {
                self.err(at, "expected a language code: en, uk or ru");
                continue;
            };
            if let Some(t) = self.string(t, &at) {
                by.push((l, t.to_owned()));
            }
        }
        if o.is_empty() {
            self.err(
                at,
                format!(
                    "expected a string or an object of texts by language ({}), found an empty object",
                    Lang::codes()
                ),
            );
            return None;
        }
        let default = Lang::ALL
            .iter()
            .find_map(|l| by.iter().find(|(m, _)| m == l))
            .map(|(_, t)| t.clone())?;
        Some((default, by))
    }

    /// A link id may be written as a string ("2") or an integer (2).
    pub(super) fn link_ref(&mut self, v: &Value, at: &str, links: &[LinkSpec]) -> Option<usize> {
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

    pub(super) fn point_ref(
        &mut self,
        v: &Value,
        at: &str,
        points: &[NamedPoint],
    ) -> Option<usize> {
        let name = self.string(v, at)?;
        let i = points.iter().position(|p| p.name == name);
        if i.is_none() {
            self.err(at, format!("unknown point \"{name}\""));
        }
        i
    }

    pub(super) fn coords(&mut self, v: &Value, at: &str) -> Option<Point> {
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

    pub(super) fn scene(&mut self, v: &Value) -> Option<Scene> {
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
                "sheet",
                "dynamics",
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
        let (title, titles) = match top.get("title") {
            Some(t) => self.localised(t, "/title").unwrap_or_default(),
            None => Default::default(),
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
        let inputs = self.inputs(top.get("input"), &points, &links, &sliders, frame);
        let positions = self.positions(top.get("positions"), &links, inputs.as_deref());
        let mut want = self.want(top.get("want"), &points);
        let sheet = self.sheet_info(top.get("sheet"));
        let count = positions.as_ref().map(PositionsSpec::count);
        if let (Some(w), Some(n), Some(at)) = (
            want.as_mut(),
            count,
            top.get("want").and_then(|w| w.get("plans_at")),
        ) {
            let numbering = positions.as_ref().map_or(Numbering::FROM_1, |p| p.numbering());
            w.plans_at = self.plans_at(at, n, numbering);
        }
        let dynamics = self.dynamics(top.get("dynamics"), &points, &links, frame, count);
        if let (Some(w), None) = (want.as_ref(), top.get("dynamics"))
            && let Some(k) = w.drawings.iter().position(|d| d == "lever")
        {
            self.err(
                format!("/want/drawings/{k}"),
                "Zhukovsky's lever draws the loads of the force analysis: the scene needs a \"dynamics\" object",
            );
        }
        if let (Some(w), Some(_)) = (want.as_mut(), top.get("dynamics")) {
            // The inertia forces need every link's accelerations, whatever
            // `want` asks to be reported.
            w.velocity = true;
            w.acceleration = true;
        }
        Some(Scene {
            title,
            titles,
            sheet,
            points,
            links,
            frame: frame?,
            sliders,
            lengths,
            positions: positions?,
            input: inputs.as_ref()?[0].clone(),
            more_inputs: inputs?[1..].to_vec(),
            want: want?,
            dynamics,
            length_unit: self.len,
            length_stated: self.len_stated,
            angle_unit: self.ang,
            input_rounding: std::mem::take(&mut self.rounding),
        })
    }

    fn units(&mut self, v: Option<&Value>) {
        self.len = 1.0;
        self.len_stated = v.is_some_and(|v| v.get("length").is_some());
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
}

pub(super) fn kind(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "a list",
        Value::Object(_) => "an object",
    }
}
