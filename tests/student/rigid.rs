//! The rigid-body solver of the method: every moving link's velocity and
//! acceleration field as one linear system, with the switches a student's
//! mistake makes in it.

use kurbo::{Point, Vec2};
use mechplan::{Analysis, Solved};
use nalgebra::{DMatrix, DVector};
use serde_json::Value;

/// `k × v`: `v` turned by +90° (counter-clockwise), as in ω × r.
pub fn perp(v: Vec2) -> Vec2 {
    Vec2::new(-v.y, v.x)
}

/// One link: its id, the points it carries (indices into
/// [`Model::names`]) and the origin its field is written about.
#[derive(Clone, Debug)]
pub struct Body {
    pub id: String,
    pub points: Vec<usize>,
    pub origin: Point,
}

/// A prismatic pair: `slider` slides on `guide` along the unit `u` (world,
/// at this position) at the contact point `point`.
#[derive(Clone, Debug)]
pub struct Pair {
    pub slider: usize,
    pub guide: usize,
    pub point: usize,
    pub u: Vec2,
}

/// An input as the scene states it (SI).
#[derive(Clone, Debug)]
pub enum Input {
    /// A crank: ω and ε of `link`.
    Crank {
        link: usize,
        omega: f64,
        epsilon: f64,
    },
    /// A driving slider (also on a moving guide: a cylinder): the relative
    /// velocity and acceleration along its pair's guide.
    Slide { pair: usize, v: f64, a: f64 },
}

/// The mechanism at one position, as the method needs it.
#[derive(Clone, Debug)]
pub struct Model {
    /// Scene point names, by point index.
    pub names: Vec<String>,
    /// Where each point is at this position (m).
    pub at: Vec<Point>,
    /// Links, by link index (the frame among them).
    pub links: Vec<Body>,
    pub frame: usize,
    /// Revolute pairs: (point, link, link).
    pub revolutes: Vec<(usize, usize, usize)>,
    pub pairs: Vec<Pair>,
    pub inputs: Vec<Input>,
}

/// A velocity field of every link: v(O_L), and ω_L (or, for a link drawn
/// with its relative velocities ∥ its radii, λ_L: v(P) = v(O) + λ·(P − O)).
#[derive(Clone, Debug)]
pub struct Velocities {
    pub v_o: Vec<Vec2>,
    pub omega: Vec<f64>,
    /// Links whose field is λ·r instead of ω × r.
    pub parallel: Option<usize>,
    /// The sliding velocity of each pair, along its line.
    pub v_rel: Vec<f64>,
    /// The line each pair's sliding velocity is laid along (u, or a wrong
    /// one).
    pub line: Vec<Vec2>,
}

/// An acceleration field of every link: a(O_L), ε_L and the ω_L used in
/// its normal components (the stated ones, in a student's plan).
#[derive(Clone, Debug)]
pub struct Accelerations {
    pub a_o: Vec<Vec2>,
    pub epsilon: Vec<f64>,
    pub omega: Vec<f64>,
    pub a_rel: Vec<f64>,
    pub line: Vec<Vec2>,
}

/// What a student may do differently: a pair's relative vector laid along
/// the line ⊥ its guide; a link's relative velocities laid ∥ its radii
/// (velocities only); points given where the student drew them, for the
/// links that take them from there ((point, the link that draws it,
/// velocity or acceleration)).
#[derive(Clone, Debug, Default)]
pub struct Options {
    pub wrong_line: Option<usize>,
    pub parallel: Option<usize>,
    pub given: Vec<(usize, usize, Vec2)>,
}

