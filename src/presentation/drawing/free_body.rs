//! The free-body drawing of one step of the force analysis: the links of
//! an Assur group (or the input link) cut out of the mechanism at μ_l, as
//! the plan of the mechanism draws them, with every force on them as an
//! arrow at its point (Φ₂ and G₂ at S₂, an external F₅, the reactions of
//! the groups solved before), couples as curved arrows, and the outer
//! reactions found by the force plan at their pairs, bold, with the τ and
//! n components the scheme found first as thin arrows. Arrows are not to
//! a scale of force: their lengths only rank the forces. A load starts at
//! its point; a reaction ends at its pair, pushed in from the link cut
//! away, so that the two kinds stay apart.

use super::canvas::{Canvas, Class, FONT, Label, Line, SMALL};
use super::free_body_marks::{self as marks, Arrow, BLOCK, Drawn, Kind};
pub use super::free_body_marks::Scene;
use super::{cylinder, mechanism};
use crate::geom::perp;
use crate::kinetostatics::force_plan::{Force, ForcePlan, ForceStep, Part};
use crate::kinetostatics::newton_euler::guide_frame;
use crate::kinetostatics::Load;
use crate::model::scene::InputSpec;
use crate::model::structure::Joint;
use crate::words::forces as names;
use kurbo::{Point, Vec2};
use std::f64::consts::PI;

/// The longest arrow of a force: this share of the group's size, within
/// [`LONGEST`] mm, so that the arrows grow with the drawing that fills
/// its field; the shortest a third of the longest.
const ARROW_SHARE: f64 = 0.6;
const LONGEST: (f64, f64) = (10.0, 30.0);
/// The radius of a couple's curved arrow, mm.
const COUPLE_R: f64 = 6.0;

/// The real extent (m) of the links of `plan`: where [`draw`] starts its
/// search for the scale.
pub fn extent(sc: &Scene, plan: &ForcePlan) -> kurbo::Rect {
    let m = &sc.an.mech;
    let mut r: Option<kurbo::Rect> = None;
    for &l in &plan.links {
        for &p in &m.links[l].points {
            let q = sc.s.config.point(m, l, p);
            let b = kurbo::Rect::from_points(q, q);
            r = Some(r.map_or(b, |x| x.union(b)));
        }
    }
    r.unwrap_or(kurbo::Rect::ZERO)
}

/// Draw the free body of `plan` at `mu_l` (m/mm), labels placed.
pub fn draw(sc: &Scene, plan: &ForcePlan, c: &mut Canvas, mu_l: f64) {
    let to = |p: Point| Point::new(p.x / mu_l, p.y / mu_l);
    let lines = links(sc, plan, c, &to);
    prismatics(sc, plan, c, mu_l, &to);
    points(sc, plan, c, &to);
    let arrows = arrows(sc, plan, &to);
    let size = extent(sc, plan);
    let longest =
        (ARROW_SHARE * size.width().hypot(size.height()) / mu_l).clamp(LONGEST.0, LONGEST.1);
    let segs = draw_arrows(c, &arrows, longest, sc.tag);
    marks::offsets(sc, c, &arrows, mu_l);
    marks::arms(sc, plan, c, (&arrows, &segs), &to);
    let mut busy = lines;
    busy.extend(arrows.iter().map(|a| (a.at, a.at + a.f)));
    for (i, (centre, value, label)) in couples(sc, plan, &to).into_iter().enumerate() {
        couple(
            c,
            centre,
            value,
            label,
            &busy,
            format!("{}-couple-{i}", sc.tag),
        );
    }
    c.place_pending();
}

/// Whether point `p` is a pair of two links or more.
fn joint(sc: &Scene, p: usize) -> bool {
    sc.an.mech.links_of_point(p).len() >= 2
}

/// Whether point `p` is a centre of mass: a point of one link named S….
fn is_mass(sc: &Scene, p: usize) -> bool {
    !joint(sc, p) && sc.an.mech.point_name(p).starts_with('S')
}

