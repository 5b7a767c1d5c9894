//! Instant centres of velocity by Kennedy's theorem, as a construction.
//!
//! Every two links i, j of a mechanism have an instant centre P_ij: the
//! point where their velocity fields agree. The primary centres come from
//! the pairs: a revolute pair is the centre of its two links; a prismatic
//! pair's centre lies at infinity, perpendicular to the guide. Kennedy's
//! theorem (the three centres of any three links lie on one line) finds the
//! rest: P_ij lies on the line P_ik P_kj for every third link k, so it is
//! the intersection of two such lines. Points are homogeneous coordinates,
//! so a centre at infinity (a link translating, at this instant, relative
//! to another) is a direction, not an overflow.
//!
//! Only the positions are used: the centres are an independent check of
//! the velocities (v_M = ω_j × (M − P_0j), and v_i(P_ij) = v_j(P_ij)).

use crate::kinematics::positions::Configuration;
use crate::kinematics::solve::Analysis;
use crate::model::mechanism::Mechanism;
use kurbo::{Point, Vec2};

/// A homogeneous point `(x, y, w)` in units of the mechanism's size about
/// its origin; `w = 0` is a point at infinity in the direction `(x, y)`.
type H = [f64; 3];

fn cross(a: &H, b: &H) -> H {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// Where an instant centre is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Place {
    /// A point of the plane (m).
    At(Point),
    /// At infinity in this direction (unit vector): the two links
    /// translate relative to each other, perpendicular to it.
    Infinity(Vec2),
}

/// How a centre was found.
#[derive(Clone, Debug, PartialEq)]
pub enum How {
    /// A revolute pair at the named point.
    Revolute(String),
    /// A prismatic pair: at infinity perpendicular to the guide.
    Prismatic,
    /// Kennedy's theorem: the lines P_ik P_kj for the two third links k.
    Kennedy([usize; 2]),
}

/// The instant centre of two links (indices into the mechanism's links,
/// `links.0 < links.1`).
#[derive(Clone, Debug)]
pub struct Centre {
    pub links: (usize, usize),
    pub place: Place,
    pub how: How,
    /// Sine of the angle between the two Kennedy lines (1 for a pair):
    /// the construction's reliability. The centre's error is about the
    /// lines' error divided by it.
    pub sin_angle: f64,
}

/// A centre Kennedy's theorem cannot place at this position: every pair of
/// lines through it coincides (or fewer than two lines exist).
#[derive(Clone, Debug)]
pub struct Undetermined {
    pub links: (usize, usize),
    pub why: Why,
}

/// Why a centre cannot be placed (named in words by `crate::words`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Why {
    /// The Kennedy lines through these two third links coincide: the
    /// centre is anywhere on them.
    Coincide([usize; 2]),
    /// Fewer than two Kennedy lines reach it.
    FewLines,
}

/// All instant centres of the solved links at one position.
#[derive(Clone, Debug)]
pub struct Centres {
    /// Links taking part (the frame and the solved links), ascending
    /// (read by the tests).
    #[cfg(feature = "internals")]
    pub links: Vec<usize>,
    pub found: Vec<Centre>,
    pub undetermined: Vec<Undetermined>,
}

#[cfg(feature = "internals")]
impl Centres {
    /// The centre of links `a` and `b` (in either order), if found.
    pub fn get(&self, a: usize, b: usize) -> Option<&Centre> {
        let key = (a.min(b), a.max(b));
        self.found.iter().find(|c| c.links == key)
    }
}

/// Below this sine two Kennedy lines are taken as parallel.
pub const PARALLEL_SIN: f64 = 1e-10;

/// Kennedy's construction at the position `c` of the analysis `an`.
pub fn find(an: &Analysis, c: &Configuration) -> Centres {
    let m = &an.mech;
    let links: Vec<usize> = (0..m.links.len())
        .filter(|&l| l == m.frame() || an.link(l))
        .collect();
    let mut k = Kennedy::primary(an, c, links);
    // Kennedy's theorem, pass by pass: each pass places every centre that
    // two lines through already known centres determine; the best pair of
    // lines (the largest angle between them) is used.
    let mut undetermined = Vec::new();
    // `last`: no pass places anything more; the centres whose lines all
    // coincide are then recorded as undetermined.
    let mut last = false;
    loop {
        let placed = k.pass(last, &mut undetermined);
        if placed.is_empty() {
            if last {
                break;
            }
            last = true;
            continue;
        }
        last = false;
        for (at, v) in placed {
            k.known[at] = Some(v);
        }
    }
    let found = k.centres(&mut undetermined);
    Centres {
        #[cfg(feature = "internals")]
        links: k.links,
        found,
        undetermined,
    }
}

/// A centre known so far: homogeneous, in the sketch's size from the
/// frame's origin; how it was found; the sine of its lines' angle.
type Known = (H, How, f64);

/// Kennedy's construction under way: the links taking part, the centres
/// known of every two of them (by `slot`).
struct Kennedy {
    links: Vec<usize>,
    known: Vec<Option<Known>>,
    origin: Point,
    size: f64,
}

