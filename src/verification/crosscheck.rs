//! The cross-check of the analysis at every position: route (a) against
//! route (b), the plans against both routes, and the data sensitivity (the
//! answer with the scene's data changed by a few units of rounding); from
//! them the error [`Bounds`] of every reported number. A position where
//! they disagree is refused.
//!
//! Without plans (`want.plans: []`, a sweep) the fast path: route (b)'s
//! equations evaluated at route (a)'s answer (the residuals of the closure
//! equations and of their first and second time derivatives, each as the
//! change of the answer that cancels it), the data sensitivity by the
//! same equations of the changed data, linearized, and solved again only
//! where the conditioning asks for it (docs/sweeps.md).

use crate::accuracy::ACCURACY;
use crate::error::{Error, Result};
use crate::kinematics::analytic::constraint::{
    Conditioning, ConstraintSolver, Settings,
};
use crate::kinematics::analytic::{Coords, Motion, Order, contour};
use crate::kinematics::construction::Plans;
use crate::kinematics::positions::{PositionSolver, describe_input};
use crate::kinematics::solve::{Analysis, Position};
use kurbo::Point;

pub use super::worst::{Quantity, Route, Worst};

/// Both routes' agreement at one position and what each cost.
#[derive(Clone, Debug)]
pub struct CrossCheck {
    /// Largest difference between the routes, each quantity relative to
    /// the largest magnitude of its kind at that position.
    pub max_rel_diff: f64,
    /// Which quantity it was ("v of B").
    pub worst: Worst,
    /// Wall time of route (a) (positions + contours), seconds.
    pub contour_time: f64,
    /// Wall time of route (b) (Newton + linear solves), seconds.
    pub constraint_time: f64,
    /// σ_min/σ_max of the scaled constraint Jacobian.
    pub conditioning: f64,
    /// Wall time of the plans' construction, seconds (0 without plans).
    pub plan_time: f64,
    /// How far the answer moves when the scene's data change by a few
    /// units of rounding, relative as `max_rel_diff`: the larger of the
    /// real rates' and the transfer functions' (`None` only before it is
    /// measured).
    pub data_sensitivity: Option<f64>,
    /// The error bound of every reported number of each kind, in SI
    /// (`None` only before the data sensitivity is measured).
    pub bound: Option<Bounds>,
    /// How the position was checked.
    pub method: Method,
    /// The fast path: the orientation of route (a)'s assembly, the sign
    /// of det Φ_q at its answer (checked against the position before).
    pub orientation: Option<f64>,
}

/// How a position was cross-checked.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// Route (a) against route (b) followed along the positions, and the
    /// plans against both; `max_rel_diff` is their largest disagreement,
    /// `constraint_time` route (b)'s time.
    Routes,
    /// The fast path (no plans): route (b)'s equations at route (a)'s
    /// answer; `max_rel_diff` is the largest change of the answer that
    /// cancels their residuals, `constraint_time` the check's time.
    /// `linear_data`: the data sensitivity by those equations linearized
    /// (else route (a) solved again on the changed data).
    Residuals { linear_data: bool },
}

/// What the fast path's check needs, made once per run: route (b)'s
/// equations of the scene and of the scene with its data changed both
/// ways ([`Analysis::changed_data`]; `None` where the changed scene is
/// refused).
pub(crate) struct Residuals<'a> {
    pub(super) base: ConstraintSolver<'a>,
    pub(super) changed: Vec<Option<ConstraintSolver<'a>>>,
    /// The orientation of the assembly the sketch shows
    /// ([`ConstraintSolver::sketch_orientation`]).
    pub sketch_orientation: Option<f64>,
}

/// The error bound of every number of one position that the routes report,
/// by kind, in SI: each reported value lies within its kind's bound of the
/// exact answer for the scene's data.
///
/// Each is (c·ε·κ + 4·d + 4·σ)·S: κ = 1/conditioning (the scaled
/// Jacobian's σ_max/σ_min: how much rounding of the linear systems is
/// amplified; c = 256 covers the few dozen roundings per equation and
/// their accumulation through the groups), d the routes' disagreement (the
/// part of their own arithmetic that κ misses near a dead point), σ the
/// data sensitivity (the part the data's rounding decides, which both
/// routes share; for the transfer functions the larger of the real rates'
/// and their own, `verification/sensitivity.rs`); S the position's scale of
/// that kind: the sketch's size
/// for places, the largest |v| or |ω|·size for velocities, the largest
/// |a|, |ε|·size or ω²·size for accelerations, the same at unit input rate
/// for the transfer functions. Angles, ω, ε and their transfer functions:
/// the same over the size.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Bounds {
    pub p: f64,
    pub v: f64,
    pub a: f64,
    pub v_q: f64,
    pub a_q: f64,
    pub angle: f64,
    pub omega: f64,
    pub epsilon: f64,
    pub phi_q: f64,
    pub phi_qq: f64,
}

