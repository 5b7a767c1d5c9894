//! The positions asked for: the input's own, a list, or equal steps over a
//! revolution.

use super::reader::Reader;
use super::{InputSpec, LinkSpec, MAX_POSITIONS, PositionsSpec, U};
use serde_json::Value;

impl Reader {
    pub(super) fn positions(
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
}
