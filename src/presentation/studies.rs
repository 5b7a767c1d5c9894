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

/// The instant centres of one position, as `mechplan centres --format
/// json` writes them (its element of `positions`).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct CentresAt {
    /// The position's number in the study's numbering.
    pub position: usize,
    /// Its input coordinate as the file writes it: rad for a crank's
    /// angle, m for a driving slider's slide.
    pub q: f64,
    /// The centres found, in the order of the file's `centres` object.
    #[serde(serialize_with = "centres_by_name")]
    pub centres: Vec<InstantCentre>,
    /// The centres Kennedy's theorem cannot place at this position.
    pub undetermined: Vec<UndeterminedCentre>,
}

/// One instant centre of velocity of two links.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct InstantCentre {
    /// Its name, P13 (the file's key).
    #[serde(skip)]
    pub name: String,
    /// Where it is, m (absent at infinity).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub at: Option<[f64; 2]>,
    /// At infinity: the unit direction it lies in (the two links
    /// translate relative to each other, perpendicular to it).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub infinity: Option<[f64; 2]>,
    /// The two links' ids.
    pub links: [String; 2],
    /// How it was found: a pair's joint, a prismatic pair, Kennedy's lines.
    pub how: String,
    /// Sine of the angle between the two Kennedy lines that place it (1
    /// for a pair): its error is about the lines' error over it.
    pub sin_angle: f64,
}

/// A centre that cannot be placed, with the reason.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct UndeterminedCentre {
    /// The two links' ids.
    pub links: [String; 2],
    /// Why Kennedy's lines do not place it.
    pub why: String,
}

/// The centres as the file's object: name → centre.
fn centres_by_name<S: serde::Serializer>(list: &[InstantCentre], s: S) -> Result<S::Ok, S::Error> {
    use serde::ser::SerializeMap;
    let mut m = s.serialize_map(Some(list.len()))?;
    for c in list {
        m.serialize_entry(&c.name, c)?;
    }
    m.end()
}

/// The centres of the chosen positions (`position`: its number in the
/// study's numbering; all if `None`), typed.
pub fn centres_records(an: &Analysis, solved: &[Solved], position: Option<usize>) -> Vec<CentresAt> {
    let m = &an.mech;
    let ids = |l: (usize, usize)| [m.link_id(l.0).to_string(), m.link_id(l.1).to_string()];
    let mut list = Vec::new();
    for (k, s) in solved.iter().enumerate() {
        if position.is_some_and(|p| p != super::position_number(an, k)) {
            continue;
        }
        let cs = find(an, &s.config);
        let centres = cs
            .found
            .iter()
            .map(|c| {
                let (p, sub) = name(m, c);
                let (at, infinity) = match c.place {
                    Place::At(p) => (Some([p.x, p.y]), None),
                    Place::Infinity(d) => (None, Some([d.x, d.y])),
                };
                InstantCentre {
                    name: format!("{p}{sub}"),
                    at,
                    infinity,
                    links: ids(c.links),
                    how: how(m, &c.how, Lang::En),
                    sin_angle: c.sin_angle,
                }
            })
            .collect();
        let undetermined = cs
            .undetermined
            .iter()
            .map(|u| UndeterminedCentre {
                links: ids(u.links),
                why: why(m, u.links, u.why, Lang::En),
            })
            .collect();
        list.push(CentresAt {
            position: super::position_number(an, k),
            q: s.q,
            centres,
            undetermined,
        });
    }
    list
}

/// The centres as JSON: per position, `{"P13": {"at": [x, y]} | {"infinity":
/// [dx, dy]}, "links", "how", "sin_angle"}` and the undetermined ones with
/// why ([`centres_records`], serialised).
pub fn centres_json(
    an: &Analysis,
    solved: &[Solved],
    position: Option<usize>,
) -> serde_json::Value {
    serde_json::json!({ "positions": centres_records(an, solved, position) })
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

/// One phase of an output's motion, as `mechplan invariants --format
/// json` writes it: angles in degrees, as the file.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct PhaseRecord {
    /// "recess", "dwell" or "approach".
    pub phase: &'static str,
    /// The crank angle it starts at, degrees in [0, 360).
    pub start_deg: f64,
    /// Its span in the sense of rotation, degrees.
    pub span_deg: f64,
    /// The output's coordinate at its start (m or rad).
    pub s0: f64,
    /// The output's coordinate at its end (m or rad).
    pub s1: f64,
    /// The stroke |s1 − s0| (a dwell: its largest deviation).
    pub stroke: f64,
    /// A moving phase's peak constants.
    #[serde(flatten, skip_serializing_if = "Option::is_none")]
    pub peaks: Option<PeakConstants>,
}

/// The peak constants of a moving phase's dimensionless motion law (x
/// from 0 to 1 over the phase), and where they are reached.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct PeakConstants {
    /// B = max|b|, the peak of the velocity b = s'/S.
    #[serde(rename = "B")]
    pub b: f64,
    /// C = max|c|, the peak of the acceleration c = s''/S.
    #[serde(rename = "C")]
    pub c: f64,
    /// D = max|d|, the peak of the kinetic power d = b·c.
    #[serde(rename = "D")]
    pub d: f64,
    /// Where B is reached (x from 0 to 1 over the phase).
    #[serde(rename = "x_B")]
    pub x_b: f64,
    /// Where C is reached.
    #[serde(rename = "x_C")]
    pub x_c: f64,
    /// Where D is reached.
    #[serde(rename = "x_D")]
    pub x_d: f64,
}

/// The phases, typed ([`PhaseRecord`]).
pub fn phase_records(list: &[Phase]) -> Vec<PhaseRecord> {
    list.iter()
        .map(|p| PhaseRecord {
            phase: p.kind.name(),
            start_deg: p.start.to_degrees().rem_euclid(360.0),
            span_deg: p.span.to_degrees(),
            s0: p.s0,
            s1: p.s1,
            stroke: p.stroke,
            peaks: p.peaks.map(|k| PeakConstants {
                b: k.b,
                c: k.c,
                d: k.d,
                x_b: k.x_b,
                x_c: k.x_c,
                x_d: k.x_d,
            }),
        })
        .collect()
}

/// The phases as JSON (angles in degrees; [`phase_records`], serialised).
pub fn invariants_json(an: &Analysis, set: &Settings, list: &[Phase]) -> serde_json::Value {
    serde_json::json!({
        "output": an.mech.link_id(set.output),
        "tolerance": set.tolerance,
        "min_dwell_deg": set.min_dwell.to_degrees(),
        "phases": phase_records(list),
    })
}
