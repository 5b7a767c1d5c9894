//! A scene made ready for the analysis ([`Analysis`]: mechanism,
//! structure, what is wanted), the input values of the positions (with the
//! extreme position found exactly for `positions.count`), and what the
//! kinematics gives at one position ([`Position`]). Solving every position
//! in order, with the cross-check and the forces, is the pipeline's
//! (`crate::pipeline`).

/// The input values asked for and the start of the working stroke.
pub mod inputs;

use crate::error::Result;
use crate::geom::perp;
use crate::kinematics::analytic::{Drives, Motion, Order};
use crate::kinematics::construction::{Drafting, Plans, Setup};
use crate::kinematics::positions::Configuration;
use crate::model::demand::Demand;
use crate::model::mechanism::Mechanism;
use crate::model::scene::Scene;
use crate::model::structure::{Structure, analyse};
use kurbo::{Point, Vec2};

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
    /// The rates computed (`want.rates`, else `want.plans`); None:
    /// positions only.
    pub order: Option<Order>,
    /// Whether the plans are built, up to `order`. Without them every
    /// position is cross-checked by route (b)'s residuals at route (a)'s
    /// answer instead of by route (b) followed along the positions
    /// ([`crate::verification::crosscheck`], docs/sweeps.md).
    pub plans: bool,
    /// Whether each position keeps its plans (`Solved::plans`, named,
    /// with their steps), as a result that prints or draws them needs;
    /// `false` where only their check is wanted (`solve`'s table and
    /// CSV): the plans are then built numbers only, without names or steps
    /// ([`crate::kinematics::construction::build_plans_numbers`]: the same
    /// plans to the bit), compared with both routes and dropped.
    pub keep_plans: bool,
    /// Whether the results print the cross-check's conditioning and
    /// bounds (the JSON result does; a table or CSV does not). Where not,
    /// the fast path's conditioning is only decided: a lower bound from
    /// the inverse's Frobenius norm (within a factor n of σ_min/σ_max),
    /// the SVD only where that bound falls below a threshold the check
    /// compares with, so every decision is the SVD's.
    pub printed_check: bool,
    /// Whether each position is handed over lean
    /// ([`crate::pipeline::Solved::lean`]: plans reduced to their rates,
    /// no transfer functions), made so where it is finished: where only the
    /// sheets read the positions held (`draw`), a chunk in flight is then
    /// some 3 kB a position, not 20 to 35.
    pub lean: bool,
    /// Where the result keeps no plans, build them by the sweep's
    /// construction kernel ([`crate::kinematics::construction::Kernel`],
    /// each plan first at the last position's scale), in the order of the
    /// positions (benches and tests only): faster, but not the same
    /// check, since the kernel draws a plan at the neighbouring scale
    /// where the build alone's first construction at unit scale takes
    /// other scale-dependent choices (docs/performance.md, issue 24).
    #[doc(hidden)]
    #[cfg(feature = "internals")]
    pub sweep_kernel: bool,
    /// A deliberate error put into route (a)'s answer, for the tests that
    /// show the cross-check catches it; never set by mechplan itself.
    #[doc(hidden)]
    #[cfg(feature = "internals")]
    pub corrupt: Option<Corruption>,
    /// Run the twins kept as references (tests and benches only): route
    /// (a) interpreted (`PositionSolver`, `contour::solve`) instead of
    /// compiled for the mechanism ([`crate::kinematics::compiled`]), and
    /// the plans named, with their steps, where the result keeps none
    /// (not numbers only), as before issue 24: the same results, the old
    /// cost.
    #[doc(hidden)]
    #[cfg(feature = "internals")]
    pub reference: bool,
    /// Fixed scales and the pencil precision of the plans.
    pub drafting: Drafting,
    /// Scales fixed for single positions (by index from 0: μ_v, μ_a),
    /// over `drafting`'s: the course sheet's common scales, given to the
    /// plans it shows so that they are built, stated and drawn at them.
    pub scales_at: std::sync::Arc<ScalesAt>,
    /// Scale of the plan of the mechanism, m/mm: `want.scales.mu_l`, else
    /// the standard value that draws the sketch's extent within 200 mm.
    pub mu_l: f64,
    /// How the positions are numbered in everything written and read
    /// (sheets, file names, result files, `--position`, reports): the
    /// scene's ([`crate::model::scene::PositionsSpec::numbering`]: a
    /// `count` sweep from 0, given values from 1), or another a study
    /// asks for (`--positions-from`).
    pub numbering: crate::model::scene::Numbering,
}

/// Plan scales fixed for single positions: by index from 0, (μ_v, μ_a).
pub type ScalesAt = std::collections::BTreeMap<usize, (Option<f64>, Option<f64>)>;

impl std::ops::Deref for Analysis {
    type Target = Demand;
    fn deref(&self) -> &Demand {
        &self.demand
    }
}