/// The constant c of [`Bounds`].
pub const BOUND_ROUNDINGS: f64 = ACCURACY.bound_roundings;

/// The largest data sensitivity accepted, as the routes' disagreement.
pub const MAX_REL_DIFF: f64 = ACCURACY.max_rel_diff;

/// The change of the data for the sensitivity check: every length and
/// sketch coordinate by this many units of rounding (relative).
pub(super) const DATA_PERTURBATION: f64 = ACCURACY.data_roundings * f64::EPSILON;

/// The scene with its data changed by a few units of rounding, both ways
/// ([`Analysis::changed_data`]).
pub(crate) type ChangedData = Vec<std::result::Result<Analysis, String>>;

/// What one position's solutions cost, and the conditioning of route (b)
/// there: measured by the analysis, reported with the cross-check.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Costs {
    /// Route (a), route (b) and the plans' construction, seconds.
    pub contour_time: f64,
    pub constraint_time: f64,
    pub plan_time: f64,
    /// σ_min/σ_max of the scaled constraint Jacobian.
    pub conditioning: f64,
}

impl Analysis {
    /// The cross-check of a solved position: route (a) against route (b)
    /// (`other`), the plans (`plans`: the position's own, or the sweep
    /// kernel's where the result keeps none) against both, and the data
    /// sensitivity; with the costs of the position and its bounds. An
    /// error (a refusal) when the routes disagree or the data's rounding
    /// decides the answer.
    pub(crate) fn cross_check(
        &self,
        s: &Position,
        other: &[Option<Motion>],
        plans: Option<&Plans>,
        costs: Costs,
        q_rounding: Coords,
        changed: &ChangedData,
    ) -> Result<CrossCheck> {
        let m = &self.mech;
        let (mut d, mut worst) = self.compare(s, other);
        for (route, mo) in [(Route::Contour, &s.motion[..]), (Route::Constraint, other)] {
            let (dp, wp) = self.compare_plans(s, plans, mo);
            if dp > d || dp.is_nan() {
                let plan = Some(route);
                (d, worst) = (dp, Worst { plan, ..wp });
            }
        }
        if d.is_nan() || d > MAX_REL_DIFF {
            return Err(Error::singular(
                describe_input(m, &s.drives.coords()),
                format!(
                    "the two analytic routes disagree ({worst}: relative difference {d:.2e}); the position is too close to a singular one to trust either"
                ),
            ));
        }
        let sens = self
            .data_sensitivity(s, q_rounding, changed)
            .map_err(|why| Error::singular(describe_input(m, &s.drives.coords()), why))?;
        let bound = self.bounds(s, costs.conditioning, d, sens);
        Ok(CrossCheck {
            max_rel_diff: d,
            worst,
            contour_time: costs.contour_time,
            constraint_time: costs.constraint_time,
            conditioning: costs.conditioning,
            plan_time: costs.plan_time,
            data_sensitivity: Some(sens.0.max(sens.1)),
            bound: Some(bound),
            method: Method::Routes,
            orientation: None,
        })
    }

    /// Route (b)'s equations for the fast path's check: of this scene and
    /// of the changed scenes `changed`.
    pub(crate) fn residual_equations<'a>(&'a self, changed: &'a ChangedData) -> Residuals<'a> {
        let solver =
            |an: &'a Analysis| ConstraintSolver::new(&an.mech, &an.include, Settings::default());
        let base = solver(self);
        let changed = changed
            .iter()
            .map(|c| {
                c.as_ref()
                    .ok()
                    .map(solver)
                    .filter(|cs| cs.links() == base.links())
            })
            .collect();
        Residuals {
            sketch_orientation: base.sketch_orientation(),
            base,
            changed,
        }
    }

