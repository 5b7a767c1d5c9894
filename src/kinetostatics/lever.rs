//! Route 3, Zhukovsky's lever: the balancing moment (force) as the course
//! draws it. The velocity plan *from the construction kernel* (drafted, not
//! route (a)'s numbers: that independence is the check), turned by 90°
//! counter-clockwise, is a rigid lever pivoted at the pole; every known
//! load is applied at the turned plan point of its point of application,
//! each couple M on a link as the pair ±M/l_PQ ⊥ PQ at two points P, Q of
//! the link, and the drive's force F_b at its point (on a crank OA: ⊥ OA
//! at A, M_b = F_b·l_OA). The moments about the pole balance: Σ M_p = 0
//! gives F_b. A force F at turned point p' = R₉₀·v/μ_v has the moment
//! p' × F = −F·v/μ_v: the lever is virtual power drawn, and one lever per
//! input (that input at unit rate, the others standing) gives each
//! input's balancing value with several inputs.

use super::loads::Load;
use super::{Balancing, Origin};
use crate::accuracy::ACCURACY;
use crate::error::{Error, Result};
use crate::geom::perp;
use crate::kinematics::analytic::Order;
use crate::kinematics::construction::{
    Drafting, Naming, Plan, Setup, build_plans_in, non_rotating,
};
use crate::kinematics::positions::describe_input;
use crate::kinematics::solve::{Analysis, Position};
use crate::model::scene::InputSpec;
use kurbo::{Point, Vec2};

/// What a force on the lever stands for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Part {
    /// A known force itself.
    Force,
    /// One of the pair that replaces a couple: at the link's first base
    /// point P (`true`) or its second Q (`false`).
    Couple { at_p: bool },
}

/// One force applied to the lever.
#[derive(Clone, Debug, PartialEq)]
pub struct LeverForce {
    /// Index into the loads the lever was drawn for ([`super::loads::loads`]).
    pub load: usize,
    pub part: Part,
    pub link: usize,
    /// The mechanism's point it acts at (a couple's base point; `None`:
    /// a one-point link's second base point, one link size along its x).
    pub point: Option<usize>,
    pub origin: Origin,
    /// The velocity plan's point it is applied at (`None`: placed by the
    /// plan's similarity here, not a point of the plan).
    pub plan_point: Option<usize>,
    /// Where it acts on the lever: the plan point turned, mm from the pole.
    pub at: Vec2,
    /// Its drafting error radius, mm (for [`Lever::err`]).
    #[cfg(feature = "internals")]
    pub err: f64,
    /// The force, N.
    pub f: Vec2,
    /// Its arm: the distance of its line from the pole, mm.
    pub arm: f64,
    /// Its moment about the pole, N·mm, counter-clockwise positive.
    pub moment: f64,
}

/// Zhukovsky's lever of one input at one position.
#[derive(Clone, Debug)]
pub struct Lever {
    /// The input (in the scene's order).
    pub input: usize,
    /// The balancing moment on a crank (N·m) or force along a driving
    /// slider's guide (N), as [`Balancing`] writes them.
    pub balancing: Balancing,
    /// The balancing force on the lever, N: ⊥ OA at A on a crank, along
    /// the guide on a driving slider (on a cylinder: on the rod, −F_b on
    /// the barrel, one force at the relative velocity's turned end).
    pub f_b: f64,
    /// The unit direction of F_b (positive F_b).
    pub dir_b: Vec2,
    /// Where F_b acts on the lever (turned plan point of A, or of the
    /// rod's point relative to the barrel's), mm.
    pub at_b: Vec2,
    /// The mechanism's point F_b acts at (A, or the slider's point).
    pub point_b: usize,
    /// The arm of F_b from the pole, mm, and its moment, N·mm.
    pub arm_b: f64,
    pub moment_b: f64,
    /// Every known force (couples as their pairs) on the lever.
    pub forces: Vec<LeverForce>,
    /// The velocity plan's scale, (m/s)/mm (with several inputs: per unit
    /// rate of this input).
    pub mu_v: f64,
    /// The first-order drafting bound of `balancing`: the plan points'
    /// error radii times the forces, Σ|F|·err, divided as M_b is (read by
    /// the tests).
    #[cfg(feature = "internals")]
    pub err: f64,
    /// Σ|moment| of the known forces, divided as M_b is: the size of the
    /// sum M_b came from (the scale of its rounding).
    pub scale: f64,
    /// The largest |moment| of one known force, divided as M_b is (read by
    /// the tests).
    #[cfg(feature = "internals")]
    pub largest: f64,
    /// The velocity plan the lever was turned from.
    pub plan: Plan,
}

impl Lever {
    /// The balancing value (M_b or F_b along the guide).
    pub fn value(&self) -> f64 {
        self.balancing.value()
    }
}

