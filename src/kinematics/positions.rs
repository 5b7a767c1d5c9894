//! Positions: the input placed exactly, then every group in the order of
//! attachment by its closed form (circle∩circle, circle∩line, line∩line, the
//! rocking-guide angle) on the branch the sketch shows. A class III group is
//! solved by a one-dimensional root search in its base angle, tracked
//! continuously from the sketch.

use crate::accuracy::ACCURACY;
use crate::error::{Error, Result};
use crate::format::format_quantity as quantity;
use crate::geom::{
    LineCut, Pose, circle_circle, circle_line, intersect_lines, rotate, sign_tol, wrap_pi,
};
use crate::kinematics::analytic::Coords;
use crate::model::mechanism::Mechanism;
use crate::model::scene::InputSpec;
use crate::model::structure::{
    AssurGroup, Conn, Cylinder, Dyad, DyadKind, InputRole, Joint, Stage, Structure, Triad,
};
use kurbo::{Point, Vec2};

/// The poses of the links solved so far (None: not needed, not computed).
#[derive(Clone, Debug)]
pub struct Configuration {
    pub poses: Vec<Option<Pose>>,
}

impl Configuration {
    #[inline]
    pub fn pose(&self, link: usize) -> Pose {
        self.poses[link].expect("link solved before use")
    }
    /// World position of `point` as carried by `link`.
    #[inline]
    pub fn point(&self, m: &Mechanism, link: usize, point: usize) -> Point {
        self.pose(link).apply(m.local(link, point))
    }
}

/// Branch of each group as the sketch shows it, plus the tracked state of
/// class III groups (their base angle).
#[derive(Clone, Debug)]
pub struct Branches {
    pub sign: Vec<f64>,
    /// Tracked base pose of each class III group.
    pub triad_pose: Vec<Pose>,
}

/// Describe the input values for messages: "φ = 123.4°" or "s = 0.05 m",
/// in the shortest decimal that is the value (near a limit, positions a
/// nano-degree apart must read apart); several inputs each with its link's
/// id: "φ1 = 30°, φ4 = 120°".
pub fn describe_input(m: &Mechanism, q: &[f64]) -> String {
    let several = m.scene.several_inputs();
    q.iter()
        .zip(m.scene.inputs())
        .map(|(&q, spec)| {
            let id = if several { m.link_id(spec.link()) } else { "" };
            match spec {
                InputSpec::Crank { .. } => format!("φ{id} = {}°", q.to_degrees()),
                InputSpec::Slider { .. } => format!("s{id} = {q} m"),
            }
        })
        .collect::<Vec<_>>()
        .join(", ")
}

fn sketch(m: &Mechanism, p: usize) -> Point {
    m.scene.points[p].sketch
}

pub(crate) fn point_of(j: Joint) -> usize {
    match j {
        Joint::R(p) => p,
        Joint::P(_) => unreachable!("a revolute pair was expected"),
    }
}

pub(crate) fn pair_of(j: Joint) -> usize {
    match j {
        Joint::P(k) => k,
        Joint::R(_) => unreachable!("a prismatic pair was expected"),
    }
}

/// Angle of `moving` given the angle of `known` across prismatic pair `k`.
pub(crate) fn angle_across(m: &Mechanism, k: usize, known: usize, known_angle: f64) -> f64 {
    let pr = &m.prismatics[k];
    if pr.guide == known {
        known_angle + pr.delta
    } else {
        known_angle - pr.delta
    }
}

/// The world line on which the local point `x` of link `moving` (at angle
/// `theta`) must lie, because of prismatic pair `k` with the posed link `known`.
pub fn slide_line(
    m: &Mechanism,
    k: usize,
    known: usize,
    known_pose: &Pose,
    theta: f64,
    x: Vec2,
) -> crate::geom::Line {
    let pr = &m.prismatics[k];
    if pr.guide == known {
        crate::geom::Line {
            point: known_pose.apply(pr.line_point) + rotate(x - pr.slider_local, theta),
            dir: known_pose.dir(pr.line_dir),
        }
    } else {
        crate::geom::Line {
            point: known_pose.apply(pr.slider_local) + rotate(x - pr.line_point, theta),
            dir: rotate(pr.line_dir, theta),
        }
    }
}

