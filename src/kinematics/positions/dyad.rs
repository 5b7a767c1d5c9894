//! The closed forms of the class II groups: RRR by circle∩circle, RRP by
//! circle∩line, RPR by the rocking guide's angle, PRP and RPP by
//! line∩line; a hydraulic cylinder in the group carried as one link of
//! variable length.

use super::{
    Configuration, angle_across, describe_input, pair_of, point_of, set_by_two_local, slide_line,
    slide_pose,
};
use crate::accuracy::ACCURACY;
use crate::error::{Error, Result};
use crate::geom::{LineCut, Pose, circle_circle, circle_line, intersect_lines, rotate};
use crate::model::mechanism::Mechanism;
use crate::model::structure::{AssurGroup, Conn, Cylinder, Dyad, DyadKind, Structure};
use crate::format::format_quantity as quantity;
use kurbo::{Point, Vec2};

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

/// The error of dyad `gi` that failed at `q` for the reason `why` (a
/// singular position when `why` is marked so, else a failure to assemble).
fn dyad_error(m: &Mechanism, s: &Structure, gi: usize, q: &[f64], why: Failure) -> Error {
    let g = &s.groups[gi];
    let kind = match g {
        AssurGroup::Dyad(d) => d.kind.name(),
        AssurGroup::Triad(_) => "class III",
    };
    let group = format!("group {} ({kind})", g.label(m));
    match why {
        Failure::Singular(why) => Error::singular(describe_input(m, q), format!("{group}: {why}")),
        Failure::Assembly(why) => Error::assembly(group, describe_input(m, q), why),
    }
}

fn known_point(m: &Mechanism, c: &Configuration, conn: &Conn, known_side: usize) -> Point {
    c.point(m, known_side, point_of(conn.joint))
}

/// Why a dyad could not be placed, in words: it does not close there,
/// or the position is singular (it closes, but in no unique way).
enum Failure {
    Assembly(String),
    Singular(String),
}

/// A failure said in words is a failure to assemble.
impl From<String> for Failure {
    fn from(why: String) -> Failure {
        Failure::Assembly(why)
    }
}

/// Place dyad `gi` of the structure at the input coordinates `q` on its
/// branch `sign` (a cylinder in it at its input's slide); a failure is
/// the solver's error ([`dyad_error`]).
pub(crate) fn solve_group_dyad(
    m: &Mechanism,
    s: &Structure,
    gi: usize,
    d: &Dyad,
    sign: f64,
    q: &[f64],
    c: &mut Configuration,
) -> Result<()> {
    let cyl = d.cylinder.map(|cy| (cy, q[cy.input]));
    solve_dyad(m, d, cyl, sign, c).map_err(|why| dyad_error(m, s, gi, q, why))
}

/// The points of an RRR group's three revolute pairs: B (outer, on K1),
/// C (middle), D (outer, on K2).
pub(crate) fn rrr_points(d: &Dyad) -> (usize, usize, usize) {
    (
        point_of(d.ext1.joint),
        point_of(d.mid.joint),
        point_of(d.ext2.joint),
    )
}

/// Place dyad `d` on its branch `sign`, a cylinder in it (`cyl`) at its
/// slide; the reason of a failure ([`Failure::Singular`] when the
/// position is singular, not impossible).
fn solve_dyad(
    m: &Mechanism,
    d: &Dyad,
    cyl: Option<(Cylinder, f64)>,
    sign: f64,
    c: &mut Configuration,
) -> std::result::Result<(), Failure> {
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
    let g = Placing { m, d, rel };
    match d.kind {
        DyadKind::Rrr => g.rrr(sign, c),
        DyadKind::Rrp => g.rrp(sign, c),
        DyadKind::Rpr => rpr(m, d, sign, c),
        DyadKind::Prp => prp(m, d, c),
        DyadKind::Rpp => rpp(m, d, c),
    }
}

/// A dyad being placed, with the cylinder's other link posed in the
/// frame of the link in the cylinder's slot (RRR, RRP).
struct Placing<'a> {
    m: &'a Mechanism,
    d: &'a Dyad,
    rel: Option<(Cylinder, Pose)>,
}

/// Tangency (a toggle) is accepted to the rounding of the numbers that
/// meet there: the group's lengths and the coordinates of its joints,
/// never a fraction of the sketch's size.
fn rounding(lens: f64, at: &[Point]) -> f64 {
    ACCURACY.tangency_roundings
        * f64::EPSILON
        * (lens + at.iter().map(|p| p.to_vec2().hypot()).sum::<f64>())
}

