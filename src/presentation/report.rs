//! Results as the JSON of `docs/scene-format.md` ("The result files"),
//! as a terminal table (the
//! tables of [`super::tables`], the handout's too, written as text) and
//! as the construction's steps.

use crate::geom::wrap_pi;
use crate::kinematics::analytic::Order;
use crate::kinematics::solve::Analysis;
use crate::model::scene::InputSpec;
use crate::pipeline::Solved;
use crate::verification::crosscheck::{CrossCheck, Method};
use crate::words::construction::Lang;
use serde_json::{Map, Value, json};
use std::fmt::Write as _;

#[cfg(feature = "internals")]
pub use super::steps::to_steps;
use super::steps::{steps_head, steps_position};
use crate::json::{number as num, vec2};
pub(crate) use super::text_table::group_kinds;
#[cfg(feature = "internals")]
pub use super::text_table::to_table;
use super::text_table::{table_head, table_position};

fn deg(a: f64) -> f64 {
    wrap_pi(a).to_degrees()
}

/// A point's or a link's rates into its entry: each first-order rate
/// (`v`, then its analogue `v_q`) followed by its second-order one (`a`,
/// `a_q`) when the analysis has accelerations.
fn insert_rates(e: &mut Map<String, Value>, acc: bool, rates: [[(&str, Value); 2]; 2]) {
    for [(k1, x1), (k2, x2)] in rates {
        e.insert(k1.into(), x1);
        if acc {
            e.insert(k2.into(), x2);
        }
    }
}

/// A matrix of second derivatives by rows (null where not computed).
fn matrix<T: Copy>(m: Option<&[Vec<T>]>, f: impl Fn(T) -> Value) -> Value {
    match m {
        Some(rows) => Value::Array(
            rows.iter()
                .map(|r| Value::Array(r.iter().map(|x| f(*x)).collect()))
                .collect(),
        ),
        None => Value::Null,
    }
}

/// The result document for `mechplan solve --format json`.
pub fn to_json(an: &Analysis, solved: &[Solved]) -> Value {
    let mut doc = json_head(an);
    doc.insert(
        "positions".into(),
        Value::Array(
            solved
                .iter()
                .enumerate()
                .map(|(k, s)| position_json(an, k, s))
                .collect(),
        ),
    );
    Value::Object(doc)
}

/// The result document's fields before `positions`.
fn json_head(an: &Analysis) -> Map<String, Value> {
    let m = &an.mech;
    let groups: Vec<Value> =
        an.structure
            .groups
            .iter()
            .map(|g| {
                let mut o = Map::new();
                o.insert("class".into(), json!(g.class()));
                o.insert("kind".into(), json!(g.kind()));
                if let crate::model::structure::AssurGroup::Dyad(d) = g {
                    o.insert("number".into(), json!(d.kind.number()));
                }
                if let Some((a, b)) = g.cylinder() {
                    // The cylinder's two links: the guide, then the slider.
                    let (guide, slider) = match m.prismatics.iter().find(|p| {
                        (p.guide == a && p.slider == b) || (p.guide == b && p.slider == a)
                    }) {
                        Some(p) => (p.guide, p.slider),
                        None => (a, b),
                    };
                    o.insert(
                        "cylinder".into(),
                        json!([m.link_id(guide), m.link_id(slider)]),
                    );
                }
                o.insert(
                    "links".into(),
                    json!(g.links().iter().map(|&l| m.link_id(l)).collect::<Vec<_>>()),
                );
                Value::Object(o)
            })
            .collect();
    let mut doc = Map::new();
    doc.insert("mechplan".into(), json!(1));
    if !m.scene.title.is_empty() {
        doc.insert("title".into(), json!(m.scene.title));
    }
    doc.insert("mu_l".into(), num(an.mu_l));
    doc.insert(
        "structure".into(),
        json!({ "dof": an.structure.dof, "formula": an.structure.formula(m), "groups": groups }),
    );
    doc
}

/// What a position's entries hold: first-order rates (`vel`), second-order
/// ones (`acc`), and the analogues by input (`several`).
#[derive(Clone, Copy)]
struct Orders {
    vel: bool,
    acc: bool,
    several: bool,
}