/// A point placed on the plan: where (unturned, mm), its error, the plan
/// point when it is one.
#[derive(Clone, Copy, Debug)]
struct Placed {
    at: Vec2,
    err: f64,
    point: Option<usize>,
}

/// The plan point of the material point of `link` at world `x`: the plan's
/// own point there, else built from the plan's known points of the link as
/// the kernel builds one (the pole on the frame, the same point on a
/// translating link, the similar figure on the best pair, the relative
/// vector of the measured ω from one).
fn place(an: &Analysis, s: &Position, plan: &Plan, link: usize, x: Point) -> Result<Placed> {
    let m = &an.mech;
    if link == m.frame() {
        return Ok(Placed {
            at: Vec2::ZERO,
            err: 0.0,
            point: Some(0),
        });
    }
    let pose = s.config.pose(link);
    let local = pose.local(x);
    let tol = ACCURACY.same_point * m.link_scale(link)
        + ACCURACY.tangency_roundings * f64::EPSILON * x.to_vec2().hypot();
    let known: Vec<_> = plan.body.iter().filter(|k| k.link == link).collect();
    if let Some(k) = known.iter().find(|k| (k.local - local).hypot() <= tol) {
        let p = &plan.points[k.point];
        return Ok(Placed {
            at: p.at,
            err: p.err,
            point: Some(k.point),
        });
    }
    let pts = &plan.points;
    if non_rotating(m)[link]
        && let Some(k) = known.first()
    {
        return Ok(Placed {
            at: pts[k.point].at,
            err: pts[k.point].err,
            point: Some(k.point),
        });
    }
    // The similar figure on the pair that moves the point least.
    let mut best: Option<Placed> = None;
    for (i, a) in known.iter().enumerate() {
        for b in &known[i + 1..] {
            let ab = b.local - a.local;
            if ab.hypot2() == 0.0 {
                continue;
            }
            let rho = (local - a.local).rotate_scale(Vec2::new(ab.x, -ab.y)) / ab.hypot2();
            let (pa, pb) = (&pts[a.point], &pts[b.point]);
            let err =
                (Vec2::new(1.0, 0.0) - rho).hypot() * pa.err + rho.hypot() * pb.err + plan.delta;
            if best.is_none_or(|x| err < x.err) {
                best = Some(Placed {
                    at: pa.at + (pb.at - pa.at).rotate_scale(rho),
                    err,
                    point: None,
                });
            }
        }
    }
    if let Some(b) = best {
        return Ok(b);
    }
    match (known.first(), plan.rates[link]) {
        (Some(a), Some((w, w_err))) => {
            let r = x - pose.apply(a.local);
            Ok(Placed {
                at: pts[a.point].at + perp(r) * (w / plan.mu),
                err: pts[a.point].err + plan.delta + w_err * r.hypot() / plan.mu,
                point: None,
            })
        }
        _ => Err(Error::Internal(format!(
            "Zhukovsky's lever: the velocity plan knows no point of link {}",
            m.link_id(link)
        ))),
    }
}

/// The plan turned into the lever: R₉₀·v (counter-clockwise).
fn turned(v: Vec2) -> Vec2 {
    perp(v)
}

/// The two base points of `link` a couple is put on: its first two
/// points of distinct places, else its one point and a point one link
/// size along its local x.
fn base_points(an: &Analysis, s: &Position, link: usize) -> ((usize, Point), (Option<usize>, Point)) {
    let m = &an.mech;
    let l = &m.links[link];
    let p = l.points[0];
    let at_p = s.config.point(m, link, p);
    let far = l
        .points
        .iter()
        .map(|&q| (q, s.config.point(m, link, q)))
        .find(|&(_, x)| (x - at_p).hypot() > ACCURACY.same_point * m.link_scale(link));
    let pose = s.config.pose(link);
    let q = match far {
        Some((q, x)) => (Some(q), x),
        None => (None, at_p + pose.dir(Vec2::new(m.link_scale(link), 0.0))),
    };
    ((p, at_p), q)
}

/// The velocity plans the levers are turned from: with one input the plan
/// of the position's own ω1 (unit rate where the input stands), with
/// several one per input at unit rate, the others standing. Every point of
/// the mechanism is a reported point, so each centre and force point is
/// a plan point the kernel built.
fn velocity_plan(
    an: &Analysis,
    s: &Position,
    input: usize,
    naming: Naming,
    mu_v: Option<f64>,
) -> Result<Plan> {
    let points: Vec<usize> = (0..an.mech.scene.points.len()).collect();
    let st = Setup {
        m: &an.mech,
        s: &an.structure,
        need: &an.need,
        points: &points,
        include: &an.include,
    };
    let own = s.drives.len() == 1 && s.drives[0].rate != 0.0;
    let drives = if own {
        s.drives
    } else {
        s.drives.unit(input, None)
    };
    let d = Drafting {
        mu_v: mu_v.or(if own { an.drafting.mu_v } else { None }),
        mu_a: None,
        ..an.drafting
    };
    let plans = build_plans_in(
        &st,
        &s.config,
        (drives, Order::Velocity),
        d,
        naming,
    )?;
    Ok(plans.velocity)
}

