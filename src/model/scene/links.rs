//! The named points of the sketch and the links that list them.

use super::reader::{Reader, ptr};
use super::{LinkSpec, MAX_LINKS, MAX_POINTS, NamedPoint};
use kurbo::Point;
use serde_json::Value;

impl Reader {
    pub(super) fn points(&mut self, v: Option<&Value>) -> Vec<NamedPoint> {
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

    pub(super) fn links(&mut self, v: Option<&Value>, points: &[NamedPoint]) -> Vec<LinkSpec> {
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

    pub(super) fn orphans(&mut self, points: &[NamedPoint], links: &[LinkSpec]) {
        for (i, p) in points.iter().enumerate() {
            if !links.iter().any(|l| l.points.contains(&i)) {
                self.err(
                    ptr("/points", &p.name),
                    format!("point \"{}\" belongs to no link", p.name),
                );
            }
        }
    }
}