/// The guide direction of pair `k` in the sketch.
fn sketch_guide_dir(m: &Mechanism, k: usize) -> Vec2 {
    let pr = &m.prismatics[k];
    m.links[pr.guide].sketch_pose.dir(pr.line_dir)
}

/// The constant h and the pins for the rocking-guide (RPR) closed form:
/// cross(u(ψ), J_S − J_G) = h, with ψ the guide link's angle.
pub(crate) struct RockingGuide {
    pub guide: usize,
    pub slider: usize,
    pub pin_guide: usize,
    pub pin_slider: usize,
    pub h: f64,
    pub alpha: f64,
    pub delta: f64,
}

pub(crate) fn rocking_guide(m: &Mechanism, d: &Dyad) -> RockingGuide {
    let k = pair_of(d.mid.joint);
    let pr = &m.prismatics[k];
    let (b, dd) = (point_of(d.ext1.joint), point_of(d.ext2.joint));
    let (l1, l2) = (d.links[0], d.links[1]);
    let (pin_guide, pin_slider) = if pr.guide == l1 { (b, dd) } else { (dd, b) };
    let jg = m.local(pr.guide, pin_guide);
    let js = m.local(pr.slider, pin_slider);
    let h = pr.line_dir.cross(pr.line_point - jg)
        - pr.line_dir.cross(rotate(pr.slider_local - js, pr.delta));
    let _ = l2;
    RockingGuide {
        guide: pr.guide,
        slider: pr.slider,
        pin_guide,
        pin_slider,
        h,
        alpha: pr.line_dir.atan2(),
        delta: pr.delta,
    }
}

/// Triad data: leash lengths and the base's joint coordinates.
struct TriadGeom {
    ext_pts: [usize; 3],
    int_pts: [usize; 3],
    r: [f64; 3],
    b: [Vec2; 3],
    /// The group's own size: its longest leash or base side.
    scale: f64,
}

fn triad_geom(m: &Mechanism, t: &Triad) -> TriadGeom {
    let ext_pts = t.ext.map(|c| point_of(c.joint));
    let int_pts = t.int.map(|c| point_of(c.joint));
    let r = [0, 1, 2]
        .map(|i| (m.local(t.leashes[i], int_pts[i]) - m.local(t.leashes[i], ext_pts[i])).hypot());
    let b = int_pts.map(|p| m.local(t.base, p));
    let scale = r
        .iter()
        .copied()
        .chain([
            (b[1] - b[0]).hypot(),
            (b[2] - b[0]).hypot(),
            (b[2] - b[1]).hypot(),
        ])
        .fold(0.0, f64::max);
    TriadGeom {
        ext_pts,
        int_pts,
        r,
        b,
        scale,
    }
}

impl Branches {
    /// Read every group's branch off the sketch.
    pub fn from_sketch(m: &Mechanism, s: &Structure) -> Result<Branches> {
        // Relative to the group's own lengths (`dyad_sign` is a sine or a
        // cosine), not to the sketch's size: a far point of some other link
        // must not make a group in general position look like a dead point.
        let tol = ACCURACY.branch_dead_band;
        let mut sign = Vec::new();
        let mut triad_pose = Vec::new();
        for g in &s.groups {
            let (sg, pose) = match g {
                AssurGroup::Dyad(d) => (dyad_sign(m, d), Pose::IDENTITY),
                // A class III group's branch is tracked continuously from the sketch.
                AssurGroup::Triad(t) => (1.0, m.links[t.base].sketch_pose),
            };
            let sg_tol = sign_tol(sg, tol);
            if sg_tol == 0.0 && sg.is_finite() && needs_sign(g) {
                return Err(Error::structure(format!(
                    "the sketch shows group {} at a dead point (its branch cannot be read off the drawing); draw it in a general position",
                    g.label(m)
                )));
            }
            sign.push(if needs_sign(g) { sg_tol } else { 1.0 });
            triad_pose.push(pose);
        }
        Ok(Branches { sign, triad_pose })
    }
}