    /// The fast path's cross-check of route (a)'s answer `s` (no plans, no
    /// route (b) along the positions): route (b)'s equations at the
    /// answer, the residuals of the closure equations and of their first
    /// and second time derivatives each turned into the change of the
    /// answer that cancels it, measured as the routes' disagreement is and
    /// refused above the same limit; a Jacobian as ill-conditioned as
    /// route (b) refuses is refused. The data sensitivity: the same
    /// equations of the changed data, linearized at the answer, unless
    /// the conditioning is below [`crate::accuracy::Accuracy::linear_data_conditioning`]
    /// or the result near the refusal, where route (a) is solved again
    /// on the changed data as [`Analysis::cross_check`] does. Its time
    /// from `t0` (route (a)'s end) on; `contour_time` route (a)'s.
    pub(crate) fn residual_check(
        &self,
        s: &Position,
        eqs: &Residuals,
        (contour_time, t0): (f64, std::time::Instant),
        q_rounding: Coords,
        changed: &ChangedData,
    ) -> Result<CrossCheck> {
        let m = &self.mech;
        let refuse = |why: String| Error::singular(describe_input(m, &s.drives.coords()), why);
        let x = s.drives.coords();
        let rates = self.input_rates();
        let u = eqs
            .base
            .unknowns(|l| s.config.pose(l), &s.motion, self.order);
        // Printed, the conditioning is σ_min/σ_max itself; else only what
        // the check compares it with must be decided as that would.
        let conditioning = if self.printed_check {
            Conditioning::Exact
        } else {
            Conditioning::Decided(
                ACCURACY
                    .min_conditioning
                    .max(ACCURACY.linear_data_conditioning),
            )
        };
        let c = eqs
            .base
            .corrected(&u, &x, &rates, conditioning)
            .map_err(refuse)?;
        if c.conditioning.is_nan() || c.conditioning < ACCURACY.min_conditioning {
            return Err(refuse(format!(
                "the constraint Jacobian is ill-conditioned (σ_min/σ_max = {:.2e})",
                c.conditioning
            )));
        }
        let mine = self.mine(s, &s.motion);
        let (d, most) = self.compare_most(&mine, &c.motion, &self.mech);
        let worst = self.named(most);
        if d.is_nan() || d > MAX_REL_DIFF {
            return Err(refuse(format!(
                "route (a)'s answer does not satisfy the closure equations and their derivatives ({worst}: relative residual {d:.2e}); a position too close to a singular one cannot be trusted"
            )));
        }
        let linear = (c.conditioning >= ACCURACY.linear_data_conditioning)
            .then(|| {
                self.linear_sensitivity(&mine, &u, eqs, &c, q_rounding, changed)
            })
            .flatten()
            .filter(|&(x, t)| x.max(t) <= ACCURACY.linear_data_sensitivity);
        let sens = match linear {
            Some(x) => x,
            None => self
                .data_sensitivity(s, q_rounding, changed)
                .map_err(refuse)?,
        };
        // Bounds only where printed.
        let bound = self
            .printed_check
            .then(|| self.bounds(s, c.conditioning, d, sens));
        Ok(CrossCheck {
            max_rel_diff: d,
            worst,
            contour_time,
            constraint_time: t0.elapsed().as_secs_f64(),
            conditioning: c.conditioning,
            plan_time: 0.0,
            data_sensitivity: Some(sens.0.max(sens.1)),
            bound,
            method: Method::Residuals {
                linear_data: linear.is_some(),
            },
            orientation: Some(c.orientation),
        })
    }

    /// The bounds of a solved position ([`Bounds`]).
    /// `sens`: the data sensitivity of the real rates (and places), and
    /// of the transfer functions, each bounding its own kinds.
    fn bounds(&self, s: &Position, conditioning: f64, diff: f64, sens: (f64, f64)) -> Bounds {
        let m = &self.mech;
        let size = m.size;
        let arithmetic = BOUND_ROUNDINGS * f64::EPSILON / conditioning + 4.0 * diff;
        let rel = arithmetic + 4.0 * sens.0;
        // The transfer functions: their own data check (places and real
        // rates do not bound them where ε1 outweighs ω1², transfer.rs).
        let rel_q = arithmetic + 4.0 * sens.0.max(sens.1);
        // The scale of one kind: the points' magnitudes and the links'
        // rates × size (and ω²·size for accelerations).
        let scale = |mo: &[Option<Motion>], acc: bool| -> f64 {
            let mut x = f64::MIN_POSITIVE;
            for &p in &self.points {
                let l = self.carrier(p);
                if let Some(k) = mo[l] {
                    let at = s.config.point(m, l, p);
                    x = x.max(
                        if acc {
                            k.acceleration(at)
                        } else {
                            k.velocity(at)
                        }
                        .hypot(),
                    );
                }
            }
            for k in mo.iter().flatten() {
                x = x.max(if acc { k.epsilon } else { k.omega }.abs() * size);
                if acc {
                    x = x.max(k.omega * k.omega * size);
                }
            }
            x
        };
        let (sv, sa) = (scale(&s.motion, false), scale(&s.motion, true));
        // The transfer functions of every input (and the mixed runs).
        let runs = std::iter::once(&s.analogue)
            .chain(&s.more_analogues)
            .chain(&s.mixed);
        let (sq, sqq) = runs.fold((f64::MIN_POSITIVE, f64::MIN_POSITIVE), |(a, b), mo| {
            (a.max(scale(mo, false)), b.max(scale(mo, true)))
        });
        Bounds {
            p: rel * size,
            v: rel * sv,
            a: rel * sa,
            v_q: rel_q * sq,
            a_q: rel_q * sqq,
            angle: rel,
            omega: rel * sv / size,
            epsilon: rel * sa / size,
            phi_q: rel_q * sq / size,
            phi_qq: rel_q * sqq / size,
        }
    }

