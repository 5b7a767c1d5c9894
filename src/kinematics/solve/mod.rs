//! The whole analysis of a scene: which groups the wanted output needs,
//! the input values of the positions (with the extreme position found
//! exactly for `positions.count`), both analytic routes and the plans at
//! every position (`run_each`). Their cross-check is verification:
//! [`crate::verification::crosscheck`] (its types re-exported here).

mod inputs;
mod run;

use crate::error::Result;
use crate::geom::perp;
use crate::kinematics::analytic::{Motion, Order};
use crate::kinematics::construction::{Drafting, Plans, Setup};
use crate::kinematics::positions::Configuration;
use crate::model::demand::Demand;
use crate::model::mechanism::Mechanism;
use crate::model::scene::Scene;
use crate::model::structure::{Structure, analyse};
use kurbo::{Point, Vec2};

pub use crate::verification::crosscheck::{BOUND_ROUNDINGS, Bounds, CrossCheck, MAX_REL_DIFF};

/// A scene made ready: mechanism, structure, and what is to be computed.
///
/// The demand's fields (`need`, `include`, `points`) read through the
/// analysis (`an.points`), as the first layout had them.
#[derive(Clone, Debug)]
pub struct Analysis {
    pub mech: Mechanism,
    pub structure: Structure,
    /// The groups, links and points the scene wants.
    pub demand: Demand,
    /// None: positions only (no plans wanted).
    pub order: Option<Order>,
    /// Fixed scales and the pencil precision of the plans.
    pub drafting: Drafting,
    /// Scale of the plan of the mechanism, m/mm: `want.scales.mu_l`, else
    /// the standard value that draws the sketch's extent within 200 mm.
    pub mu_l: f64,
}

impl std::ops::Deref for Analysis {
    type Target = Demand;
    fn deref(&self) -> &Demand {
        &self.demand
    }
}

/// Positions found and finished at a time by [`Analysis::run_each`]:
/// enough to keep both cores busy, few enough that a sweep of the largest
/// count allowed needs no more memory than a short one.
pub const RUN_CHUNK: usize = 512;

/// One solved position.
#[derive(Clone, Debug)]
pub struct Solved {
    /// The input coordinate (rad or m) and its rates.
    pub q: f64,
    pub rate: f64,
    pub rate2: f64,
    pub config: Configuration,
    /// Route (a) motions; `None` for links not solved.
    pub motion: Vec<Option<Motion>>,
    /// Route (a) with unit input rate and zero input acceleration: the
    /// transfer functions (analogues of velocity and acceleration).
    pub analogue: Vec<Option<Motion>>,
    /// The plans of velocities and accelerations, as constructions.
    pub plans: Option<Plans>,
    pub check: Option<CrossCheck>,
}

impl Analysis {
    pub fn new(scene: Scene) -> Result<Analysis> {
        Analysis::of(Mechanism::new(scene)?)
    }

    /// The analysis of a mechanism already built.
    pub(crate) fn of(mech: Mechanism) -> Result<Analysis> {
        let structure = analyse(&mech)?;
        let demand = Demand::of(&mech, &structure);
        let sc = &mech.scene;
        let order = match (sc.want.velocity, sc.want.acceleration) {
            (_, true) => Some(Order::Acceleration),
            (true, false) => Some(Order::Velocity),
            (false, false) => None,
        };
        let mu_l = sc.want.scales.mu_l.unwrap_or_else(|| {
            crate::kinematics::construction::scale::standard_scale(mech.size, 200.0)
        });
        let drafting = Drafting {
            mu_v: sc.want.scales.mu_v,
            mu_a: sc.want.scales.mu_a,
            ..Drafting::default()
        };
        Ok(Analysis {
            mech,
            structure,
            demand,
            order,
            drafting,
            mu_l,
        })
    }

    /// The link that reports point `p`: the first solved link carrying it.
    pub fn carrier(&self, p: usize) -> usize {
        self.demand.carrier(&self.mech, p)
    }

