//! The dyads (class II groups). Each of the five kinds finds its unknown
//! point the one way the method has: two vector equations, one per side
//! of the dyad — through a rigid link from a known joint (normal and
//! tangential parts) or along a guide from the coincident point of the
//! known link (Coriolis and relative parts), or through a cylinder (the
//! given relative velocity laid off first, then the rigid parts of the
//! link that turns) — drawn as two lines that meet at the point; then the
//! links' rates are measured or taken over.

use super::builder::Builder;
use super::plan::{Mistake, PointId};
use super::record::{Act, Eqn, Name, Ray, Way, What};
use crate::error::Result;
use crate::geom::perp;
use crate::model::mechanism::Prismatic;
use crate::model::structure::{Conn, Dyad, DyadKind, Joint};

/// A cylinder's side in a dyad: the known joint J on the link `link` in
/// the dyad's slot (the one that turns about it), the unknown point on
/// the cylinder's other link `moving`, their driving pair and input.
#[derive(Clone, Copy)]
pub(super) struct Cyl {
    pub link: usize,
    pub from: At,
    pub moving: usize,
    pub pair: usize,
    pub input: usize,
}
use kurbo::{Point, Vec2};

/// A prismatic pair seen from a group: the link being found, the known
/// link it slides on (or that slides on it), and which of them is the guide.
#[derive(Clone, Copy)]
pub(super) struct Slide {
    pub unknown: usize,
    pub known: usize,
    pub guide: usize,
}

/// A known plan point: its index, where it is on the mechanism, its name.
pub(super) type At = (usize, Point, Name);

/// One side of a group's unknown point X.
#[derive(Clone, Copy)]
pub(super) enum Side {
    /// X of rigid `link` from its known point `from`.
    Rigid { link: usize, from: At },
    /// X sliding along `u` from plan point `kx` (named `kn`) of the known
    /// link.
    Slide {
        kx: usize,
        kn: Name,
        u: Vec2,
        slide: Slide,
    },
    /// X on a cylinder's link that slides (as given) on the link that
    /// turns about the known joint.
    Cylinder(Cyl),
}

fn revolute(j: Joint) -> usize {
    match j {
        Joint::R(p) => p,
        Joint::P(_) => unreachable!("a revolute pair"),
    }
}

fn prismatic(j: Joint) -> usize {
    match j {
        Joint::P(k) => k,
        Joint::R(_) => unreachable!("a prismatic pair"),
    }
}