    /// The scene with every datum (length, sketch coordinate, guide line)
    /// changed by a few units of its own rounding, in a fixed alternating
    /// pattern, both ways; built once per run, its shapes with this
    /// mechanism's decisions (rounding must not change which rule places a
    /// point). An error when such a change already makes the mechanism
    /// another one (a structure decided by rounding).
    pub(crate) fn changed_data(&self) -> ChangedData {
        [1.0, -1.0]
            .iter()
            .map(|sign| {
                let k = sign * DATA_PERTURBATION;
                self.changed_by(|n| if n.is_multiple_of(2) { k } else { -k })
            })
            .collect()
    }

    /// The scene with datum `i` alone (in the order [`Analysis::changed_data`]
    /// walks them, from 1) changed by as many units of its rounding;
    /// `None` past the last datum. Summing what each datum alone moves
    /// bounds what they move together, where the alternating changes of
    /// [`Analysis::changed_data`] may cancel in a quantity.
    pub(crate) fn changed_datum(&self, i: usize) -> Option<std::result::Result<Analysis, String>> {
        (i <= self.data_count())
            .then(|| self.changed_by(|n| if n == i { DATA_PERTURBATION } else { 0.0 }))
    }

    /// How many data [`Analysis::changed_by`] changes.
    fn data_count(&self) -> usize {
        let mut n = 0;
        each_datum(&mut self.mech.scene.clone(), |_| n += 1);
        n
    }

    /// The scene with datum n (from 1, in the order of [`each_datum`])
    /// multiplied by 1 + `change(n)`, its shapes with this mechanism's
    /// decisions.
    fn changed_by(&self, change: impl Fn(usize) -> f64) -> std::result::Result<Analysis, String> {
        let m = &self.mech;
        let mut scene = m.scene.clone();
        let mut n = 0usize;
        // Each datum relative to its own magnitude: a coordinate near the
        // origin is known better than one far from it.
        each_datum(&mut scene, |x| {
            n += 1;
            *x *= 1.0 + change(n);
        });
        m.with_data(scene)
            .and_then(Analysis::of)
            .map_err(|e| e.to_string())
    }

    /// How far the answer at a solved position moves with the data changed
    /// by a few units of rounding ([`Analysis::changed_data`]): the largest
    /// relative change, as the routes' comparison measures it, each scene's
    /// points on its own shapes. Both routes start from the same rounded
    /// data, so their agreement cannot show this. An error (a refusal) when
    /// the data's rounding decides the answer: the changed mechanism does
    /// not assemble here, or the answer moves by more than [`MAX_REL_DIFF`].
    fn data_sensitivity(
        &self,
        s: &Position,
        q_rounding: Coords,
        changed: &ChangedData,
    ) -> std::result::Result<(f64, f64), String> {
        let order = self.order.unwrap_or(Order::Velocity);
        let units = DATA_PERTURBATION / f64::EPSILON;
        let mut worst = (0.0f64, Worst::default());
        let mut transfer = 0.0f64;
        for (an, sign) in changed.iter().zip([1.0, -1.0]) {
            // The input moves with the data, by as many units of its own
            // rounding (exact reductions leave an ulp of the angle).
            let mut q = s.drives.coords();
            for (q, r) in q.iter_mut().zip(q_rounding.iter()) {
                *q += sign * units * r;
            }
            let mut drives = s.drives;
            for (d, &q) in drives.iter_mut().zip(q.iter()) {
                d.q = q;
            }
            let moved = an
                .as_ref()
                .map_err(|e| e.clone())
                .and_then(|an| {
                    let mut ps = PositionSolver::new(&an.mech, &an.structure, an.need.clone())
                        .map_err(|e| e.to_string())?;
                    let c = ps.solve_coords(q).map_err(|e| e.to_string())?;
                    let mo = contour::solve(&an.mech, &an.structure, &an.need, &c, drives, order)
                        .map_err(|e| e.to_string())?;
                    let moved = self.transfer_moved(s, an, &c, drives, order)?;
                    Ok((an, mo, moved))
                })
                .map_err(|e| {
                    format!(
                        "the position is within rounding of a dead point: with the data changed by {units} units of rounding the mechanism has no answer here ({e})"
                    )
                })?;
            let (d, what) = self.compare_with(s, &s.motion, &moved.1, &moved.0.mech);
            if d > worst.0 || d.is_nan() {
                worst = (d, what);
            }
            if moved.2 > transfer || moved.2.is_nan() {
                transfer = moved.2;
            }
        }
        if worst.0.is_nan() || worst.0 > MAX_REL_DIFF {
            return Err(format!(
                "the answer is decided by the rounding of the data: a change of {units} units of rounding in the data moves {} by {:.2e} (relative); the position is too close to a dead point",
                worst.1, worst.0
            ));
        }
        if transfer.is_nan() || transfer > MAX_REL_DIFF {
            return Err(format!(
                "the answer is decided by the rounding of the data: a change of {units} units of rounding in the data moves the transfer functions by {transfer:.2e} (relative); the position is too close to a dead point"
            ));
        }
        Ok((worst.0, transfer))
    }

