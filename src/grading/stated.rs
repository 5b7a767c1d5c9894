//! The values an acceleration answer states as read off its velocity
//! plan (`velocity.values`: the links' ω, relative sliding velocities),
//! each judged against the true value with the tolerance of reading it
//! off a velocity plan drawn at the student's μ_v with their pencil (the
//! plan's drafting error of the measured segment) and of the digits it is
//! written with. A value stated wrong is a mistake of its own, made before
//! the acceleration plan is drawn; the plan is then judged as built with
//! it (every normal component and Coriolis acceleration with the ω the
//! student states), so its consistent steps are not blamed.

use super::answer::{Stated, StatedQuantity};
use super::candidates::Builds;
use super::items::slide_of;
use super::verdict::{Candidate, Found, Judgement, Verdict};
use crate::accuracy::ACCURACY;
use crate::error::{Issue, Result};
use crate::format::format_number;
use crate::kinematics::construction::{Op, Plan};
use crate::lang::Lang;
use crate::words::check;
use crate::words::numbers::decimals;

/// One stated value judged: its verdict, and the mistake when it is wrong.
pub(super) struct StatedJudged {
    pub(super) verdict: Verdict,
    pub(super) found: Option<Found>,
}

/// The true value of a stated quantity on the velocity plan `vel`: the
/// value (signed ω; a sliding velocity's magnitude), its drafting bound,
/// its segment on the plan (mm) and the plan's step that measures it.
struct Truth {
    value: f64,
    bound: f64,
    mm_per_unit: f64,
    step: Option<usize>,
    /// A sliding velocity's segment on the plan (b2b3), where no step
    /// measures it.
    segment: Option<String>,
    unit: &'static str,
}

/// Every stated value of the answer judged; `Err` names a link or point
/// the scene does not have.
pub(super) fn judge(b: &Builds, lang: Lang) -> Result<Vec<StatedJudged>> {
    if b.ans.stated.is_empty() {
        return Ok(Vec::new());
    }
    let vel = b.velocity_plan(&b.s.config)?;
    let mut issues = Vec::new();
    let mut truths = Vec::new();
    for s in &b.ans.stated {
        match truth(b, &vel, s) {
            Ok(t) => truths.push(t),
            Err(i) => issues.push(i),
        }
    }
    if !issues.is_empty() {
        return Err(crate::error::Error::fields(issues));
    }
    // A number written to fewer digits than the plan reads it to (ω = 3
    // read off as 3.40) is allowed its rounding only up to the plan's own
    // bound: a coarse number is no licence for a wrong one.
    let stated: Vec<Stated> = b
        .ans
        .stated
        .iter()
        .zip(&truths)
        .map(|(s, t)| Stated {
            rounding: s.rounding.min(t.bound),
            ..s.clone()
        })
        .collect();
    let common = common_factor(&stated, &truths);
    let w = check::phrases(lang);
    let fmt = |x: f64| decimals(&format_number(x), lang);
    let mut out = Vec::new();
    for (index, (s, t)) in stated.iter().zip(&truths).enumerate() {
        let name = name_of(s);
        let tol = t.bound + s.rounding;
        let difference = (s.value - t.value).abs();
        let wrong = difference > tol;
        let unreadable = if wrong {
            None
        } else {
            ambiguous(b, s, t, &vel, lang)
        };
        let sentence = match (t.step, &t.segment) {
            (Some(k), _) => check::step(&vel, k, lang),
            (None, Some(segment)) => check::fill(
                &w.stated_slide,
                &[
                    ("name", &name),
                    ("segment", segment),
                    ("mm", &fmt(t.value * t.mm_per_unit)),
                    ("mu", &fmt(1.0 / t.mm_per_unit)),
                    ("value", &fmt(t.value)),
                ],
            ),
            (None, None) => {
                check::fill(&w.stated_given, &[("name", &name), ("value", &fmt(t.value))])
            }
        };
        let step_text = check::fill(&w.stated_step, &[("sentence", &sentence)]);
        let found = wrong.then(|| {
            let yours = check::fill(
                &w.yours,
                &[("value", &format!("{} {}", fmt(s.value), crate::words::numbers::unit(t.unit, lang)))],
            );
            Found {
                explanation: Some(Candidate::Stated { index }),
                mistake: Some(diagnosis(b, s, t, &vel, common, lang)),
                step: (0, format!("{step_text} ({yours})")),
                points: Vec::new(),
                alternatives: Vec::new(),
            }
        });
        out.push(StatedJudged {
            verdict: Verdict {
                pointer: s.pointer.clone(),
                key: s.key.clone(),
                what: check::fill(&w.stated_item, &[("name", &name)]),
                expected: t.value,
                given: s.value,
                difference,
                tolerance: tol,
                unit: t.unit,
                on_plan: (t.mm_per_unit > 0.0)
                    .then(|| (t.value.abs() * t.mm_per_unit, s.value.abs() * t.mm_per_unit)),
                step: Some((0, step_text)),
                judgement: match unreadable {
                    _ if wrong => Judgement::Wrong,
                    Some(why) => Judgement::CannotJudge(why),
                    None => Judgement::Right,
                },
            },
            found,
        });
    }
    Ok(out)
}

