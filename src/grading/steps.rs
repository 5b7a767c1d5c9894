//! Step-relative judging ("error carried forward"), as a teacher marks:
//! the construction replayed with the student's own points in place of
//! the constructed ones ([`crate::kinematics::construction::replay`]),
//! each point the student drew judged at the step that draws it, from the
//! student's earlier points, with that step's own tolerance (the pencil's
//! δ, the reading of the points it uses, a value's own error where one
//! enters) — nothing accumulated along the construction.
//!
//! A wrong step is explained by the typical mistake that, made at that
//! step or at an earlier one whose result the student did not draw, puts
//! the point where the student drew it (every mistake at each of its
//! decisions, the other branch of a group, a slip in one laid-off
//! length); everything after it is judged from the student's points, so
//! a mistake is counted once. A right step "cannot be judged" only where
//! such a mistake would put the point within the step's tolerance too,
//! visibly elsewhere, and explains it at least as well (as likely a
//! place for the mistaken drawing as for the right one); the verdict
//! says how much larger the plan would have to be drawn to tell them
//! apart.

use super::candidates::{Builds, MISTAKES, mistake_sentence_at, other_branches};
use super::verdict::{Candidate, Found, Judgement, MAX_TOLERANCE_OF_PLAN, StepReport, StepVerdict};
use crate::accuracy::ACCURACY;
use crate::error::Result;
use crate::kinematics::construction::{Drawing, Judged, Mistake, Plan, PlanKind, Variant};
use crate::lang::Lang;
use crate::words::check;
use crate::words::numbers::{decimals, quantity};
use kurbo::Vec2;

/// The points the answer gives, as a replay takes them
/// ([`super::table::drawing`]: drawn points, and a table's measures).
pub(super) fn given_points(b: &Builds, standard: &Plan) -> Drawing {
    super::table::drawing(b, standard)
}

/// A mistaken construction replayed on the student's points, and the
/// step (of the right construction, from 0) where it first draws
/// something else.
struct Try {
    c: Candidate,
    plan: Plan,
    enters: usize,
}

impl Try {
    fn entry(&self, j: &Judged) -> Option<&Judged> {
        self.plan
            .judged
            .iter()
            .find(|x| x.id == j.id && x.nth == j.nth)
    }
}

/// What the judge works with: the builds, the student's points, the
/// plain replay, the right plan's size (mm) and the language.
struct Judge<'a> {
    b: &'a Builds<'a>,
    given: &'a Drawing,
    plain: &'a Plan,
    size: f64,
    lang: Lang,
}

