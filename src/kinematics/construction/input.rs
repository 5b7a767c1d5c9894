//! The input links: a crank's point from ω1 (and ε1), a driving slider's
//! own velocity (acceleration) along a guide of the frame, or the given
//! relative velocity (and the Coriolis and relative accelerations) of a
//! slider on a moving guide from the guide's coincident point.

use super::builder::Builder;
use super::plan::{Mistake, PointId};
use super::record::{Act, Eqn, Name, Product, Rate, Way, What};
use crate::error::Result;
use crate::geom::perp;
use crate::model::scene::InputSpec;

impl Builder<'_> {
    pub(super) fn input(&mut self, i: usize, (rate, rate2): (f64, f64)) -> Result<()> {
        let m = self.m();
        match *m.scene.input_at(i) {
            InputSpec::Crank { link, pivot, .. } => {
                let pts = &m.links[link].points;
                let other = if pts[0] == pivot { pts[1] } else { pts[0] };
                let (o, a) = (self.world(link, pivot), self.world(link, other));
                self.register(link, o, 0);
                let (on, an) = (Name::Point(pivot), Name::Point(other));
                let seg = (on, an);
                let id = PointId::Named(other);
                let r = a - o;
                let (omega, eps) = (Rate::Omega(link), Rate::Epsilon(link));
                let idx = if self.vel_kind() {
                    self.plan.rates[link] = Some((rate, 0.0));
                    self.step(|| Act::Equation(Eqn::CrankVelocity { a: an, o: on, link }));
                    let sense = if self.making(Mistake::OmegaWrongSense) {
                        -1.0
                    } else {
                        1.0
                    };
                    self.lay_off(
                        0,
                        perp(r) * (rate * sense),
                        What::Product(Product::new(omega, seg)),
                        Way::PerpSense(seg, omega),
                        id,
                        0.0,
                    )
                } else {
                    self.plan.rates[link] = Some((rate2, 0.0));
                    let w = self.omega(link);
                    let mut rate2 = rate2;
                    if rate2 != 0.0 && self.making(Mistake::Epsilon1Forgotten) {
                        rate2 = 0.0;
                    } else if rate2 == 0.0 && self.making(Mistake::Epsilon1Added) {
                        rate2 = w * w;
                    }
                    // The crank's normal component: forgotten, or laid off
                    // from the centre, as the students do.
                    let forgotten = w != 0.0 && self.making(Mistake::NormalForgotten);
                    let toward = if forgotten || w == 0.0 {
                        0.0
                    } else {
                        self.normal_sense()
                    };
                    if rate2 != 0.0 {
                        self.step(|| Act::Equation(Eqn::CrankAcceleration { a: an, o: on }));
                        let n = if forgotten {
                            self.plan.skipped.push(PointId::Normal { link });
                            0
                        } else {
                            self.normal(0, r * (toward * w * w), link, (an, on), seg, 0.0)
                        };
                        let tangential = What::Component {
                            sup: 't',
                            x: an,
                            j: on,
                            is: Product::new(eps, seg),
                        };
                        self.lay_off(
                            n,
                            perp(r) * rate2,
                            tangential,
                            Way::PerpSense(seg, eps),
                            id,
                            0.0,
                        )
                    } else {
                        self.step(|| Act::Equation(Eqn::CrankNormal { a: an, o: on, link }));
                        let normal = What::Component {
                            sup: 'n',
                            x: an,
                            j: on,
                            is: Product::squared(omega, seg),
                        };
                        let v = r * (toward * w * w);
                        self.lay_off(0, v, normal, Way::Toward((an, on)), id, 0.0)
                    }
                };
                self.register(link, a, idx);
                self.plan.of_point[other] = Some(idx);
            }
            InputSpec::Slider { link, pair, .. } => {
                let pr = &m.prismatics[pair];
                let x = self.world(link, pr.point);
                let u = self.c.pose(m.frame()).dir(pr.line_dir);
                let v = if self.vel_kind() { rate } else { rate2 };
                self.plan.rates[link] = Some((0.0, 0.0));
                let idx = self.lay_off(
                    0,
                    u * v,
                    What::Drive(Name::Point(pr.point)),
                    Way::Guide(m.frame()),
                    PointId::Named(pr.point),
                    0.0,
                );
                self.register(link, x, idx);
                self.plan.of_point[pr.point] = Some(idx);
            }
        }
        Ok(())
    }

    /// The link a driving pair `pair` places on its known link `known` (a
    /// chained input, or a cylinder's link that hangs on its other): at
    /// the slider's point X, v_X = v_Xk + v_rel (given, ∥ guide); a_X =
    /// a_Xk + a^K (2·ω_k × v_rel, on a rotating guide) + a^r (given).
    pub(super) fn chained(&mut self, pair: usize, known: usize, (rate, rate2): (f64, f64)) {
        let m = self.m();
        let pr = &m.prismatics[pair];
        let placed = if pr.guide == known {
            pr.slider
        } else {
            pr.guide
        };
        let p = pr.point;
        let x = self.world(pr.slider, p);
        // The two links' points at X: the slider's is the named point.
        let id_of = |l: usize| {
            if l == pr.slider {
                PointId::Named(p)
            } else {
                PointId::Coincident { point: p, link: l }
            }
        };
        let name_of = |l: usize| {
            if l == pr.slider {
                Name::Point(p)
            } else {
                Name::On(p, l)
            }
        };
        let kx = if known == pr.slider {
            self.named(known, p)
        } else {
            self.coincident(known, x, p)
        };
        // The relative motion of the placed link: the slider's along the
        // guide, the guide's against it.
        let sense = if placed == pr.slider { 1.0 } else { -1.0 };
        let u = self.c.pose(pr.guide).dir(pr.line_dir) * sense;
        let (xp, xk) = (name_of(placed), name_of(known));
        let rotating = !self.t.nr[known];
        self.step(|| {
            Act::Equation(Eqn::Driven {
                x: xp,
                base: xk,
                moving: placed,
                known,
                rotating,
            })
        });
        let given = What::Given {
            x: xp,
            moving: placed,
            known,
        };
        let out = if self.vel_kind() {
            self.lay_off(
                kx,
                u * rate,
                given,
                Way::Guide(pr.guide),
                id_of(placed),
                0.0,
            )
        } else {
            let w = self.omega(known);
            let mut from = kx;
            if !self.t.nr[known] && w != 0.0 {
                from = self.coriolis(kx, u * rate, w, (xp, placed, known, pr.guide), 0.0);
            }
            self.lay_off(
                from,
                u * rate2,
                given,
                Way::Guide(pr.guide),
                id_of(placed),
                0.0,
            )
        };
        self.register(placed, x, out);
        if let PointId::Named(p) = id_of(placed) {
            self.plan.of_point[p].get_or_insert(out);
        }
        self.same_rate(placed, known);
        // The reported points of the placed link.
        for &q in &m.links[placed].points {
            if self.t.reported_on[q].is_some() && self.plan.of_point[q].is_none() {
                let carrier = (0..m.links.len())
                    .find(|&l| self.st.include[l] && m.links[l].points.contains(&q));
                if carrier == Some(placed) {
                    self.named(placed, q);
                }
            }
        }
    }

    /// Lay off from `from` the Coriolis acceleration 2·ω×v_rel of X of
    /// link `unknown` sliding on `known` (ω of `known`, equal to the
    /// guide's, the rate the sheets name: `guide`, `vrel` the relative
    /// velocity, `verr` the error of its value): the point k. The error of
    /// its length is the worst case of ω ± Δω and v_rel ± Δv:
    /// 2·(|ω|·Δv + Δω·|v_rel| + Δω·Δv).
    pub(super) fn coriolis(
        &mut self,
        from: usize,
        vrel: kurbo::Vec2,
        w: f64,
        (x, unknown, known, guide): (Name, usize, usize, usize),
        verr: f64,
    ) -> usize {
        if self.forgets(
            Mistake::CoriolisForgotten,
            PointId::Coriolis { link: unknown },
        ) {
            return from;
        }
        let sense = if self.making(Mistake::CoriolisReversed) {
            -1.0
        } else {
            1.0
        };
        let factor = if self.making(Mistake::CoriolisFactorOne) {
            1.0
        } else {
            2.0
        };
        let k_vec = perp(vrel) * (factor * w * sense);
        self.lay_off(
            from,
            k_vec,
            What::Coriolis {
                x,
                unknown,
                known,
                guide,
            },
            Way::Turned {
                x,
                unknown,
                known,
                guide,
            },
            PointId::Coriolis { link: unknown },
            2.0 * (w.abs() * verr + self.omega_err(known) * (vrel.hypot() + verr)),
        )
    }
}