/// A deliberate error of route (a)'s answer (tests only), in the link
/// that reports the last point on a moving link: its pose moved along x
/// by `Position(x)` times the mechanism's size, or the velocity
/// (acceleration) of its frame's origin by `x` times the largest velocity
/// (acceleration) of a reported point at that position.
#[doc(hidden)]
#[cfg(feature = "internals")]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Corruption {
    Position(f64),
    Velocity(f64),
    Acceleration(f64),
}

/// One position as the kinematics solves it: the inputs' values, the
/// configuration, route (a)'s motions and transfer functions, the plans.
#[derive(Clone, Debug)]
pub struct Position {
    /// The (first) input's coordinate (rad or m) and its rates.
    pub q: f64,
    pub rate: f64,
    pub rate2: f64,
    /// Every input's coordinate and rates, in the scene's order.
    pub drives: Drives,
    pub config: Configuration,
    /// Route (a) motions; `None` for links not solved.
    pub motion: Vec<Option<Motion>>,
    /// Route (a) with unit input rate and zero input acceleration: the
    /// transfer functions (analogues of velocity and acceleration). With
    /// several inputs: of the first, the others standing (∂/∂q1).
    pub analogue: Vec<Option<Motion>>,
    /// With several inputs, the transfer functions of the others: route
    /// (a) with input i (from the second) at unit rate, the others
    /// standing: ∂/∂q_i and ∂²/∂q_i².
    pub more_analogues: Vec<Vec<Option<Motion>>>,
    /// With several inputs and accelerations: route (a) with inputs i and
    /// j (i < j, in the order (0, 1), (0, 2) … (1, 2) …) at unit rate, the
    /// others standing: its accelerations are ∂²/∂q_i² + ∂²/∂q_j² +
    /// 2·∂²/∂q_i∂q_j, whence the mixed second derivatives.
    pub mixed: Vec<Vec<Option<Motion>>>,
    /// The plans of velocities and accelerations, as constructions.
    pub plans: Option<Box<Plans>>,
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
            crate::kinematics::construction::scale::Series::Drawing.scale(mech.size, 200.0)
        });
        let drafting = Drafting {
            mu_v: sc.want.scales.mu_v,
            mu_a: sc.want.scales.mu_a,
            ..Drafting::default()
        };
        let plans = sc.want.plans && order.is_some();
        let numbering = sc.positions.numbering();
        Ok(Analysis {
            mech,
            structure,
            demand,
            order,
            plans,
            keep_plans: true,
            printed_check: true,
            lean: false,
            #[cfg(feature = "internals")]
            sweep_kernel: false,
            #[cfg(feature = "internals")]
            corrupt: None,
            #[cfg(feature = "internals")]
            reference: false,
            drafting,
            scales_at: Default::default(),
            mu_l,
            numbering,
        })
    }

    /// How the plans of position `index` (from 0) are drafted: the scene's
    /// scales, or the ones [`Analysis::scales_at`] fixes there.
    pub fn drafting_at(&self, index: usize) -> Drafting {
        match self.scales_at.get(&index) {
            Some(&(mu_v, mu_a)) => Drafting {
                mu_v: self.drafting.mu_v.or(mu_v),
                mu_a: self.drafting.mu_a.or(mu_a),
                ..self.drafting
            },
            None => self.drafting,
        }
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
        s: &Position,
        order: Order,
        mu_v: Option<f64>,
        mu_a: Option<f64>,
    ) -> Result<crate::kinematics::construction::Plans> {
        let (mu_v, mu_a) = (self.drafting.mu_v.or(mu_v), self.drafting.mu_a.or(mu_a));
        self.plans_at_given_scales(s, order, mu_v, mu_a)
    }

    /// [`Analysis::plans_at_scales`] with the scales given winning over
    /// the scene's (what a scene's scale would be, were it another).
    pub fn plans_at_given_scales(
        &self,
        s: &Position,
        order: Order,
        mu_v: Option<f64>,
        mu_a: Option<f64>,
    ) -> Result<crate::kinematics::construction::Plans> {
        let d = Drafting {
            mu_v: mu_v.or(self.drafting.mu_v),
            mu_a: mu_a.or(self.drafting.mu_a),
            ..self.drafting
        };
        crate::kinematics::construction::build_plans(&self.setup(), &s.config, s.drives, order, d)
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

/// The transfer functions of a quantity with several inputs: its first
/// partial derivatives by each input, and (with accelerations) the second
/// ones, rows and columns in the scene's order of inputs.
#[derive(Clone, Debug, PartialEq)]
pub struct Partials<T> {
    pub first: Vec<T>,
    pub second: Option<Vec<Vec<T>>>,
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
    /// Transfer functions s' and s'' (of the first input).
    pub s_q: f64,
    pub s_qq: f64,
    /// With several inputs: ∂s/∂q_i, and ∂²s/∂q_i∂q_j (rows i, columns j);
    /// empty for one input.
    pub s_qs: Vec<f64>,
    pub s_qqs: Vec<Vec<f64>>,
}

/// Route (a)'s answers at a position besides its configuration: the
/// motions, and the transfer functions of each input and each pair of
/// inputs (see [`Position`]'s fields of the same names).
#[derive(Clone, Debug, Default)]
pub struct Motions {
    /// The links' motions at the inputs' rates.
    pub motion: Vec<Option<Motion>>,
    /// At unit rate of the first input, the others standing.
    pub analogue: Vec<Option<Motion>>,
    /// At unit rate of each further input.
    pub more_analogues: Vec<Vec<Option<Motion>>>,
    /// At unit rates of each pair of inputs.
    pub mixed: Vec<Vec<Option<Motion>>>,
}

impl Position {
    /// A position of its inputs' `drives`, its configuration, route (a)'s
    /// motions and (where built) its plans.
    pub fn new(drives: Drives, config: Configuration, m: Motions, plans: Option<Plans>) -> Position {
        let first = drives.first();
        Position {
            q: first.q,
            rate: first.rate,
            rate2: first.rate2,
            drives,
            config,
            motion: m.motion,
            analogue: m.analogue,
            more_analogues: m.more_analogues,
            mixed: m.mixed,
            plans: plans.map(Box::new),
        }
    }
}

impl Position {
    /// The transfer functions of input `i`: route (a) at unit rate of
    /// input i, the others standing.
    pub fn analogue_of(&self, i: usize) -> &[Option<Motion>] {
        if i == 0 {
            &self.analogue
        } else {
            &self.more_analogues[i - 1]
        }
    }

    /// The second derivatives ∂²f/∂q_i∂q_j of a quantity `f` of the
    /// accelerations of a route-(a) run (a point's acceleration, a link's
    /// ε): from the runs of the transfer functions (and, for i ≠ j, the
    /// mixed run: (f_ij − f_ii − f_jj)/2).
    pub fn second<T>(
        &self,
        i: usize,
        j: usize,
        f: impl Fn(&[Option<Motion>]) -> Option<T>,
    ) -> Option<T>
    where
        T: std::ops::Sub<Output = T> + std::ops::Mul<f64, Output = T>,
    {
        if i == j {
            return f(self.analogue_of(i));
        }
        let (i, j) = (i.min(j), i.max(j));
        let w = self.drives.len();
        // Index of (i, j) in the order (0,1), (0,2) … (1,2) …
        let k = (0..i).map(|a| w - 1 - a).sum::<usize>() + (j - i - 1);
        Some((f(self.mixed.get(k)?)? - f(self.analogue_of(i))? - f(self.analogue_of(j))?) * 0.5)
    }

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
            let w = self.drives.len();
            let (mut s_qs, mut s_qqs) = (Vec::new(), Vec::new());
            if w > 1 {
                for i in 0..w {
                    s_qs.push(rel(self.analogue_of(i)).map_or(0.0, |r| r.0));
                    let row: Vec<f64> = (0..w)
                        .map(|j| self.second(i, j, |mo| rel(mo).map(|r| r.1)).unwrap_or(0.0))
                        .collect();
                    s_qqs.push(row);
                }
            }
            out.push(Slide {
                pair: k,
                s,
                v,
                a,
                coriolis,
                s_q,
                s_qq,
                s_qs,
                s_qqs,
            });
        }
        out
    }

    /// The transfer functions of point `p` with several inputs: ∂P/∂q_i,
    /// and ∂²P/∂q_i∂q_j (rows i, columns j); `None` without velocities.
    pub fn point_partials(&self, an: &Analysis, p: usize) -> Option<Partials<Vec2>> {
        let l = an.carrier(p);
        let at = self.config.point(&an.mech, l, p);
        self.partials(|mo| mo[l].map(|x| (x.velocity(at), x.acceleration(at))))
    }

    /// The transfer functions of link `l`'s angle with several inputs:
    /// ∂φ/∂q_i and ∂²φ/∂q_i∂q_j.
    pub fn link_partials(&self, l: usize) -> Option<Partials<f64>> {
        self.partials(|mo| mo[l].map(|x| (x.omega, x.epsilon)))
    }

    /// First and second partial derivatives of a quantity whose (rate,
    /// rate of rate) a route-(a) run gives by `f`.
    fn partials<T>(&self, f: impl Fn(&[Option<Motion>]) -> Option<(T, T)>) -> Option<Partials<T>>
    where
        T: Copy + std::ops::Sub<Output = T> + std::ops::Mul<f64, Output = T>,
    {
        let w = self.drives.len();
        let first: Vec<T> = (0..w)
            .map(|i| f(self.analogue_of(i)).map(|x| x.0))
            .collect::<Option<_>>()?;
        let second = if w > 1 && self.mixed.len() == w * (w - 1) / 2 {
            (0..w)
                .map(|i| {
                    (0..w)
                        .map(|j| self.second(i, j, |mo| f(mo).map(|x| x.1)))
                        .collect::<Option<Vec<T>>>()
                })
                .collect::<Option<Vec<Vec<T>>>>()
        } else {
            None
        };
        Some(Partials { first, second })
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
