//! Placing a point of a link from what the plan knows of the link: the
//! pole for the frame, the same plan point for a translating link, the
//! similar figure on two known points, or the relative vector of the
//! link's measured rates from one — whichever comes out best conditioned.

use super::builder::Builder;
use super::plan::{Known, Mistake, PlanPoint, PointId};
use super::record::{Act, By, Name, Product, Rate, Way, What};
use crate::accuracy::ACCURACY;
use crate::geom::perp;
use kurbo::{Point, Vec2};

/// The complex ratio ρ of the point at `local` on the pair at `la`, `lb`
/// (a + ρ·(b − a)), when the point is off their line: a figure on that
/// pair has a shape, and can be mirrored.
fn off_line_ratio(local: Vec2, la: Vec2, lb: Vec2) -> Option<Vec2> {
    let ab = lb - la;
    if ab.hypot2() == 0.0 {
        return None;
    }
    let r = (local - la).rotate_scale(Vec2::new(ab.x, -ab.y)) / ab.hypot2();
    (r.y.abs() > ACCURACY.collinear_ratio * r.hypot().max(1.0)).then_some(r)
}

fn off_line(local: Vec2, la: Vec2, lb: Vec2) -> bool {
    off_line_ratio(local, la, lb).is_some()
}

/// The first pair of the link's `known` points the point at `local` is
/// off the line of, with its ratio.
fn off_line_pair(local: Vec2, known: &[(Vec2, usize)]) -> Option<(usize, usize, Vec2)> {
    (0..known.len())
        .flat_map(|i| (i + 1..known.len()).map(move |j| (i, j)))
        .find_map(|(i, j)| off_line_ratio(local, known[i].0, known[j].0).map(|r| (i, j, r)))
}

/// The figure on plan points `a`, `b` at the complex ratio ρ (the new
/// point at a + ρ·(b − a)): its place, and its error radius drawn by
/// proportional division or by two arcs. The figure moves with its base
/// (|1 − ρ|·e_a + |ρ|·e_b: an extension grows it by its ratio); a division
/// adds δ and the point's offset from the line, which it does not draw;
/// two arcs add how far their crossing moves with each radius off by up to
/// δ ([`arcs_spread`]: the worst case of the construction itself, not its
/// first-order δ/sin(φ/2), which falls short where the arcs meet at a
/// glancing angle). `sine`: the sine of the angle of the figure's sides at
/// the new point, the angle the arcs meet at.
struct FigureOn {
    at: Vec2,
    divide: f64,
    arcs: f64,
    sine: f64,
}

fn figure_on((a, b): (&PlanPoint, &PlanPoint), ratio: Vec2, delta: f64) -> FigureOn {
    let moved = (Vec2::new(1.0, 0.0) - ratio).hypot() * a.err + ratio.hypot() * b.err;
    let divide = moved + delta + ratio.y.abs() * (b.at - a.at).hypot();
    let at = a.at + (b.at - a.at).rotate_scale(ratio);
    let (ca, cb) = (at - a.at, at - b.at);
    let sine = if ca.hypot() * cb.hypot() > 0.0 {
        (ca.cross(cb) / (ca.hypot() * cb.hypot())).abs()
    } else {
        1.0
    };
    let arcs = moved + arcs_spread(a.at, b.at, at, delta);
    FigureOn {
        at,
        divide,
        arcs,
        sine,
    }
}

/// How far two arcs drawn from `a` and `b` through `s` put their crossing
/// from `s` when each radius is off by up to `delta`: the largest move
/// over the radii's errors at the corners and the middles of the sides of
/// their square (where the crossing moves most: it moves monotonically
/// with each radius). Where the arcs so drawn would not meet, the student
/// marks the point between them, on the radical line (the chord's foot).
/// To first order this is δ/sin(φ/2), φ the angle the arcs meet at; near
/// tangency (a triangle with an angle of 160° and more at s) the
/// crossing runs along the arcs farther than that.
pub(super) fn arcs_spread(a: Vec2, b: Vec2, s: Vec2, delta: f64) -> f64 {
    let d = b - a;
    let dist = d.hypot();
    if dist == 0.0 {
        return delta;
    }
    let u = d / dist;
    let side = if d.cross(s - a) < 0.0 { -1.0 } else { 1.0 };
    let (r1, r2) = ((s - a).hypot(), (s - b).hypot());
    let mut worst: f64 = 0.0;
    for (e1, e2) in [
        (1.0, 1.0),
        (1.0, -1.0),
        (-1.0, 1.0),
        (-1.0, -1.0),
        (1.0, 0.0),
        (-1.0, 0.0),
        (0.0, 1.0),
        (0.0, -1.0),
    ] {
        let (ra, rb) = ((r1 + e1 * delta).max(0.0), (r2 + e2 * delta).max(0.0));
        let x = (dist * dist + ra * ra - rb * rb) / (2.0 * dist);
        let h = (ra * ra - x * x).max(0.0).sqrt();
        let p = a + u * x + perp(u) * (side * h);
        worst = worst.max((p - s).hypot());
    }
    worst
}