/// Zhukovsky's lever of every input at solved position `s` for its known
/// `loads` ([`super::loads::loads`]); `naming` [`Naming::Full`] for a plan
/// to draw.
pub fn levers(an: &Analysis, s: &Position, loads: &[Load], naming: Naming) -> Result<Vec<Lever>> {
    (0..an.mech.scene.input_count())
        .map(|i| lever(an, s, loads, i, naming))
        .collect()
}

/// Zhukovsky's lever of input `input`, on the velocity plan at its
/// standard scale (the scene's `want.scales.mu_v` with one input).
pub fn lever(
    an: &Analysis,
    s: &Position,
    loads: &[Load],
    input: usize,
    naming: Naming,
) -> Result<Lever> {
    lever_at(an, s, loads, input, naming, None)
}

/// The loads carried onto the lever turned from `plan`, each with its
/// moment about the pole (a couple as two forces at its link's base
/// points).
fn lever_forces(an: &Analysis, s: &Position, plan: &Plan, loads: &[Load]) -> Result<Vec<LeverForce>> {
    let mut forces = Vec::new();
    let on_lever =
        |load: usize, part, link, point, origin, x: Point, f: Vec2| -> Result<LeverForce> {
            let p = place(an, s, plan, link, x)?;
            let at = turned(p.at);
            let moment = at.cross(f);
            let arm = if f.hypot() > 0.0 {
                moment.abs() / f.hypot()
            } else {
                0.0
            };
            Ok(LeverForce {
                load,
                part,
                link,
                point,
                origin,
                plan_point: p.point,
                at,
                #[cfg(feature = "internals")]
                err: p.err,
                f,
                arm,
                moment,
            })
        };
    for (k, load) in loads.iter().enumerate() {
        match *load {
            Load::Force {
                link,
                point,
                at,
                f,
                origin,
            } => {
                if f != Vec2::ZERO {
                    forces.push(on_lever(k, Part::Force, link, Some(point), origin, at, f)?);
                }
            }
            Load::Couple { link, m: c, origin } => {
                if c == 0.0 {
                    continue;
                }
                // M = (P − Q) × F_P with F_P ⊥ PQ, |F_P| = M/l_PQ; −F_P at Q.
                let ((p, at_p), (q, at_q)) = base_points(an, s, link);
                let pq = at_p - at_q;
                let f = perp(pq) * (c / pq.hypot2());
                let part = Part::Couple { at_p: true };
                forces.push(on_lever(k, part, link, Some(p), origin, at_p, f)?);
                let part = Part::Couple { at_p: false };
                forces.push(on_lever(k, part, link, q, origin, at_q, -f)?);
            }
        }
    }
    Ok(forces)
}

/// The balancing force of an input on the lever: the point it acts at
/// and its place on the turned plan (with the plan's error there), its
/// direction, and the factor from the force to the input's balancing
/// value (l_OA of a crank).
struct LeverDrive {
    point: usize,
    at: Vec2,
    #[cfg(feature = "internals")]
    err: f64,
    dir: Vec2,
    per_unit: f64,
}

/// The balancing force of input `input` on the lever turned from `plan`.
fn lever_drive(an: &Analysis, s: &Position, plan: &Plan, input: usize) -> Result<LeverDrive> {
    let m = &an.mech;
    Ok(match *m.scene.input_at(input) {
        InputSpec::Crank { link, pivot, .. } => {
            let pts = &m.links[link].points;
            let a = if pts[0] == pivot { pts[1] } else { pts[0] };
            let (o, x) = (s.config.point(m, link, pivot), s.config.point(m, link, a));
            let pa = place(an, s, plan, link, x)?;
            let oa = x - o;
            // F_b ⊥ OA at A, counter-clockwise about O for F_b > 0.
            LeverDrive {
                point: a,
                at: turned(pa.at),
                #[cfg(feature = "internals")]
                err: pa.err,
                dir: perp(oa) / oa.hypot(),
                per_unit: oa.hypot(),
            }
        }
        InputSpec::Slider { link, pair, .. } => {
            let pr = &m.prismatics[pair];
            let x = s.config.point(m, link, pr.point);
            let u = s.config.pose(pr.guide).dir(pr.line_dir);
            let rod = place(an, s, plan, link, x)?;
            let barrel = place(an, s, plan, pr.guide, x)?;
            // F_b·u on the rod at x, −F_b·u on the barrel at x: on the
            // lever one force at the relative velocity's turned end.
            LeverDrive {
                point: pr.point,
                at: turned(rod.at - barrel.at),
                #[cfg(feature = "internals")]
                err: rod.err + barrel.err,
                dir: u,
                per_unit: 1.0,
            }
        }
    })
}