/// The stated value's name as the lecture writes it: ω2, v_B3B2.
fn name_of(s: &Stated) -> String {
    match &s.quantity {
        StatedQuantity::Omega(id) => format!("ω{id}"),
        StatedQuantity::Slide(raw) => format!("v_{raw}"),
    }
}

/// What the true velocity plan gives for stated value `s`.
fn truth(b: &Builds, vel: &Plan, s: &Stated) -> std::result::Result<Truth, Issue> {
    let m = &b.an.mech;
    let issue = |message: String| Issue {
        pointer: s.pointer.clone(),
        message,
    };
    match &s.quantity {
        StatedQuantity::Omega(id) => {
            let l = m
                .scene
                .link_index(id)
                .ok_or_else(|| issue(format!("unknown link \"{id}\"")))?;
            let (value, bound) = vel.rates[l].ok_or_else(|| {
                issue(format!(
                    "link {id} is not constructed on the velocity plan: its ω is not read off it"
                ))
            })?;
            let name = format!("ω{id}");
            let step = vel.steps.iter().position(|st| match &st.op {
                Op::Measure {
                    rate: Some((r, ..)),
                    ..
                } => *r == name,
                Op::Same { link, what, .. } => link == id && what == "ω",
                _ => false,
            });
            let len = vel.rate_len[l];
            Ok(Truth {
                value,
                bound,
                mm_per_unit: if len > 0.0 { len / vel.mu } else { 0.0 },
                step,
                segment: None,
                unit: "rad/s",
            })
        }
        StatedQuantity::Slide(raw) => {
            let (p, l1, l2) = slide_of(m, raw).ok_or_else(|| {
                issue(format!(
                    "cannot read \"{raw}\" as a point of one link relative to another (v_B3B2: B of link 3 on link 2)"
                ))
            })?;
            let c = &b.s.config;
            let at = super::candidates::world_of(m, c, p)
                .ok_or_else(|| issue(format!("point {} is not on the velocity plan", m.point_name(p))))?;
            let find = |l: usize| {
                c.poses[l]?;
                let local = c.pose(l).local(at);
                vel.known_at(l, local, 1e-9 * m.link_scale(l).max(1e-300))
            };
            let (Some(i1), Some(i2)) = (find(l1), find(l2)) else {
                return Err(issue(format!(
                    "v_{raw}: the velocity plan has no points of {} on links {} and {} to read it off",
                    m.point_name(p),
                    m.link_id(l1),
                    m.link_id(l2)
                )));
            };
            let (a, z) = (&vel.points[i1], &vel.points[i2]);
            Ok(Truth {
                value: (a.at - z.at).hypot() * vel.mu,
                bound: (a.err + z.err + b.ans.delta) * vel.mu,
                mm_per_unit: 1.0 / vel.mu,
                step: None,
                segment: Some(format!("{}{}", z.name(), a.name())),
                unit: "m/s",
            })
        }
    }
}

/// The typical ways a value is read off the velocity plan wrong, as
/// factors of the true value, each with its name: the sense the wrong way
/// (×−1), μ_v in the wrong units (×1000, ×1/1000), the relative segment
/// taken half or twice (×½, ×2), the link's length taken for another's
/// (× l_own/l_other).
fn misreadings(b: &Builds, s: &Stated, vel: &Plan, lang: Lang) -> Vec<(f64, String)> {
    let w = check::phrases(lang);
    let name = name_of(s);
    let mut out = vec![
        (-1.0, check::fill(&w.stated_sense, &[("name", &name)])),
        (1000.0, w.stated_units.clone()),
        (1e-3, w.stated_units.clone()),
        (0.5, check::fill(&w.stated_plain, &[("name", &name)])),
        (2.0, check::fill(&w.stated_plain, &[("name", &name)])),
    ];
    if matches!(s.quantity, StatedQuantity::Slide(_)) {
        out.remove(0);
    }
    out.extend(lengths(b, s, vel).into_iter().map(|(f, own, other)| {
        let args = [("name", name.as_str()), ("own", &own), ("other", &other)];
        (f, check::fill(&w.stated_length, &args))
    }));
    out
}