fn needs_sign(g: &AssurGroup) -> bool {
    match g {
        AssurGroup::Dyad(d) => !matches!(d.kind, DyadKind::Prp | DyadKind::Rpp),
        AssurGroup::Triad(_) => false,
    }
}

fn dyad_sign(m: &Mechanism, d: &Dyad) -> f64 {
    match d.kind {
        DyadKind::Rrr => {
            let (b, c, dd) = (
                sketch(m, point_of(d.ext1.joint)),
                sketch(m, point_of(d.mid.joint)),
                sketch(m, point_of(d.ext2.joint)),
            );
            (dd - b).cross(c - b) / ((dd - b).hypot() * (c - b).hypot()).max(f64::MIN_POSITIVE)
        }
        DyadKind::Rrp => {
            let b = sketch(m, point_of(d.ext1.joint));
            let c = sketch(m, point_of(d.mid.joint));
            (c - b).dot(sketch_guide_dir(m, pair_of(d.ext2.joint)))
                / (c - b).hypot().max(f64::MIN_POSITIVE)
        }
        DyadKind::Rpr => {
            let rg = rocking_guide(m, d);
            let u = sketch_guide_dir(m, pair_of(d.mid.joint));
            let w = sketch(m, rg.pin_slider) - sketch(m, rg.pin_guide);
            u.dot(w) / w.hypot().max(f64::MIN_POSITIVE)
        }
        DyadKind::Prp | DyadKind::Rpp => 1.0,
    }
}

/// Place input `i`'s link exactly at its coordinate `q` (rad or m): a
/// crank about its pivot, a slider on a guide of the frame.
pub fn place_input(m: &Mechanism, i: usize, q: f64) -> Pose {
    match *m.scene.input_at(i) {
        InputSpec::Crank { link, pivot, .. } => {
            let pts = &m.links[link].points;
            let other = if pts[0] == pivot { pts[1] } else { pts[0] };
            let w = m.local(link, other) - m.local(link, pivot);
            let at = m.links[m.frame()]
                .sketch_pose
                .apply(m.local(m.frame(), pivot));
            Pose::through(at, m.local(link, pivot), q - w.atan2())
        }
        InputSpec::Slider { pair, .. } => {
            let pr = &m.prismatics[pair];
            let line = pr.line(&Pose::IDENTITY);
            let q0 = sketch_slider_ref(m, pair);
            Pose::through(q0 + line.dir * q, pr.slider_local, pr.delta)
        }
    }
}

/// The reference of a driving slider's displacement: its point in the
/// sketch, projected onto the guide.
pub fn sketch_slider_ref(m: &Mechanism, pair: usize) -> Point {
    let pr = &m.prismatics[pair];
    let line = pr.line(&Pose::IDENTITY);
    let p = sketch(m, pr.point);
    line.point + line.dir * (p - line.point).dot(line.dir)
}

/// Where the sketch has the slider's point of pair `k` along its guide
/// line, from the line's point, in the guide's frame: the zero of the
/// pair's slide.
pub fn slide_ref(m: &Mechanism, k: usize) -> f64 {
    let pr = &m.prismatics[k];
    let q0 = m.links[pr.guide].sketch_pose.local(sketch(m, pr.point));
    pr.line_dir.dot(q0 - pr.line_point)
}

/// The slider's pose in its guide's frame when the slider's point of pair
/// `k` has slid by `x` along the guide from where the sketch has it.
pub fn slide_pose(m: &Mechanism, k: usize, x: f64) -> Pose {
    let pr = &m.prismatics[k];
    let at = pr.line_point + pr.line_dir * (slide_ref(m, k) + x);
    Pose::through(at.to_point(), pr.slider_local, pr.delta)
}

/// The pose of the link a driving pair `k` places, its other link
/// (`known`) at `known_pose` and the slide `x`.
pub fn place_across(m: &Mechanism, k: usize, known: usize, known_pose: &Pose, x: f64) -> Pose {
    let rel = slide_pose(m, k, x);
    if m.prismatics[k].guide == known {
        known_pose.then(&rel)
    } else {
        known_pose.then(&rel.inverse())
    }
}

