//! The class III three-leash group: its base pose by Newton's method,
//! tracked continuously from the sketch.

use super::{Configuration, describe_input, point_of, set_by_two_local};
use crate::error::Error;
use crate::geom::Pose;
use crate::model::mechanism::Mechanism;
use crate::model::structure::{Structure, Triad};
use kurbo::{Point, Vec2};

/// Triad data: leash lengths and the base's joint coordinates.
struct TriadGeom {
    ext_pts: [usize; 3],
    int_pts: [usize; 3],
    r: [f64; 3],
    b: [Vec2; 3],
    /// The group's own size: its longest leash or base side.
    scale: f64,
}

/// The group's own size: its longest leash or base side.
pub(super) fn triad_scale(m: &Mechanism, t: &Triad) -> f64 {
    triad_geom(m, t).scale
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