/// Judge the answer's drawn points step by step; `None` when it draws no
/// point (its segments and values are then judged on the right plan).
pub(super) fn judge(b: &Builds, standard: &Plan, lang: Lang) -> Result<Option<StepReport>> {
    let given = given_points(b, standard);
    if given.points.is_empty() && given.circles.is_empty() {
        return Ok(None);
    }
    let plain = b.replay(&b.s.config, Variant::default(), &given)?;
    let size = standard
        .points
        .iter()
        .map(|p| p.at.hypot())
        .fold(0.0, f64::max);
    let j = Judge {
        b,
        given: &given,
        plain: &plain,
        size,
        lang,
    };
    let tries = j.tries();
    let mut steps = Vec::new();
    let mut mistakes: Vec<Found> = Vec::new();
    for (k, e) in plain.judged.iter().enumerate() {
        let predicted = e.nearest().0;
        let (off, tolerance) = e.apart(e.given);
        let mut v = StepVerdict {
            step: j.step(e.step),
            point: plain.points[e.point].name(),
            predicted,
            given: e.given,
            off,
            tolerance,
            judgement: Judgement::Right,
            mistake: None,
        };
        let fitting: Vec<(&Try, f64, f64)> = tries
            .iter()
            .filter(|t| j.applies(t, k))
            .filter_map(|t| {
                let x = t.entry(e)?;
                // How far the mistaken construction draws it from the
                // right one, in the step's own measure.
                let moved = e.apart(x.nearest().0).0;
                (x.misfit() <= 1.0).then_some((t, x.misfit(), moved))
            })
            .collect();
        // (For a point where two lines meet, also its place along them: two
        // nearly parallel lines leave it undetermined.)
        // (A point of a figure is judged by whichever right construction
        // fits it best, with that one's tolerance.)
        let along = if e.lines.is_empty() { 0.0 } else { e.tol };
        let wide = tolerance.max(along) > MAX_TOLERANCE_OF_PLAN * size;
        if e.misfit() <= 1.0 && wide {
            // Predicted from points far back (the student drew few), near
            // a dead point: the step cannot place it.
            let tol = quantity(tolerance.max(along), "mm", lang);
            let size = quantity(size, "mm", lang);
            let w = check::phrases(lang);
            // A table's lengths leave their points' directions open: those
            // directions would decide it.
            let open: Vec<String> = plain.judged[..=k]
                .iter()
                .filter(|x| x.on_circle)
                .map(|x| format!("{} {}", plain.points[0].name(), plain.points[x.point].name()))
                .collect();
            let why = if open.is_empty() {
                check::fill(&w.too_wide_step, &[("tol", &tol), ("size", &size)])
            } else {
                let segs = open.join(", ");
                check::fill(&w.too_wide_table, &[("tol", &tol), ("size", &size), ("segs", &segs)])
            };
            v.judgement = Judgement::CannotJudge(why);
        } else if e.misfit() <= 1.0 {
            v.judgement = j
                .ambiguous(e, &fitting)
                .map_or(Judgement::Right, Judgement::CannotJudge);
        } else {
            v.judgement = Judgement::Wrong;
            let found = j.explain(k, &fitting);
            // A mistake explaining several drawn points is counted once.
            let same = mistakes.iter().position(|f| {
                f.explanation.is_some()
                    && f.explanation == found.explanation
                    && f.step == found.step
            });
            let at = match same {
                Some(i) => i,
                None => {
                    mistakes.push(found);
                    mistakes.len() - 1
                }
            };
            mistakes[at].points.push(v.point.clone());
            v.mistake = Some(at);
        }
        steps.push(v);
    }
    // The mistakes in the order of the steps where they enter.
    let mut order: Vec<usize> = (0..mistakes.len()).collect();
    order.sort_by_key(|&i| mistakes[i].step.0);
    for v in &mut steps {
        v.mistake = v.mistake.map(|m| order.iter().position(|&i| i == m).expect("a mistake"));
    }
    let mut mistakes: Vec<Option<Found>> = mistakes.into_iter().map(Some).collect();
    let mistakes = order.iter().map(|&i| mistakes[i].take().expect("once")).collect();
    Ok(Some(StepReport {
        steps,
        mistakes,
        replay: plain,
    }))
}