    /// Largest relative difference between the plans (measured values × μ)
    /// and an analytic route.
    fn compare_plans(
        &self,
        s: &Position,
        plans: Option<&Plans>,
        mo: &[Option<Motion>],
    ) -> (f64, Worst) {
        let Some(plans) = plans else {
            return (0.0, Worst::default());
        };
        let m = &self.mech;
        let mut worst = (0.0f64, Worst::default());
        for (plan, acc) in [
            (Some(&plans.velocity), false),
            (plans.acceleration.as_ref(), true),
        ] {
            let Some(plan) = plan else { continue };
            let mut items: Vec<(Worst, f64, f64)> = Vec::new();
            for &p in &self.points {
                let l = self.carrier(p);
                let at = s.config.point(m, l, p);
                let exact = if acc {
                    mo[l].unwrap().acceleration(at)
                } else {
                    mo[l].unwrap().velocity(at)
                };
                if let Some(got) = plan.value_of(p) {
                    items.push((
                        Worst::of(
                            if acc {
                                Quantity::Acceleration
                            } else {
                                Quantity::Velocity
                            },
                            m.point_name(p),
                        ),
                        (got - exact).hypot(),
                        exact.hypot(),
                    ));
                }
            }
            for (l, (rate, x)) in plan.rates.iter().zip(mo).enumerate() {
                if let (Some((r, _)), Some(x)) = (rate, x) {
                    let exact = if acc { x.epsilon } else { x.omega };
                    items.push((
                        Worst::of(
                            if acc { Quantity::Epsilon } else { Quantity::Omega },
                            m.link_id(l),
                        ),
                        (r - exact).abs() * m.size,
                        exact.abs() * m.size,
                    ));
                }
            }
            let scale = items.iter().map(|e| e.2).fold(f64::MIN_POSITIVE, f64::max);
            for (what, d, _) in items {
                if d / scale > worst.0 || d.is_nan() {
                    worst = (d / scale, what);
                }
            }
        }
        worst
    }

    /// Largest relative difference between route (a) and route (b).
    fn compare(&self, s: &Position, other: &[Option<Motion>]) -> (f64, Worst) {
        self.compare_with(s, &s.motion, other, &self.mech)
    }
}

/// Every datum of `scene` the data check changes, in a fixed order:
/// lengths, sketch coordinates, guide lines (`through`, `angle`, `offset`).
fn each_datum(scene: &mut crate::model::scene::Scene, mut f: impl FnMut(&mut f64)) {
    use crate::model::scene::{Direction, Through};
    for l in scene.lengths.iter_mut() {
        f(&mut l.value);
    }
    let point = |p: &mut Point, f: &mut dyn FnMut(&mut f64)| {
        let (mut x, mut y) = (p.x, p.y);
        f(&mut x);
        f(&mut y);
        *p = Point::new(x, y);
    };
    for p in scene.points.iter_mut() {
        point(&mut p.sketch, &mut f);
    }
    for sl in scene.sliders.iter_mut() {
        if let Through::Coords(c) = &mut sl.line.through {
            point(c, &mut f);
        }
        if let Direction::Angle(a) = &mut sl.line.direction {
            f(a);
        }
        f(&mut sl.line.offset);
    }
}