impl Placing<'_> {
    /// Point p of the group's link in `slot`, carried by `carrier`, in the
    /// frame of the slot's link.
    fn unit_local(&self, slot: usize, carrier: usize, p: usize) -> Vec2 {
        let m = self.m;
        match self.rel {
            Some((cy, r)) if cy.slot == slot && carrier == cy.other => {
                r.apply(m.local(cy.other, p)).to_vec2()
            }
            _ => m.local(carrier, p),
        }
    }

    /// The cylinder's other link, once the slot's link is posed.
    fn place_other(&self, c: &mut Configuration) {
        if let Some((cy, r)) = self.rel {
            c.poses[cy.other] = Some(c.pose(self.d.links[cy.slot]).then(&r));
        }
    }

    /// RRR: the circles about B and D meet at C.
    fn rrr(&self, sign: f64, c: &mut Configuration) -> std::result::Result<(), Failure> {
        let (m, d) = (self.m, self.d);
        let [l1, l2] = d.links;
        let (pb, pc, pd) = rrr_points(d);
        let b = known_point(m, c, &d.ext1, d.ext1.from);
        let dd = known_point(m, c, &d.ext2, d.ext2.to);
        let (b1, c1) = (
            self.unit_local(0, l1, pb),
            self.unit_local(0, d.mid.from, pc),
        );
        let (d2, c2) = (self.unit_local(1, l2, pd), self.unit_local(1, d.mid.to, pc));
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
        self.place_other(c);
        Ok(())
    }

    /// RRP: the circle about B meets the guide line of link 2.
    fn rrp(&self, sign: f64, c: &mut Configuration) -> std::result::Result<(), Failure> {
        let (m, d) = (self.m, self.d);
        let [l1, l2] = d.links;
        let (pb, pc) = (point_of(d.ext1.joint), point_of(d.mid.joint));
        let k = pair_of(d.ext2.joint);
        let k2 = d.ext2.to;
        let b = known_point(m, c, &d.ext1, d.ext1.from);
        let th2 = angle_across(m, k, k2, c.pose(k2).angle);
        let line = slide_line(m, k, k2, &c.pose(k2), th2, m.local(l2, pc));
        let (b1, c1) = (
            self.unit_local(0, l1, pb),
            self.unit_local(0, d.mid.from, pc),
        );
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
        self.place_other(c);
        c.poses[l2] = Some(Pose::through(x, m.local(l2, pc), th2));
        Ok(())
    }
}

/// RPR: the rocking guide's angle in closed form.
fn rpr(
    m: &Mechanism,
    d: &Dyad,
    sign: f64,
    c: &mut Configuration,
) -> std::result::Result<(), Failure> {
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
        return Err(Failure::Singular(format!(
            "{} is on {} (the guide through it), so the guide's direction is not determined",
            m.point_name(rg.pin_slider),
            m.point_name(rg.pin_guide)
        )));
    }
    if !s.is_finite() || rg.h.abs() - dist > tol || dist <= tol {
        return Err(format!(
            "the guide passes {} from {} but {} is only {} away",
            quantity(rg.h.abs(), "m"),
            m.point_name(rg.pin_guide),
            m.point_name(rg.pin_slider),
            quantity(dist, "m")
        )
        .into());
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
    Ok(())
}

/// PRP: the two guide lines through C meet.
fn prp(m: &Mechanism, d: &Dyad, c: &mut Configuration) -> std::result::Result<(), Failure> {
    let [l1, l2] = d.links;
    let min_sin = ACCURACY.min_line_sine;
    let pc = point_of(d.mid.joint);
    let (k1, k2) = (d.ext1.from, d.ext2.to);
    let (j1, j2) = (pair_of(d.ext1.joint), pair_of(d.ext2.joint));
    let th1 = angle_across(m, j1, k1, c.pose(k1).angle);
    let th2 = angle_across(m, j2, k2, c.pose(k2).angle);
    let a = slide_line(m, j1, k1, &c.pose(k1), th1, m.local(l1, pc));
    let b = slide_line(m, j2, k2, &c.pose(k2), th2, m.local(l2, pc));
    let LineCut::Point { at, .. } = intersect_lines(&a, &b, min_sin) else {
        return Err(Failure::Assembly(
            "the two guides are parallel: the joint is not determined".into(),
        ));
    };
    c.poses[l1] = Some(Pose::through(at, m.local(l1, pc), th1));
    c.poses[l2] = Some(Pose::through(at, m.local(l2, pc), th2));
    Ok(())
}

/// RPP: link 1 through B at the angle of the guides, the slide where its
/// guide line meets link 2's.
fn rpp(m: &Mechanism, d: &Dyad, c: &mut Configuration) -> std::result::Result<(), Failure> {
    let [l1, l2] = d.links;
    let min_sin = ACCURACY.min_line_sine;
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
        return Err(Failure::Assembly(
            "the two guides are parallel: the slide is not determined".into(),
        ));
    };
    c.poses[l2] = Some(Pose::new(at, th2));
    Ok(())
}