impl Orders {
    fn of(an: &Analysis) -> Orders {
        Orders {
            vel: an.order.is_some(),
            acc: an.order == Some(Order::Acceleration),
            several: an.mech.scene.several_inputs(),
        }
    }
}

/// One position of the result document, the `k`-th (from 0) of the
/// sweep: first its `position`, its number as the sheets show it (the
/// study's numbering: a `count` sweep from 0, given input values from 1).
pub fn position_json(an: &Analysis, k: usize, s: &Solved) -> Value {
    let want = Orders::of(an);
    let mut o = Map::new();
    o.insert("position".into(), json!(super::position_number(an, k)));
    o.insert("input".into(), inputs_json(an, s, want));
    o.insert("points".into(), points_json(an, s, want));
    o.insert("links".into(), links_json(an, s, want));
    let slides = slides_json(an, s, want);
    if !slides.is_empty() {
        o.insert("sliders".into(), Value::Array(slides));
    }
    if let Some(plans) = &s.plans {
        let mut pl = Map::new();
        pl.insert("velocity".into(), plan_json(&plans.velocity));
        if let Some(a) = &plans.acceleration {
            pl.insert("acceleration".into(), plan_json(a));
        }
        o.insert("plans".into(), Value::Object(pl));
    }
    if let Some(c) = &s.check {
        o.insert("crosscheck".into(), crosscheck_json(c, want));
    }
    if let Some(d) = &s.dynamics {
        o.insert("dynamics".into(), super::dynamics::dynamics_json(an, d));
    }
    Value::Object(o)
}

/// A position's inputs: the one input's object, or an array of them.
fn inputs_json(an: &Analysis, s: &Solved, want: Orders) -> Value {
    let inputs: Vec<Value> = an
        .mech
        .scene
        .inputs()
        .zip(s.drives.iter())
        .map(|(spec, d)| match spec {
            InputSpec::Crank { .. } => json!({ "angle": num(d.q.to_degrees()), "omega": num(d.rate), "epsilon": num(d.rate2) }),
            InputSpec::Slider { .. } => json!({ "s": num(d.q), "v": num(d.rate), "a": num(d.rate2) }),
        })
        .collect();
    if want.several {
        Value::Array(inputs)
    } else {
        inputs.into_iter().next().expect("one input")
    }
}

/// The wanted points of a position by name: place, rates and analogues.
fn points_json(an: &Analysis, s: &Solved, want: Orders) -> Value {
    let m = &an.mech;
    let mut pts = Map::new();
    for &p in &an.points {
        let ps = s.point(an, p);
        let (at, st, an_) = (ps.at, ps.rates, ps.analogue);
        let mut e = Map::new();
        e.insert("p".into(), json!([num(at.x), num(at.y)]));
        if want.vel {
            let (v, a) = st.unwrap();
            let (vq, aq) = match s.point_partials(an, p).filter(|_| want.several) {
                // Several inputs: ∂P/∂q_i, and ∂²P/∂q_i∂q_j by rows.
                Some(pp) => (
                    Value::Array(pp.first.iter().map(|x| vec2(*x)).collect()),
                    matrix(pp.second.as_deref(), vec2),
                ),
                None => {
                    let (vq, aq) = an_.unwrap();
                    (vec2(vq), vec2(aq))
                }
            };
            let rates = [("v", vec2(v)), ("a", vec2(a))];
            let analogues = [("v_q", vq), ("a_q", aq)];
            insert_rates(&mut e, want.acc, [rates, analogues]);
        }
        pts.insert(m.point_name(p).to_string(), Value::Object(e));
    }
    Value::Object(pts)
}

