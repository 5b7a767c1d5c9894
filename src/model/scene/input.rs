//! The driving links and their motion: a crank or a driving slider (on a
//! guide of the frame, or on a moving guide: a hydraulic cylinder), one
//! input as an object or several as a list.

use super::reader::{Reader, kind};
use super::{InputSpec, LinkSpec, MAX_INPUTS, NamedPoint, SliderSpec, U};
use serde_json::{Map, Value};

impl Reader {
    /// `input`: one object, or a list of them (each as one input); the
    /// inputs in the order listed.
    pub(super) fn inputs(
        &mut self,
        v: Option<&Value>,
        points: &[NamedPoint],
        links: &[LinkSpec],
        sliders: &[SliderSpec],
        frame: Option<usize>,
    ) -> Option<Vec<InputSpec>> {
        let Some(v) = v else {
            self.err("/input", "missing: the driving link and its motion");
            return None;
        };
        let list: Vec<(String, &Value)> = match v {
            Value::Array(a) if a.is_empty() => {
                self.err("/input", "an empty list: give at least one input");
                return None;
            }
            Value::Array(a) if a.len() > MAX_INPUTS => {
                self.err(
                    "/input",
                    format!("{} inputs; at most {MAX_INPUTS}", a.len()),
                );
                return None;
            }
            Value::Array(a) => a
                .iter()
                .enumerate()
                .map(|(k, x)| (format!("/input/{k}"), x))
                .collect(),
            x => vec![("/input".to_string(), x)],
        };
        let mut out = Vec::new();
        let mut rounding = Vec::new();
        let mut failed = false;
        for (at, x) in &list {
            match self.one_input(x, at, points, links, sliders, frame) {
                Some((spec, r)) => {
                    out.push(spec);
                    rounding.push(r);
                }
                None => failed = true,
            }
        }
        // A link is driven once.
        for (i, a) in out.iter().enumerate() {
            if let Some(j) = out[..i].iter().position(|b| b.link() == a.link()) {
                self.err(
                    format!("/input/{i}/link"),
                    format!(
                        "link \"{}\" is driven by /input/{j} already: each input drives its own link",
                        links[a.link()].id
                    ),
                );
                failed = true;
            }
        }
        self.rounding = rounding;
        (!failed).then_some(out)
    }

    /// One input at `at`, and the rounding of its value as written.
    fn one_input(
        &mut self,
        v: &Value,
        at: &str,
        points: &[NamedPoint],
        links: &[LinkSpec],
        sliders: &[SliderSpec],
        frame: Option<usize>,
    ) -> Option<(InputSpec, f64)> {
        let o = self.object(v, at)?;
        let is_slider = match o.get("slider") {
            None => false,
            Some(Value::Bool(b)) => *b,
            Some(x) => {
                self.err(
                    format!("{at}/slider"),
                    format!("expected true or false, found {}", kind(x)),
                );
                return None;
            }
        };
        let link = match o.get("link") {
            Some(l) => self.link_ref(l, &format!("{at}/link"), links),
            None => {
                self.err(format!("{at}/link"), "missing: the id of the driving link");
                None
            }
        };
        if link.is_some() && link == frame {
            self.err(format!("{at}/link"), "the frame cannot be the driving link");
            return None;
        }
        if is_slider {
            return self.slider_input(o, at, link, links, sliders, frame);
        }
        self.crank_input(o, at, link, points, links, frame)
    }

    /// A number of input `o` at `at`: missing is an error unless it has a
    /// default.
    fn input_number(
        &mut self,
        o: &Map<String, Value>,
        at: &str,
        key: &str,
        default: Option<f64>,
    ) -> Option<f64> {
        match o.get(key) {
            Some(x) => self.number(x, &format!("{at}/{key}")),
            None => {
                if default.is_none() {
                    self.err(format!("{at}/{key}"), "missing");
                }
                default
            }
        }
    }

