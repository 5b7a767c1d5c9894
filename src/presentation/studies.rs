//! The studies' results as tables and JSON: the instant centres, the
//! kinematic diagrams, the motion-law invariants (the studies themselves
//! compute numbers only).

use crate::kinematics::solve::Analysis;

use crate::model::mechanism::Mechanism;
use crate::pipeline::Solved;
use crate::studies::centres::{How, Place, find, name};
use crate::studies::diagrams::{Diagrams, central};
use crate::studies::invariants::{Phase, Settings};

/// One centre as text: "(x, y) m", or "at infinity, direction (dx, dy)".
fn place_text(p: &Place) -> String {
    match p {
        Place::At(p) => format!("({:.6}, {:.6}) m", p.x, p.y),
        Place::Infinity(d) => format!("at infinity, direction ({:.6}, {:.6})", d.x, d.y),
    }
}

fn how_text(m: &Mechanism, h: &How) -> String {
    match h {
        How::Revolute(p) => format!("revolute pair {p}"),
        How::Prismatic => "prismatic pair: ⊥ the guide".into(),
        How::Kennedy([a, b]) => format!(
            "Kennedy: lines through links {} and {}",
            m.link_id(*a),
            m.link_id(*b)
        ),
    }
}

/// The centres of the chosen positions (`position`: from 1; all if `None`)
/// as a table.
pub fn centres_table(an: &Analysis, solved: &[Solved], position: Option<usize>) -> String {
    let m = &an.mech;
    let mut out = String::new();
    for (k, s) in solved.iter().enumerate() {
        if position.is_some_and(|p| p != k + 1) {
            continue;
        }
        let cs = find(an, &s.config);
        out += &format!(
            "position {}: {}\n  centre   place                                        found by                                   sin θ\n",
            k + 1,
            crate::kinematics::positions::describe_input(m, &s.drives.coords())
        );
        for c in &cs.found {
            let (p, sub) = name(m, c);
            out += &format!(
                "  {:<8} {:<44} {:<42} {:.1e}\n",
                format!("{p}{sub}"),
                place_text(&c.place),
                how_text(m, &c.how),
                c.sin_angle
            );
        }
        for u in &cs.undetermined {
            out += &format!(
                "  P{}{}: undetermined: {}\n",
                m.link_id(u.links.0),
                m.link_id(u.links.1),
                u.why
            );
        }
        out.push('\n');
    }
    out
}

/// The centres as JSON: per position, `{"P13": {"at": [x, y]} | {"infinity":
/// [dx, dy]}, "how", "sin_angle"}` and the undetermined ones with why.
pub fn centres_json(
    an: &Analysis,
    solved: &[Solved],
    position: Option<usize>,
) -> serde_json::Value {
    use serde_json::{Map, Value, json};
    let m = &an.mech;
    let mut list = Vec::new();
    for (k, s) in solved.iter().enumerate() {
        if position.is_some_and(|p| p != k + 1) {
            continue;
        }
        let cs = find(an, &s.config);
        let mut centres = Map::new();
        for c in &cs.found {
            let (p, sub) = name(m, c);
            let mut e = match c.place {
                Place::At(p) => json!({ "at": [p.x, p.y] }),
                Place::Infinity(d) => json!({ "infinity": [d.x, d.y] }),
            };
            e["links"] = json!([m.link_id(c.links.0), m.link_id(c.links.1)]);
            e["how"] = Value::String(how_text(m, &c.how));
            e["sin_angle"] = json!(c.sin_angle);
            centres.insert(format!("{p}{sub}"), e);
        }
        let undetermined: Vec<Value> = cs
            .undetermined
            .iter()
            .map(|u| {
                json!({
                    "links": [m.link_id(u.links.0), m.link_id(u.links.1)],
                    "why": u.why,
                })
            })
            .collect();
        list.push(json!({
            "position": k + 1,
            "q": s.q,
            "centres": centres,
            "undetermined": undetermined,
        }));
    }
    json!({ "positions": list })
}