/// The input coordinates the sketch itself shows.
pub fn sketch_input(m: &Mechanism) -> Coords {
    let q: Vec<f64> = m
        .scene
        .inputs()
        .map(|spec| match *spec {
            InputSpec::Crank { link, pivot, .. } => {
                let pts = &m.links[link].points;
                let other = if pts[0] == pivot { pts[1] } else { pts[0] };
                (sketch(m, other) - sketch(m, pivot)).atan2()
            }
            InputSpec::Slider { .. } => 0.0,
        })
        .collect();
    Coords::new(&q)
}

/// The largest step of input `i` in which class III groups are tracked: 2°
/// of a crank, a hundredth of the smallest class III group of a slider.
pub(crate) fn triad_step(m: &Mechanism, s: &Structure, need: &[bool], i: usize) -> f64 {
    match m.scene.input_at(i) {
        InputSpec::Crank { .. } => 2f64.to_radians(),
        // A hundredth of the smallest class III group: the groups'
        // own size, not the sketch's.
        InputSpec::Slider { .. } => {
            0.01 * s
                .groups
                .iter()
                .zip(need)
                .filter_map(|(g, &n)| match g {
                    AssurGroup::Triad(t) if n => Some(triad_geom(m, t).scale),
                    _ => None,
                })
                .fold(f64::INFINITY, f64::min)
        }
    }
}

/// The change of the input coordinates from `from` to `to`: a crank the
/// short way round, a slider straight.
pub fn span(m: &Mechanism, from: &[f64], to: &[f64]) -> Coords {
    let mut d = Coords::new(to);
    for ((d, &a), spec) in d.iter_mut().zip(from).zip(m.scene.inputs()) {
        *d = match spec {
            InputSpec::Crank { .. } => wrap_pi(*d - a),
            InputSpec::Slider { .. } => *d - a,
        };
    }
    d
}

/// The position solver: closed forms per group with the sketch's branches.
#[derive(Clone, Debug)]
pub struct PositionSolver<'a> {
    pub m: &'a Mechanism,
    pub s: &'a Structure,
    /// Which groups to solve (demand-driven).
    pub need: Vec<bool>,
    pub branches: Branches,
    /// The input coordinates of the last solved position (for tracking).
    pub last_q: Coords,
}

impl<'a> PositionSolver<'a> {
    pub fn new(m: &'a Mechanism, s: &'a Structure, need: Vec<bool>) -> Result<Self> {
        Ok(PositionSolver {
            m,
            s,
            need,
            branches: Branches::from_sketch(m, s)?,
            last_q: sketch_input(m),
        })
    }

    /// Whether a class III group is tracked (its positions by continuation).
    pub fn has_triads(&self) -> bool {
        self.s
            .groups
            .iter()
            .zip(&self.need)
            .any(|(g, &n)| n && matches!(g, AssurGroup::Triad(_)))
    }

    /// Solve at input coordinate `q` (a single input), reached
    /// continuously from the last solved position (from the sketch at
    /// first), the short way round.
    pub fn solve(&mut self, q: f64) -> Result<Configuration> {
        self.solve_coords(Coords::one(q))
    }

    /// Solve at the input coordinates `q`, reached continuously from the
    /// last solved position (from the sketch at first), each crank the
    /// short way round.
    pub fn solve_coords(&mut self, q: Coords) -> Result<Configuration> {
        if self.has_triads() {
            // Track class III groups in small steps so they stay on their branch.
            let span = span(self.m, &self.last_q, &q);
            let n = span
                .iter()
                .enumerate()
                .map(|(i, d)| (d.abs() / triad_step(self.m, self.s, &self.need, i)).ceil())
                .fold(0.0, f64::max) as usize;
            for k in 1..n {
                let mut qk = self.last_q;
                for (x, d) in qk.iter_mut().zip(span.iter()) {
                    *x += d * k as f64 / n as f64;
                }
                self.solve_at_coords(qk)?;
            }
        }
        let c = self.solve_at_coords(q)?;
        self.last_q = q;
        Ok(c)
    }