impl Builder<'_> {
    /// Plan point of the joint of connection `cn` on its known side `k`.
    pub(super) fn joint_on(&mut self, k: usize, cn: &Conn) -> At {
        let p = revolute(cn.joint);
        let i = self.named(k, p);
        (i, self.world(k, p), Name::Point(p))
    }

    /// The joint of connection `cn` on its known side `k`, known on `link`
    /// too: the side of X through `link`.
    fn rigid_side(&mut self, link: usize, k: usize, cn: &Conn) -> Side {
        let from = self.joint_on(k, cn);
        self.register(link, from.1, from.0);
        Side::Rigid { link, from }
    }

    /// The side of X of `unknown` sliding in pair `pr` on `known`, from
    /// plan point `kx` of `known`, named `kn`.
    fn slide_side(
        &self,
        (kx, kn): (usize, Name),
        pr: &Prismatic,
        unknown: usize,
        known: usize,
    ) -> Side {
        Side::Slide {
            kx,
            kn,
            u: self.c.pose(pr.guide).dir(pr.line_dir),
            slide: Slide {
                unknown,
                known,
                guide: pr.guide,
            },
        }
    }

    /// The line of a rigid relation X ∈ link with known point J:
    /// v_X = v_J + v_XJ (⊥ JX); a_X = a_J + a^n_XJ (toward J) + a^t_XJ (⊥ JX).
    /// Returns the line and the plan point the relative (tangential) part
    /// starts from.
    pub(super) fn rigid(
        &mut self,
        link: usize,
        (j, jw, jn): At,
        (x, xn): (Point, Name),
    ) -> (Ray, usize) {
        let seg = (jn, xn);
        let u = if self.making(Mistake::TangentialParallel) {
            x - jw
        } else {
            perp(x - jw)
        };
        if self.vel_kind() {
            return (self.line(j, u, Way::Perp(seg)), j);
        }
        let mut w = self.omega(link);
        if self.t.nr[link]
            || w == 0.0
            || self.forgets(Mistake::NormalForgotten, PointId::Normal { link })
        {
            return (self.line(j, u, Way::Perp(seg)), j);
        }
        let input = self.m().scene.input.link();
        // (A driving slider has no ω1 to take by mistake.)
        if link != input && self.omega(input) != 0.0 && self.making(Mistake::OmegaWrongLink) {
            w = self.omega(input);
        }
        let r = x - jw;
        let toward = if self.making(Mistake::NormalFromCentre) {
            1.0
        } else {
            -1.0
        };
        let err = self.normal_err(link, w, r.hypot());
        let n = self.normal(j, r * (toward * w * w), link, (xn, jn), seg, err);
        (self.line(n, u, Way::Perp(seg)), n)
    }

    /// The line of a slide of `unknown` along `u` relative to `known`, the
    /// point of `known` at x being plan point `kx`:
    /// v_X = v_Xk + v_rel (∥ guide); a_X = a_Xk + a^K + a^r (∥ guide),
    /// a^K = 2·ω×v_rel turned by 90° in the sense of ω (on a rotating guide).
    fn slide(&mut self, kx: usize, u: Vec2, s: Slide, (x, xn): (Point, Name)) -> Ray {
        let way = Way::Guide(s.guide);
        let u = if self.making(Mistake::SlideAcross) {
            perp(u)
        } else {
            u
        };
        if self.vel_kind() || self.t.nr[s.known] {
            return self.line(kx, u, way);
        }
        let w = self.omega(s.known);
        // v_rel of `unknown` relative to `known` at x, from the velocity plan.
        let vel = self.vel.expect("acceleration plan after the velocity plan");
        let at = |l: usize| vel.known_at(l, self.local(l, x), self.same_point(l, x));
        let (Some(iu), Some(ik)) = (at(s.unknown), at(s.known)) else {
            unreachable!("the velocity plan has both coincident points");
        };
        let vrel = (vel.points[iu].at - vel.points[ik].at) * vel.mu;
        let verr = (vel.points[iu].err + vel.points[ik].err) * vel.mu;
        let k = self.coriolis(kx, vrel, w, (xn, s.unknown, s.known, s.guide), verr);
        self.line(k, u, way)
    }

    /// The point `id` of a group at `x` where its two `sides` meet: their
    /// vector equations (in the order `equations` lists the sides; none
    /// for a class III group's third leash), their lines, the point, the
    /// rates of the rigid sides measured. `mistake`: the one this group
    /// can make where the lines meet.
    pub(super) fn meet(
        &mut self,
        id: PointId,
        x: Point,
        sides: [Side; 2],
        equations: Option<[usize; 2]>,
        mistake: Option<Mistake>,
    ) -> Result<usize> {
        let (p, xn) = match id {
            PointId::Named(p) => (p, Name::Point(p)),
            PointId::Coincident { point, link } => (point, Name::On(point, link)),
            _ => unreachable!("a group's point is a joint"),
        };
        if let Some(order) = equations.filter(|_| self.record) {
            let [a, b] = order.map(|i| match sides[i] {
                Side::Rigid { link, from } => self.relation(xn, from.2, true, link),
                Side::Slide { kn, slide, .. } => self.relation(xn, kn, false, slide.known),
                Side::Cylinder(c) => {
                    let mut r = self.relation(xn, c.from.2, true, c.link);
                    r.via = Some((c.moving, c.link));
                    r
                }
            });
            self.step(|| Act::Equation(Eqn::Pair(a, b)));
        } else if equations.is_some() {
            // The same step, counted, without building what only its
            // record would keep.
            self.taken += 1;
        }
        let [(mut la, ta), (mut lb, tb)] = sides.map(|side| match side {
            Side::Rigid { link, from } => self.rigid(link, from, (x, xn)),
            Side::Slide { kx, u, slide, .. } => (self.slide(kx, u, slide, (x, Name::Point(p))), kx),
            Side::Cylinder(c) => self.cylinder_line(c, (x, p)),
        });
        let out = match mistake {
            Some(Mistake::WrongPerpendicular) if self.making(Mistake::WrongPerpendicular) => {
                // Each line ⊥ the other link of the group.
                std::mem::swap(&mut la.unit, &mut lb.unit);
                std::mem::swap(&mut la.way, &mut lb.way);
                self.intersect(la, lb, id)?
            }
            // The guide's coincident point taken as the slider's: the
            // relative sliding ignored, the point drawn where the other
            // link's point is (so that a replay finds it there).
            Some(Mistake::WrongLink) if self.making(Mistake::WrongLink) => {
                let kx = sides
                    .iter()
                    .find_map(|s| match s {
                        Side::Slide { kx, .. } => Some(*kx),
                        Side::Rigid { .. } | Side::Cylinder(_) => None,
                    })
                    .expect("a slide");
                let (at, err) = (self.plan.points[kx].at, self.plan.points[kx].err);
                let out = self.add_point(id, at, err);
                self.step(|| Act::Coincide {
                    out,
                    with: kx,
                    translates: None,
                });
                out
            }
            _ => self.intersect(la, lb, id)?,
        };
        for side in sides {
            let link = match side {
                Side::Rigid { link, .. } => link,
                Side::Slide { slide, .. } => slide.unknown,
                Side::Cylinder(c) => c.moving,
            };
            self.register(link, x, out);
        }
        if let PointId::Named(p) = id {
            self.plan.of_point[p].get_or_insert(out);
        }
        for (side, t) in sides.into_iter().zip([ta, tb]) {
            match side {
                Side::Rigid { link, from } => {
                    self.measure_rate(link, t, out, (from.1, from.2), (x, xn))
                }
                // The segment from the relative vector's end: ω×JX of the
                // link that turns (X as its point).
                Side::Cylinder(c) => self.measure_rate(
                    c.link,
                    t,
                    out,
                    (c.from.1, c.from.2),
                    (x, Name::On(p, c.link)),
                ),
                Side::Slide { .. } => {}
            }
        }
        Ok(out)
    }

    /// The line of X of a cylinder's link `c.moving`, sliding as given on
    /// the link `c.link` that turns about the known joint J:
    /// v_X = v_J + v_rel (given, ∥ guide) + v_XJ (⊥ JX), and
    /// a_X = a_J + a^n (toward J) + a^K (2·ω×v_rel) + a^r (given, ∥ guide)
    /// plus a^t (⊥ JX). The known parts are laid off from j in that order
    /// (the construction starts from the relative velocity along the
    /// cylinder); returns the line and the plan point its part starts from.
    fn cylinder_line(&mut self, c: Cyl, (x, p): (Point, usize)) -> (Ray, usize) {
        let m = self.m();
        let pr = &m.prismatics[c.pair];
        let (j, jw, jn) = c.from;
        let xu = Name::On(p, c.link);
        let xn = Name::Point(p);
        let seg = (jn, xu);
        // The moving link's relative motion on the turning one.
        let sense = if c.moving == pr.slider { 1.0 } else { -1.0 };
        let ug = self.c.pose(pr.guide).dir(pr.line_dir) * sense;
        let d = self.drives[c.input];
        let given = What::Given {
            x: xn,
            moving: c.moving,
            known: c.link,
        };
        let id = PointId::Relative { link: c.moving };
        let u = if self.making(Mistake::TangentialParallel) {
            x - jw
        } else {
            perp(x - jw)
        };
        let way = Way::Guide(pr.guide);
        if self.vel_kind() {
            let r = if d.rate != 0.0 {
                self.lay_off(j, ug * d.rate, given, way, id, 0.0)
            } else {
                j
            };
            return (self.line(r, u, Way::Perp(seg)), r);
        }
        let w = self.omega(c.link);
        let mut from = j;
        let turns = !self.t.nr[c.link] && w != 0.0;
        if turns && !self.forgets(Mistake::NormalForgotten, PointId::Normal { link: c.link }) {
            let toward = if self.making(Mistake::NormalFromCentre) {
                1.0
            } else {
                -1.0
            };
            let r = x - jw;
            let err = self.normal_err(c.link, w, r.hypot());
            from = self.normal(j, r * (toward * w * w), c.link, (xu, jn), seg, err);
        }
        if turns && d.rate != 0.0 {
            from = self.coriolis(from, ug * d.rate, w, (xn, c.moving, c.link, pr.guide), 0.0);
        }
        if d.rate2 != 0.0 {
            from = self.lay_off(from, ug * d.rate2, given, way, id, 0.0);
        }
        (self.line(from, u, Way::Perp(seg)), from)
    }

    /// The side of a dyad's link in `slot` (0: ext1's, 1: ext2's): a rigid
    /// link from its known joint, or a cylinder whose other link carries
    /// the middle joint.
    fn group_side(&mut self, d: &Dyad, slot: usize) -> Side {
        let (link, k, cn, carrier) = if slot == 0 {
            (d.links[0], d.ext1.from, d.ext1, d.mid.from)
        } else {
            (d.links[1], d.ext2.to, d.ext2, d.mid.to)
        };
        match d.cylinder {
            Some(cy) if cy.slot == slot && carrier == cy.other => {
                let from = self.joint_on(k, &cn);
                self.register(link, from.1, from.0);
                Side::Cylinder(Cyl {
                    link,
                    from,
                    moving: cy.other,
                    pair: cy.pair,
                    input: cy.input,
                })
            }
            _ => self.rigid_side(link, k, &cn),
        }
    }

    /// A cylinder's other link after its group: it turns with the link in
    /// the slot; when it carries no joint of the group it hangs on that
    /// link by the given slide.
    fn cylinder_other(&mut self, d: &Dyad) {
        let Some(cy) = d.cylinder else { return };
        let own = d.links[cy.slot];
        let carrier = if cy.slot == 0 { d.mid.from } else { d.mid.to };
        if carrier == cy.other {
            self.same_rate(cy.other, own);
        } else {
            let dr = self.drives[cy.input];
            self.chained(cy.pair, own, (dr.rate, dr.rate2));
        }
    }

    pub(super) fn dyad(&mut self, d: &Dyad) -> Result<()> {
        let m = self.m();
        let [l1, l2] = d.links;
        let (ends, mid) = ([d.ext1.from, d.ext2.to], d.mid.joint);
        match d.kind {
            DyadKind::Rrr => {
                let a = self.group_side(d, 0);
                let b = self.group_side(d, 1);
                let pc = revolute(mid);
                let cw = self.world(d.mid.from, pc);
                let mistake = Some(Mistake::WrongPerpendicular);
                self.meet(PointId::Named(pc), cw, [a, b], Some([0, 1]), mistake)?;
                self.cylinder_other(d);
            }
            DyadKind::Rrp => {
                let a = self.group_side(d, 0);
                let (pc, k2) = (revolute(mid), ends[1]);
                let cw = self.world(d.mid.from, pc);
                let kc = (self.coincident(k2, cw, pc), Name::On(pc, k2));
                let b = self.slide_side(kc, &m.prismatics[prismatic(d.ext2.joint)], l2, k2);
                self.meet(PointId::Named(pc), cw, [a, b], Some([0, 1]), None)?;
                self.same_rate(l2, k2);
                self.cylinder_other(d);
            }
            DyadKind::Rpr => {
                let pr = &m.prismatics[prismatic(mid)];
                let (g, s) = (pr.guide, pr.slider);
                let (cg, cs) = if g == l1 {
                    (d.ext1, d.ext2)
                } else {
                    (d.ext2, d.ext1)
                };
                let kg = if cg.to == g { cg.from } else { cg.to };
                let ks = if cs.to == s { cs.from } else { cs.to };
                let a = self.rigid_side(g, kg, &cg);
                let (js, jsw, jsn) = self.joint_on(ks, &cs);
                self.register(s, jsw, js);
                let b = self.slide_side((js, jsn), pr, g, s);
                // B3 of the guide: the slide's equation first.
                let x = PointId::Coincident {
                    point: revolute(cs.joint),
                    link: g,
                };
                self.meet(x, jsw, [a, b], Some([1, 0]), Some(Mistake::WrongLink))?;
                self.same_rate(s, g);
            }
            DyadKind::Prp => {
                let pc = revolute(mid);
                let cw = self.world(l1, pc);
                let pairs = [(d.ext1.joint, l1, ends[0]), (d.ext2.joint, l2, ends[1])];
                let sides = pairs.map(|(joint, l, k)| {
                    let kx = (self.coincident(k, cw, pc), Name::On(pc, k));
                    self.slide_side(kx, &m.prismatics[prismatic(joint)], l, k)
                });
                self.meet(PointId::Named(pc), cw, sides, Some([0, 1]), None)?;
                self.same_rate(l1, ends[0]);
                self.same_rate(l2, ends[1]);
            }
            DyadKind::Rpp => {
                let (b, bw, bn) = self.joint_on(ends[0], &d.ext1);
                self.register(l1, bw, b);
                let (k2, pb) = (ends[1], revolute(d.ext1.joint));
                self.same_rate(l2, k2);
                self.same_rate(l1, k2);
                let bk = (self.coincident(k2, bw, pb), Name::On(pb, k2));
                let sides = [
                    self.slide_side((b, bn), &m.prismatics[prismatic(mid)], l2, l1),
                    self.slide_side(bk, &m.prismatics[prismatic(d.ext2.joint)], l2, k2),
                ];
                let x = PointId::Coincident {
                    point: pb,
                    link: l2,
                };
                self.meet(x, bw, sides, Some([0, 1]), None)?;
            }
        }
        Ok(())
    }
}