    /// What the construction kernel builds the plans from: this
    /// analysis's mechanism, structure, groups, points and links.
    /// The plans of solved position `s` built again at the scales `mu_v`,
    /// `mu_a` (a sheet's own, where the scene fixes none): a new
    /// construction on the same configuration, up to the plan of `order`.
    pub fn plans_at_scales(
        &self,
        s: &Solved,
        order: Order,
        mu_v: Option<f64>,
        mu_a: Option<f64>,
    ) -> Result<crate::kinematics::construction::Plans> {
        let d = Drafting {
            mu_v: self.drafting.mu_v.or(mu_v),
            mu_a: self.drafting.mu_a.or(mu_a),
            ..self.drafting
        };
        crate::kinematics::construction::build_plans(
            &self.setup(),
            &s.config,
            crate::kinematics::analytic::Drive {
                q: s.q,
                rate: s.rate,
                rate2: s.rate2,
            },
            order,
            d,
        )
    }

    pub fn setup(&self) -> Setup<'_> {
        Setup {
            m: &self.mech,
            s: &self.structure,
            need: &self.need,
            points: &self.points,
            include: &self.include,
        }
    }
}

/// A point's place and, when velocities were computed, its (v, a) and
/// their transfer functions (v_q, a_q).
#[derive(Clone, Copy, Debug)]
pub struct PointState {
    pub at: Point,
    pub rates: Option<(Vec2, Vec2)>,
    pub analogue: Option<(Vec2, Vec2)>,
}

/// A prismatic pair's relative motion at one position.
#[derive(Clone, Debug)]
pub struct Slide {
    pub pair: usize,
    /// Displacement of the slider's point along the guide from the sketch (m).
    pub s: f64,
    /// Relative velocity and acceleration along the guide.
    pub v: f64,
    pub a: f64,
    /// Coriolis acceleration 2·ω_guide × v_rel (zero on a fixed guide).
    pub coriolis: Vec2,
    /// Transfer functions s' and s''.
    pub s_q: f64,
    pub s_qq: f64,
}

impl Solved {
    /// Relative motion in every prismatic pair between solved links.
    pub fn slides(&self, an: &Analysis) -> Vec<Slide> {
        let m = &an.mech;
        let mut out = Vec::new();
        for (k, pr) in m.prismatics.iter().enumerate() {
            if !(an.link(pr.slider) && an.link(pr.guide)) {
                continue;
            }
            let (ps, pg) = (self.config.pose(pr.slider), self.config.pose(pr.guide));
            let u = pg.dir(pr.line_dir);
            let q = ps.apply(pr.slider_local);
            let gs = m.links[pr.guide].sketch_pose;
            let q_local = crate::geom::rotate(q - pg.origin, -pg.angle);
            let q0_local =
                crate::geom::rotate(m.scene.points[pr.point].sketch - gs.origin, -gs.angle);
            let s = pr.line_dir.dot(q_local - q0_local);
            let rel = |mo: &[Option<Motion>]| -> Option<(f64, f64, Vec2)> {
                let (a, b) = (mo[pr.slider]?, mo[pr.guide]?);
                let v = u.dot(a.velocity(q) - b.velocity(q));
                let cor = perp(u) * (2.0 * b.omega * v);
                let acc = u.dot(a.acceleration(q) - b.acceleration(q) - cor);
                Some((v, acc, cor))
            };
            let (v, a, coriolis) = rel(&self.motion).unwrap_or((0.0, 0.0, Vec2::ZERO));
            let (s_q, s_qq, _) = rel(&self.analogue).unwrap_or((0.0, 0.0, Vec2::ZERO));
            out.push(Slide {
                pair: k,
                s,
                v,
                a,
                coriolis,
                s_q,
                s_qq,
            });
        }
        out
    }

    /// Place, velocity, acceleration of point `p` (route (a)).
    pub fn point(&self, an: &Analysis, p: usize) -> PointState {
        let l = an.carrier(p);
        let at = self.config.point(&an.mech, l, p);
        let st = |mo: &[Option<Motion>]| mo[l].map(|x| (x.velocity(at), x.acceleration(at)));
        PointState {
            at,
            rates: st(&self.motion),
            analogue: st(&self.analogue),
        }
    }
}