/// How a point of a link is placed ([`Builder::best_construction`]).
#[derive(Clone, Copy, Debug)]
enum Construction {
    /// The figure similar to the link's on known points `a`, `b` (indices
    /// in the list of the link's known points), the new point at
    /// a + ρ·(b − a) with the complex ratio ρ.
    Figure {
        a: usize,
        b: usize,
        ratio: Vec2,
        err: FigureErr,
    },
    /// From known point `a` by the relative vector of the link's rates.
    Relation { a: usize },
}

/// The way a similar figure is drawn, and the new point's error radius.
#[derive(Clone, Copy, Debug)]
enum FigureErr {
    /// Proportional division of the segment (the point on or a hair off
    /// the line of the two).
    Divide(f64),
    /// Two arcs meeting at an angle of sine `.1`.
    Arcs(f64, f64),
}

impl Builder<'_> {
    /// The named point `p` carried by `link` (registering it on every link
    /// carrying it that the plan knows).
    pub(super) fn named(&mut self, link: usize, p: usize) -> usize {
        let x = self.world(link, p);
        // (A point the plan knows on the link is found by `point_on`.)
        let i = self.point_on(link, x, PointId::Named(p), Name::Point(p));
        self.plan.of_point[p].get_or_insert(i);
        i
    }

    /// The coincident point of `link` at world `x` (named after point `p`
    /// with the link's number as subscript: b₃ is B as a point of link 3).
    pub(super) fn coincident(&mut self, link: usize, x: Point, p: usize) -> usize {
        self.point_on(
            link,
            x,
            PointId::Coincident { point: p, link },
            Name::On(p, link),
        )
    }

    /// The name of a known point of `link` (its local place and plan
    /// point): the mechanism's point there, else the plan point's figure
    /// (B3).
    fn known_name(&self, link: usize, (local, idx): (Vec2, usize)) -> Name {
        let m = self.m();
        m.links[link]
            .points
            .iter()
            .find(|&&p| {
                (m.local(link, p) - local).hypot() <= ACCURACY.same_point * m.link_scale(link)
            })
            .map_or(Name::Figure(idx), |&p| Name::Point(p))
    }

    /// The plan point `id` of the material point of `link` now at `x`,
    /// built from what the plan knows of that link: the pole for the
    /// frame, the same point for a translating link, the similarity
    /// theorem from two known points, or, from one known point, the
    /// relative vector of the link's measured rates. `figure` is the
    /// point's name on the mechanism.
    fn point_on(&mut self, link: usize, x: Point, id: PointId, figure: Name) -> usize {
        let local = self.local(link, x);
        let tol = self.same_point(link, x);
        if let Some(i) = self.plan.known_at(link, local, tol) {
            return i;
        }
        // The link's known points, in the builder's scratch list (no
        // allocation once it has grown).
        let mut known = std::mem::take(&mut self.t.scratch);
        known.clear();
        known.extend(
            self.plan
                .body
                .iter()
                .filter(|k| k.link == link)
                .map(|k| (k.local, k.point)),
        );
        let out = self.point_from((link, x, local), id, figure, &known);
        self.t.scratch = known;
        out
    }

    /// [`Builder::point_on`] from the link's known points `known`.
    ///
    /// The plan knows no point of `link` at `local` (`point_on` looked):
    /// the new point is added to the link's known points without looking
    /// again.
    fn point_from(
        &mut self,
        (link, x, local): (usize, Point, Vec2),
        id: PointId,
        figure: Name,
        known: &[(Vec2, usize)],
    ) -> usize {
        let m = self.m();
        let learn = |b: &mut Self, out: usize| {
            b.plan.body.push(Known {
                link,
                local,
                point: out,
            })
        };
        if link == m.frame() {
            let out = self.add_point(id, Vec2::ZERO, 0.0);
            self.step(|| Act::Coincide {
                out,
                with: 0,
                translates: None,
            });
            learn(self, out);
            return out;
        }
        if let (true, Some(&(_, with))) = (self.t.nr[link], known.first()) {
            // A translating link: all its points share one plan point.
            let (at, err) = (self.plan.points[with].at, self.plan.points[with].err);
            let out = self.add_point(id, at, err);
            self.step(|| Act::Coincide {
                out,
                with,
                translates: Some(link),
            });
            learn(self, out);
            return out;
        }
        assert!(
            !known.is_empty(),
            "a link is constructed only after one of its points"
        );
        if let PointId::Named(_) = id
            && let Some(out) = self.on_neighbour(link, x, id, figure)
        {
            learn(self, out);
            return out;
        }
        if let PointId::Named(_) = id
            && let Some(out) = self.at_neighbour(local, id, known)
        {
            learn(self, out);
            return out;
        }
        let out = match self.best_construction(link, local, x, known) {
            Construction::Figure { a, b, ratio, err } => {
                let ((la, pa), (lb, pb)) = (known[a], known[b]);
                let mut ratio = ratio;
                // One decision per point that has a shape on some pair.
                let shaped = off_line_pair(local, known).is_some();
                let mirrored = shaped && self.making(Mistake::MirroredFigure);
                let ((la, pa), (lb, pb)) = match off_line_pair(local, known) {
                    // Mirrored, the figure is drawn on a pair the point is
                    // off the line of (on its own pair it would not change).
                    Some((i, j, r)) if mirrored && !off_line(local, known[a].0, known[b].0) => {
                        ratio = r;
                        (known[i], known[j])
                    }
                    _ => ((la, pa), (lb, pb)),
                };
                if mirrored {
                    ratio.y = -ratio.y;
                }
                let (a_at, b_at) = (self.plan.points[pa].at, self.plan.points[pb].at);
                let at = a_at + (b_at - a_at).rotate_scale(ratio) + self.pencil();
                // The names only a narrated build records.
                let fig = self.record.then(|| {
                    [
                        self.known_name(link, (la, pa)),
                        self.known_name(link, (lb, pb)),
                        figure,
                    ]
                });
                let (e, by) = match err {
                    FigureErr::Divide(e) => (e, By::Divide { ratio: ratio.x }),
                    FigureErr::Arcs(e, s) => {
                        if s < 1.0 {
                            self.plan.worst_sin = self.plan.worst_sin.min(s.max(0.0));
                        }
                        (e, By::Similar { link })
                    }
                };
                let out = self.add_point(id, at, e);
                if self.plan.judged.last().is_some_and(|j| j.point == out) {
                    self.other_routes(link, (x, local), known, mirrored);
                }
                self.step(|| Act::Figure {
                    a: pa,
                    b: pb,
                    out,
                    figure: fig.expect("named when recorded"),
                    by,
                });
                out
            }
            Construction::Relation { a } => self.by_rates(link, x, id, figure, known[a]),
        };
        learn(self, out);
        out
    }

    /// A replay: the same point by the figure on any other pair of the
    /// link's known points is as right — the student's own points, drawn
    /// right or carried forward from a mistake — and so is the relative
    /// vector of the link's rates from one of them (in the right
    /// construction: in a mistaken one it would be the right place again);
    /// but a rate measured off a point the student drew wrong is no excuse
    /// (its sense read off a relative segment drawn along the link allows
    /// the mirrored figure too): the relative vector only where the rate
    /// and its start stand on points drawn right. Each is read off as the
    /// point itself is (to δ, and typed to its digits).
    fn other_routes(
        &mut self,
        link: usize,
        (x, local): (Point, Vec2),
        known: &[(Vec2, usize)],
        mirrored: bool,
    ) {
        let known_right: Vec<(Vec2, usize)> = known
            .iter()
            .copied()
            .filter(|k| !self.drawn_wrong(k.1))
            .collect();
        let mut others = self.figures(local, known, mirrored);
        if self.variant.mistake.is_none() && self.rate_stands_right(link) {
            others.extend(self.relations(link, x, &known_right));
        }
        let j = self.plan.judged.last_mut().expect("just judged");
        j.others = others
            .into_iter()
            .map(|(p, t)| (p, t + j.rounding))
            .collect();
    }

    /// In a replay, is plan point `i` one the student drew off its step's
    /// tolerance?
    fn drawn_wrong(&self, i: usize) -> bool {
        self.plan
            .judged
            .iter()
            .any(|j| j.point == i && j.misfit() > 1.0)
    }

    /// Does the rate of `link` this plan measured stand on points drawn
    /// right?
    fn rate_stands_right(&self, link: usize) -> bool {
        self.plan
            .measured
            .iter()
            .filter(|q| q.of == super::plan::Quantity::Rate(link))
            .all(|q| !self.drawn_wrong(q.from) && !self.drawn_wrong(q.to))
    }

    /// The places of the material point of `link` at `local` by the figure
    /// similar to the link's on every pair of its `known` points
    /// (`mirrored`: each figure mirrored), each with its tolerance: the
    /// error radius as [`Builder::best_construction`] reckons it, plus δ
    /// for reading the point.
    fn figures(&self, local: Vec2, known: &[(Vec2, usize)], mirrored: bool) -> Vec<(Vec2, f64)> {
        let (delta, pts) = (self.plan.delta, &self.plan.points);
        let mut out = Vec::new();
        for a in 0..known.len() {
            for b in a + 1..known.len() {
                let ((la, pa), (lb, pb)) = (known[a], known[b]);
                let ab = lb - la;
                if ab.hypot2() == 0.0 {
                    continue;
                }
                let mut ratio = (local - la).rotate_scale(Vec2::new(ab.x, -ab.y)) / ab.hypot2();
                if mirrored {
                    ratio.y = -ratio.y;
                }
                // (A mirror image keeps every error radius.)
                let f = figure_on((&pts[pa], &pts[pb]), ratio, delta);
                out.push((f.at, f.divide.min(f.arcs) + delta));
            }
        }
        out
    }

    /// The places of the point of `link` at world `x` by the relative
    /// vector of the link's measured rates from each of its `known`
    /// points (ω×AX; −ω²·AX + ε×AX), each with its tolerance: the error
    /// radius as [`Builder::best_construction`] reckons it, plus δ for
    /// reading the point. None before the plan has measured the rates.
    ///
    /// Where the plan does not show the rate's sense (its relative segment
    /// within its error of the link's line: a link that hardly turns, as
    /// near an extreme position), the student may read it either way: the
    /// rate is then anywhere within ±(|rate| + its error), and the route
    /// is the one of no rate (the known point, and the normal ω²·AX on an
    /// acceleration plan) with the whole |rate|·AX added to its tolerance.
    fn relations(&self, link: usize, x: Point, known: &[(Vec2, usize)]) -> Vec<(Vec2, f64)> {
        let Some((rate, rate_err)) = self.plan.rates[link] else {
            return Vec::new();
        };
        let (rate, rate_err) = if self.plan.rate_sense[link] {
            (rate, rate_err)
        } else {
            (0.0, rate_err + rate.abs())
        };
        let (delta, mu) = (self.plan.delta, self.plan.mu);
        let w = self.omega(link);
        known
            .iter()
            .map(|&(la, pa)| {
                let from = &self.plan.points[pa];
                let r = x - self.c.pose(link).apply(la);
                let v = if self.vel_kind() {
                    perp(r) * rate
                } else {
                    perp(r) * rate - r * (w * w)
                };
                let err = self.relation_err(link, from.err, r.hypot(), rate_err);
                (from.at + v / mu, err + delta)
            })
            .collect()
    }

    /// The error radius of a point of `link` laid off by the relative
    /// vector of its rates from a known point of error `from_err`, `r`
    /// away: δ per vector laid off (the normal one too, with the error of
    /// ω² on an acceleration plan) and the rate's error times the distance.
    fn relation_err(&self, link: usize, from_err: f64, r: f64, rate_err: f64) -> f64 {
        let (delta, mu) = (self.plan.delta, self.plan.mu);
        let normal = match self.omega(link) {
            w if !self.vel_kind() && w != 0.0 => delta + self.normal_err(link, w, r) / mu,
            _ => 0.0,
        };
        from_err + normal + delta + rate_err * r / mu
    }

    /// The mistake of placing a named point of `link` by the figure of a
    /// neighbouring link (the first rotating link sharing a joint with it
    /// whose figure the plan knows by two points), where it is made: the
    /// plan point, else `None` (no neighbour, or the decision taken right).
    fn on_neighbour(&mut self, link: usize, x: Point, id: PointId, figure: Name) -> Option<usize> {
        if self.variant.mistake != Some(Mistake::NeighbourLink)
            && self.variant.also != Some(Mistake::NeighbourLink)
        {
            return None;
        }
        let m = self.m();
        let shares = |l: usize| {
            m.links[l]
                .points
                .iter()
                .any(|p| m.links[link].points.contains(p))
        };
        let (nb, (la, pa), (lb, pb)) = (0..m.links.len())
            .filter(|&l| l != link && l != m.frame() && !self.t.nr[l] && shares(l))
            .find_map(|l| {
                let mut on = self.plan.body.iter().filter(|k| k.link == l);
                let (a, b) = (on.next()?, on.next()?);
                Some((l, (a.local, a.point), (b.local, b.point)))
            })?;
        if !self.making(Mistake::NeighbourLink) {
            return None;
        }
        let ab = lb - la;
        let ratio = (self.local(nb, x) - la).rotate_scale(Vec2::new(ab.x, -ab.y)) / ab.hypot2();
        let (a_at, b_at) = (self.plan.points[pa].at, self.plan.points[pb].at);
        let at = a_at + (b_at - a_at).rotate_scale(ratio);
        // The figure moves with its base (an extension grows its error by
        // its ratio), plus the pencil's δ.
        let (ea, eb) = (self.plan.points[pa].err, self.plan.points[pb].err);
        let err = (Vec2::new(1.0, 0.0) - ratio).hypot() * ea + ratio.hypot() * eb + self.plan.delta;
        let out = self.add_point(id, at, err);
        let fig = self.record.then(|| {
            [
                self.known_name(nb, (la, pa)),
                self.known_name(nb, (lb, pb)),
                figure,
            ]
        });
        self.step(|| Act::Figure {
            a: pa,
            b: pb,
            out,
            figure: fig.expect("named when recorded"),
            by: By::Similar { link: nb },
        });
        Some(out)
    }

    /// The mistake of taking a named point at the plan point of one of
    /// its link's known points (s₂ drawn at b), where it is made: the plan
    /// point, else `None`.
    fn at_neighbour(&mut self, local: Vec2, id: PointId, known: &[(Vec2, usize)]) -> Option<usize> {
        if self.variant.mistake != Some(Mistake::PointAtNeighbour)
            && self.variant.also != Some(Mistake::PointAtNeighbour)
        {
            return None;
        }
        // One decision per known point of the link, the nearest first
        // (s₂ put at b or at a).
        let mut near: Vec<(f64, usize)> = known
            .iter()
            .filter(|k| k.1 != 0)
            .map(|k| ((k.0 - local).hypot2(), k.1))
            .collect();
        near.sort_by(|a, b| a.0.total_cmp(&b.0));
        let with = near
            .into_iter()
            .map(|n| n.1)
            .find(|_| self.making(Mistake::PointAtNeighbour))?;
        let (at, err) = (self.plan.points[with].at, self.plan.points[with].err);
        let out = self.add_point(id, at, err + self.plan.delta);
        self.step(|| Act::Coincide {
            out,
            with,
            translates: None,
        });
        Some(out)
    }

    /// From one known point A of `link` (local place, plan point) and the
    /// link's rates: v_X = v_A + ω×AX, a_X = a_A + ε×AX − ω²·AX.
    fn by_rates(
        &mut self,
        link: usize,
        x: Point,
        id: PointId,
        figure: Name,
        (la, pa): (Vec2, usize),
    ) -> usize {
        let r = x - self.c.pose(link).apply(la);
        // The known point's name only a narrated build records.
        let an = if self.record {
            self.known_name(link, (la, pa))
        } else {
            Name::Figure(pa)
        };
        let w = self.omega(link);
        let seg = (an, figure);
        let (rate, rate_err) = self.plan.rates[link].unwrap_or((0.0, 0.0));
        let mut from = pa;
        let rate_sym = if self.vel_kind() {
            Rate::Omega(link)
        } else {
            if w != 0.0 && !self.forgets(Mistake::NormalForgotten, PointId::Normal { link }) {
                let normal = What::Product(Product::squared(Rate::Omega(link), seg));
                let err = self.normal_err(link, w, r.hypot());
                let n = PointId::Normal { link };
                from = self.lay_off(pa, -r * (w * w), normal, Way::Toward((figure, an)), n, err);
                self.note_normal(link, from);
            }
            Rate::Epsilon(link)
        };
        // ω×AX on the velocity plan, ε×AX on the acceleration plan: the
        // rate this plan measured.
        let what = What::Product(Product::new(rate_sym, seg));
        let way = Way::PerpSense(seg, rate_sym);
        self.lay_off(from, perp(r) * rate, what, way, id, rate_err * r.hypot())
    }

    /// The best-conditioned way a careful draftsman places the material
    /// point of `link` at `local` (world `x`) from what the plan knows of
    /// the link (`known`: local place and plan point): the similar figure
    /// on any pair of its known points — by proportional division when the
    /// point is (nearly) on their line, by two arcs otherwise — or, from
    /// one known point, the relative vector of the link's measured rates.
    /// Each way's first-order error radius: the similar figure moves with
    /// its base as a + ρ·(b − a) does (|1 − ρ|·e_a + |ρ|·e_b: an extension
    /// beyond b grows it by its ratio), plus the pencil's δ for a division
    /// and the point's offset from the line the division ignores, or how
    /// far the arcs' crossing moves with their radii off by δ
    /// ([`arcs_spread`]); the relative vector adds δ per
    /// vector laid off and the rate's error times the distance. The least
    /// wins, so a point a hair off a rod is divided, not found by two
    /// nearly tangent arcs.
    fn best_construction(
        &self,
        link: usize,
        local: Vec2,
        x: Point,
        known: &[(Vec2, usize)],
    ) -> Construction {
        let delta = self.plan.delta;
        let pts = &self.plan.points;
        let mut best: Option<(f64, Construction)> = None;
        let consider = |e: f64, c: Construction, best: &mut Option<(f64, Construction)>| {
            if best.as_ref().is_none_or(|b| e < b.0) {
                *best = Some((e, c));
            }
        };
        for a in 0..known.len() {
            for b in a + 1..known.len() {
                let ((la, pa), (lb, pb)) = (known[a], known[b]);
                let ab = lb - la;
                if ab.hypot2() == 0.0 {
                    continue;
                }
                let ratio = (local - la).rotate_scale(Vec2::new(ab.x, -ab.y)) / ab.hypot2();
                let f = figure_on((&pts[pa], &pts[pb]), ratio, delta);
                let (divide, arcs, s) = (f.divide, f.arcs, f.sine);
                let by_division = Construction::Figure {
                    a,
                    b,
                    ratio,
                    err: FigureErr::Divide(divide),
                };
                if ratio.y.abs() <= ACCURACY.collinear_ratio * ratio.hypot().max(1.0) {
                    consider(divide, by_division, &mut best);
                } else {
                    // A triangle is drawn by arcs (the lecture's way); a
                    // point a hair off the line by division, where the
                    // arcs would meet at too small an angle.
                    if ACCURACY.division_over_arcs * divide < arcs {
                        consider(divide, by_division, &mut best);
                    } else {
                        let by_arcs = Construction::Figure {
                            a,
                            b,
                            ratio,
                            err: FigureErr::Arcs(arcs, s),
                        };
                        consider(arcs, by_arcs, &mut best);
                    }
                }
            }
        }
        // A replay draws a point of a link the way the student did, by
        // its figure where the link has two known points.
        let replay = !(self.t.given.points.is_empty() && self.t.given.circles.is_empty()) && best.is_some();
        if let Some((_, rate_err)) = self.plan.rates[link].filter(|_| !replay) {
            for (a, &(la, pa)) in known.iter().enumerate() {
                let r = (x - self.c.pose(link).apply(la)).hypot();
                let e = self.relation_err(link, pts[pa].err, r, rate_err);
                // The similar figure is the lecture's way: the relative
                // vector takes over only where it is clearly better.
                consider(
                    e * ACCURACY.relation_over_figure,
                    Construction::Relation { a },
                    &mut best,
                );
            }
        }
        best.map(|b| b.1).unwrap_or(Construction::Relation { a: 0 })
    }
}