impl Judge<'_> {
    /// Step `k` (from 0) of the right construction: its number and sentence.
    fn step(&self, k: usize) -> (usize, String) {
        let k = k.min(self.plain.steps.len().saturating_sub(1));
        (k + 1, check::step(self.plain, k, self.lang))
    }

    /// A number of a sentence, with the language's decimal mark.
    fn number(&self, x: f64) -> String {
        decimals(&crate::format::format_number(x), self.lang)
    }

    /// Every typical mistake at each of its decisions (and, for an
    /// acceleration answer, made on the velocity plan), and the other
    /// branch of each group, replayed on the student's points; those that
    /// draw nothing else are left out.
    fn tries(&self) -> Vec<Try> {
        let (b, an) = (self.b, self.b.an);
        let kind = b.ans.plan;
        let mut out = Vec::new();
        let mut keep = |c: Candidate, plan: Plan| {
            if let Some(enters) = self.plain.first_difference(&plan) {
                out.push(Try { c, plan, enters });
            }
        };
        for m in MISTAKES {
            let variant = |at: Option<usize>, on: PlanKind| Variant {
                mistake: Some(m),
                at,
                on: Some(on),
                ..Variant::default()
            };
            let Ok(count) = b.replay(&b.s.config, variant(Some(usize::MAX), kind), self.given)
            else {
                continue;
            };
            // Each decision alone, and the decisions that first move the
            // same drawn point together (both lines of a point drawn
            // wrong, both normals before it reversed).
            let mut groups: Vec<(usize, u64, usize)> = Vec::new();
            for i in 0..count.decisions {
                let Ok(p) = b.replay(&b.s.config, variant(Some(i), kind), self.given) else {
                    continue;
                };
                if let Some(first) = self.first_moved(&p)
                    && i < 64
                {
                    match groups.iter_mut().find(|g| g.0 == first) {
                        Some(g) => {
                            g.1 |= 1 << i;
                            g.2 += 1;
                        }
                        None => groups.push((first, 1 << i, 1)),
                    }
                }
                let c = Candidate::Mistake {
                    m,
                    at: Some(i),
                    both: false,
                };
                keep(c, p);
            }
            for (_, among, n) in groups {
                let v = Variant {
                    among,
                    ..variant(None, kind)
                };
                if n > 1
                    && let Ok(p) = b.replay(&b.s.config, v, self.given)
                {
                    let at = Some(among.trailing_zeros() as usize);
                    keep(Candidate::Mistake { m, at, both: false }, p);
                }
            }
            if count.decisions > 1
                && let Ok(p) = b.replay(&b.s.config, variant(None, kind), self.given)
            {
                keep(Candidate::Mistake { m, at: None, both: false }, p);
            }
            // (An answer that states its ω shows a velocity plan's
            // mistake in those, not here.)
            if kind == PlanKind::Acceleration && !states_omega(b.ans) {
                let on_velocity = variant(None, PlanKind::Velocity);
                if let Ok(p) = b.replay(&b.s.config, on_velocity, self.given) {
                    let c = Candidate::Mistake {
                        m,
                        at: None,
                        both: true,
                    };
                    keep(c, p);
                }
            }
        }
        for (g, c) in other_branches(an, b.s) {
            if let Ok(p) = b.replay(&c, Variant::default(), self.given) {
                keep(Candidate::Branch(g), p);
            }
        }
        out
    }

    /// The first drawn point a mistaken replay `p` puts elsewhere.
    fn first_moved(&self, p: &Plan) -> Option<usize> {
        let scale = 1e-9 * self.size.max(1.0);
        self.plain.judged.iter().position(|e| {
            p.judged
                .iter()
                .find(|x| x.id == e.id && x.nth == e.nth)
                .is_some_and(|x| (x.predicted - e.predicted).hypot() > scale)
        })
    }

    /// Can `t` explain the drawn point `k` of the plain replay? Its
    /// mistake enters at or before the point's step, it moves the point,
    /// its own tolerance there is below a fifth of the plan (else it
    /// judges nothing), and it leaves every earlier point that is right
    /// right (a mistake that shows earlier would have been seen there).
    fn applies(&self, t: &Try, k: usize) -> bool {
        let e = &self.plain.judged[k];
        let Some(x) = t.entry(e) else { return false };
        // (Before the mistake enters, the two constructions are the same
        // step for step; a mistake may add or leave out steps.)
        if t.enters > x.step.max(e.step) {
            return false;
        }
        if x.apart(x.given).1 > MAX_TOLERANCE_OF_PLAN * self.size.max(1e-300)
            || (x.predicted - e.predicted).hypot() <= 1e-9 * self.size.max(1.0)
        {
            return false;
        }
        self.plain.judged[..k]
            .iter()
            .filter(|i| i.misfit() <= 1.0)
            .all(|i| t.entry(i).is_some_and(|y| y.misfit() <= 1.0))
    }

    /// A right point that a mistaken construction (`fitting`: those that
    /// put it within their own tolerance too) would also give, visibly
    /// elsewhere (by more than 2δ where the student put it), and as
    /// likely ([`odds`]): why it cannot be judged here.
    fn ambiguous(&self, e: &Judged, fitting: &[(&Try, f64, f64)]) -> Option<String> {
        // Two constructions whose points lie less than 2δ apart give the
        // same drawing: each is drawn to δ.
        let visible = 2.0 * self.plain.delta;
        // (The other assembly branch is a mistake of the plan of the
        // mechanism, judged there: the scene fixes its branch.)
        let (t, _, moved) = fitting
            .iter()
            .filter(|f| !matches!(f.0.c, Candidate::Branch(_)))
            .filter(|f| {
                let x = f.0.entry(e).expect("fits");
                // Where both draw two lines, one drawing where those that
                // differ pass the student's point within 2δ of each other
                // (their meeting points may lie far apart along lines at
                // a glancing angle); else where their places do.
                let seen = match (e.lines.as_slice(), x.lines.as_slice()) {
                    // A point known by its length alone: where the two
                    // constructions' lengths are apart (a plan turned
                    // through the pole has every length the same).
                    _ if e.on_circle => {
                        (x.predicted.hypot() - e.predicted.hypot()).abs() > visible
                    }
                    ([_, _], [_, _]) => separation(e, x) > visible,
                    _ => f.2 > visible,
                };
                // A point known by its length alone: the mistake's own
                // replay puts every later point of the answer on its
                // circle too, or the answer rules it out.
                let whole = !e.on_circle || f.0.plan.judged.iter().all(|y| y.misfit() <= 1.0);
                seen && whole && odds(e, x) >= 0.0
            })
            .min_by(|a, b| a.2.total_cmp(&b.2))?;
        let mu = self.b.ans.mu;
        let x = t.entry(e).expect("fits");
        // Told apart when their tolerances' disks no longer overlap: the
        // distance between them grows with the plan's size.
        let tol = e.apart(e.given).1;
        // Drawn k times larger, each construction's place lies k times
        // farther from the other's lines (or place) while the tolerances
        // stay: told apart when each is two tolerances from the other.
        let m = x
            .misfit_at(e.nearest().0)
            .min(e.misfit_at(x.nearest().0))
            .max(1e-9);
        let k = (2.0 / m).max(1.1);
        if e.on_circle {
            // A length without its direction: the direction decides.
            let seg = format!("{} {}", self.plain.points[0].name(), self.plain.points[e.point].name());
            return Some(check::fill(
                &check::phrases(self.lang).ambiguous_circle,
                &[
                    ("tol", &quantity(tol, "mm", self.lang)),
                    ("moved", &quantity(*moved, "mm", self.lang)),
                    ("mistake", &self.sentence(t)),
                    ("seg", &seg),
                ],
            ));
        }
        Some(check::fill(
            &check::phrases(self.lang).ambiguous_step,
            &[
                ("tol", &quantity(tol, "mm", self.lang)),
                ("moved", &quantity(*moved, "mm", self.lang)),
                ("mistake", &self.sentence(t)),
                ("k", &self.number((k * 10.0).ceil() / 10.0)),
                ("mu", &self.number(mu / k)),
            ],
        ))
    }

    /// The step where `t`'s mistake enters: its number, and the right
    /// construction's sentence for it (the step drawn wrong or left out);
    /// for a step the mistake adds (a tangential component of the crank
    /// although ε1 = 0), the added step's own.
    fn entry_step(&self, t: &Try) -> (usize, String) {
        let adds = matches!(
            t.c,
            Candidate::Mistake {
                m: Mistake::Epsilon1Added,
                ..
            }
        );
        if adds && t.enters < t.plan.steps.len() {
            return (t.enters + 1, check::step(&t.plan, t.enters, self.lang));
        }
        let (k, mut sentence) = self.step(t.enters);
        if let Some(yours) = self.yours(k - 1) {
            sentence.push_str(&format!(" ({yours})"));
        }
        (k, sentence)
    }

    /// The student's own length beside the right one of step `k` (from
    /// 0), where it lays off a vector whose end the student drew
    /// elsewhere: "yours: 75.58 mm".
    fn yours(&self, k: usize) -> Option<String> {
        let crate::kinematics::construction::Op::LayOff { from, to, value, .. } =
            self.plain.steps.get(k)?.op
        else {
            return None;
        };
        self.plain.judged.iter().find(|j| j.point == to)?;
        let pts = &self.plain.points;
        let drawn = (pts[to].at - pts[from].at).hypot();
        let right = value / self.plain.mu;
        ((drawn - right).abs() > 0.01).then(|| {
            let mm = quantity(drawn, "mm", self.lang);
            check::fill(&check::phrases(self.lang).yours, &[("value", &mm)])
        })
    }

    fn sentence(&self, t: &Try) -> String {
        let what = match self.plain.steps.get(t.enters).map(|s| &s.op) {
            Some(crate::kinematics::construction::Op::LayOff { what, .. }) => what.clone(),
            _ => check::phrases(self.lang).a_vector.clone(),
        };
        let at = Some((self.plain, t.enters));
        let s = mistake_sentence_at(t.c, self.b.ans.mu, &what, at, self.lang);
        match t.c {
            Candidate::Mistake { both: true, .. } => {
                check::fill(&check::phrases(self.lang).on_velocity_plan, &[("mistake", &s)])
            }
            _ => s,
        }
    }

    /// The mistake that explains wrong point `k`: of the constructions
    /// that put it within their tolerance, the one that fits best, named
    /// unless one of another kind fits about as well; else a slip in one
    /// laid-off length; else not recognised, at the point's own step.
    fn explain(&self, k: usize, fitting: &[(&Try, f64, f64)]) -> Found {
        let e = &self.plain.judged[k];
        let mut by_fit: Vec<&(&Try, f64, f64)> = fitting.iter().collect();
        by_fit.sort_by(|a, b| a.1.total_cmp(&b.1));
        if let Some(&&(best, misfit, _)) = by_fit.first() {
            let mut alternatives: Vec<String> = by_fit[1..]
                .iter()
                .filter(|f| {
                    f.1 <= ACCURACY.step_distinct_misfit * misfit.max(0.05)
                        && !same_kind(f.0.c, best.c)
                })
                .map(|f| self.sentence(f.0))
                .collect();
            let mut seen = std::collections::HashSet::new();
            alternatives.retain(|a| seen.insert(a.clone()));
            let named = alternatives.is_empty();
            if !named {
                alternatives.insert(0, self.sentence(best));
            }
            return Found {
                explanation: named.then_some(best.c),
                mistake: named.then(|| self.sentence(best)),
                step: self.entry_step(best),
                points: Vec::new(),
                alternatives,
            };
        }
        if let Some(t) = self.slip(k) {
            return Found {
                explanation: Some(t.c),
                mistake: Some(self.sentence(&t)),
                step: self.entry_step(&t),
                points: Vec::new(),
                alternatives: Vec::new(),
            };
        }
        Found {
            explanation: None,
            mistake: None,
            step: self.step(e.step),
            points: Vec::new(),
            alternatives: Vec::new(),
        }
    }

    /// A slip in one laid-off length that puts wrong point `k` where the
    /// student drew it: each laid-off vector before the point's step, its
    /// factor found from two replays (the point moves linearly with it
    /// while the student's later points are held) and confirmed by a
    /// third; factors that are another named mistake (0: forgotten, −1:
    /// reversed, ½: a factor 2 forgotten) are left to those.
    fn slip(&self, k: usize) -> Option<Try> {
        let (b, e) = (self.b, &self.plain.judged[k]);
        let variant = |at: usize, factor: f64| Variant {
            mistake: Some(Mistake::Slip),
            at: Some(at),
            on: Some(b.ans.plan),
            factor,
            ..Variant::default()
        };
        let count = b
            .replay(&b.s.config, variant(usize::MAX, 1.0), self.given)
            .ok()?
            .decisions;
        let mut best: Option<(Try, f64)> = None;
        for at in 0..count {
            let Ok(twice) = b.replay(&b.s.config, variant(at, 2.0), self.given) else {
                continue;
            };
            let Some(enters) = self.plain.first_difference(&twice) else {
                continue;
            };
            let t = Try {
                c: Candidate::Slip { at, factor: 2.0 },
                plan: twice,
                enters,
            };
            if !self.applies(&t, k) {
                continue;
            }
            let d = t.entry(e).expect("applies").predicted - e.predicted;
            let factor = 1.0 + (e.given - e.predicted).dot(d) / d.hypot2();
            // A slip is a length misread or miscomputed, not another
            // vector: a factor beyond 50 or below 1/50, or a vector turned
            // back (a negative one), is no slip.
            if [0.0, -1.0, 0.5, 1.0]
                .iter()
                .any(|&x| (factor - x).abs() < 0.02)
                || !(0.02..=50.0).contains(&factor)
            {
                continue;
            }
            let Ok(plan) = b.replay(&b.s.config, variant(at, factor), self.given) else {
                continue;
            };
            let t = Try {
                c: Candidate::Slip { at, factor },
                plan,
                enters,
            };
            let Some(misfit) = t.entry(e).map(Judged::misfit) else {
                continue;
            };
            if misfit <= 1.0 && self.applies(&t, k) && best.as_ref().is_none_or(|x| misfit < x.1) {
                best = Some((t, misfit));
            }
        }
        best.map(|b| b.0)
    }
}

