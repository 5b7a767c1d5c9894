//! The analytic route: d'Alembert's equilibrium of every moving link (ΣF
//! = 0, ΣM = 0 with the inertia loads), all links at once as one square
//! linear system. Unknowns: a revolute pair's reaction (2), a prismatic
//! pair's normal force and couple (2: frictionless, the force is
//! perpendicular to the guide), an input's balancing moment or force (1).
//! Square exactly when 3n = 2·p5 + W, Chebyshev's count with W inputs.
//!
//! Scaled so that every unknown is a force (couples over the mechanism's
//! size L) and every equation a force (moments over L); solved by LU with
//! one step of refinement, refused where its reciprocal condition number
//! says the answer would carry more than the cross-check's relative error.

use super::loads::Load;
use crate::accuracy::ACCURACY;
use crate::error::{Error, Result};
use crate::geom::perp;
use crate::kinematics::positions::describe_input;
use crate::kinematics::solve::{Analysis, Position};
use crate::model::scene::InputSpec;
use kurbo::{Point, Vec2};
use nalgebra::{DMatrix, DVector};


/// The unknowns found: in the mechanism's order of pairs and the scene's
/// order of inputs.
#[derive(Clone, Debug, PartialEq)]
pub struct Unknowns {
    /// Per revolute pair (`Mechanism::revolutes`): the force of its first
    /// link on its second, N.
    pub revolute: Vec<Vec2>,
    /// Per prismatic pair (`Mechanism::prismatics`): the guide's normal
    /// force on the slider as a signed magnitude along the guide's left
    /// normal, N, and the guide's couple on the slider about the pair's
    /// point, N·m.
    pub prismatic: Vec<(f64, f64)>,
    /// Per input: the balancing moment (N·m) on a crank, the balancing
    /// force (N) along a driving slider's guide direction.
    pub drives: Vec<f64>,
    /// The scaled system's reciprocal condition number (1-norm).
    pub rcond: f64,
}

/// The geometry of prismatic pair `k` at a position: the slider's point Q
/// on the line, the guide's direction u and its left normal n.
pub fn guide_frame(an: &Analysis, s: &Position, k: usize) -> (Point, Vec2, Vec2) {
    let m = &an.mech;
    let pr = &m.prismatics[k];
    let q = s.config.point(m, pr.slider, pr.point);
    let u = s.config.pose(pr.guide).dir(pr.line_dir);
    (q, u, perp(u))
}

/// The system's columns and rows, and how loads enter them.
struct System<'a> {
    an: &'a Analysis,
    s: &'a Position,
    /// First row of each link's three equations (None: the frame).
    row: Vec<Option<usize>>,
    /// The length that turns moments into forces.
    l: f64,
    a: DMatrix<f64>,
    b: DVector<f64>,
}

impl System<'_> {
    /// Column `c` gets a unit force `e` through `at` on `link`, sign `sign`.
    fn force(&mut self, c: usize, link: usize, at: Point, e: Vec2, sign: f64) {
        let Some(r) = self.row[link] else { return };
        let o = self.s.config.pose(link).origin;
        self.a[(r, c)] += sign * e.x;
        self.a[(r + 1, c)] += sign * e.y;
        self.a[(r + 2, c)] += sign * (at - o).cross(e) / self.l;
    }
    /// Column `c` (a couple over L) on `link`, sign `sign`.
    fn couple(&mut self, c: usize, link: usize, sign: f64) {
        if let Some(r) = self.row[link] {
            self.a[(r + 2, c)] += sign;
        }
    }
    /// A known load goes to the right-hand side.
    fn load(&mut self, load: &Load) {
        let link = load.link();
        let Some(r) = self.row[link] else { return };
        let o = self.s.config.pose(link).origin;
        if let Load::Force { f, .. } = *load {
            self.b[r] -= f.x;
            self.b[r + 1] -= f.y;
        }
        self.b[r + 2] -= load.moment_about(o) / self.l;
    }
}