/// The solved links of a position by id: angle, rates and analogues.
fn links_json(an: &Analysis, s: &Solved, want: Orders) -> Value {
    let m = &an.mech;
    let mut links = Map::new();
    for l in 0..m.links.len() {
        if !an.link(l) {
            continue;
        }
        let mut e = Map::new();
        // The local x-axis runs from the link's first point to its
        // second (a one-point slider: along its guide), as the
        // contract defines a link's angle.
        e.insert("angle".into(), num(deg(s.config.pose(l).angle)));
        if want.vel {
            let mo = s.motion[l].unwrap();
            let (pq, pqq) = match s.link_partials(l).filter(|_| want.several) {
                Some(pp) => (
                    Value::Array(pp.first.iter().map(|x| num(*x)).collect()),
                    matrix(pp.second.as_deref(), num),
                ),
                None => {
                    let aq = s.analogue[l].unwrap();
                    (num(aq.omega), num(aq.epsilon))
                }
            };
            let rates = [("omega", num(mo.omega)), ("epsilon", num(mo.epsilon))];
            let analogues = [("phi_q", pq), ("phi_qq", pqq)];
            insert_rates(&mut e, want.acc, [rates, analogues]);
        }
        links.insert(m.link_id(l).to_string(), Value::Object(e));
    }
    Value::Object(links)
}

/// The sliders of a position: each slide along its guide with its rates
/// and analogues (and the Coriolis acceleration on a moving guide).
fn slides_json(an: &Analysis, s: &Solved, want: Orders) -> Vec<Value> {
    let m = &an.mech;
    s.slides(an)
        .iter()
        .map(|sl| {
            let pr = &m.prismatics[sl.pair];
            let mut e = Map::new();
            e.insert("slider".into(), json!(m.link_id(pr.slider)));
            e.insert("guide".into(), json!(m.link_id(pr.guide)));
            e.insert("point".into(), json!(m.point_name(pr.point)));
            e.insert("s".into(), num(sl.s));
            let (s_q, s_qq) = if want.several {
                (
                    Value::Array(sl.s_qs.iter().map(|x| num(*x)).collect()),
                    matrix(Some(&sl.s_qqs), num),
                )
            } else {
                (num(sl.s_q), num(sl.s_qq))
            };
            if want.vel {
                e.insert("v".into(), num(sl.v));
                e.insert("s_q".into(), s_q);
            }
            if want.acc {
                e.insert("a".into(), num(sl.a));
                e.insert("s_qq".into(), s_qq);
                if pr.guide != m.frame() {
                    e.insert("coriolis".into(), vec2(sl.coriolis));
                }
            }
            Value::Object(e)
        })
        .collect()
}

/// A position's cross-check of the routes (or the fast path's residuals),
/// with the data sensitivity and the bounds when found.
fn crosscheck_json(c: &CrossCheck, want: Orders) -> Value {
    let mut check = match c.method {
        Method::Routes => json!({
            "max_rel_diff": num(c.max_rel_diff),
            "worst": c.worst.to_string(),
            "conditioning": num(c.conditioning),
            "time_s": { "contour": num(c.contour_time), "constraint": num(c.constraint_time), "plans": num(c.plan_time) },
        }),
        // The fast path: route (b)'s equations at route (a)'s answer.
        Method::Residuals { .. } => json!({
            "method": "residuals",
            "max_rel_residual": num(c.max_rel_diff),
            "worst": c.worst.to_string(),
            "conditioning": num(c.conditioning),
            "time_s": { "contour": num(c.contour_time), "check": num(c.constraint_time) },
        }),
    };
    if let Some(sens) = c.data_sensitivity {
        check["data_sensitivity"] = num(sens);
    }
    if let Method::Residuals { linear_data } = c.method {
        check["data_check"] = json!(if linear_data { "linear" } else { "solved" });
    }
    if let Some(b) = &c.bound {
        let mut fields = vec![("p", b.p), ("angle", b.angle)];
        if want.vel {
            fields.extend([("v", b.v), ("omega", b.omega)]);
            fields.extend([("v_q", b.v_q), ("phi_q", b.phi_q)]);
        }
        if want.acc {
            fields.extend([("a", b.a), ("epsilon", b.epsilon)]);
            fields.extend([("a_q", b.a_q), ("phi_qq", b.phi_qq)]);
        }
        let bound: Map<String, Value> = fields
            .into_iter()
            .map(|(k, x)| (k.to_string(), num(x)))
            .collect();
        check["bound"] = Value::Object(bound);
    }
    check
}