/// Does the answer state any ω it took from its velocity plan?
fn states_omega(ans: &super::answer::Answer) -> bool {
    ans.stated
        .iter()
        .any(|s| matches!(s.quantity, super::answer::StatedQuantity::Omega(_)))
}

/// Two candidates that name the same mistake.
fn same_kind(a: Candidate, b: Candidate) -> bool {
    match (a, b) {
        (Candidate::Mistake { m: x, .. }, Candidate::Mistake { m: y, .. }) => x == y,
        (Candidate::Branch(_), Candidate::Branch(_)) => true,
        (Candidate::Slip { .. }, Candidate::Slip { .. }) => true,
        _ => a == b,
    }
}

/// A line a judged point is read off: a point on it, its direction, its
/// tolerance.
type Line = (Vec2, Vec2, f64);

/// The lines of `of` that `other` does not draw alike.
fn distinct<'a>(of: &'a [Line], other: &'a [Line]) -> impl Iterator<Item = &'a Line> {
    let same = |a: &Line, b: &Line| {
        let scale = 1.0 + a.0.hypot().max(b.0.hypot());
        a.1.cross(b.1).abs() <= 1e-9 && (b.0 - a.0).cross(a.1).abs() <= 1e-9 * scale
    };
    of.iter().filter(move |l| !other.iter().any(|m| same(l, m)))
}

