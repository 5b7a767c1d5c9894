//! What is wanted: the plans, the points, the drawings, the scales, the
//! language.

use super::reader::Reader;
use crate::lang::Lang;
use super::{NamedPoint, Scales, Want};
use serde_json::Value;

impl Reader {
    pub(super) fn want(&mut self, v: Option<&Value>, points: &[NamedPoint]) -> Option<Want> {
        let mut w = Want::default();
        let Some(v) = v else { return Some(w) };
        let o = self.object(v, "/want")?;
        self.only_keys(
            o,
            "/want",
            &[
                "plans", "rates", "points", "drawings", "scales", "lang", "plans_at",
            ],
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
        // The highest order named: 0 none, 1 velocity, 2 acceleration
        // (accelerations need velocities, so they come with them).
        let order = |list: &[String]| {
            if list.iter().any(|x| x == "acceleration") {
                2
            } else {
                usize::from(list.iter().any(|x| x == "velocity"))
            }
        };
        let plans = o
            .contains_key("plans")
            .then(|| order(&names(self, "plans", &["velocity", "acceleration"])));
        let rates = o
            .contains_key("rates")
            .then(|| order(&names(self, "rates", &["velocity", "acceleration"])));
        // The rates are `rates`, else those of the plans; the plans are
        // drawn up to the rates or not at all.
        match (plans, rates) {
            (Some(p), Some(r)) if p != 0 && p != r => self.err(
                "/want/plans",
                "the plans are drawn up to the rates computed (want.rates) or not at all (\"plans\": [])",
            ),
            _ => {}
        }
        if let Some(r) = rates.or(plans) {
            w.velocity = r >= 1;
            w.acceleration = r >= 2;
        }
        w.plans = plans.is_none_or(|p| p != 0) && (w.velocity || w.acceleration);
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
                    "course",
                    "lever",
                    "forces",
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
            self.lang(l, &mut w.lang);
        }
        Some(w)
    }

    /// `want.lang`: a language's code ([`Lang::parse`]).
    fn lang(&mut self, l: &Value, to: &mut String) {
        match l.as_str().filter(|s| Lang::parse(s).is_some()) {
            Some(s) => *to = s.to_owned(),
            None => self.err(
                "/want/lang",
                format!("expected a language code: {}", Lang::codes()),
            ),
        }
    }
}