/// Draw the links of `plan` as the plan of the mechanism does, with their
/// numbers; returns their lines (the couples' arcs keep clear of them).
fn links(
    sc: &Scene,
    plan: &ForcePlan,
    c: &mut Canvas,
    to: &dyn Fn(Point) -> Point,
) -> Vec<(Point, Point)> {
    let (m, s) = (&sc.an.mech, sc.s);
    let mut lines: Vec<(Point, Point)> = Vec::new();
    for &l in &plan.links {
        let xy: Vec<Point> = m.links[l]
            .points
            .iter()
            .filter(|&&p| !is_mass(sc, p))
            .map(|&p| to(s.config.point(m, l, p)))
            .collect();
        mechanism::link_body(c, &xy);
        for i in 0..xy.len() {
            for j in i + 1..xy.len() {
                lines.push((xy[i], xy[j]));
            }
        }
        for &p in &m.links[l].points {
            let q = to(s.config.point(m, l, p));
            let on = xy.len() == 2 && mechanism::on_body(&xy, q);
            if is_mass(sc, p) && xy.len() == 2 && !on {
                c.seg(xy[0], q, Class::Main);
                lines.push((xy[0], q));
            }
        }
        let mid = match xy.as_slice() {
            [a, b, ..] => a.midpoint(*b),
            [a] => *a + Vec2::new(0.0, 4.0),
            [] => continue,
        };
        c.label_later(
            mid,
            Label::new(m.link_id(l), ""),
            SMALL,
            Some(format!("{}-link-{}", sc.tag, m.link_id(l))),
        );
    }
    lines
}

/// Prismatic pairs at the group: the slot of a guide link in it, the axis
/// of a guide cut away, the slider's block; a cylinder inside the group by
/// its symbol.
fn prismatics(
    sc: &Scene,
    plan: &ForcePlan,
    c: &mut Canvas,
    mu_l: f64,
    to: &dyn Fn(Point) -> Point,
) {
    let (an, s) = (sc.an, sc.s);
    let ours = |l: usize| plan.links.contains(&l);
    let cylinders = cylinder::pairs(an);
    for (k, pr) in an.mech.prismatics.iter().enumerate() {
        let (slider, guide) = (ours(pr.slider), ours(pr.guide));
        if !slider && !guide {
            continue;
        }
        if cylinders.contains(&k) {
            if slider && guide {
                cylinder::one(an, s, c, mu_l, k);
            }
            continue;
        }
        let (q, u, _) = guide_frame(an, s, k);
        let q = to(q);
        if guide {
            c.seg(q - u * 10.0, q + u * 10.0, Class::Main);
        } else {
            c.path(vec![q - u * 14.0, q + u * 14.0], Line::DashDot);
        }
        if slider {
            let (a, b) = BLOCK;
            mechanism::slider_block(
                c,
                q,
                &mechanism::block_corners(q, u, a, b),
                Some(format!("{}-slider-{k}", sc.tag)),
            );
        }
    }
}

/// The points of the links: pairs, centres of mass, others, named.
fn points(sc: &Scene, plan: &ForcePlan, c: &mut Canvas, to: &dyn Fn(Point) -> Point) {
    let (m, s) = (&sc.an.mech, sc.s);
    let mut seen: Vec<usize> = Vec::new();
    for &l in &plan.links {
        for &p in &m.links[l].points {
            if seen.contains(&p) {
                continue;
            }
            seen.push(p);
            let at = to(s.config.point(m, l, p));
            mechanism::point_symbol(c, at, joint(sc, p), is_mass(sc, p));
            let name = m.point_name(p);
            // A pair's circle by its name, where the body's size is read.
            if let Some(super::canvas::Prim::Circle { id, .. }) = c.last_drawn_mut() {
                *id = Some(format!("{}-joint-{name}", sc.tag));
            }
            mechanism::point_label(c, at, name, format!("{}-point-{name}", sc.tag));
        }
    }
}

/// The couples on the links of `plan`: the loads' and the input's
/// balancing moment, each at its centre with its value and name.
fn couples(sc: &Scene, plan: &ForcePlan, to: &dyn Fn(Point) -> Point) -> Vec<(Point, f64, Label)> {
    let (m, s) = (&sc.an.mech, sc.s);
    let ours = |l: usize| plan.links.contains(&l);
    let mut couples: Vec<(Point, f64, Label)> = Vec::new();
    for l in sc.loads {
        if let Load::Couple { link, m: mc, .. } = *l
            && ours(link)
            && mc != 0.0
        {
            let centre =
                sc.d.inertia
                    .iter()
                    .find(|i| i.link == link)
                    .map(|i| to(i.at))
                    .unwrap_or_else(|| {
                        centroid(
                            m.links[link]
                                .points
                                .iter()
                                .map(|&p| to(s.config.point(m, link, p))),
                        )
                    });
            couples.push((centre, mc, names::load(m, l)));
        }
    }
    for st in &plan.steps {
        if let ForceStep::Balancing { input, value } = st
            && *value != 0.0
            && let Some(InputSpec::Crank { link, pivot, .. }) = m.scene.inputs().nth(*input)
            && ours(*link)
        {
            couples.push((
                to(s.config.point(m, *link, *pivot)),
                *value,
                names::balancing_moment(sc.lang),
            ));
        }
    }
    couples
}

