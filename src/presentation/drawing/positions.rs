//! The positions sheet (lecture Fig. 2.1): the mechanism in every solved
//! position, numbered from 1, the first in main lines, with the
//! trajectories of the coupler points drawn through many more positions.

use super::canvas::{Canvas, Class, Label, SMALL};
use crate::kinematics::positions::PositionSolver;
use crate::kinematics::solve::{Analysis, Solved};
use crate::model::scene::InputSpec;
use kurbo::Point;

pub fn draw(an: &Analysis, solved: &[Solved], c: &mut Canvas, mu_l: f64) {
    let m = &an.mech;
    if solved.is_empty() {
        return;
    }
    let to = |p: Point| Point::new(p.x / mu_l, p.y / mu_l);
    super::mechanism::draw(an, &solved[0], c, mu_l, true);
    let input = m.scene.input.link();
    let tip = m.links[input]
        .points
        .iter()
        .copied()
        .find(|&p| !m.links_of_point(p).contains(&m.frame()));
    for (k, s) in solved.iter().enumerate() {
        if k > 0 {
            for (l, link) in m.links.iter().enumerate() {
                if l == m.frame() || !an.link(l) || link.points.len() < 2 {
                    continue;
                }
                let xy: Vec<Point> = link
                    .points
                    .iter()
                    .map(|&p| to(s.config.point(m, l, p)))
                    .collect();
                for i in 1..xy.len() {
                    c.seg(xy[i - 1], xy[i], Class::Thin);
                }
            }
        }
        // Number every position, from 1, at the input's moving point.
        if let Some(p) = tip {
            let at = to(s.config.point(m, input, p));
            c.circle(at, 0.4, "black", 0.0);
            c.label_later(
                at,
                Label::new(format!("{}", k + 1), ""),
                SMALL,
                Some(format!("pos-{}", k + 1)),
            );
        }
    }
    // Guides on the frame long enough for the whole stroke.
    for pr in &m.prismatics {
        if pr.guide != m.frame() || !an.link(pr.slider) {
            continue;
        }
        let u = pr.line(&crate::geom::Pose::IDENTITY).dir;
        let pts: Vec<Point> = solved
            .iter()
            .map(|s| to(s.config.point(m, pr.slider, pr.point)))
            .collect();
        let ts: Vec<f64> = pts.iter().map(|p| (*p - pts[0]).dot(u)).collect();
        let (lo, hi) = ts
            .iter()
            .fold((0.0f64, 0.0f64), |(a, b), &t| (a.min(t), b.max(t)));
        c.seg(
            pts[0] + u * (lo - 12.0),
            pts[0] + u * (hi + 12.0),
            Class::Main,
        );
        for p in &pts {
            c.circle(*p, 0.5, "black", 0.0);
        }
    }
    // Trajectories of points not fixed to the frame nor turning about a
    // fixed pivot, through 72 positions per revolution (or the solved ones).
    let full_turn = matches!(m.scene.input, InputSpec::Crank { .. })
        && !m.scene.several_inputs()
        && solved.len() >= 12;
    let mut paths: Vec<Vec<Point>> = Vec::new();
    let tracked: Vec<(usize, usize)> = (0..m.scene.points.len())
        .filter_map(|p| {
            let ls = m.links_of_point(p);
            let l = *ls.iter().find(|&&l| an.link(l))?;
            let pivoted = |l: usize| {
                l == m.frame()
                    || m.links[l]
                        .points
                        .iter()
                        .any(|&q| m.links_of_point(q).contains(&m.frame()))
            };
            let slides_on_frame = m
                .prismatics
                .iter()
                .any(|pr| pr.slider == l && pr.guide == m.frame());
            (!ls.iter().all(|&l| pivoted(l)) && !slides_on_frame).then_some((p, l))
        })
        .collect();
    if full_turn && let Ok(mut ps) = PositionSolver::new(m, &an.structure, an.need.clone()) {
        {
            let q0 = solved[0].q;
            let dir = m.scene.input.sense();
            let mut ok = true;
            let mut samples: Vec<Vec<Point>> = vec![Vec::new(); tracked.len()];
            for k in 0..=72 {
                match ps.solve(q0 + dir * std::f64::consts::TAU * k as f64 / 72.0) {
                    Ok(cfg) => {
                        for (i, &(p, l)) in tracked.iter().enumerate() {
                            samples[i].push(to(cfg.point(m, l, p)));
                        }
                    }
                    Err(_) => {
                        ok = false;
                        break;
                    }
                }
            }
            if ok {
                paths = samples;
            }
        }
    }
    if paths.is_empty() {
        paths = tracked
            .iter()
            .map(|&(p, l)| solved.iter().map(|s| to(s.config.point(m, l, p))).collect())
            .collect();
    }
    for path in paths {
        for w in path.windows(2) {
            c.seg(w[0], w[1], Class::Thin);
        }
    }
    c.place_pending();
}