impl Model {
    /// The model of `scene` (its JSON) at the solved position `s`: names,
    /// pairs and inputs from the scene file; where the points are and
    /// which way each guide line runs, from the solved position.
    pub fn new(scene: &Value, an: &Analysis, s: &Solved) -> Model {
        let sc = &an.mech.scene;
        let names: Vec<String> = sc.points.iter().map(|p| p.name.clone()).collect();
        let point = |name: &str| sc.point_index(name).expect("a scene point");
        let link = |id: &str| sc.link_index(id).expect("a scene link");
        let frame = an.mech.frame();
        let mut links: Vec<Body> = (0..sc.links.len())
            .map(|l| Body {
                id: an.mech.link_id(l).to_string(),
                points: Vec::new(),
                origin: Point::ORIGIN,
            })
            .collect();
        for (id, l) in scene["links"].as_object().unwrap() {
            let k = link(id);
            links[k].points = l["points"]
                .as_array()
                .unwrap()
                .iter()
                .map(|p| point(p.as_str().unwrap()))
                .collect();
        }
        // Where each point is: as carried by the first link listing it.
        let mut at = vec![Point::ORIGIN; names.len()];
        let mut placed = vec![false; names.len()];
        for (l, b) in links.iter().enumerate() {
            for &p in &b.points {
                if !placed[p] {
                    at[p] = s.config.point(&an.mech, l, p);
                    placed[p] = true;
                }
            }
        }
        for b in &mut links {
            if let Some(&p) = b.points.first() {
                b.origin = at[p];
            }
        }
        // Revolute pairs: every point listed by several links joins the
        // first of them to each of the others.
        let mut revolutes = Vec::new();
        for p in 0..names.len() {
            let on: Vec<usize> = (0..links.len())
                .filter(|&l| links[l].points.contains(&p))
                .collect();
            for &b in on.iter().skip(1) {
                revolutes.push((p, on[0], b));
            }
        }
        let mut pairs = Vec::new();
        for e in scene["sliders"].as_array().into_iter().flatten() {
            let (slider, guide) = (
                link(e["slider"].as_str().unwrap()),
                link(e["guide"].as_str().unwrap()),
            );
            let p = point(e["point"].as_str().unwrap());
            let prism = an
                .mech
                .prismatics
                .iter()
                .find(|q| q.slider == slider && q.guide == guide && q.point == p)
                .expect("the scene's pair in the mechanism");
            let dir = prism.line(&s.config.pose(guide)).dir;
            pairs.push(Pair {
                slider,
                guide,
                point: p,
                u: dir / dir.hypot(),
            });
        }
        let unit = match scene["units"]["length"].as_str() {
            Some("mm") => 0.001,
            _ => 1.0,
        };
        let list: Vec<&Value> = match &scene["input"] {
            Value::Array(a) => a.iter().collect(),
            v => vec![v],
        };
        let inputs = list
            .into_iter()
            .map(|i| {
                let l = link(i["link"].as_str().unwrap());
                if i["slider"].as_bool() == Some(true) {
                    // Its pair: where it slides; on the frame when several.
                    let mine: Vec<usize> =
                        (0..pairs.len()).filter(|&k| pairs[k].slider == l).collect();
                    let pair = *mine
                        .iter()
                        .find(|&&k| pairs[k].guide == frame)
                        .unwrap_or(&mine[0]);
                    Input::Slide {
                        pair,
                        v: i["v"].as_f64().unwrap() * unit,
                        a: i["a"].as_f64().unwrap_or(0.0) * unit,
                    }
                } else {
                    let omega = match i.get("omega") {
                        Some(w) => w.as_f64().unwrap(),
                        None => i["rpm"].as_f64().unwrap() * std::f64::consts::TAU / 60.0,
                    };
                    Input::Crank {
                        link: l,
                        omega,
                        epsilon: i["epsilon"].as_f64().unwrap_or(0.0),
                    }
                }
            })
            .collect();
        Model {
            names,
            at,
            links,
            frame,
            revolutes,
            pairs,
            inputs,
        }
    }

    /// The column of link `l`'s first unknown (v_O or a_O: two, then ω or
    /// ε); `None` for the frame.
    fn col(&self, l: usize) -> Option<usize> {
        (l != self.frame).then(|| 3 * (l - usize::from(l > self.frame)))
    }

    fn unknowns(&self) -> usize {
        3 * (self.links.len() - 1) + self.pairs.len()
    }

    /// The coefficients of link `l`'s field at `p` in the rows x and y:
    /// (column, coefficient) each. `radial`: the rate's column multiplies
    /// r (λ·r) instead of k × r.
    fn field_at(&self, l: usize, p: Point, radial: bool) -> [Vec<(usize, f64)>; 2] {
        let Some(c) = self.col(l) else {
            return [Vec::new(), Vec::new()];
        };
        let r = p - self.links[l].origin;
        let turn = if radial { r } else { perp(r) };
        [
            vec![(c, 1.0), (c + 2, turn.x)],
            vec![(c + 1, 1.0), (c + 2, turn.y)],
        ]
    }