/// The centre of a link's points (where a couple on a link without a
/// centre of mass is drawn).
fn centroid(pts: impl Iterator<Item = Point>) -> Point {
    let (mut s, mut n) = (Vec2::ZERO, 0.0);
    for p in pts {
        s += p.to_vec2();
        n += 1.0;
    }
    if n > 0.0 {
        (s / n).to_point()
    } else {
        Point::ORIGIN
    }
}

/// The forces on the links of `plan` as arrows at their points (mm), the
/// vectors of the plan that act on the group from outside it.
fn arrows(sc: &Scene, plan: &ForcePlan, to: &dyn Fn(Point) -> Point) -> Vec<Arrow> {
    let (an, s) = (sc.an, sc.s);
    let m = &an.mech;
    let ours = |l: usize| plan.links.contains(&l);
    // Where a reaction acts: a pin's point, a guide's force where it acts
    // (its couple placed it), else the pair's point.
    let place = |joint: Joint, on: usize| match joint {
        Joint::R(p) => Some(to(s.config.point(m, on, p))),
        Joint::P(k) => {
            // At the slider's centre, on its body: the line of action
            // (which may lie far off the block) is shown by its offset.
            (k < m.prismatics.len()).then(|| to(guide_frame(an, s, k).0))
        }
    };
    let guide_of = |f: Force| match f {
        Force::Reaction {
            joint: Joint::P(k), ..
        } => Some(k),
        _ => None,
    };
    let found = |vi: usize| plan.steps.contains(&ForceStep::Measure(vi));
    let mut out: Vec<Arrow> = Vec::new();
    let mut done: Vec<Force> = Vec::new();
    for (vi, v) in plan.vectors.iter().enumerate() {
        if done.contains(&v.force) {
            continue;
        }
        let Some(label) = names::force(m, sc.loads, v.force, sc.lang) else {
            continue;
        };
        let arrow = match v.force {
            Force::Load(i) => match sc.loads.get(i) {
                Some(&Load::Force { link, at, .. }) if ours(link) => {
                    Some((to(at), Kind::Known, link))
                }
                _ => None,
            },
            Force::Reaction {
                from,
                to: on,
                joint,
                part,
            } if ours(on) && !ours(from) => {
                let kind = match part {
                    Part::Whole if found(vi) => Kind::Found,
                    Part::Whole => Kind::Known,
                    _ => Kind::Component,
                };
                place(joint, on).map(|at| (at, kind, on))
            }
            Force::Drive { input, on } if ours(on) => match m.scene.inputs().nth(input) {
                Some(&InputSpec::Slider { pair, .. }) if pair < m.prismatics.len() => {
                    Some((to(guide_frame(an, s, pair).0), Kind::Known, on))
                }
                _ => None,
            },
            _ => None,
        };
        let Some((at, kind, link)) = arrow else {
            continue;
        };
        let sub = label.sub.clone();
        done.push(v.force);
        let guide = guide_of(v.force);
        let line = guide
            .and_then(|k| sc.d.prismatics.get(k))
            .and_then(|g| g.at)
            .map_or(at, to);
        out.push(Arrow {
            at,
            f: v.value,
            label,
            kind,
            reaction: !matches!(v.force, Force::Load(_)),
            guide,
            vi: Some(vi),
            link,
            line,
        });
        // A component found first: the rest of its reaction (n after τ)
        // is the other component.
        if let Force::Reaction {
            from,
            to: on,
            joint,
            part: part @ (Part::Tangential | Part::AlongGuide),
        } = v.force
        {
            let other = if part == Part::Tangential {
                Part::Normal
            } else {
                Part::AcrossGuide
            };
            let of = |part| Force::Reaction { from, to: on, joint, part };
            // Not where that component is laid off itself (a class III
            // group's third leash: R^n from the moments about S).
            let laid = plan.vectors.iter().any(|w| w.force == of(other));
            if let Some(w) = plan.vectors.iter().find(|w| w.force == of(Part::Whole) && !laid) {
                out.push(Arrow {
                    at,
                    f: w.value - v.value,
                    label: Label::new("R", sub).with_sup(names::part_sup(other)),
                    kind: Kind::Component,
                    reaction: true,
                    guide: guide_of(v.force),
                    vi: None,
                    link: on,
                    line,
                });
            }
        }
    }
    out
}