/// What `solve` prints.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Style {
    /// [`to_table`], in a language.
    Table(Lang),
    /// [`to_json`], pretty-printed, with a final newline.
    Json,
    /// A row per position ([`csv_head`], [`csv_row`]).
    Csv,
    /// A line per position: [`position_json`] on one line.
    Jsonl,
    /// [`to_steps`].
    Steps(Lang),
}

/// A CSV field: as it is, or in double quotes (doubled inside) when it
/// holds a comma, a quote or a line break (RFC 4180).
pub fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// A number as the JSON result writes it (shortest round trip, no `-0`),
/// appended to `out` without a string of its own: serde_json's own writing
/// of a number (zmij's shortest round trip; `null` where not finite), the
/// same text to the byte.
fn push_num(out: &mut String, x: f64) {
    if x.is_finite() {
        let x = if x == 0.0 { 0.0 } else { x };
        out.push_str(zmij::Buffer::new().format_finite(x));
    } else {
        out.push_str("null");
    }
}

/// The CSV result's header line (docs/scene-format.md, "CSV and JSONL
/// results"): `position`; each input's value (`phi_ID` in degrees for a
/// crank, `s_ID` in m for a slider, ID its link's id); each wanted point's
/// `x_P`, `y_P`, then with velocities `vx_P`, `vy_P`, with accelerations
/// `ax_P`, `ay_P`; each solved link's `angle_N` (degrees), then `omega_N`,
/// `epsilon_N` as wanted.
pub fn csv_head(an: &Analysis) -> String {
    let m = &an.mech;
    let Orders { vel, acc, .. } = Orders::of(an);
    let mut cols = vec!["position".to_string()];
    for spec in m.scene.inputs() {
        let id = m.link_id(spec.link());
        cols.push(match spec {
            InputSpec::Crank { .. } => format!("phi_{id}"),
            InputSpec::Slider { .. } => format!("s_{id}"),
        });
    }
    for &p in &an.points {
        let name = m.point_name(p);
        let mut kinds = vec!["x", "y"];
        if vel {
            kinds.extend(["vx", "vy"]);
        }
        if acc {
            kinds.extend(["ax", "ay"]);
        }
        cols.extend(kinds.iter().map(|k| format!("{k}_{name}")));
    }
    for l in (0..m.links.len()).filter(|&l| an.link(l)) {
        let id = m.link_id(l);
        cols.push(format!("angle_{id}"));
        if vel {
            cols.push(format!("omega_{id}"));
        }
        if acc {
            cols.push(format!("epsilon_{id}"));
        }
    }
    let cols: Vec<String> = cols.iter().map(|c| csv_field(c)).collect();
    cols.join(",") + "\n"
}

/// The CSV row of position `k` (from 0), the columns of [`csv_head`] (its
/// `position` the number the sheets show), the numbers as the JSON result
/// writes them.
pub fn csv_row(an: &Analysis, k: usize, s: &Solved) -> String {
    let m = &an.mech;
    let Orders { vel, acc, .. } = Orders::of(an);
    let mut row = String::with_capacity(512);
    write!(row, "{}", super::position_number(an, k)).expect("a String takes any text");
    let mut cell = |x: f64| {
        row.push(',');
        push_num(&mut row, x);
    };
    for (spec, d) in m.scene.inputs().zip(s.drives.iter()) {
        cell(match spec {
            InputSpec::Crank { .. } => d.q.to_degrees(),
            InputSpec::Slider { .. } => d.q,
        });
    }
    for &p in &an.points {
        let ps = s.point(an, p);
        cell(ps.at.x);
        cell(ps.at.y);
        if let Some((v, a)) = ps.rates.filter(|_| vel) {
            cell(v.x);
            cell(v.y);
            if acc {
                cell(a.x);
                cell(a.y);
            }
        }
    }
    for l in (0..m.links.len()).filter(|&l| an.link(l)) {
        cell(deg(s.config.pose(l).angle));
        if let Some(mo) = s.motion[l].filter(|_| vel) {
            cell(mo.omega);
            if acc {
                cell(mo.epsilon);
            }
        }
    }
    row.push('\n');
    row
}