/// Solve the equilibrium of every moving link at solved position `s`
/// under the known `loads`.
pub fn solve(an: &Analysis, s: &Position, loads: &[Load]) -> Result<Unknowns> {
    let m = &an.mech;
    let sc = &m.scene;
    let mut row = vec![None; m.links.len()];
    let mut n = 0;
    for (l, r) in row.iter_mut().enumerate() {
        if l != m.frame() {
            *r = Some(3 * n);
            n += 1;
        }
    }
    let unknowns = 2 * m.revolutes.len() + 2 * m.prismatics.len() + sc.input_count();
    if unknowns != 3 * n {
        return Err(Error::structure(format!(
            "the force analysis needs as many unknowns as equations: {n} moving links give 3·{n} = {} equations, but {} revolute and {} prismatic pairs and {} inputs give {unknowns} unknowns (3n = 2·p5 + W)",
            3 * n,
            m.revolutes.len(),
            m.prismatics.len(),
            sc.input_count()
        )));
    }
    let mut sys = System {
        an,
        s,
        row,
        l: m.size,
        a: DMatrix::zeros(unknowns, unknowns),
        b: DVector::zeros(unknowns),
    };
    let mut c = 0;
    for rv in &m.revolutes {
        let at = s.config.point(m, rv.b, rv.point);
        for e in [Vec2::new(1.0, 0.0), Vec2::new(0.0, 1.0)] {
            sys.force(c, rv.b, at, e, 1.0);
            sys.force(c, rv.a, at, e, -1.0);
            c += 1;
        }
    }
    for (k, pr) in m.prismatics.iter().enumerate() {
        let (q, _, nrm) = guide_frame(sys.an, sys.s, k);
        sys.force(c, pr.slider, q, nrm, 1.0);
        sys.force(c, pr.guide, q, nrm, -1.0);
        sys.couple(c + 1, pr.slider, 1.0);
        sys.couple(c + 1, pr.guide, -1.0);
        c += 2;
    }
    for input in sc.inputs() {
        match *input {
            InputSpec::Crank { link, .. } => sys.couple(c, link, 1.0),
            InputSpec::Slider { link, pair, .. } => {
                // The drive pushes the slider along its guide and the guide
                // back (a cylinder's rod and barrel; the frame: no row).
                let (q, u, _) = guide_frame(sys.an, sys.s, pair);
                sys.force(c, link, q, u, 1.0);
                sys.force(c, m.prismatics[pair].guide, q, u, -1.0);
            }
        }
        c += 1;
    }
    for load in loads {
        sys.load(load);
    }
    let (a, b, l) = (sys.a, sys.b, sys.l);
    let at = || describe_input(m, &s.drives.coords());
    let lu = a.clone().lu();
    let inverse = lu.try_inverse().ok_or_else(|| {
        Error::singular(
            at(),
            "the equilibrium equations of the links are singular (the reactions are not determined: a dead point of a group)",
        )
    })?;
    let rcond = 1.0 / (norm1(&a) * norm1(&inverse));
    // NaN (an overflowed inverse) is refused too.
    if rcond.is_nan() || rcond < ACCURACY.min_force_conditioning {
        return Err(Error::singular(
            at(),
            format!(
                "the equilibrium equations of the links are ill-conditioned (reciprocal condition number {rcond:.1e} < {:.1e}): the reactions would carry a relative error above {:.0e}",
                ACCURACY.min_force_conditioning, ACCURACY.max_rel_diff
            ),
        ));
    }
    let mut x = lu.solve(&b).expect("a regular matrix solves");
    let r = &b - &a * &x;
    x += lu.solve(&r).expect("a regular matrix solves");
    let mut c = 0;
    let mut next = || {
        c += 1;
        x[c - 1]
    };
    let revolute = m
        .revolutes
        .iter()
        .map(|_| Vec2::new(next(), next()))
        .collect();
    let prismatic = m.prismatics.iter().map(|_| (next(), next() * l)).collect();
    let drives = sc
        .inputs()
        .map(|i| if i.is_crank() { next() * l } else { next() })
        .collect();
    Ok(Unknowns {
        revolute,
        prismatic,
        drives,
        rcond,
    })
}

/// The 1-norm of a matrix: its largest column sum of magnitudes.
fn norm1(a: &DMatrix<f64>) -> f64 {
    a.column_iter()
        .map(|c| c.iter().map(|x| x.abs()).sum::<f64>())
        .fold(0.0, f64::max)
}
