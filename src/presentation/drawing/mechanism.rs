//! The plan of the mechanism at μ_l, with the symbols of kinematic schemes
//! (ГОСТ 2.770): fixed pivots with hatched bases, revolute pairs as small
//! circles, slider blocks on guides, links as lines or shaded ternary
//! links, link numbers, point labels, the input's ω1 (and ε1) arrows and
//! centres of mass.

use super::canvas::{Canvas, Class, FONT, Label, MAIN, SMALL, THIN};
use crate::geom::perp;
use crate::kinematics::solve::{Analysis, Solved};
use crate::model::scene::InputSpec;
use kurbo::{Point, Vec2};

/// Hatching under a fixed base: a base line of width `w` perpendicular to
/// `down` at `at`, with short strokes at 45° on the far side.
pub fn hatch(c: &mut Canvas, at: Point, down: Vec2, w: f64) {
    let down = down.normalize();
    let along = perp(down);
    let (a, b) = (at - along * (w / 2.0), at + along * (w / 2.0));
    c.seg(a, b, Class::Main);
    let n = (w / 1.5).floor() as usize;
    for k in 0..=n {
        let p = a + (b - a) * (k as f64 / n.max(1) as f64);
        c.seg(p, p + (down - along) * 1.6, Class::Thin);
    }
}

/// A fixed pivot: the pair's circle on a small triangle standing on a
/// hatched base.
fn pivot(c: &mut Canvas, at: Point, down: Vec2) {
    let down = down.normalize();
    let side = perp(down);
    let base = at + down * 4.0;
    c.seg(at + down * 1.0 - side * 0.9, base - side * 2.5, Class::Main);
    c.seg(at + down * 1.0 + side * 0.9, base + side * 2.5, Class::Main);
    hatch(c, base, down, 8.0);
    c.circle(at, 1.2, "white", MAIN);
}

/// A centre of mass: a circle with two opposite quarters filled.
fn centre_of_mass(c: &mut Canvas, at: Point) {
    let r = 1.4;
    c.circle(at, r, "white", THIN);
    for q in [0.0, std::f64::consts::PI] {
        let mut pts = vec![at];
        for k in 0..=6 {
            pts.push(at + Vec2::from_angle(q + std::f64::consts::FRAC_PI_2 * k as f64 / 6.0) * r);
        }
        c.poly(pts, "black", 0.0);
    }
}

