//! The input link: a crank's point from ω1 (and ε1), or a driving
//! slider's own velocity (acceleration) along its guide.

use super::builder::Builder;
use super::plan::{Mistake, PointId};
use super::record::{Act, Eqn, Name, Product, Rate, Way, What};
use crate::error::Result;
use crate::geom::perp;
use crate::model::scene::InputSpec;

impl Builder<'_> {
    pub(super) fn input(&mut self, (rate, rate2): (f64, f64)) -> Result<()> {
        let m = self.m();
        match m.scene.input {
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
                    self.step(Act::Equation(Eqn::CrankVelocity { a: an, o: on, link }));
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
                    if rate2 != 0.0 {
                        self.step(Act::Equation(Eqn::CrankAcceleration { a: an, o: on }));
                        let n = self.normal(0, -r * (w * w), link, (an, on), seg, 0.0);
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
                        self.step(Act::Equation(Eqn::CrankNormal { a: an, o: on, link }));
                        let normal = What::Component {
                            sup: 'n',
                            x: an,
                            j: on,
                            is: Product::squared(omega, seg),
                        };
                        self.lay_off(0, -r * (w * w), normal, Way::Toward((an, on)), id, 0.0)
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
}