/// Why a stated value within its tolerance cannot be judged: a typical
/// misreading ([`misreadings`]) puts the value within its own tolerance
/// too (the misread value's tolerance scales with it), visibly apart from
/// the true one (by more than the rounding of the digits written), and no
/// worse than the true value explains it. On a
/// velocity plan drawn so coarsely, or so near a dead point, that its
/// tolerance covers both, the stated value could be either; elsewhere a
/// value near the true one is right.
fn ambiguous(b: &Builds, s: &Stated, t: &Truth, vel: &Plan, lang: Lang) -> Option<String> {
    let w = check::phrases(lang);
    let fmt = |x: f64| decimals(&format_number(x), lang);
    misreadings(b, s, vel, lang).into_iter().find_map(|(f, why)| {
        let value = f * t.value;
        let (tol_t, tol_m) = (t.bound + s.rounding, f.abs() * t.bound + s.rounding);
        let within = (s.value - value).abs() <= tol_m;
        // Two readings less than 2δ apart on the velocity plan (or within
        // the digits written) are one reading: each is drawn to δ; nor is
        // a misreading another reading where it changes the value by less
        // than half the true reading's tolerance and less than a quarter
        // of the value (an honest hand scatters that far: a factor near 1,
        // as two links of nearly one length give, is no alternative; half
        // or twice the value always is).
        let moved = (value - t.value).abs();
        let apart = moved > 2.0 * s.rounding
            && moved > (0.5 * tol_t).min(0.25 * t.value.abs())
            && (t.mm_per_unit == 0.0 || moved * t.mm_per_unit > 2.0 * b.ans.delta);
        // As likely a reading as the right one: each scatters within its
        // own tolerance as a step's point does (ACCURACY.step_scatter), so
        // the misreading's wider spread makes a value near it less likely.
        let density = |d: f64, tol: f64| {
            let m = d / tol.max(1e-300);
            ACCURACY.step_scatter * (1.0 - m * m).max(1e-300).ln() - tol.max(1e-300).ln()
        };
        let likelier =
            density((s.value - value).abs(), tol_m) >= density((s.value - t.value).abs(), tol_t);
        (within && apart && likelier).then(|| {
            // Drawn k times larger, the velocity plan's bound shrinks k
            // times while the two values stay apart.
            let k = (2.0 * (f.abs() + 1.0) * t.bound / (value - t.value).abs()).max(1.1);
            let tol_mm = t.bound * t.mm_per_unit;
            check::fill(
                &w.ambiguous_stated,
                &[
                    ("tol", &fmt(t.bound + s.rounding)),
                    ("mistake", &why),
                    ("value", &fmt(value)),
                    ("mm", &fmt(tol_mm)),
                    ("k", &fmt((k * 10.0).ceil() / 10.0)),
                ],
            )
        })
    })
}

/// The factor by which every stated ω is off, where at least two are
/// wrong and one factor explains them all (each within its tolerance):
/// the velocity plan's μ_v applied wrongly.
fn common_factor(stated: &[Stated], truths: &[Truth]) -> Option<f64> {
    let pairs: Vec<(&Stated, &Truth)> = stated
        .iter()
        .zip(truths)
        .filter(|(s, t)| {
            matches!(s.quantity, StatedQuantity::Omega(_))
                && t.value != 0.0
                && (s.value - t.value).abs() > t.bound + s.rounding
        })
        .collect();
    if pairs.len() < 2 {
        return None;
    }
    let (s0, t0) = pairs[0];
    let q = s0.value / t0.value;
    (q > 0.0
        && pairs
            .iter()
            .all(|(s, t)| (s.value - q * t.value).abs() <= q.abs() * t.bound + s.rounding))
    .then_some(q)
}

