//! Prismatic pairs and their guide lines.

use super::reader::Reader;
use super::{Direction, GuideLine, LinkSpec, NamedPoint, SliderSpec, Through};
use serde_json::Value;

impl Reader {
    pub(super) fn sliders(
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
}