    /// The line each pair's relative vector is laid along.
    fn lines(&self, o: &Options) -> Vec<Vec2> {
        self.pairs
            .iter()
            .enumerate()
            .map(|(k, q)| {
                if o.wrong_line == Some(k) {
                    perp(q.u)
                } else {
                    q.u
                }
            })
            .collect()
    }

    /// The system of one plan: rows of (column, coefficient) with their
    /// right-hand sides. `quad(l, r)` is what link `l`'s field has besides
    /// the unknowns at r = P − O_L (−ω²·r for accelerations, 0 for
    /// velocities); `rel(k)` the known part of pair k's relative vector
    /// (the Coriolis acceleration); `input(i)` the stated rate of input i;
    /// `given` the points drawn where the student drew them.
    #[allow(clippy::type_complexity)]
    fn system(
        &self,
        o: &Options,
        quad: &dyn Fn(usize, Vec2) -> Vec2,
        rel: &dyn Fn(usize) -> Vec2,
        input: &dyn Fn(&Input) -> f64,
    ) -> Option<Vec<f64>> {
        let n = self.unknowns();
        let mut rows: Vec<(Vec<(usize, f64)>, f64)> = Vec::new();
        let lines = self.lines(o);
        let pair_col = |k: usize| 3 * (self.links.len() - 1) + k;
        let radial = |l: usize| o.parallel == Some(l);
        let known = |l: usize, p: Point| {
            if l == self.frame {
                Vec2::ZERO
            } else {
                quad(l, p - self.links[l].origin)
            }
        };
        // field_i(P) − field_j(P) (+ extra columns) = rhs, two rows.
        let difference =
            |i: usize, j: Option<usize>, p: Point, extra: Vec<[(usize, f64); 2]>, rhs: Vec2| {
                let mut out = Vec::with_capacity(2);
                let fi = self.field_at(i, p, radial(i));
                let fj = j.map(|j| self.field_at(j, p, radial(j)));
                let ki = known(i, p);
                let kj = j.map_or(Vec2::ZERO, |j| known(j, p));
                for axis in 0..2 {
                    let mut row = fi[axis].clone();
                    if let Some(fj) = &fj {
                        row.extend(fj[axis].iter().map(|&(c, v)| (c, -v)));
                    }
                    row.extend(extra.iter().map(|e| e[axis]));
                    let (k, r) = if axis == 0 {
                        (ki.x - kj.x, rhs.x)
                    } else {
                        (ki.y - kj.y, rhs.y)
                    };
                    out.push((row, r - k));
                }
                out
            };
        for &(p, a, b) in &self.revolutes {
            let at = self.at[p];
            let given = o.given.iter().find(|g| g.0 == p);
            match given {
                Some(&(_, up, value)) if up == a => {
                    rows.extend(difference(b, None, at, Vec::new(), value))
                }
                Some(&(_, up, value)) if up == b => {
                    rows.extend(difference(a, None, at, Vec::new(), value))
                }
                _ => rows.extend(difference(a, Some(b), at, Vec::new(), Vec2::ZERO)),
            }
        }
        for (k, q) in self.pairs.iter().enumerate() {
            let w = lines[k];
            let c = pair_col(k);
            rows.extend(difference(
                q.slider,
                Some(q.guide),
                self.at[q.point],
                vec![[(c, -w.x), (c, -w.y)]],
                rel(k),
            ));
            // No relative rotation.
            let mut row = Vec::new();
            if let Some(cs) = self.col(q.slider) {
                row.push((cs + 2, 1.0));
            }
            if let Some(cg) = self.col(q.guide) {
                row.push((cg + 2, -1.0));
            }
            rows.push((row, 0.0));
        }
        for i in &self.inputs {
            let col = match i {
                Input::Crank { link, .. } => self.col(*link).unwrap() + 2,
                Input::Slide { pair, .. } => pair_col(*pair),
            };
            rows.push((vec![(col, 1.0)], input(i)));
        }
        let mut a = DMatrix::<f64>::zeros(rows.len(), n);
        let mut b = DVector::<f64>::zeros(rows.len());
        for (r, (row, rhs)) in rows.iter().enumerate() {
            for &(c, v) in row {
                a[(r, c)] += v;
            }
            b[r] = *rhs;
        }
        let svd = a.clone().svd(true, true);
        let (hi, lo) = svd
            .singular_values
            .iter()
            .fold((0.0f64, f64::MAX), |(h, l), &s| (h.max(s), l.min(s)));
        if svd.singular_values.len() < n || lo <= 1e-10 * hi {
            return None;
        }
        let x = svd.solve(&b, 0.0).ok()?;
        let residual = (&a * &x - &b).amax();
        (residual <= 1e-9 * b.amax().max(1e-300)).then(|| x.iter().copied().collect())
    }

