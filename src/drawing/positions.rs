//! The positions sheet (lecture Fig. 2.1): the mechanism in every solved
//! position, numbered, with the trajectories of chosen points.

use super::canvas::{Canvas, Class, Label, SMALL};
use crate::solve::{Analysis, Solved};

/// Draw all positions thinly, the first one in main lines, and the path of
/// every coupler point (points of links that neither are the frame nor
/// turn about a fixed pivot) through the positions.
pub fn draw(an: &Analysis, solved: &[Solved], c: &mut Canvas, mu_l: f64) {
    let m = &an.mech;
    if solved.is_empty() {
        return;
    }
    super::mechanism::draw(an, &solved[0], c, mu_l, true);
    for (k, s) in solved.iter().enumerate().skip(1) {
        for (l, link) in m.links.iter().enumerate() {
            if l == m.frame() || !an.include[l] || link.points.len() < 2 {
                continue;
            }
            let xy: Vec<kurbo::Point> = link
                .points
                .iter()
                .map(|&p| {
                    let q = s.config.point(m, l, p);
                    kurbo::Point::new(q.x / mu_l, q.y / mu_l)
                })
                .collect();
            for i in 1..xy.len() {
                c.seg(xy[i - 1], xy[i], Class::Thin);
            }
        }
        // Number the position at the crank's (input's) moving point.
        let input = m.scene.input.link();
        if let Some(&p) = m.links[input]
            .points
            .iter()
            .find(|&&p| !m.links_of_point(p).contains(&m.frame()))
        {
            let q = s.config.point(m, input, p);
            c.label(
                kurbo::Point::new(q.x / mu_l, q.y / mu_l),
                Label::new(format!("{k}"), ""),
                SMALL,
                Some(format!("pos-{k}")),
            );
        }
    }
    // Trajectories: points not on the frame and not on a link pivoted on it.
    for p in 0..m.scene.points.len() {
        let ls = m.links_of_point(p);
        let Some(&l) = ls.iter().find(|&&l| an.include[l]) else {
            continue;
        };
        let pivoted = |l: usize| {
            m.links[l]
                .points
                .iter()
                .any(|&q| m.links_of_point(q).contains(&m.frame()))
        };
        if ls.contains(&m.frame())
            || ls.iter().all(|&l| pivoted(l))
            || m.prismatics
                .iter()
                .any(|pr| pr.slider == l && pr.guide == m.frame())
        {
            continue;
        }
        let pts: Vec<kurbo::Point> = solved
            .iter()
            .map(|s| {
                let q = s.config.point(m, l, p);
                kurbo::Point::new(q.x / mu_l, q.y / mu_l)
            })
            .collect();
        for i in 0..pts.len() {
            let j = (i + 1) % pts.len();
            if j == 0 && pts.len() < 3 {
                break;
            }
            c.prims.push(super::canvas::Prim::Seg {
                a: pts[i],
                b: pts[j],
                class: Class::Thin,
                id: None,
            });
        }
    }
}
