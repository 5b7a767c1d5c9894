//! The studies' results as tables and JSON: the instant centres, the
//! kinematic diagrams, the motion-law invariants (the studies themselves
//! compute numbers only).

use crate::kinematics::positions::describe_input_with;
use crate::kinematics::solve::Analysis;
use crate::lang::Lang;
use crate::pipeline::Solved;
use crate::studies::centres::{Place, find, name};
use crate::studies::diagrams::{Diagrams, central};
use crate::studies::invariants::{Phase, Settings};
use crate::words::catalogue::{DiagramPhrases, catalogue, fill};
use crate::words::numbers::{decimals, unit};
use crate::words::terminal::{centres, how, why};

/// One centre as text in `l`: "(x, y) m", or "at infinity, direction
/// (dx, dy)".
fn place_text(p: &Place, l: Lang) -> String {
    let w = centres(l);
    let (x, y) = match p {
        Place::At(p) => (p.x, p.y),
        Place::Infinity(d) => (d.x, d.y),
    };
    let (x, y) = (format!("{x:.6}"), format!("{y:.6}"));
    match p {
        Place::At(_) => fill(&w.at, &[("x", &x), ("y", &y), ("unit", &unit("m", l))]),
        Place::Infinity(_) => fill(&w.infinity, &[("x", &x), ("y", &y)]),
    }
}

/// The centres of the chosen positions (`position`: its number in the
/// study's numbering, as the sheets show it; all if `None`)
/// as a table in `l`, every number in its decimal mark.
/// A position's inputs as the solve table writes them: "φ = 40.804°",
/// "s = 0.050000 m", to the table's digits, not the shortest decimal of
/// the value (59.99999999999999°).
fn inputs_text(m: &crate::model::mechanism::Mechanism, q: &[f64], metre: &str) -> String {
    describe_input_with(
        m,
        q,
        &|q| format!("{:.3}°", q.to_degrees().rem_euclid(360.0)),
        &|q| format!("{q:.6} {metre}"),
    )
}

pub fn centres_table(
    an: &Analysis,
    solved: &[Solved],
    position: Option<usize>,
    l: Lang,
) -> String {
    let m = &an.mech;
    let w = centres(l);
    let [centre, place, found] = &w.heads;
    let word = &catalogue(l).sheets.position;
    let mut out = String::new();
    for (k, s) in solved.iter().enumerate() {
        if position.is_some_and(|p| p != super::position_number(an, k)) {
            continue;
        }
        let cs = find(an, &s.config);
        out += &format!(
            "{word} {}: {}\n  {centre:<8} {place:<44} {found:<42} sin θ\n",
            super::position_number(an, k),
            inputs_text(m, &s.drives.coords(), &unit("m", l))
        );
        for c in &cs.found {
            let (p, sub) = name(m, c);
            out += &format!(
                "  {:<8} {:<44} {:<42} {:.1e}\n",
                format!("{p}{sub}"),
                place_text(&c.place, l),
                how(m, &c.how, l),
                c.sin_angle
            );
        }
        for u in &cs.undetermined {
            out += &format!(
                "  P{}{}: {}: {}\n",
                m.link_id(u.links.0),
                m.link_id(u.links.1),
                w.undetermined,
                why(m, u.links, u.why, l)
            );
        }
        out.push('\n');
    }
    decimals(&out, l)
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
        if position.is_some_and(|p| p != super::position_number(an, k)) {
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
            e["how"] = Value::String(how(m, &c.how, Lang::En));
            e["sin_angle"] = json!(c.sin_angle);
            centres.insert(format!("{p}{sub}"), e);
        }
        let undetermined: Vec<Value> = cs
            .undetermined
            .iter()
            .map(|u| {
                json!({
                    "links": [m.link_id(u.links.0), m.link_id(u.links.1)],
                    "why": why(m, u.links, u.why, Lang::En),
                })
            })
            .collect();
        list.push(json!({
            "position": super::position_number(an, k),
            "q": s.q,
            "centres": centres,
            "undetermined": undetermined,
        }));
    }
    json!({ "positions": list })
}