    /// Solve at `q` (a single input) from the current tracked state
    /// without stepping.
    pub fn solve_at(&mut self, q: f64) -> Result<Configuration> {
        self.solve_at_coords(Coords::one(q))
    }

    /// Solve at the input coordinates `q` from the current tracked state
    /// without stepping.
    pub fn solve_at_coords(&mut self, q: Coords) -> Result<Configuration> {
        let m = self.m;
        let mut c = Configuration {
            poses: vec![None; m.links.len()],
        };
        c.poses[m.frame()] = Some(Pose::IDENTITY);
        for &st in &self.s.stages {
            let gi = match st {
                Stage::Input(i) => {
                    match self.s.roles[i] {
                        InputRole::Frame => {
                            c.poses[m.scene.input_at(i).link()] = Some(place_input(m, i, q[i]))
                        }
                        InputRole::Chained { known, pair } => {
                            let pr = &m.prismatics[pair];
                            let other = if pr.guide == known {
                                pr.slider
                            } else {
                                pr.guide
                            };
                            let Some(kp) = c.poses[known] else {
                                continue;
                            };
                            c.poses[other] = Some(place_across(m, pair, known, &kp, q[i]));
                        }
                        InputRole::InGroup { .. } => {}
                    }
                    continue;
                }
                Stage::Group(gi) => gi,
            };
            if !self.need[gi] {
                continue;
            }
            let sign = self.branches.sign[gi];
            match &self.s.groups[gi] {
                AssurGroup::Dyad(d) => {
                    let cyl = d.cylinder.map(|cy| (cy, q[cy.input]));
                    solve_dyad(m, d, cyl, sign, &mut c)
                        .map_err(|why| dyad_error(m, self.s, gi, &q, why))?
                }
                AssurGroup::Triad(t) => {
                    let pose = solve_triad(m, t, self.branches.triad_pose[gi], &mut c)
                        .map_err(|why| triad_error(m, self.s, gi, &q, why))?;
                    self.branches.triad_pose[gi] = pose;
                }
            }
        }
        Ok(c)
    }
}

/// The error of dyad `gi` that failed at `q` for the reason `why` (a
/// singular position when `why` is marked so, else a failure to assemble).
pub(crate) fn dyad_error(m: &Mechanism, s: &Structure, gi: usize, q: &[f64], why: String) -> Error {
    let g = &s.groups[gi];
    let kind = match g {
        AssurGroup::Dyad(d) => d.kind.name(),
        AssurGroup::Triad(_) => "class III",
    };
    let group = format!("group {} ({kind})", g.label(m));
    match why.strip_prefix(SINGULAR) {
        Some(why) => Error::singular(describe_input(m, q), format!("{group}: {why}")),
        None => Error::assembly(group, describe_input(m, q), why),
    }
}

/// The error of class III group `gi` that failed at `q` for the reason `why`.
pub(crate) fn triad_error(
    m: &Mechanism,
    s: &Structure,
    gi: usize,
    q: &[f64],
    why: String,
) -> Error {
    Error::assembly(
        format!("group {} (class III)", s.groups[gi].label(m)),
        describe_input(m, q),
        why,
    )
}

fn known_point(m: &Mechanism, c: &Configuration, conn: &Conn, known_side: usize) -> Point {
    c.point(m, known_side, point_of(conn.joint))
}

/// The mark of a dyad's failure that is a singular position, not a
/// failure to assemble.
const SINGULAR: &str = "singular: ";

