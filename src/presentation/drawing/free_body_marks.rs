//! The marks a free body carries besides its forces: the arms h of the
//! moment equations the method writes, from the moment point to each
//! known force's line of action, and a guide's reaction's offset x from
//! its slider's centre to its line of action.

use super::canvas::{Canvas, Class, FONT, Label, Line};
use crate::geom::perp;
use crate::kinetostatics::force_plan::{ForcePlan, ForceStep};
use crate::kinetostatics::newton_euler::guide_frame;
use crate::model::scene::InputSpec;
use crate::words::forces as names;
use crate::kinematics::solve::Analysis;
use crate::kinetostatics::{Dynamics, Load};
use crate::pipeline::Solved;
use crate::words::construction::Lang;
use kurbo::{Point, Vec2};

/// A slider block's half length and half width, mm (as on the plan of
/// the mechanism).
pub(super) const BLOCK: (f64, f64) = (5.0, 3.0);

/// What a force of the drawing is: a load or a known reaction, an
/// unknown reaction found, or a component of one.
#[derive(Clone, Copy, PartialEq)]
pub(super) enum Kind {
    Known,
    Found,
    Component,
}

/// A force drawn as an arrow from its point.
pub(super) struct Arrow {
    pub(super) at: Point,
    pub(super) f: Vec2,
    pub(super) label: Label,
    pub(super) kind: Kind,
    /// A reaction (of a pair), not a load.
    pub(super) reaction: bool,
    /// A prismatic pair's reaction: the pair (its arrow drawn at the
    /// slider's centre, its line of action shown by [`offsets`]).
    pub(super) guide: Option<usize>,
    /// The plan's vector it draws (none for a component found as the rest).
    pub(super) vi: Option<usize>,
    /// The link it acts on.
    pub(super) link: usize,
    /// A point of its line of action (mm): `at` but for a guide's
    /// reaction, whose line lies off the slider's centre.
    pub(super) line: Point,
}

/// What the drawing of one plan needs: the analysis, the position, its
/// force analysis and loads, the language and the ids' prefix.
pub struct Scene<'a> {
    pub an: &'a Analysis,
    pub s: &'a Solved,
    pub d: &'a Dynamics,
    pub loads: &'a [Load],
    pub lang: Lang,
    /// Prefixes every id, so that the panels of one sheet stay apart.
    pub tag: &'a str,
}

/// An arrow as drawn: its tail and its tip (mm); `None` where too short.
pub(super) type Drawn = Option<(Point, Point)>;

/// The shortest arm drawn, mm: a force through the moment point (or
/// nearly) has none.
const LEAST_ARM: f64 = 1.0;

/// The moment equations the method writes for `plan`: the point each is
/// taken about (m) and the links whose forces enter it, with the step's
/// number — ΣM_B of a side for a tangential component, ΣM_C of both
/// sides (RPR), ΣM_O of the input link for the balancing moment.
pub fn moment_points(sc: &Scene, plan: &ForcePlan) -> Vec<(usize, Point, Vec<usize>)> {
    let m = &sc.an.mech;
    plan.steps
        .iter()
        .enumerate()
        .filter_map(|(i, st)| match st {
            ForceStep::Moment { links, about, .. } => Some((i, *about, links.clone())),
            ForceStep::Balancing { input, .. } => match m.scene.inputs().nth(*input) {
                Some(&InputSpec::Crank { link, pivot, .. }) => {
                    Some((i, sc.s.config.point(m, link, pivot), vec![link]))
                }
                _ => None,
            },
            _ => None,
        })
        .collect()
}