impl Kennedy {
    /// The primary centres: the pairs.
    fn primary(an: &Analysis, c: &Configuration, links: Vec<usize>) -> Kennedy {
        let m = &an.mech;
        let n = links.len();
        let mut k = Kennedy {
            links,
            known: vec![None; n * n],
            origin: m.links[m.frame()].sketch_pose.origin,
            size: m.size,
        };
        let (origin, size) = (k.origin, k.size);
        let to_h = |p: Point| -> H { [(p.x - origin.x) / size, (p.y - origin.y) / size, 1.0] };
        for r in &m.revolutes {
            if let (Some(i), Some(j)) = (k.idx(r.a), k.idx(r.b)) {
                let l = if an.link(r.a) { r.a } else { r.b };
                let at = c.point(m, l, r.point);
                let slot = k.slot(i, j);
                k.known[slot] = Some((to_h(at), How::Revolute(m.point_name(r.point).into()), 1.0));
            }
        }
        for pr in &m.prismatics {
            if let (Some(i), Some(j)) = (k.idx(pr.guide), k.idx(pr.slider)) {
                let u = c.pose(pr.guide).dir(pr.line_dir);
                let nrm = Vec2::new(-u.y, u.x);
                let slot = k.slot(i, j);
                k.known[slot] = Some(([nrm.x, nrm.y, 0.0], How::Prismatic, 1.0));
            }
        }
        k
    }

    fn idx(&self, l: usize) -> Option<usize> {
        self.links.iter().position(|&x| x == l)
    }

    fn slot(&self, i: usize, j: usize) -> usize {
        i.min(j) * self.links.len() + i.max(j)
    }

    /// The lines P_ik P_kj through the centre of links i and j (unit
    /// normals, a² + b² = 1), with k.
    fn lines(&self, i: usize, j: usize) -> Vec<(usize, H)> {
        let known = &self.known;
        (0..self.links.len())
            .filter(|&k| k != i && k != j)
            .filter_map(|k| {
                let a = &known[self.slot(i, k)].as_ref()?.0;
                let b = &known[self.slot(k, j)].as_ref()?.0;
                let l = cross(a, b);
                let h = l[0].hypot(l[1]);
                (h > 1e-12).then(|| (k, [l[0] / h, l[1] / h, l[2] / h]))
            })
            .collect()
    }

    /// One pass: every centre not yet known that two lines determine
    /// (by slot); with `last`, those whose lines all coincide are
    /// recorded in `undetermined` (and placed nowhere).
    fn pass(&self, last: bool, undetermined: &mut Vec<Undetermined>) -> Vec<(usize, Known)> {
        let (n, links) = (self.links.len(), &self.links);
        let mut placed = Vec::new();
        for i in 0..n {
            for j in i + 1..n {
                let slot = self.slot(i, j);
                if self.known[slot].is_some() {
                    continue;
                }
                let lines = self.lines(i, j);
                let mut best: Option<(f64, usize, usize)> = None;
                for (x, (_, la)) in lines.iter().enumerate() {
                    for (y, (_, lb)) in lines.iter().enumerate().skip(x + 1) {
                        let s = (la[0] * lb[1] - la[1] * lb[0]).abs();
                        if best.is_none_or(|b| s > b.0) {
                            best = Some((s, x, y));
                        }
                    }
                }
                let Some((s, x, y)) = best else { continue };
                let (la, lb) = (&lines[x].1, &lines[y].1);
                let p = cross(la, lb);
                let via = [links[lines[x].0], links[lines[y].0]];
                if s > PARALLEL_SIN {
                    placed.push((slot, (p, How::Kennedy(via), s)));
                } else {
                    // Parallel lines: distinct ones meet at infinity (a
                    // relative translation), coincident ones say nothing.
                    let gap = (la[2] - lb[2] * (la[0] * lb[0] + la[1] * lb[1]).signum()).abs();
                    if gap > 1e-9 {
                        let d = [-la[1], la[0], 0.0];
                        placed.push((slot, (d, How::Kennedy(via), s)));
                    } else if !last {
                        // Coincident: wait for more lines from later passes.
                    } else {
                        undetermined.push(Undetermined {
                            links: (links[i], links[j]),
                            why: Why::Coincide(via),
                        });
                        placed.push((slot, ([0.0, 0.0, 0.0], How::Kennedy(via), 0.0)));
                    }
                }
            }
        }
        placed
    }

    /// The centres found, in the world; those no two lines reach recorded
    /// in `undetermined`.
    fn centres(&self, undetermined: &mut Vec<Undetermined>) -> Vec<Centre> {
        let (n, links) = (self.links.len(), &self.links);
        let (origin, size) = (self.origin, self.size);
        let mut found = Vec::new();
        for i in 0..n {
            for j in i + 1..n {
                let pair = (links[i], links[j]);
                match self.known[self.slot(i, j)].clone() {
                    Some((h, how, s)) if h != [0.0, 0.0, 0.0] => {
                        let place = if h[2] == 0.0 {
                            let d = Vec2::new(h[0], h[1]);
                            Place::Infinity(d / d.hypot())
                        } else {
                            Place::At(Point::new(
                                origin.x + h[0] / h[2] * size,
                                origin.y + h[1] / h[2] * size,
                            ))
                        };
                        found.push(Centre {
                            links: pair,
                            place,
                            how,
                            sin_angle: s,
                        });
                    }
                    Some(_) => {}
                    None => undetermined.push(Undetermined {
                        links: pair,
                        why: Why::FewLines,
                    }),
                }
            }
        }
        found
    }
}

/// The name of a centre as the lecture writes it: P₁₃ is "P13", or
/// "P1,13" when a link id has more than one character.
pub fn name(m: &Mechanism, c: &Centre) -> (String, String) {
    let (a, b) = (m.link_id(c.links.0), m.link_id(c.links.1));
    let sub = if a.chars().count() == 1 && b.chars().count() == 1 {
        format!("{a}{b}")
    } else {
        format!("{a},{b}")
    };
    ("P".into(), sub)
}