/// The table of the diagrams in `l`: per node and per interval midpoint
/// the analytic values and the numerical ones, then the errors; every
/// number in the language's decimal mark.
pub fn diagrams_table(an: &Analysis, d: &Diagrams, l: Lang) -> String {
    let w = &catalogue(l).diagrams;
    let m = &an.mech;
    let sym = if d.slide {
        "s".to_string()
    } else {
        format!("φ{}", m.link_id(d.output))
    };
    let x = match d.stroke {
        true => {
            let (a, b, _) = d.abscissa(an);
            a + &b
        }
        false => "φ".to_string(),
    };
    let mut out = diagrams_title(an, d, &sym, &x, l);
    let (cv, ca) = central(&d.s, d.h);
    let chord_v = d.chord_velocity();
    let chord_a = d.chord_acceleration();
    let (v, a) = (format!("{sym}′"), format!("{sym}″"));
    let (exact, central_, chords) = (&w.exact, &w.central, &catalogue(l).sheets.chords);
    out += &format!(
        "  {:<6} {}   {sym:<12} {v} {exact:<8} {v} {central_:<8} {a} {exact:<8} {a} {chords:<8} {a} {central_}\n",
        w.node,
        if d.stroke {
            format!("{:<8}", format!("{x} [{}]", unit("m", l)))
        } else {
            "φ1 [°]".to_string()
        },
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
    let midpoint = fill(&w.midpoint, &[("y", &v)]);
    let ordinate = fill(&w.ordinate, &[("y", &v)]);
    out += &format!("\n  {:<8}   {midpoint:<24}   {ordinate}\n", w.interval);
    for (k, (exact, chord)) in d.ds_mid.iter().zip(&chord_v).enumerate() {
        out += &format!("  {:>3}–{:<3}    {exact:<26.6} {chord:.6}\n", k, k + 1);
    }
    out += &diagrams_errors(d, w, &sym);
    decimals(&out, l)
}

/// The diagrams' title and scales in `l` (`sym` the ordinate's symbol,
/// `x` the abscissa's), with the empty line after them.
fn diagrams_title(an: &Analysis, d: &Diagrams, sym: &str, x: &str, l: Lang) -> String {
    let w = &catalogue(l).diagrams;
    let m = &an.mech;
    let unit_of = |u: &str| unit(u, l);
    let ordinate = if d.slide { "m" } else { "rad" };
    let abscissa = if d.stroke { d.abscissa(an).2 } else { "rad" };
    let start = if d.stroke {
        fill(
            &w.stroke,
            &[
                ("x", x),
                ("from", &crate::format::num(d.phi0)),
                ("to", &crate::format::num(d.phi0 + d.h * d.n as f64)),
                ("unit", &unit_of("m")),
            ],
        )
    } else {
        let angle = format!("{:.3}", d.phi0.to_degrees().rem_euclid(360.0));
        fill(&w.turn, &[("angle", &angle)])
    };
    let what = match d.point {
        Some(p) => fill(&w.point, &[("p", m.point_name(p))]),
        None => fill(&w.link, &[("id", m.link_id(d.output))]),
    };
    let of = &w.of[match (d.point, d.slide) {
        (Some(_), _) => 0,
        (None, true) => 1,
        (None, false) => 2,
    }];
    let n = d.n.to_string();
    let title = fill(
        &w.title,
        &[("what", &what), ("of", of), ("n", &n), ("start", &start)],
    );
    let (unit, x_unit) = (
        unit_of(&format!("{ordinate}/mm")),
        unit_of(&format!("{abscissa}/mm")),
    );
    format!(
        "{title}\n\
         {}: μ_{sym} = {} {unit}, μ_{x} = {:.6} {x_unit}, H1 = {} {mm}, H2 = {} {mm}, μ_{sym}′ = μ_{sym}/(H1·μ_{x}) = {:.6} {unit}, μ_{sym}″ = μ_{sym}′/(H2·μ_{x}) = {:.6} {unit}\n\n",
        w.scales,
        crate::format::num(d.mu_s),
        d.mu_phi,
        d.h1,
        d.h2,
        d.mu_v,
        d.mu_a,
        mm = unit_of("mm"),
    )
}

/// The diagrams' largest errors, relative to the largest value of each
/// curve, where each is (`w`: the words; `sym` the ordinate's symbol).
fn diagrams_errors(d: &Diagrams, w: &DiagramPhrases, sym: &str) -> String {
    let e = d.errors();
    let sci = |x: f64| format!("{x:.2e}");
    let (v, a) = (format!("{sym}′"), format!("{sym}″"));
    let at = |(_, k): (f64, usize)| k.to_string();
    let errors = fill(
        &w.errors,
        &[
            ("v", &v),
            ("a", &a),
            ("s", sym),
            ("cv", &sci(e.chord_v.0)),
            ("cv_at", &at(e.chord_v)),
            ("ca", &sci(e.chord_a.0)),
            ("ca_at", &at(e.chord_a)),
            ("dv", &sci(e.central_v.0)),
            ("dv_at", &at(e.central_v)),
            ("da", &sci(e.central_a.0)),
            ("da_at", &at(e.central_a)),
            ("ends", &sci(e.central_a_ends.0)),
            ("is", &sci(e.chord_s.0)),
            ("is_at", &at(e.chord_s)),
            ("ts", &sci(e.trapezoid_s.0)),
            ("ts_at", &at(e.trapezoid_s)),
        ],
    );
    format!("\n{errors}\n")
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