/// The result text of `solve` a position at a time: this head, then
/// [`text_position`] of every position in order, then [`text_tail`];
/// together, byte for byte, the text of the whole result in `style`, so
/// that a long sweep need be neither kept nor built as one document.
pub fn text_head(an: &Analysis, style: Style) -> String {
    match style {
        Style::Table(lang) => table_head(an, lang),
        Style::Steps(lang) => steps_head(an, lang),
        Style::Csv => csv_head(an),
        Style::Jsonl => String::new(),
        Style::Json => {
            // The document with no positions ends `"positions": []\n}`:
            // the head is everything before the brackets.
            let mut doc = json_head(an);
            doc.insert("positions".into(), Value::Array(Vec::new()));
            let text =
                serde_json::to_string_pretty(&Value::Object(doc)).expect("JSON of finite numbers");
            text.strip_suffix("[]\n}")
                .expect("positions come last")
                .to_string()
        }
    }
}

/// The text of position `k` (from 0) of the result, after those before it.
pub fn text_position(an: &Analysis, style: Style, k: usize, s: &Solved) -> String {
    match style {
        Style::Table(lang) => table_position(an, k, s, lang),
        Style::Steps(lang) => steps_position(an, k, s, lang),
        Style::Csv => csv_row(an, k, s),
        Style::Jsonl => {
            serde_json::to_string(&position_json(an, k, s)).expect("JSON of finite numbers") + "\n"
        }
        Style::Json => {
            // An element of the top-level array: pretty-printed two levels
            // deep, so every line is indented by four spaces (strings
            // escape their line breaks, so lines are the printer's own).
            let text = serde_json::to_string_pretty(&position_json(an, k, s))
                .expect("JSON of finite numbers");
            let mut out = String::with_capacity(text.len() + text.len() / 8);
            out.push_str(if k == 0 { "[\n" } else { ",\n" });
            for (i, line) in text.split('\n').enumerate() {
                if i > 0 {
                    out.push('\n');
                }
                out.push_str("    ");
                out.push_str(line);
            }
            out
        }
    }
}

/// The end of the result text, after `count` positions.
pub fn text_tail(_an: &Analysis, style: Style, count: usize) -> String {
    match style {
        Style::Table(_) | Style::Steps(_) | Style::Csv | Style::Jsonl => String::new(),
        Style::Json if count == 0 => "[]\n}\n".into(),
        Style::Json => "\n  ]\n}\n".into(),
    }
}

/// The whole result text in `style` (as [`text_head`], [`text_position`]
/// of each, [`text_tail`]).
#[cfg(feature = "internals")]
pub fn to_text(an: &Analysis, solved: &[Solved], style: Style) -> String {
    let mut t = text_head(an, style);
    for (k, s) in solved.iter().enumerate() {
        t += &text_position(an, style, k, s);
    }
    t + &text_tail(an, style, solved.len())
}

/// A plan in the result: μ, the plan points in mm from the pole (named
/// points by their lower-case names, construction points as documented in
/// docs/scene-format.md), the worst intersection angle and the drafting
/// bounds of what was measured.
fn plan_json(plan: &crate::kinematics::construction::Plan) -> Value {
    let mut points = Map::new();
    for p in plan.points.iter().skip(1) {
        points.insert(p.key.clone(), json!([num(p.at.x), num(p.at.y)]));
    }
    let measured: Vec<Value> = plan
        .measured
        .iter()
        .map(|q| json!({ "quantity": q.quantity, "from": plan.points[q.from].key, "to": plan.points[q.to].key, "mm": num(q.mm), "value": num(q.value), "bound": num(q.bound) }))
        .collect();
    json!({
        "mu": num(plan.mu),
        "points": points,
        "worst_angle": num(plan.worst_angle_deg()),
        "delta": num(plan.delta),
        "measured": measured,
    })
}