/// Draw the arrows from their points, lengths ranked by magnitude; one
/// that would lie along another from the same point is moved aside.
fn draw_arrows(
    c: &mut Canvas,
    arrows: &[Arrow],
    longest: f64,
    tag: &str,
) -> Vec<Drawn> {
    let fmax = arrows.iter().map(|a| a.f.hypot()).fold(0.0, f64::max);
    let mut drawn: Vec<(Point, Vec2)> = Vec::new();
    let mut segs = Vec::new();
    for (i, a) in arrows.iter().enumerate() {
        let mag = a.f.hypot();
        if !(mag > 0.0 && mag.is_finite()) {
            segs.push(None);
            continue;
        }
        let u = a.f / mag;
        let len = (longest * mag / fmax).clamp(longest / 3.0, longest);
        // A reaction pushes into its pair: drawn along −u from there.
        let load = a.kind == Kind::Known && !a.reaction;
        let out = if load { u } else { -u };
        let along = drawn
            .iter()
            .filter(|(p, d)| (*p - a.at).hypot() < 0.5 && d.dot(out) > 0.98)
            .count();
        let at = a.at + perp(u) * (2.5 * along as f64);
        drawn.push((a.at, out));
        let class = match a.kind {
            Kind::Found => Class::Bold,
            Kind::Known => Class::Vector,
            Kind::Component => Class::Thin,
        };
        let (from, tip) = if load {
            (at, at + u * len)
        } else {
            (at - u * len, at)
        };
        let id = match a.guide {
            Some(k) => format!("{tag}-force-{i}-p{k}"),
            None => format!("{tag}-force-{i}"),
        };
        c.vector(from, tip, class, Some(id));
        segs.push(Some((from, tip)));
        // The name at the far end, away from the crowd at the point.
        c.label_later(
            at + out * len,
            a.label.clone(),
            FONT,
            Some(format!("{tag}-flabel-{i}")),
        );
    }
    segs
}

/// A couple as a curved arrow about `centre` in the widest free sector
/// between the lines from there, counter-clockwise when positive.
fn couple(
    c: &mut Canvas,
    centre: Point,
    value: f64,
    label: Label,
    busy: &[(Point, Point)],
    id: String,
) {
    let mut angles: Vec<f64> = Vec::new();
    for &(a, b) in busy {
        for (p, q) in [(a, b), (b, a)] {
            if (p - centre).hypot() < 0.5 && (q - p).hypot() > 1e-9 {
                angles.push((q - p).atan2());
            } else if (q - p).hypot() > 1e-9 {
                // A line passing near: where it crosses the arc's circle.
                for k in 0..=24 {
                    let x = p + (q - p) * (k as f64 / 24.0);
                    let r = (x - centre).hypot();
                    if (COUPLE_R - 1.5..=COUPLE_R + 1.5).contains(&r) {
                        angles.push((x - centre).atan2());
                    }
                }
            }
        }
    }
    angles.sort_by(f64::total_cmp);
    // The widest gap between the busy directions.
    let (mid, gap) = if angles.is_empty() {
        (PI / 4.0, 2.0 * PI)
    } else {
        let mut best = (angles[0] + PI, 2.0 * PI);
        for i in 0..angles.len() {
            let a = angles[i];
            let b = if i + 1 < angles.len() {
                angles[i + 1]
            } else {
                angles[0] + 2.0 * PI
            };
            if i == 0 || b - a > best.1 {
                best = ((a + b) / 2.0, b - a);
            }
        }
        best
    };
    let sweep = (0.75 * gap).clamp(0.8, 3.0) * value.signum();
    let a0 = mid - sweep / 2.0;
    c.arc(centre, COUPLE_R, a0, sweep);
    let end = a0 + sweep;
    let tip = centre + Vec2::from_angle(end) * COUPLE_R;
    c.arrow(tip, perp(Vec2::from_angle(end)) * value.signum());
    c.label_later(
        centre + Vec2::from_angle(mid) * (COUPLE_R + 2.0),
        label,
        FONT,
        Some(id),
    );
}