pub(crate) fn solve_dyad(
    m: &Mechanism,
    d: &Dyad,
    cyl: Option<(Cylinder, f64)>,
    sign: f64,
    c: &mut Configuration,
) -> std::result::Result<(), String> {
    let [l1, l2] = d.links;
    // A cylinder is one link of variable length: the other of its two
    // placed in the frame of the one in the dyad's slot, at the slide.
    let rel = cyl.map(|(cy, x)| {
        let own = d.links[cy.slot];
        let sl = slide_pose(m, cy.pair, x);
        (
            cy,
            if m.prismatics[cy.pair].guide == own {
                sl
            } else {
                sl.inverse()
            },
        )
    });
    // Point p of the group's link in `slot`, carried by `carrier`, in the
    // frame of the slot's link.
    let unit_local = |slot: usize, carrier: usize, p: usize| -> Vec2 {
        match rel {
            Some((cy, r)) if cy.slot == slot && carrier == cy.other => {
                r.apply(m.local(cy.other, p)).to_vec2()
            }
            _ => m.local(carrier, p),
        }
    };
    // The cylinder's other link, once the slot's link is posed.
    let place_other = |c: &mut Configuration| {
        if let Some((cy, r)) = rel {
            c.poses[cy.other] = Some(c.pose(d.links[cy.slot]).then(&r));
        }
    };
    // Tangency (a toggle) is accepted to the rounding of the numbers that
    // meet there: the group's lengths and the coordinates of its joints,
    // never a fraction of the sketch's size.
    let rounding = |lens: f64, at: &[Point]| {
        ACCURACY.tangency_roundings
            * f64::EPSILON
            * (lens + at.iter().map(|p| p.to_vec2().hypot()).sum::<f64>())
    };
    let min_sin = ACCURACY.min_line_sine;
    match d.kind {
        DyadKind::Rrr => {
            let (pb, pc, pd) = (
                point_of(d.ext1.joint),
                point_of(d.mid.joint),
                point_of(d.ext2.joint),
            );
            let b = known_point(m, c, &d.ext1, d.ext1.from);
            let dd = known_point(m, c, &d.ext2, d.ext2.to);
            let (b1, c1) = (unit_local(0, l1, pb), unit_local(0, d.mid.from, pc));
            let (d2, c2) = (unit_local(1, l2, pd), unit_local(1, d.mid.to, pc));
            let r1 = (c1 - b1).hypot();
            let r2 = (c2 - d2).hypot();
            let tol = rounding(r1 + r2, &[b, dd]);
            let x = circle_circle(b, r1, dd, r2, sign, tol).ok_or_else(|| {
                format!(
                    "the circles of radius {} about {} and {} about {} do not meet ({} and {} are {} apart)",
                    quantity(r1, "m"),
                    m.point_name(pb),
                    quantity(r2, "m"),
                    m.point_name(pd),
                    m.point_name(pb),
                    m.point_name(pd),
                    quantity(b.distance(dd), "m")
                )
            })?;
            set_by_two_local(c, l1, b1, b, c1, x);
            set_by_two_local(c, l2, d2, dd, c2, x);
            place_other(c);
        }
        DyadKind::Rrp => {
            let (pb, pc) = (point_of(d.ext1.joint), point_of(d.mid.joint));
            let k = pair_of(d.ext2.joint);
            let k2 = d.ext2.to;
            let b = known_point(m, c, &d.ext1, d.ext1.from);
            let th2 = angle_across(m, k, k2, c.pose(k2).angle);
            let line = slide_line(m, k, k2, &c.pose(k2), th2, m.local(l2, pc));
            let (b1, c1) = (unit_local(0, l1, pb), unit_local(0, d.mid.from, pc));
            let r1 = (c1 - b1).hypot();
            let tol = rounding(r1, &[b, line.point]);
            let x = circle_line(b, r1, &line, sign, tol).ok_or_else(|| {
                format!(
                    "the circle of radius {} about {} does not reach the guide line ({} away)",
                    quantity(r1, "m"),
                    m.point_name(pb),
                    quantity(line.signed_distance(b).abs(), "m")
                )
            })?;
            set_by_two_local(c, l1, b1, b, c1, x);
            place_other(c);
            c.poses[l2] = Some(Pose::through(x, m.local(l2, pc), th2));
        }
        DyadKind::Rpr => {
            let rg = rocking_guide(m, d);
            let known_of = |p: usize| {
                if p == point_of(d.ext1.joint) {
                    c.point(m, d.ext1.from, p)
                } else {
                    c.point(m, d.ext2.to, p)
                }
            };
            let jg = known_of(rg.pin_guide);
            let js = known_of(rg.pin_slider);
            let w = js - jg;
            let dist = w.hypot();
            let s = rg.h / dist;
            let tol = rounding(rg.h.abs(), &[jg, js]);
            if dist <= tol && rg.h.abs() <= tol {
                // The pin on the guide's pivot: any direction through it is
                // a guide line; the position is singular, not impossible.
                return Err(format!(
                    "{SINGULAR}{} is on {} (the guide through it), so the guide's direction is not determined",
                    m.point_name(rg.pin_slider),
                    m.point_name(rg.pin_guide)
                ));
            }
            if !s.is_finite() || rg.h.abs() - dist > tol || dist <= tol {
                return Err(format!(
                    "the guide passes {} from {} but {} is only {} away",
                    quantity(rg.h.abs(), "m"),
                    m.point_name(rg.pin_guide),
                    m.point_name(rg.pin_slider),
                    quantity(dist, "m")
                ));
            }
            let s = s.clamp(-1.0, 1.0);
            let gamma_minus_beta = s.atan2(sign * (1.0 - s * s).max(0.0).sqrt());
            let psi = w.atan2() - gamma_minus_beta - rg.alpha;
            c.poses[rg.guide] = Some(Pose::through(jg, m.local(rg.guide, rg.pin_guide), psi));
            c.poses[rg.slider] = Some(Pose::through(
                js,
                m.local(rg.slider, rg.pin_slider),
                psi + rg.delta,
            ));
        }
        DyadKind::Prp => {
            let pc = point_of(d.mid.joint);
            let (k1, k2) = (d.ext1.from, d.ext2.to);
            let (j1, j2) = (pair_of(d.ext1.joint), pair_of(d.ext2.joint));
            let th1 = angle_across(m, j1, k1, c.pose(k1).angle);
            let th2 = angle_across(m, j2, k2, c.pose(k2).angle);
            let a = slide_line(m, j1, k1, &c.pose(k1), th1, m.local(l1, pc));
            let b = slide_line(m, j2, k2, &c.pose(k2), th2, m.local(l2, pc));
            let LineCut::Point { at, .. } = intersect_lines(&a, &b, min_sin) else {
                return Err("the two guides are parallel: the joint is not determined".into());
            };
            c.poses[l1] = Some(Pose::through(at, m.local(l1, pc), th1));
            c.poses[l2] = Some(Pose::through(at, m.local(l2, pc), th2));
        }
        DyadKind::Rpp => {
            let pb = point_of(d.ext1.joint);
            let (jm, j2) = (pair_of(d.mid.joint), pair_of(d.ext2.joint));
            let k2 = d.ext2.to;
            let b = known_point(m, c, &d.ext1, d.ext1.from);
            let th2 = angle_across(m, j2, k2, c.pose(k2).angle);
            let th1 = angle_across(m, jm, l2, th2);
            let p1 = Pose::through(b, m.local(l1, pb), th1);
            c.poses[l1] = Some(p1);
            let a = slide_line(m, j2, k2, &c.pose(k2), th2, Vec2::ZERO);
            let bl = slide_line(m, jm, l1, &p1, th2, Vec2::ZERO);
            let LineCut::Point { at, .. } = intersect_lines(&a, &bl, min_sin) else {
                return Err("the two guides are parallel: the slide is not determined".into());
            };
            c.poses[l2] = Some(Pose::new(at, th2));
        }
    }
    Ok(())
}