/// Draw the mechanism at position `s` with scale `mu_l` (m/mm).
pub fn draw(an: &Analysis, s: &Solved, c: &mut Canvas, mu_l: f64, with_labels: bool) {
    let m = &an.mech;
    let frame = m.frame();
    let to = |p: Point| Point::new(p.x / mu_l, p.y / mu_l);
    let place = |l: usize, p: usize| to(s.config.point(m, l, p));
    let at_point = |p: usize| {
        let l = m
            .links_of_point(p)
            .into_iter()
            .find(|&l| an.link(l))
            .unwrap_or(frame);
        place(l, p)
    };
    let joints: Vec<bool> = (0..m.scene.points.len())
        .map(|p| m.links_of_point(p).len() >= 2)
        .collect();
    let is_mass = |p: usize| !joints[p] && m.point_name(p).starts_with('S');
    let shown: Vec<Point> = (0..m.scene.points.len())
        .filter(|&p| m.links_of_point(p).iter().any(|&l| an.link(l)))
        .map(at_point)
        .collect();
    let centre = Point::new(
        shown.iter().map(|p| p.x).sum::<f64>() / shown.len().max(1) as f64,
        shown.iter().map(|p| p.y).sum::<f64>() / shown.len().max(1) as f64,
    );
    // Guides first (under the links): the frame's guides with hatching.
    let cylinders = super::cylinder::pairs(an);
    for (k, pr) in m.prismatics.iter().enumerate() {
        if !an.link(pr.slider) || !an.link(pr.guide) || cylinders.contains(&k) {
            continue;
        }
        let q = place(pr.slider, pr.point);
        let u = s.config.pose(pr.guide).dir(pr.line_dir);
        if pr.guide == frame {
            let half = 18.0;
            c.seg(q - u * half, q + u * half, Class::Main);
            // Hatch on the side away from the links that reach the slider.
            let mut toward = Vec2::ZERO;
            for &l in m
                .links_of_point(pr.point)
                .iter()
                .filter(|&&l| l != pr.slider && an.link(l))
            {
                for &o in m.links[l].points.iter().filter(|&&o| o != pr.point) {
                    toward += place(l, o) - q;
                }
            }
            if toward.hypot() < 1e-9 {
                toward = centre - q;
            }
            let n = perp(u);
            let n = if n.dot(toward) > 0.0 { n } else { -n };
            let (b0, b1) = (q - u * half - n * 3.2, q + u * half - n * 3.2);
            c.seg(b0, b1, Class::Thin);
            for k in 0..=12 {
                let p = b0 + (b1 - b0) * (k as f64 / 12.0);
                c.seg(p, p - (u + n) * 1.4, Class::Thin);
            }
        } else {
            // A guide on a moving link (a kulisa): its slot through the
            // slider. A one-point link carrying a slot (a sliding yoke) is
            // drawn as the slot itself, reaching its own point, so that the
            // slot and the yoke read as one link.
            let (mut lo, mut hi) = (-10.0f64, 10.0f64);
            if m.links[pr.guide].points.len() == 1 {
                let t = (place(pr.guide, m.links[pr.guide].points[0]) - q).dot(u);
                lo = lo.min(t - 3.0);
                hi = hi.max(t + 3.0);
            }
            c.seg(q + u * lo, q + u * hi, Class::Main);
        }
    }
    // Links.
    for (l, link) in m.links.iter().enumerate() {
        if l == frame || !an.link(l) {
            continue;
        }
        let pts: Vec<usize> = link
            .points
            .iter()
            .copied()
            .filter(|&p| !is_mass(p))
            .collect();
        let xy: Vec<Point> = pts.iter().map(|&p| place(l, p)).collect();
        if xy.len() >= 3 {
            c.poly(xy.clone(), "#d9d9d9", MAIN);
        } else if xy.len() == 2 {
            c.seg(xy[0], xy[1], Class::Main);
        }
        // Centres of mass lie on their links: draw the link to them.
        for &p in &link.points {
            if is_mass(p) && xy.len() == 2 {
                let q = place(l, p);
                let on = (xy[1] - xy[0]).cross(q - xy[0]).abs() <= 1e-6 * (xy[1] - xy[0]).hypot2();
                if !on {
                    c.seg(xy[0], q, Class::Main);
                }
            }
        }
        // A slider block (a cylinder's rod: the cylinder's symbol).
        if let Some(pr) = m
            .prismatics
            .iter()
            .enumerate()
            .find(|(k, pr)| pr.slider == l && !cylinders.contains(k))
            .map(|(_, pr)| pr)
        {
            let q = place(l, pr.point);
            let u = s.config.pose(pr.guide).dir(pr.line_dir);
            let n = perp(u);
            let (a, b) = (5.0, 3.0);
            let corners = vec![
                q - u * a - n * b,
                q + u * a - n * b,
                q + u * a + n * b,
                q - u * a + n * b,
            ];
            c.poly(corners, "white", MAIN);
        }
        // Link number beside the middle of its first segment.
        let mid = if xy.len() >= 2 {
            xy[0].midpoint(xy[1])
        } else {
            xy.first().copied().unwrap_or(Point::ORIGIN) + Vec2::new(0.0, 4.0)
        };
        c.label_later(
            mid,
            Label::new(link.id.clone(), ""),
            SMALL,
            Some(format!("link-{}", link.id)),
        );
    }
    super::cylinder::draw(an, s, c, mu_l);
    // Pairs and points.
    for (p, &joint) in joints.iter().enumerate() {
        let ls = m.links_of_point(p);
        let moving = ls.iter().any(|&l| an.link(l) && l != frame);
        if !(moving || ls.contains(&frame) && joint) {
            continue;
        }
        let at = at_point(p);
        if ls.contains(&frame) && joint {
            // The base stands on the side away from the links at the pivot,
            // snapped to a multiple of 45° so it looks drawn, not computed.
            let mut away = Vec2::ZERO;
            for &l in ls.iter().filter(|&&l| l != frame && an.link(l)) {
                for &q in m.links[l].points.iter().filter(|&&q| q != p) {
                    let d = place(l, q) - at;
                    if d.hypot() > 0.0 {
                        away -= d.normalize();
                    }
                }
            }
            let down = if away.hypot() < 1e-9 {
                Vec2::new(0.0, -1.0)
            } else {
                away
            };
            let snapped =
                (down.atan2() / std::f64::consts::FRAC_PI_4).round() * std::f64::consts::FRAC_PI_4;
            pivot(c, at, Vec2::from_angle(snapped));
        } else if joint {
            c.circle(at, 1.2, "white", MAIN);
        } else if is_mass(p) {
            centre_of_mass(c, at);
        } else {
            c.circle(at, 0.6, "black", 0.0);
        }
        if with_labels {
            let name = m.point_name(p);
            let split = name
                .find(|ch: char| ch.is_ascii_digit() || ch == '_')
                .unwrap_or(name.len());
            c.label_later(
                at,
                Label::new(&name[..split], name[split..].trim_start_matches('_')),
                FONT,
                Some(format!("point-{name}")),
            );
        }
    }
    // The inputs' motion: ω1 (and ε1) as arcs about each crank's pivot.
    for (i, spec) in m.scene.inputs().enumerate() {
        let InputSpec::Crank {
            link, pivot: pv, ..
        } = *spec
        else {
            continue;
        };
        let (w, e) = (s.drives[i].rate, s.drives[i].rate2);
        let o = at_point(pv);
        let other = m.links[link]
            .points
            .iter()
            .copied()
            .find(|&p| p != pv)
            .unwrap();
        let dir = (place(link, other) - o).atan2();
        for (k, (val, name)) in [(w, "ω"), (e, "ε")].into_iter().enumerate() {
            if val == 0.0 {
                continue;
            }
            // On the far side of the pivot from the crank, as textbooks draw it.
            let r = 6.0 + 3.5 * k as f64;
            let sweep = 1.6 * val.signum();
            let a0 = dir + std::f64::consts::PI - sweep / 2.0;
            c.prims
                .push(super::canvas::Prim::Arc { c: o, r, a0, sweep });
            let end = a0 + sweep;
            let tip = o + Vec2::from_angle(end) * r;
            let tangent = perp(Vec2::from_angle(end)) * val.signum();
            c.prims
                .push(super::canvas::Prim::Arrow { tip, dir: tangent });
            c.label_later(
                o + Vec2::from_angle(a0 + sweep / 2.0) * (r + 1.0),
                Label::new(name, m.link_id(link)),
                FONT,
                Some(if i == 0 {
                    format!("input-{name}")
                } else {
                    format!("input-{name}{}", m.link_id(link))
                }),
            );
        }
    }
}