/// The table of the diagrams: per node and per interval midpoint the
/// analytic values and the numerical ones, then the errors.
pub fn diagrams_table(an: &Analysis, d: &Diagrams) -> String {
    let m = &an.mech;
    let (sym, unit) = if d.slide {
        ("s".to_string(), "m")
    } else {
        (format!("φ{}", m.link_id(d.output)), "rad")
    };
    let (x, x_unit) = if d.stroke {
        let (a, b, unit) = d.abscissa(an);
        (a + &b, unit)
    } else {
        ("φ".to_string(), "rad")
    };
    let start = if d.stroke {
        format!(
            "over the stroke {x} = {} … {} m of the driving slider",
            crate::format::num(d.phi0),
            crate::format::num(d.phi0 + d.h * d.n as f64)
        )
    } else {
        format!(
            "from φ1 = {:.3}° (the start of the working stroke)",
            d.phi0.to_degrees().rem_euclid(360.0)
        )
    };
    let mut out = format!(
        "kinematic diagrams of {} ({}), N = {}, {start}\n\
         scales: μ_{sym} = {} {unit}/mm, μ_{x} = {:.6} {x_unit}/mm, H1 = {} mm, H2 = {} mm, μ_{sym}′ = μ_{sym}/(H1·μ_{x}) = {:.6} {unit}/mm, μ_{sym}″ = μ_{sym}′/(H2·μ_{x}) = {:.6} {unit}/mm\n\n",
        match d.point {
            Some(p) => format!("point {}", m.point_name(p)),
            None => format!("link {}", m.link_id(d.output)),
        },
        match (d.point, d.slide) {
            (Some(_), _) => "the arc length of its path",
            (None, true) => "its slide",
            (None, false) => "its angle",
        },
        d.n,
        crate::format::num(d.mu_s),
        d.mu_phi,
        d.h1,
        d.h2,
        d.mu_v,
        d.mu_a
    );
    let (cv, ca) = central(&d.s, d.h);
    let chord_v = d.chord_velocity();
    let chord_a = d.chord_acceleration();
    out += &format!(
        "  node   {}   {sym:<12} {sym}′ exact    {sym}′ central  {sym}″ exact    {sym}″ chords   {sym}″ central\n",
        if d.stroke {
            format!("{:<8}", format!("{x} [m]"))
        } else {
            "φ1 [°]".to_string()
        }
    );
    for k in 0..=d.n {
        let x = if d.stroke {
            d.phi0 + d.h * k as f64
        } else {
            (d.phi0 + d.dir * d.h * k as f64)
                .to_degrees()
                .rem_euclid(360.0)
        };
        let prec = if d.stroke { 4 } else { 2 };
        // Over a stroke the chords of s″ end at node N − 1.
        let chord = if d.stroke && k == d.n {
            "–".to_string()
        } else {
            format!("{:.6}", chord_a[k % d.n])
        };
        out += &format!(
            "  {k:>4} {x:>8.prec$}   {:<12.6} {:<12.6} {:<13.6} {:<12.6} {chord:<13} {:<12.6}\n",
            d.s[k], d.ds[k], cv[k], d.dds[k], ca[k]
        );
    }
    out += &format!("\n  interval   {sym}′ exact at the midpoint   {sym}′ chords (ordinate × μ)\n");
    for (k, (exact, chord)) in d.ds_mid.iter().zip(&chord_v).enumerate() {
        out += &format!("  {:>3}–{:<3}    {exact:<26.6} {chord:.6}\n", k, k + 1);
    }
    let e = d.errors();
    out += &format!(
        "\nlargest error, relative to the largest value of its curve (at node or interval):\n\
         \x20 chords {sym}′ {:.2e} ({}), chords {sym}″ {:.2e} ({}), central {sym}′ {:.2e} ({}), central {sym}″ {:.2e} ({}; at the ends {:.2e}),\n\
         \x20 integration by chords {sym} {:.2e} ({}), trapezoids {sym} {:.2e} ({})\n",
        e.chord_v.0,
        e.chord_v.1,
        e.chord_a.0,
        e.chord_a.1,
        e.central_v.0,
        e.central_v.1,
        e.central_a.0,
        e.central_a.1,
        e.central_a_ends.0,
        e.chord_s.0,
        e.chord_s.1,
        e.trapezoid_s.0,
        e.trapezoid_s.1
    );
    out
}

/// The phases as a table: angles in degrees, strokes in m (or degrees for
/// a link's angle), the peak constants.
pub fn invariants_table(an: &Analysis, set: &Settings, list: &[Phase]) -> String {
    let m = &an.mech;
    let slide = m
        .prismatics
        .iter()
        .any(|p| p.slider == set.output && p.guide == m.frame());
    let unit = |x: f64| {
        if slide {
            format!("{x:.6} m")
        } else {
            format!("{:.4}°", x.to_degrees())
        }
    };
    let mut out = format!(
        "output: link {} ({}); dwell tolerance E = {} of the whole stroke, shortest dwell {:.1}°\n\
         phase      from [°]    φ_p [°]   stroke           B          C          D\n",
        m.link_id(set.output),
        if slide {
            "its slide along the guide"
        } else {
            "its angle"
        },
        set.tolerance,
        set.min_dwell.to_degrees()
    );
    for p in list {
        let (b, c, d) = p
            .peaks
            .map(|k| {
                (
                    format!("{:.6}", k.b),
                    format!("{:.6}", k.c),
                    format!("{:.6}", k.d),
                )
            })
            .unwrap_or_else(|| ("–".into(), "–".into(), "–".into()));
        out += &format!(
            "{:<10} {:>9.3} {:>10.3}   {:<14} {:>10} {:>10} {:>10}\n",
            p.kind.name(),
            p.start.to_degrees().rem_euclid(360.0),
            p.span.to_degrees(),
            unit(p.stroke),
            b,
            c,
            d
        );
    }
    out
}

/// The phases as JSON (angles in degrees).
pub fn invariants_json(an: &Analysis, set: &Settings, list: &[Phase]) -> serde_json::Value {
    use serde_json::json;
    let phases: Vec<_> = list
        .iter()
        .map(|p| {
            let mut v = json!({
                "phase": p.kind.name(),
                "start_deg": p.start.to_degrees().rem_euclid(360.0),
                "span_deg": p.span.to_degrees(),
                "s0": p.s0,
                "s1": p.s1,
                "stroke": p.stroke,
            });
            if let Some(k) = p.peaks {
                v["B"] = json!(k.b);
                v["C"] = json!(k.c);
                v["D"] = json!(k.d);
                v["x_B"] = json!(k.x_b);
                v["x_C"] = json!(k.x_c);
                v["x_D"] = json!(k.x_d);
            }
            v
        })
        .collect();
    json!({
        "output": an.mech.link_id(set.output),
        "tolerance": set.tolerance,
        "min_dwell_deg": set.min_dwell.to_degrees(),
        "phases": phases,
    })
}