    /// Every link's velocity field, with the student's switches `o`.
    pub fn velocities(&self, o: &Options) -> Option<Velocities> {
        let x = self.system(o, &|_, _| Vec2::ZERO, &|_| Vec2::ZERO, &|i| match i {
            Input::Crank { omega, .. } => *omega,
            Input::Slide { v, .. } => *v,
        })?;
        let mut v_o = vec![Vec2::ZERO; self.links.len()];
        let mut omega = vec![0.0; self.links.len()];
        for l in 0..self.links.len() {
            if let Some(c) = self.col(l) {
                v_o[l] = Vec2::new(x[c], x[c + 1]);
                omega[l] = x[c + 2];
            }
        }
        let base = 3 * (self.links.len() - 1);
        Some(Velocities {
            v_o,
            omega,
            parallel: o.parallel,
            v_rel: x[base..].to_vec(),
            line: self.lines(o),
        })
    }

    /// Every link's acceleration field on the velocity plan `vel`, with
    /// `omega` (by link) in every normal component and Coriolis term (the
    /// true ω, or the ones a student stated), and the switches `o`.
    pub fn accelerations(
        &self,
        vel: &Velocities,
        omega: &[f64],
        o: &Options,
    ) -> Option<Accelerations> {
        let x = self.system(
            o,
            &|l, r| -r * (omega[l] * omega[l]),
            &|k| {
                let q = &self.pairs[k];
                let w_g = if q.guide == self.frame {
                    0.0
                } else {
                    omega[q.guide]
                };
                perp(vel.line[k] * vel.v_rel[k]) * (2.0 * w_g)
            },
            &|i| match i {
                Input::Crank { epsilon, .. } => *epsilon,
                Input::Slide { a, .. } => *a,
            },
        )?;
        let mut a_o = vec![Vec2::ZERO; self.links.len()];
        let mut epsilon = vec![0.0; self.links.len()];
        for l in 0..self.links.len() {
            if let Some(c) = self.col(l) {
                a_o[l] = Vec2::new(x[c], x[c + 1]);
                epsilon[l] = x[c + 2];
            }
        }
        let base = 3 * (self.links.len() - 1);
        Some(Accelerations {
            a_o,
            epsilon,
            omega: omega.to_vec(),
            a_rel: x[base..].to_vec(),
            line: self.lines(o),
        })
    }

    /// Whether link `l` moves (is not the frame).
    pub fn moving(&self, l: usize) -> bool {
        l != self.frame
    }

    /// The first moving link carrying point `p` (a point only on the frame:
    /// none).
    pub fn carrier(&self, p: usize) -> Option<usize> {
        (0..self.links.len()).find(|&l| l != self.frame && self.links[l].points.contains(&p))
    }
}

impl Velocities {
    /// The velocity of link `l`'s material point at `p`.
    pub fn at(&self, m: &Model, l: usize, p: Point) -> Vec2 {
        if l == m.frame {
            return Vec2::ZERO;
        }
        let r = p - m.links[l].origin;
        if self.parallel == Some(l) {
            self.v_o[l] + r * self.omega[l]
        } else {
            self.v_o[l] + perp(r) * self.omega[l]
        }
    }
}

impl Accelerations {
    /// The acceleration of link `l`'s material point at `p`.
    pub fn at(&self, m: &Model, l: usize, p: Point) -> Vec2 {
        if l == m.frame {
            return Vec2::ZERO;
        }
        let r = p - m.links[l].origin;
        self.a_o[l] + perp(r) * self.epsilon[l] - r * (self.omega[l] * self.omega[l])
    }
}
