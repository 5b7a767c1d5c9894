//! The three-leash group (class III) by Assur's special point.

use super::builder::Builder;
use super::dyad::{At, Side};
use super::plan::{Mistake, PointId};
use super::record::{Act, Eqn, Name, Ray, Way};
use crate::accuracy::ACCURACY;
use crate::error::{Error, Result};
use crate::geom::{Line, LineCut, perp};
use crate::kinematics::positions::describe_input;
use crate::model::structure::{Joint, Triad};
use kurbo::Point;

/// A pair of leashes (i, j) and the third, k.
type Pair = (usize, usize, usize);

/// The pairs of leashes a special point can be taken on, and the third.
const PAIRS: [(usize, usize, usize); 3] = [(0, 1, 2), (0, 2, 1), (1, 2, 0)];

impl Builder<'_> {
    /// A three-leash group by Assur's special point: the axes of two
    /// leashes meet at S, taken on the base link; v_S (a_S) is reached from
    /// both leashes' outer joints along lines ⊥ their axes. The pair of
    /// leashes whose construction is best conditioned: each of the three
    /// pairs is drawn in turn and the one whose points come out with the
    /// smallest largest error radius is kept (the largest angle between
    /// the axes is not enough: a special point far out on the base carries
    /// large normal components ω²·l of the base).
    pub(super) fn triad(&mut self, t: &Triad) -> Result<()> {
        let saved = (
            (*self.plan).clone(),
            self.t.normal_of.clone(),
            self.rng.clone(),
        );
        let (start, mark, taken) = (self.plan.points.len(), self.t.acts.len(), self.taken);
        let judged = self.plan.judged.len();
        let mut best: Option<((f64, f64), Pair)> = None;
        let mut first_err = None;
        // The pair is the right construction's: a deliberate mistake is
        // made on it, not allowed to choose another (its decisions are
        // then the same lines in every build).
        let variant = self.variant;
        self.variant.mistake = None;
        self.variant.also = None;
        for pair in PAIRS {
            (*self.plan, self.t.normal_of, self.rng) = saved.clone();
            self.t.acts.truncate(mark);
            self.taken = taken;
            match self.triad_by(t, Some(pair)) {
                Ok(()) => {
                    let worst = self.plan.points[start..]
                        .iter()
                        .map(|p| p.err)
                        .fold(0.0, f64::max);
                    // A replay takes the pair on which the student drew
                    // their special point, where they drew one: the
                    // student may have taken any pair.
                    let fit = self.plan.judged[judged..]
                        .iter()
                        .find(|j| matches!(j.id, PointId::Special { .. }))
                        .map_or(0.0, |j| j.misfit().max(1.0));
                    // Where the student's points fit several pairs alike,
                    // the right plan's pair (its special point is the σ
                    // they measured).
                    let hint = self.t.given.triads.get(self.plan.triads.len());
                    let worst = if hint.is_some_and(|&h| h == pair) {
                        -1.0
                    } else {
                        worst
                    };
                    let score = (fit, worst);
                    if best.is_none_or(|b| score.0 < b.0.0 || (score.0 == b.0.0 && score.1 < b.0.1))
                    {
                        best = Some((score, pair));
                    }
                }
                Err(e) => {
                    first_err.get_or_insert(e);
                }
            }
        }
        (*self.plan, self.t.normal_of, self.rng) = saved;
        self.t.acts.truncate(mark);
        self.taken = taken;
        self.variant = variant;
        match best {
            Some((_, pair)) => {
                self.plan.triads.push(pair);
                self.triad_by(t, Some(pair))
            }
            // No pair constructs: the error of the best-angled one.
            None => self
                .triad_by(t, None)
                .and(Err(first_err.expect("three tries"))),
        }
    }

    /// The three-leash group by the special point of leashes (i, j), the
    /// third leash k found from it; `None`: the pair whose axes meet at the
    /// largest angle.
    fn triad_by(&mut self, t: &Triad, pair: Option<(usize, usize, usize)>) -> Result<()> {
        let m = self.m();
        let e: Vec<At> = (0..3)
            .map(|i| self.joint_on(t.ext[i].from, &t.ext[i]))
            .collect();
        let jp: Vec<usize> = t
            .int
            .iter()
            .map(|c| match c.joint {
                Joint::R(p) => p,
                Joint::P(_) => unreachable!(),
            })
            .collect();
        let jw: Vec<Point> = jp.iter().map(|&p| self.world(t.base, p)).collect();
        let jn: Vec<Name> = jp.iter().map(|&p| Name::Point(p)).collect();
        for (leash, ei) in t.leashes.iter().zip(&e) {
            self.register(*leash, ei.1, ei.0);
        }
        let axis = |i: usize| Line::new(e[i].1, jw[i] - e[i].1);
        let (i, j, k) = pair.unwrap_or_else(|| {
            *PAIRS
                .iter()
                .max_by(|a, b| {
                    axis(a.0)
                        .dir
                        .cross(axis(a.1).dir)
                        .abs()
                        .total_cmp(&axis(b.0).dir.cross(axis(b.1).dir).abs())
                })
                .unwrap()
        });
        let LineCut::Point { at: sw, .. } =
            crate::geom::intersect_lines(&axis(i), &axis(j), ACCURACY.min_line_sine)
        else {
            return Err(Error::singular(
                describe_input(m, &self.drives.coords()),
                "all three leashes of the class III group are parallel",
            ));
        };
        let group_size = t
            .leashes
            .iter()
            .chain([&t.base])
            .map(|&l| m.link_scale(l))
            .fold(0.0, f64::max);
        if (sw - jw[k]).hypot() <= ACCURACY.same_point * group_size {
            return Err(Error::singular(
                describe_input(m, &self.drives.coords()),
                "the three leashes' axes meet in one point: a dead point of the class III group",
            ));
        }
        let sname = Name::Special(t.base);
        self.step(|| {
            Act::Equation(Eqn::Special {
                base: t.base,
                leashes: [(e[i].2, jn[i]), (e[j].2, jn[j])],
            })
        });
        // The line for S from leash n: through e_n (+ normals) ⊥ E_n J_n.
        let line_for_s = |b: &mut Builder, n: usize| -> Ray {
            let axis = jw[n] - e[n].1;
            let u = if b.making(Mistake::TangentialParallel) {
                axis
            } else {
                perp(axis)
            };
            let seg = (e[n].2, jn[n]);
            if b.vel_kind() {
                return b.line(e[n].0, u, Way::Perp(seg));
            }
            let mut from = e[n].0;
            let leash = t.leashes[n];
            let (wl, wb) = (b.omega(leash), b.omega(t.base));
            let r1 = jw[n] - e[n].1;
            if wl != 0.0 && !b.forgets(Mistake::NormalForgotten, PointId::Normal { link: leash }) {
                let err = b.normal_err(leash, wl, r1.hypot());
                let (x, j) = (jn[n], e[n].2);
                let toward = b.normal_sense();
                from = b.normal(from, r1 * (toward * wl * wl), leash, (x, j), (j, x), err);
            }
            let r2 = sw - jw[n];
            let base = PointId::Normal { link: t.base };
            if wb != 0.0 && r2.hypot() > 0.0 && !b.forgets(Mistake::NormalForgotten, base) {
                let err = b.normal_err(t.base, wb, r2.hypot());
                let xj = (sname, jn[n]);
                let toward = b.normal_sense();
                from = b.normal(from, r2 * (toward * wb * wb), t.base, xj, xj, err);
            }
            b.line(from, u, Way::Perp(seg))
        };
        let la = line_for_s(self, i);
        let lb = line_for_s(self, j);
        let s_idx = self.intersect(la, lb, PointId::Special { base: t.base })?;
        self.register(t.base, sw, s_idx);
        // Third leash: J_k from S on the base and from E_k on the leash.
        let sides = [
            Side::Rigid {
                link: t.base,
                from: (s_idx, sw, sname),
            },
            Side::Rigid {
                link: t.leashes[k],
                from: e[k],
            },
        ];
        self.meet(PointId::Named(jp[k]), jw[k], sides, None, None)?;
        // The other joints by similarity on the base, then the leashes' rates.
        for n in [i, j] {
            let jn_idx = self.named(t.base, jp[n]);
            self.register(t.leashes[n], jw[n], jn_idx);
            let from = if self.vel_kind() || self.omega(t.leashes[n]) == 0.0 {
                e[n].0
            } else {
                self.t.normal_of[t.leashes[n]].unwrap_or(e[n].0)
            };
            self.measure_rate(t.leashes[n], from, jn_idx, (e[n].1, e[n].2), (jw[n], jn[n]));
        }
        Ok(())
    }
}
