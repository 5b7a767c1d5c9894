//! The positions asked for: the inputs' own, a list, equal steps over a
//! revolution, or (several inputs) one list of values per position.

use super::reader::Reader;
use super::{InputSpec, LinkSpec, MAX_COUNT, MAX_POSITIONS, PositionsSpec, U};
use serde_json::{Map, Value};

impl Reader {
    pub(super) fn positions(
        &mut self,
        v: Option<&Value>,
        links: &[LinkSpec],
        inputs: Option<&[InputSpec]>,
    ) -> Option<PositionsSpec> {
        let Some(v) = v else {
            return Some(PositionsSpec::Single);
        };
        let o = self.object(v, "/positions")?;
        self.only_keys(
            o,
            "/positions",
            &["angles", "s", "count", "output", "values"],
        );
        let several = inputs.is_some_and(|i| i.len() > 1);
        let input = inputs.and_then(|i| i.first());
        let crank = !several && matches!(input, Some(InputSpec::Crank { .. }));
        let slider = !several && matches!(input, Some(InputSpec::Slider { .. }));
        let n = ["angles", "s", "count", "values"]
            .iter()
            .filter(|k| o.contains_key(**k))
            .count();
        if n != 1 {
            self.err(
                "/positions",
                "give exactly one of \"angles\", \"s\", \"count\" or \"values\"",
            );
            return None;
        }
        if o.contains_key("values") {
            return self.values(&o["values"], inputs?);
        }
        if several {
            self.several_inputs(o, inputs.map_or(0, |i| i.len()));
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
            return self.position_list(o, "angles", 1.0).map(|v| {
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
            return self.position_list(o, "s", self.len).map(|v| {
                self.rounding = v.iter().map(|&x| 2.0 * U * x.abs()).collect();
                PositionsSpec::List(v)
            });
        }
        self.count(o, links, slider)
    }

    /// A list of positions `key` (each × `unit`).
    fn position_list(&mut self, o: &Map<String, Value>, key: &str, unit: f64) -> Option<Vec<f64>> {
        let at = format!("/positions/{key}");
        let a = o[key].as_array();
        match a {
            Some(a) if !a.is_empty() && a.len() <= MAX_POSITIONS => {
                let mut out = Vec::new();
                for (k, x) in a.iter().enumerate() {
                    out.push(self.number(x, &format!("{at}/{k}"))? * unit);
                }
                Some(out)
            }
            Some(a) if a.len() > MAX_POSITIONS => {
                self.err(
                    at,
                    format!("{} positions; at most {MAX_POSITIONS}", a.len()),
                );
                None
            }
            _ => {
                self.err(at, "expected a non-empty list of numbers");
                None
            }
        }
    }

    /// The error of positions given as for one input to a scene of `n`.
    fn several_inputs(&mut self, o: &Map<String, Value>, n: usize) {
        let key = ["angles", "s", "count"]
            .into_iter()
            .find(|k| o.contains_key(*k))
            .expect("one key");
        self.err(
            format!("/positions/{key}"),
            format!(
                "the scene has {} inputs: give \"values\", one list [q1, q2, ...] per position with a value for each input in the order of /input{}",
                n,
                if key == "count" {
                    " (equal steps over a revolution are defined for a single crank)"
                } else {
                    ""
                }
            ),
        );
    }

    /// `count`: equal steps over a revolution of a crank, from the output
    /// link's extreme position when `output` names one.
    fn count(
        &mut self,
        o: &Map<String, Value>,
        links: &[LinkSpec],
        slider: bool,
    ) -> Option<PositionsSpec> {
        let count = match o["count"].as_u64() {
            Some(c) if (1..=MAX_COUNT as u64).contains(&c) => c as usize,
            _ => {
                self.err(
                    "/positions/count",
                    format!("expected a whole number from 1 to {MAX_COUNT}"),
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
        // The input's own rounding is kept: where the output turns fully
        // the steps start at the input's angle as written.
        Some(PositionsSpec::Count { count, output })
    }

    /// `values`: one list per position, one value per input (an angle for
    /// a crank, a slide for a slider, in the file's units).
    fn values(&mut self, v: &Value, inputs: &[InputSpec]) -> Option<PositionsSpec> {
        let at = "/positions/values";
        let Some(a) = v.as_array().filter(|a| !a.is_empty()) else {
            self.err(
                at,
                "expected a non-empty list of positions, each a list of one value per input",
            );
            return None;
        };
        if a.len() > MAX_POSITIONS {
            self.err(
                at,
                format!("{} positions; at most {MAX_POSITIONS}", a.len()),
            );
            return None;
        }
        let w = inputs.len();
        let mut out = Vec::with_capacity(a.len());
        let mut rounding = Vec::with_capacity(a.len() * w);
        let mut ok = true;
        for (k, row) in a.iter().enumerate() {
            let here = format!("{at}/{k}");
            let Some(row) = row.as_array() else {
                self.err(
                    &here,
                    format!("expected a list of {w} values, one per input"),
                );
                ok = false;
                continue;
            };
            if row.len() != w {
                self.err(
                    &here,
                    format!(
                        "{} value{}, but the scene has {w} input{}: one value per input, in the order of /input",
                        row.len(),
                        if row.len() == 1 { "" } else { "s" },
                        if w == 1 { "" } else { "s" }
                    ),
                );
                ok = false;
                continue;
            }
            let mut q = Vec::with_capacity(w);
            for (i, (x, spec)) in row.iter().zip(inputs).enumerate() {
                let Some(x) = self.number(x, &format!("{here}/{i}")) else {
                    ok = false;
                    continue;
                };
                match spec {
                    InputSpec::Crank { .. } => {
                        rounding.push(self.angle_rounding(x));
                        q.push(self.angle(x));
                    }
                    InputSpec::Slider { .. } => {
                        let s = x * self.len;
                        rounding.push(2.0 * U * s.abs());
                        q.push(s);
                    }
                }
            }
            out.push(q);
        }
        if !ok {
            return None;
        }
        self.rounding = rounding;
        Some(if w == 1 {
            PositionsSpec::List(out.into_iter().map(|q| q[0]).collect())
        } else {
            PositionsSpec::Values(out)
        })
    }
}