/// How far from each other the lines that differ between the right
/// step `e` and a mistaken one `x` pass where the student put the point:
/// each line paired with the one it corresponds to (the pairing that
/// keeps them closest), the distance from the foot of the point on each
/// to the other, the largest.
fn separation(e: &Judged, x: &Judged) -> f64 {
    let at = e.given;
    let foot = |l: &Line| l.0 + l.1 * (at - l.0).dot(l.1);
    let off = |p: Vec2, l: &Line| (p - l.0).cross(l.1).abs();
    let apart = |l: &Line, m: &Line| off(foot(l), m).max(off(foot(m), l));
    let own: Vec<&Line> = distinct(&e.lines, &x.lines).collect();
    let mis: Vec<&Line> = distinct(&x.lines, &e.lines).collect();
    match (own.as_slice(), mis.as_slice()) {
        ([l], [m]) => apart(l, m),
        ([l1, l2], [m1, m2]) => {
            let straight = apart(l1, m1).max(apart(l2, m2));
            let crossed = apart(l1, m2).max(apart(l2, m1));
            straight.min(crossed)
        }
        _ => 0.0,
    }
}

/// The log odds of a mistaken construction's step `x` over the right
/// one's `e` for the student's point: how likely each draws the point
/// there, each point scattering about its construction's place as the
/// step's errors do (ACCURACY.step_scatter). A point where two lines
/// meet is scattered across each line, and spread along them by 1/sine
/// of their angle: a mistake whose lines meet at a glancing angle could
/// have put the point anywhere along a long stretch, and is that much
/// less likely to have put it just here. A line both constructions draw
/// alike weighs the same for both and is left out.
fn odds(e: &Judged, x: &Judged) -> f64 {
    // The log density of a point at misfit m (distance over tolerance).
    let scatter = |m: f64| ACCURACY.step_scatter * (1.0 - m * m).max(1e-300).ln();
    let at = e.given;
    if let ([l1, l2], [m1, m2]) = (e.lines.as_slice(), x.lines.as_slice()) {
        let off = |l: &Line| (at - l.0).cross(l.1).abs() / l.2.max(1e-300);
        let spread = |a: &Line, b: &Line| (a.2 * b.2 / a.1.cross(b.1).abs().max(1e-300)).ln();
        let r: f64 = distinct(&e.lines, &x.lines).map(|l| scatter(off(l))).sum();
        let m: f64 = distinct(&x.lines, &e.lines).map(|l| scatter(off(l))).sum();
        return (m - r) - (spread(m1, m2) - spread(l1, l2));
    }
    // A point judged by its place: by the right construction it is
    // judged by (`apart`), its misfit and its spread from the same one.
    let weight = |j: &Judged| {
        let (d, t) = j.apart(j.given);
        scatter(d / t.max(1e-300)) - 2.0 * t.max(1e-300).ln()
    };
    weight(x) - weight(e)
}