    /// A driving slider: its prismatic pair is the `sliders` entry in which
    /// its link slides (the frame's when it slides in several; a moving
    /// guide is a hydraulic cylinder).
    fn slider_input(
        &mut self,
        o: &Map<String, Value>,
        at: &str,
        link: Option<usize>,
        links: &[LinkSpec],
        sliders: &[SliderSpec],
        frame: Option<usize>,
    ) -> Option<(InputSpec, f64)> {
        self.only_keys(o, at, &["link", "slider", "s", "v", "a"]);
        let s = self
            .input_number(o, at, "s", Some(0.0))
            .map(|x| x * self.len);
        let vv = self.input_number(o, at, "v", None).map(|x| x * self.len);
        let a = self
            .input_number(o, at, "a", Some(0.0))
            .map(|x| x * self.len);
        let link = link?;
        let own: Vec<usize> = (0..sliders.len())
            .filter(|&k| sliders[k].slider == link)
            .collect();
        let on_frame = own
            .iter()
            .copied()
            .find(|&k| Some(sliders[k].guide) == frame);
        let pair = match (own.len(), on_frame) {
            (0, _) => {
                let as_guide: Vec<String> = (0..sliders.len())
                    .filter(|&k| sliders[k].guide == link)
                    .map(|k| format!("/sliders/{k} (slider \"{}\")", links[sliders[k].slider].id))
                    .collect();
                let message = if as_guide.is_empty() {
                    format!(
                        "link \"{}\" slides in no prismatic pair: a driving slider is the slider of an entry in /sliders",
                        links[link].id
                    )
                } else {
                    format!(
                        "link \"{}\" is the guide of {}, the link it would slide on is its own: a driving slider is the link that slides (the rod, not the cylinder)",
                        links[link].id,
                        as_guide.join(", ")
                    )
                };
                self.err(format!("{at}/link"), message);
                None
            }
            (1, _) => Some(own[0]),
            (_, Some(k)) => Some(k),
            (_, None) => {
                self.err(
                    format!("{at}/link"),
                    format!(
                        "link \"{}\" slides in several prismatic pairs ({}): which one is driven is not determined",
                        links[link].id,
                        own.iter()
                            .map(|k| format!("/sliders/{k}"))
                            .collect::<Vec<_>>()
                            .join(", ")
                    ),
                );
                None
            }
        };
        let (s, v, a) = (s?, vv?, a?);
        Some((
            InputSpec::Slider {
                link,
                pair: pair?,
                s,
                v,
                a,
            },
            2.0 * U * s.abs(),
        ))
    }

    /// A crank about a frame point.
    fn crank_input(
        &mut self,
        o: &Map<String, Value>,
        at: &str,
        link: Option<usize>,
        points: &[NamedPoint],
        links: &[LinkSpec],
        frame: Option<usize>,
    ) -> Option<(InputSpec, f64)> {
        self.only_keys(
            o,
            at,
            &[
                "link", "slider", "pivot", "angle", "omega", "rpm", "epsilon",
            ],
        );
        let pivot = match o.get("pivot") {
            Some(p) => self.point_ref(p, &format!("{at}/pivot"), points),
            None => {
                self.err(
                    format!("{at}/pivot"),
                    "missing: the frame point the crank turns about",
                );
                None
            }
        };
        let raw = self.input_number(o, at, "angle", None);
        let rounding = raw.map(|x| self.angle_rounding(x));
        let angle = raw.map(|x| self.angle(x));
        let omega = match (o.get("omega"), o.get("rpm")) {
            (Some(w), None) => self.number(w, &format!("{at}/omega")),
            (None, Some(n)) => self
                .number(n, &format!("{at}/rpm"))
                .map(|n| n * std::f64::consts::TAU / 60.0),
            (Some(_), Some(_)) => {
                self.err(at, "give either \"omega\" or \"rpm\", not both");
                None
            }
            (None, None) => {
                self.err(
                    format!("{at}/omega"),
                    "missing: the crank's angular velocity (omega, rad/s, or rpm)",
                );
                None
            }
        };
        let epsilon = self.input_number(o, at, "epsilon", Some(0.0));
        let (link, pivot) = (link?, pivot?);
        if let Some(f) = frame
            && !links[f].points.contains(&pivot)
        {
            self.err(
                format!("{at}/pivot"),
                format!(
                    "pivot \"{}\" is not a point of the frame",
                    points[pivot].name
                ),
            );
        }
        let base = &links[link].points;
        if base.len() < 2 || !base[..2].contains(&pivot) {
            self.err(
                format!("{at}/pivot"),
                format!(
                    "a crank's first two points must be its pivot \"{}\" and the point whose ray gives the angle; link \"{}\" lists {:?}",
                    points[pivot].name,
                    links[link].id,
                    base.iter().map(|&p| points[p].name.as_str()).collect::<Vec<_>>()
                ),
            );
        }
        Some((
            InputSpec::Crank {
                link,
                pivot,
                angle: angle?,
                omega: omega?,
                epsilon: epsilon?,
            },
            rounding?,
        ))
    }
}