/// Why stated value `s` is wrong, in one sentence: its sense read the
/// wrong way, μ_v in the wrong units, the link's length taken for
/// another's, μ_v applied wrongly (every ω off by one factor), else read
/// off wrong.
fn diagnosis(
    b: &Builds,
    s: &Stated,
    t: &Truth,
    vel: &Plan,
    common: Option<f64>,
    lang: Lang,
) -> String {
    let w = check::phrases(lang);
    let fmt = |x: f64| decimals(&format_number(x), lang);
    let name = name_of(s);
    let unit = crate::words::numbers::unit(t.unit, lang);
    let head = check::fill(
        &w.stated_wrong,
        &[
            ("name", &name),
            ("given", &fmt(s.value)),
            ("expected", &fmt(t.value)),
            ("tol", &fmt(t.bound + s.rounding)),
            ("unit", &unit),
        ],
    );
    let tol = t.bound + s.rounding;
    let why = if matches!(s.quantity, StatedQuantity::Omega(_)) && (s.value + t.value).abs() <= tol {
        check::fill(&w.stated_sense, &[("name", &name)])
    } else if [1000.0, 1e-3]
        .iter()
        .any(|f| (s.value - f * t.value).abs() <= f * tol + s.rounding)
    {
        w.stated_units.clone()
    } else if let Some((own, other)) = other_length(b, s, t, vel) {
        check::fill(
            &w.stated_length,
            &[("name", &name), ("own", &own), ("other", &other)],
        )
    } else if let Some(q) = common {
        check::fill(&w.stated_common, &[("factor", &fmt(q))])
    } else {
        check::fill(&w.stated_plain, &[("name", &name)])
    };
    format!("{head} {why}")
}

/// The factors l_own/l_other by which a stated ω is off where it is its
/// relative velocity over another length: ab read with the crank's length
/// (ω2 = v_BA/l_OA), a rocking guide's whole length for the length the
/// slider stands at (l_CD for l_CB3). Its own length is the one the
/// velocity plan `vel` measures it over; the others, the lengths it
/// measures the other links' ω over, the cranks' and the link's own whole
/// length (between its first two points). Each with the two segments'
/// names (l_AB, l_OA).
fn lengths(b: &Builds, s: &Stated, vel: &Plan) -> Vec<(f64, String, String)> {
    let StatedQuantity::Omega(id) = &s.quantity else {
        return Vec::new();
    };
    let m = &b.an.mech;
    let Some(l) = m.scene.link_index(id) else {
        return Vec::new();
    };
    let c = &b.s.config;
    // The segments the velocity plan measures rates over: (link, length,
    // name).
    let measured: Vec<(usize, f64, String)> = vel
        .steps
        .iter()
        .filter_map(|st| match &st.op {
            Op::Measure {
                length: Some(len),
                rate: Some((name, _, (j, x))),
                ..
            } => {
                let k = m.scene.link_index(name.trim_start_matches('ω'))?;
                Some((k, *len, format!("l_{j}{x}")))
            }
            _ => None,
        })
        .collect();
    let whole = |k: usize| -> Option<(f64, String)> {
        let pts = &m.links[k].points;
        let (&p, &q) = (pts.first()?, pts.get(1)?);
        c.poses[k]?;
        let d = (c.point(m, k, q) - c.point(m, k, p)).hypot();
        (d > 0.0).then(|| (d, format!("l_{}{}", m.point_name(p), m.point_name(q))))
    };
    let Some((own, own_name)) = measured
        .iter()
        .find(|x| x.0 == l)
        .map(|x| (x.1, x.2.clone()))
        .or_else(|| whole(l))
    else {
        return Vec::new();
    };
    // The lengths a student takes by mistake: another link's the plan
    // measures a rate over, the crank's, the link's own whole length (a
    // rocking guide's CD for the CB3 the slider stands at).
    let mut others: Vec<(f64, String)> = measured
        .iter()
        .filter(|x| x.0 != l)
        .map(|x| (x.1, x.2.clone()))
        .collect();
    let inputs = m.scene.inputs().map(|i| i.link());
    others.extend(inputs.chain([l]).filter(|&k| k != m.frame()).filter_map(whole));
    let mut out: Vec<(f64, String, String)> = Vec::new();
    for (d, name) in others {
        if (d - own).abs() > 1e-6 * own && !out.iter().any(|o| o.2 == name) {
            out.push((own / d, own_name.clone(), name));
        }
    }
    out
}

/// Where a stated ω is its relative velocity over another link's length:
/// the link's own segment and the other one's.
fn other_length(b: &Builds, s: &Stated, t: &Truth, vel: &Plan) -> Option<(String, String)> {
    let tol = t.bound + s.rounding;
    lengths(b, s, vel)
        .into_iter()
        .find(|(f, ..)| (s.value.abs() - t.value.abs() * f).abs() <= tol * f + s.rounding)
        .map(|(_, own, other)| (own, other))
}