/// The arms h of the known forces in each moment equation of `plan`
/// (the loads and the reactions of the groups solved before, on the
/// equation's links), as the course draws them on the free body: a thin
/// line from the moment point perpendicular to the force's line of
/// action, the line of action drawn on thin from the arrow to the foot,
/// labelled h₁, h₂, … Ids `{tag}-arm-s{step}-v{vector}`.
pub(super) fn arms(
    sc: &Scene,
    plan: &ForcePlan,
    c: &mut Canvas,
    (arrows, segs): (&[Arrow], &[Drawn]),
    to: &dyn Fn(Point) -> Point,
) {
    let mut n = 0;
    let mut seen: Vec<(Point, usize)> = Vec::new();
    for (step, about, links) in moment_points(sc, plan) {
        let p = to(about);
        for (a, seg) in arrows.iter().zip(segs) {
            let (Some(vi), Some((from, tip))) = (a.vi, *seg) else {
                continue;
            };
            if a.kind != Kind::Known || !links.contains(&a.link) {
                continue;
            }
            if seen.iter().any(|(q, v)| *v == vi && (*q - p).hypot() < 1e-6) {
                continue;
            }
            let u = a.f.normalize();
            let foot = a.line + u * (p - a.line).dot(u);
            if (foot - p).hypot() < LEAST_ARM {
                continue;
            }
            seen.push((p, vi));
            n += 1;
            // The line of action on from the arrow to the foot.
            let t = |q: Point| (q - a.line).dot(u);
            let (t0, t1) = (t(from).min(t(tip)), t(from).max(t(tip)));
            let tf = t(foot);
            if tf < t0 - 0.5 || tf > t1 + 0.5 {
                let (near, beyond) = if tf < t0 {
                    (t0, tf - 2.0)
                } else {
                    (t1, tf + 2.0)
                };
                c.path(vec![a.line + u * near, a.line + u * beyond], Line::Dashed);
            }
            let id = format!("{}-arm-s{step}-v{vi}", sc.tag);
            c.prims.push(super::canvas::Prim::Seg {
                a: p,
                b: foot,
                class: Class::Thin,
                id: Some(id.clone()),
            });
            c.avoid_thin.push((p, foot));
            // The right angle at the foot.
            let along = (p - foot).normalize() * 1.5;
            // On the arrow's side of the foot.
            let side = if (t0 + t1) / 2.0 >= tf {
                u * 1.5
            } else {
                -u * 1.5
            };
            c.path(
                vec![foot + along, foot + along + side, foot + side],
                Line::Thin,
            );
            c.label_later(
                p.midpoint(foot),
                Label::new("h", n.to_string()),
                FONT,
                Some(format!("{id}-label")),
            );
        }
    }
}

/// The longest offset of a guide's reaction drawn to scale, mm: a longer
/// one is drawn this long, open at its far end, its value written.
const OFFSET_REACH: f64 = 25.0;
/// How far from the guide's axis an offset's dimension line runs, mm.
const OFFSET_AT: f64 = BLOCK.1 + 4.0;

/// Each prismatic pair's reaction drawn on the free body: its arrow at
/// the slider's centre Q and its offset x along the guide from Q to its
/// line of action (found from the slider's moments, the guide's couple
/// c = x·N), as a thin dimension line beside the block labelled with its
/// value in m; a thin line of action at its far end where it is in reach.
pub(super) fn offsets(sc: &Scene, c: &mut Canvas, arrows: &[Arrow], mu_l: f64) {
    let (an, s) = (sc.an, sc.s);
    let mut done: Vec<usize> = Vec::new();
    for a in arrows {
        let Some(k) = a.guide else { continue };
        if a.kind == Kind::Component || done.contains(&k) || a.f.hypot() == 0.0 {
            continue;
        }
        done.push(k);
        let Some(line) = sc.d.prismatics.get(k).and_then(|g| g.at) else {
            continue;
        };
        let (q, u, _) = guide_frame(an, s, k);
        let x = (line - q).dot(u);
        let drawn = x / mu_l;
        if drawn.abs() < 0.5 {
            continue;
        }
        let sign = drawn.signum();
        let len = drawn.abs().min(OFFSET_REACH);
        // Beside the block on the side the force pushes to (its arrow's
        // tail on the other).
        let n = perp(u);
        let side = if a.f.dot(n) >= 0.0 { n } else { -n };
        let q = a.at;
        let (p0, p1) = (q + side * OFFSET_AT, q + side * OFFSET_AT + u * (sign * len));
        c.seg(q + side * (BLOCK.1 + 0.5), p0 + side * 1.5, Class::Thin);
        if drawn.abs() <= OFFSET_REACH {
            let far = q + u * drawn;
            c.seg(far - side * 4.0, p1 + side * 1.5, Class::Thin);
        }
        c.prims.push(super::canvas::Prim::Seg {
            a: p0,
            b: p1,
            class: Class::Thin,
            id: Some(format!("{}-offset-{k}", sc.tag)),
        });
        c.avoid_thin.push((p0, p1));
        c.arrow(p1, u * sign);
        c.arrow(p0, -u * sign);
        let m = &an.mech;
        let pr = &m.prismatics[k];
        let sub = names::pair_sub(m.link_id(pr.guide), m.link_id(pr.slider));
        let value = super::table::number(round3(x.abs()), sc.lang);
        let metre = super::table::unit("m", sc.lang);
        c.label_later(
            p0.midpoint(p1),
            Label::new("x", sub).with_tail(format!(" = {value} {metre}")),
            FONT,
            Some(format!("{}-offset-{k}-label", sc.tag)),
        );
    }
}

/// Three significant digits.
fn round3(x: f64) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let p = 10f64.powi(2 - x.abs().log10().floor() as i32);
    (x * p).round() / p
}
