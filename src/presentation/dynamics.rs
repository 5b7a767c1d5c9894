//! The force analysis of a position in the result file: the contract's
//! `dynamics` (`inertia`, `pairs`, `balancing`) and mechplan's `check`
//! (docs/scene-format.md, docs/kinetostatics.md).

use crate::json::{number as num, vec2};
use crate::kinematics::solve::Analysis;
use crate::kinetostatics::{Balancing, Dynamics};
use serde_json::{Map, Value, json};

/// A balancing value as the contract writes it: `{ "M": m }` on a crank,
/// `{ "F": f }` along a driving slider.
fn balancing(b: Balancing) -> Value {
    match b {
        Balancing::Moment(m) => json!({ "M": num(m) }),
        Balancing::Force(f) => json!({ "F": num(f) }),
    }
}

/// One object per input, or a list of them with several inputs (as
/// `input` itself).
fn per_input(an: &Analysis, values: Vec<Value>) -> Value {
    if an.mech.scene.several_inputs() {
        Value::Array(values)
    } else {
        values.into_iter().next().expect("one input")
    }
}

/// The `dynamics` object of a position.
pub fn dynamics_json(an: &Analysis, d: &Dynamics) -> Value {
    let m = &an.mech;
    let mut inertia = Map::new();
    for i in &d.inertia {
        inertia.insert(
            m.link_id(i.link).to_string(),
            json!({ "F": vec2(i.f), "M": num(i.m) }),
        );
    }
    let mut pairs: Vec<Value> = d
        .revolutes
        .iter()
        .map(|r| {
            json!({
                "point": m.point_name(r.point),
                "links": [m.link_id(r.first), m.link_id(r.second)],
                "R": vec2(r.r),
            })
        })
        .collect();
    pairs.extend(d.prismatics.iter().map(|p| {
        json!({
            "slider": m.link_id(p.slider),
            "guide": m.link_id(p.guide),
            "point": m.point_name(p.point),
            "N": vec2(p.n),
            "M": num(p.m),
            "at": p.at.map_or(Value::Null, |a| json!([num(a.x), num(a.y)])),
        })
    }));
    let by_power = d
        .balancing
        .iter()
        .zip(&d.virtual_power)
        .map(|(b, &v)| {
            balancing(match b {
                Balancing::Moment(_) => Balancing::Moment(v),
                Balancing::Force(_) => Balancing::Force(v),
            })
        })
        .collect();
    let by_lever = d
        .balancing
        .iter()
        .zip(&d.lever)
        .map(|(b, &v)| {
            balancing(match b {
                Balancing::Moment(_) => Balancing::Moment(v),
                Balancing::Force(_) => Balancing::Force(v),
            })
        })
        .collect();
    let mut out = json!({
        "inertia": inertia,
        "pairs": pairs,
        "balancing": per_input(an, d.balancing.iter().map(|b| balancing(*b)).collect()),
        "check": {
            "virtual_power": per_input(an, by_power),
            "lever": per_input(an, by_lever),
            "rel_diff": num(d.balancing_diff),
            "conditioning": num(d.rcond),
        },
    });
    if let (Some(fp), Some(diff)) = (&d.force_plans, d.force_plans_diff) {
        out["check"]["force_plans"] = num(diff);
        out["force_plans"] = fp
            .plans
            .iter()
            .map(|p| {
                json!({
                    "links": p.links.iter().map(|&l| m.link_id(l)).collect::<Vec<_>>(),
                    "mu": num(p.mu),
                })
            })
            .collect();
    }
    out
}
