//! The input link's plan, last: its balancing moment (force) and the
//! reaction of the link it turns or slides on.

use super::draft::Draft;
use super::dyad::{couple_step, reaction};
use super::plan::{Force, ForcePlan, ForcePlans, ForceStep, Part, Slip};
use super::known::{Applied, ScaleOf, Side, record};
use crate::error::Result;
use crate::kinematics::solve::{Analysis, Position};
use crate::kinetostatics::newton_euler::guide_frame;
use crate::model::scene::InputSpec;
use crate::model::structure::Joint;
use kurbo::Vec2;

/// The input link `i` (a crank, a driving slider on the frame or a chained
/// slider): its balancing moment (force) and the reaction of the link it
/// turns or slides on.
pub(super) fn input_plan(
    an: &Analysis,
    s: &Position,
    i: usize,
    (known, out): (&mut Vec<Applied>, &mut ForcePlans),
    (delta, scale, slip): (f64, ScaleOf, Option<Slip>),
) -> Result<ForcePlan> {
    let m = &an.mech;
    let spec = m.scene.input_at(i);
    let link = spec.link();
    let side = Side {
        links: vec![link],
        known,
    };
    let sum = side.sum();
    let draw = |mu: f64| {
        let mut dr = Draft::new(mu, delta);
        dr.plan.links = vec![link];
        for a in side.forces().filter(|a| a.f != Vec2::ZERO) {
            dr.lay_off(a.f, a.force);
        }
        dr
    };
    let trial = draw(1.0);
    let mu = scale(&trial.plan.points);
    let mut dr = draw(mu);
    let end = dr.last();
    match *spec {
        InputSpec::Crank { pivot, .. } => {
            let o = s.config.point(m, link, pivot);
            // The arms a student measures, force by force as laid off.
            dr.plan.arms = side
                .forces()
                .filter(|a| a.f != Vec2::ZERO)
                .enumerate()
                .map(|(k, a)| (k, (a.at - o).cross(a.f.normalize()).abs()))
                .collect();
            let about = match slip {
                Some(Slip::BalancingAbout) => other_joint(an, s, link, pivot).unwrap_or(o),
                _ => o,
            };
            let mb = -side.moment_about(about);
            dr.plan.steps.push(ForceStep::Balancing {
                input: i,
                value: mb,
            });
            out.drives[i] = Some(mb);
            let frame = m.frame();
            let joint = Joint::R(pivot);
            let force = reaction(frame, link, joint, Part::Whole);
            let r = dr.measure(end, 0, force);
            record((an, s), out, joint, frame, link, r, 0.0);
        }
        InputSpec::Slider { pair, .. } => {
            let pr = &m.prismatics[pair];
            let other = if pr.slider == link {
                pr.guide
            } else {
                pr.slider
            };
            let (q, u, n) = guide_frame(an, s, pair);
            let sign = if pr.slider == link { 1.0 } else { -1.0 };
            let fb = -sum.dot(u) * sign;
            dr.plan.steps.push(ForceStep::Balancing {
                input: i,
                value: fb,
            });
            out.drives[i] = Some(fb);
            let normal = -sum.dot(n);
            let couple = -side.moment_about(q);
            let joint = Joint::P(pair);
            let force = reaction(other, link, joint, Part::Whole);
            dr.lay_off(u * (fb * sign), Force::Drive { input: i, on: link });
            let r = dr.measure(dr.last(), 0, force);
            couple_step(&mut dr, &[link], force, couple, r, q);
            record((an, s), out, joint, other, link, n * normal, couple);
            // The chained slider's guide link feels the opposite.
            known.push(Applied {
                link: other,
                at: q,
                f: -(n * normal) - u * (fb * sign),
                couple: -couple,
                force: reaction(link, other, joint, Part::Whole),
            });
        }
    }
    Ok(dr.plan)
}

/// The crank's other joint (the first revolute of `link` not at `pivot`):
/// where a student slips and takes the balancing moment's arms from.
fn other_joint(an: &Analysis, s: &Position, link: usize, pivot: usize) -> Option<kurbo::Point> {
    let m = &an.mech;
    m.revolutes
        .iter()
        .find(|r| (r.a == link || r.b == link) && r.point != pivot)
        .map(|r| s.config.point(m, link, r.point))
}
