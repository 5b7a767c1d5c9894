//! The driving link and its motion: a crank or a driving slider.

use super::reader::{Reader, kind};
use super::{InputSpec, LinkSpec, NamedPoint, SliderSpec, U};
use serde_json::Value;

impl Reader {
    pub(super) fn input(
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
}