/// Pose a link by two of its points at known world places.
fn set_by_two(
    m: &Mechanism,
    c: &mut Configuration,
    link: usize,
    p: usize,
    at_p: Point,
    q: usize,
    at_q: Point,
) {
    set_by_two_local(c, link, m.local(link, p), at_p, m.local(link, q), at_q);
}

/// Pose a link by two points at local places `lp`, `lq` at known world
/// places.
fn set_by_two_local(
    c: &mut Configuration,
    link: usize,
    lp: Vec2,
    at_p: Point,
    lq: Vec2,
    at_q: Point,
) {
    let (w, l) = (at_q - at_p, lq - lp);
    let angle = w.atan2() - l.atan2();
    // The turn from l to w: its cosine and sine straight from the vectors.
    let norm = w.hypot() * l.hypot();
    let turn = (l.dot(w) / norm, l.cross(w) / norm);
    c.poses[link] = Some(Pose::through_turned(at_p, lp, angle, turn));
}

/// Solve a three-leash group: the base pose (x, y, ψ) such that every
/// leash closes, |J_i − E_i| = r_i, by Newton's method from `start` (the
/// previous solution, or the sketch). The branch is the one continuous
/// from the sketch; a dead point of the group (the three leashes' axes
/// through one point) shows as a singular 3×3 system.
pub(crate) fn solve_triad(
    m: &Mechanism,
    t: &Triad,
    start: Pose,
    c: &mut Configuration,
) -> std::result::Result<Pose, String> {
    let tg = triad_geom(m, t);
    let e = [0, 1, 2].map(|i| c.point(m, t.ext[i].from, tg.ext_pts[i]));
    let residual =
        |p: &Pose| [0, 1, 2].map(|i| (p.apply(tg.b[i]) - e[i]).hypot2() - tg.r[i] * tg.r[i]);
    let mut pose = start;
    // The group's own size scales its angle and its tolerances; the
    // coordinates' magnitude bounds how small a correction can get.
    let size = tg.scale;
    let far = e.iter().map(|p| p.to_vec2().hypot()).fold(0.0, f64::max);
    let floor = 4.0 * f64::EPSILON * (size + far);
    let mut converged = false;
    for _ in 0..60 {
        let r = residual(&pose);
        let mut j = nalgebra::Matrix3::<f64>::zeros();
        for i in 0..3 {
            let d = pose.apply(tg.b[i]) - e[i];
            let turn = crate::geom::perp(pose.dir(tg.b[i]));
            j[(i, 0)] = 2.0 * d.x;
            j[(i, 1)] = 2.0 * d.y;
            j[(i, 2)] = 2.0 * d.dot(turn) / size;
        }
        let Some(step) = j.lu().solve(&nalgebra::Vector3::new(r[0], r[1], r[2])) else {
            return Err(
                "the group is at a dead point (its leashes' axes meet in one point)".into(),
            );
        };
        // Damp the step so that a far start cannot jump to the other branch.
        let mut k = 1.0;
        let norm = |r: [f64; 3]| r.iter().map(|x| x.abs()).fold(0.0, f64::max);
        let r0 = norm(r);
        let mut next;
        loop {
            next = Pose::new(
                pose.origin - Vec2::new(step[0], step[1]) * k,
                pose.angle - step[2] / size * k,
            );
            // At the level of rounding the residual cannot fall: take the
            // full step there, or the damping would fake convergence.
            if norm(residual(&next)) <= r0 || r0 <= 1e-13 * size * (size + far) || k < 1e-3 {
                break;
            }
            k *= 0.5;
        }
        let moved = (step[0].abs().max(step[1].abs()).max(step[2].abs())) * k;
        pose = next;
        if !moved.is_finite() {
            break;
        }
        if moved <= floor {
            converged = true;
            break;
        }
    }
    let r = residual(&pose).iter().map(|x| x.abs()).fold(0.0, f64::max);
    // |J − E|² − r² ≈ 2·r·δ: a residual of 1e-13·size² is a length error of
    // order 1e-13·size.
    // Near the group's dead point the steps need not fall below 1e-14·size
    // (the nearly singular system amplifies rounding), but a residual at
    // the level of rounding still means the group closes.
    if !(converged || r <= 1e-15 * size * (size + far))
        || !r.is_finite()
        || r > 1e-13 * size * (size + far)
    {
        return Err(format!(
            "no position of the base link {} near the previous one closes the group (residual {r:.2e} m²)",
            m.link_id(t.base)
        ));
    }
    c.poses[t.base] = Some(pose);
    for (i, ei) in e.iter().enumerate() {
        let j = pose.apply(tg.b[i]);
        set_by_two(m, c, t.leashes[i], tg.ext_pts[i], *ei, tg.int_pts[i], j);
    }
    Ok(pose)
}
