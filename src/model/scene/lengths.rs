//! The given distances between points of one link.

use super::reader::{Reader, ptr};
use super::{LengthSpec, LinkSpec, NamedPoint};
use serde_json::Value;

impl Reader {
    pub(super) fn lengths(
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
}