/// Zhukovsky's lever of input `input` on the velocity plan drawn at
/// `mu_v` ((m/s)/mm; `None`: as [`lever`]): a sheet's own scale.
pub fn lever_at(
    an: &Analysis,
    s: &Position,
    loads: &[Load],
    input: usize,
    naming: Naming,
    mu_v: Option<f64>,
) -> Result<Lever> {
    let m = &an.mech;
    let plan = velocity_plan(an, s, input, naming, mu_v)?;
    let forces = lever_forces(an, s, &plan, loads)?;
    // The drive's force: its place on the lever and its direction.
    let LeverDrive {
        point: point_b,
        at: at_b,
        #[cfg(feature = "internals")]
        err: err_b,
        dir: dir_b,
        per_unit,
    } = lever_drive(an, s, &plan, input)?;
    let arm_unit = at_b.cross(dir_b);
    let at = || describe_input(m, &s.drives.coords());
    if arm_unit == 0.0 || !arm_unit.is_finite() {
        return Err(Error::singular(
            at(),
            "Zhukovsky's lever: the balancing force's arm on the turned velocity plan is zero (the input's point stands on the plan)",
        ));
    }
    let sum: f64 = forces.iter().map(|f| f.moment).sum();
    let f_b = -sum / arm_unit;
    // Divided as M_b is: the moment sum over the arm, times l_OA on a crank.
    let divide = per_unit / arm_unit.abs();
    let scale = forces.iter().map(|f| f.moment.abs()).sum::<f64>() * divide;
    #[cfg(feature = "internals")]
    let largest = forces.iter().map(|f| f.moment.abs()).fold(0.0, f64::max) * divide;
    #[cfg(feature = "internals")]
    let drafting: f64 = forces.iter().map(|f| f.f.hypot() * f.err).sum::<f64>() + f_b.abs() * err_b;
    let value = f_b * per_unit;
    let balancing = if m.scene.input_at(input).is_crank() {
        Balancing::Moment(value)
    } else {
        Balancing::Force(value)
    };
    if !value.is_finite() {
        return Err(Error::singular(
            at(),
            "Zhukovsky's lever: the moment sum is not finite",
        ));
    }
    Ok(Lever {
        input,
        balancing,
        f_b,
        dir_b,
        at_b,
        point_b,
        arm_b: arm_unit.abs(),
        moment_b: arm_unit * f_b,
        forces,
        mu_v: plan.mu,
        #[cfg(feature = "internals")]
        err: drafting * divide,
        scale,
        #[cfg(feature = "internals")]
        largest,
        plan,
    })
}

/// The balancing value of every input by the lever, checked against the
/// links' equilibrium `by_links`: a position where they differ by more
/// than 10⁻⁶ (`accuracy::max_balancing_diff`) of the lever's moment sum
/// is refused. The tolerance is the rounding's, not the drafting's: the
/// plan's points are exact constructions, their error radii what a pencil
/// would add.
pub fn check(
    an: &Analysis,
    s: &Position,
    loads: &[Load],
    by_links: &[Balancing],
    floors: &[f64],
) -> Result<Vec<f64>> {
    let levers = levers(an, s, loads, Naming::NumbersOnly)?;
    for ((l, b), &floor) in levers.iter().zip(by_links).zip(floors) {
        let d = (l.value() - b.value()).abs();
        // Against the lever's moments, never less than `floor` (a dead
        // centre without gravity has none).
        let rel = if d == 0.0 {
            0.0
        } else {
            d / l.scale.max(floor).max(f64::MIN_POSITIVE)
        };
        if rel.is_nan() || rel > ACCURACY.max_balancing_diff {
            return Err(Error::singular(
                describe_input(&an.mech, &s.drives.coords()),
                format!(
                    "the balancing {} of input {} by the links' equilibrium {} and by Zhukovsky's lever {} differ by {rel:.1e} of the lever's moments (more than {:.0e})",
                    if l.balancing == Balancing::Moment(l.value()) {
                        "moment"
                    } else {
                        "force"
                    },
                    l.input + 1,
                    b.value(),
                    l.value(),
                    ACCURACY.max_balancing_diff
                ),
            ));
        }
    }
    Ok(levers.iter().map(Lever::value).collect())
}
