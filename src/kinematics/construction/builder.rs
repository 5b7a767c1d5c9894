//! The builder's core: the drafting operations (lay off a vector, draw a
//! line, intersect two lines, measure a segment), the points the plan
//! knows on each link, the deliberate mistakes and the pencil, and the
//! order of the construction (the pole, the input link, the groups in the
//! order of attachment, the measured values).

use super::plan::{
    Drawing, Judged, Known, Measured, Mistake, Plan, PlanKind, PlanPoint, PointId, Quantity, Setup,
    Variant, non_rotating,
};
use super::record::{Act, Name, Product, Rate, Ray, Reading, Relation, Seg, Way, What, key_label};
use crate::accuracy::ACCURACY;
use crate::error::{Error, Result};
use crate::geom::{Line, LineCut, perp};
use crate::kinematics::analytic::Drives;
use crate::kinematics::positions::{Configuration, describe_input};
use crate::model::mechanism::Mechanism;
use crate::model::structure::{AssurGroup, InputRole, Stage};
use kurbo::{Point, Vec2};
use rand::rngs::StdRng;

pub(super) struct Builder<'a> {
    pub variant: Variant,
    pub rng: Option<StdRng>,
    pub st: &'a Setup<'a>,
    pub c: &'a Configuration,
    pub plan: &'a mut Plan,
    /// Keep the record (a build that is narrated).
    pub record: bool,
    /// Steps taken so far, recorded or not.
    pub taken: usize,
    /// The velocity plan, when building the acceleration plan.
    pub vel: Option<&'a Plan>,
    /// Every input's coordinate and rates.
    pub drives: Drives,
    /// The buffers: the record, the non-rotating links, the reported
    /// points' carriers, the normal points, a scratch list (borrowed: a
    /// sweep's builders share them without moving them).
    pub t: &'a mut Tools,
}

/// A builder's buffers, handed from one construction to the next of a
/// sweep (`Kernel`): no allocation per position once they have grown.
pub(super) struct Tools {
    /// The construction's record, step by step, in ids (kept only when
    /// `record`).
    pub acts: Vec<Act>,
    pub nr: Vec<bool>,
    /// Of every point of the mechanism: reported (`Setup::points`), on
    /// which link ([`Tools::carrier`]).
    pub reported_on: Vec<Option<usize>>,
    /// The first normal-component point laid off for each link (n₂ …).
    pub normal_of: Vec<Option<usize>>,
    /// A scratch list of a link's known points (local place, plan point).
    pub scratch: Vec<(Vec2, usize)>,
    /// A replay's student drawing; empty in every other build.
    pub given: Drawing,
}

impl Tools {
    pub fn new(st: &Setup) -> Tools {
        let m = st.m;
        let mut reported_on = vec![None; m.scene.points.len()];
        for &p in st.points {
            reported_on[p] = Some(Tools::carrier(st, p));
        }
        Tools {
            acts: Vec::new(),
            nr: non_rotating(m),
            reported_on,
            normal_of: vec![None; m.links.len()],
            scratch: Vec::new(),
            given: Drawing::default(),
        }
    }
}

impl<'a> Builder<'a> {
    /// A builder for `plan` (emptied by [`Builder::again`] before a run)
    /// with the buffers `t` (of the same mechanism).
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        st: &'a Setup<'a>,
        c: &'a Configuration,
        drives: Drives,
        plan: &'a mut Plan,
        vel: Option<&'a Plan>,
        variant: Variant,
        rng: Option<StdRng>,
        t: &'a mut Tools,
    ) -> Builder<'a> {
        Builder {
            variant,
            rng,
            st,
            c,
            plan,
            record: false,
            taken: 0,
            vel,
            drives,
            t,
        }
    }
    /// The same builder for a new construction at scale `mu`, its buffers
    /// emptied and kept.
    pub fn again(&mut self, mu: f64, rng: Option<StdRng>) {
        self.plan.clear(mu);
        self.t.acts.clear();
        self.taken = 0;
        self.t.normal_of.fill(None);
        self.rng = rng;
    }
    #[inline]
    pub fn m(&self) -> &'a Mechanism {
        self.st.m
    }
    #[inline]
    pub fn vel_kind(&self) -> bool {
        self.plan.kind == PlanKind::Velocity
    }
    /// Take a step: counted always, recorded for the naming pass only
    /// when the build narrates (a probe or a numbers-only build would only
    /// pay for the record).
    /// (The act is made only when it is recorded.)
    #[inline]
    pub fn step(&mut self, act: impl FnOnce() -> Act) {
        self.taken += 1;
        if self.record {
            self.t.acts.push(act());
        }
    }
    #[inline]
    pub fn world(&self, link: usize, p: usize) -> Point {
        self.c.point(self.m(), link, p)
    }
    #[inline]
    pub fn local(&self, link: usize, x: Point) -> Vec2 {
        self.c.pose(link).local(x)
    }
    /// Remember the first normal-component point of `link`.
    pub fn note_normal(&mut self, link: usize, idx: usize) {
        self.t.normal_of[link].get_or_insert(idx);
    }
    /// ω of a link from the velocity plan (for the acceleration plan).
    #[inline]
    pub fn omega(&self, l: usize) -> f64 {
        match self.vel {
            Some(v) => v.rates[l].map(|r| r.0).unwrap_or(0.0),
            None => self.plan.rates[l].map(|r| r.0).unwrap_or(0.0),
        }
    }
    #[inline]
    pub fn omega_err(&self, l: usize) -> f64 {
        self.vel
            .and_then(|v| v.rates[l].map(|r| r.1))
            .unwrap_or(0.0)
    }
    /// The error of the value of a normal component ω²·r of `link`
    /// computed with `w` (`r` its length, m), ω known to ±Δω: |(ω ± Δω)²
    /// − ω²|·r ≤
    /// (2|ω| + Δω)·Δω·r — the worst case, not only its first order
    /// 2|ω|·Δω·r (a stated ω is anywhere within half a unit of its last
    /// digit of what was read).
    #[inline]
    pub fn normal_err(&self, link: usize, w: f64, r: f64) -> f64 {
        let dw = self.omega_err(link);
        (2.0 * w.abs() + dw) * dw * r
    }

    /// The place of the next plan point of `id` among those of its id
    /// (points a mistake left out counted too).
    fn nth(&self, id: PointId) -> usize {
        self.plan.points.iter().filter(|p| p.id == id).count()
            + self.plan.skipped.iter().filter(|&&s| s == id).count()
    }

    /// Is mistake `m` made at this decision, leaving out the plan point
    /// `id` it would have drawn? (Recorded as left out.)
    pub fn forgets(&mut self, m: Mistake, id: PointId) -> bool {
        let made = self.making(m);
        if made {
            self.plan.skipped.push(id);
        }
        made
    }

    /// In a replay, where the student drew the next plan point of `id`.
    #[inline]
    pub fn given(&self, id: PointId) -> Option<(Vec2, f64)> {
        if self.t.given.points.is_empty() && self.t.given.circles.is_empty() {
            return None;
        }
        let nth = self.nth(id);
        self.t
            .given
            .points
            .iter()
            .find(|g| g.0 == id && g.1 == nth)
            .map(|g| (g.2, g.3))
    }

    /// In a replay, the next plan point of `id` where the student's
    /// circle about the pole (their length without its direction) is
    /// nearest the construction's place `at`, and its rounding.
    fn on_circle(&self, id: PointId, at: Vec2) -> Option<(Vec2, f64)> {
        if self.t.given.circles.is_empty() {
            return None;
        }
        let nth = self.nth(id);
        let &(_, _, r, rounding) = self
            .t
            .given
            .circles
            .iter()
            .find(|c| c.0 == id && c.1 == nth)?;
        let d = at.hypot();
        let unit = if d > 0.0 { at / d } else { Vec2::new(1.0, 0.0) };
        Some((unit * r, rounding))
    }

    /// A new plan point `id` where the construction puts it, with its
    /// error radius; in a replay, a point the student drew is judged
    /// against that place and then taken where the student drew it, read
    /// to δ: every later step starts from the student's own points.
    #[inline]
    pub fn add_point(&mut self, id: PointId, at: Vec2, err: f64) -> usize {
        let circle = self.on_circle(id, at);
        let (at, err) = match self.given(id).or(circle) {
            Some((given, rounding)) => {
                let nth = self.nth(id);
                // Read to δ, and typed to its digits.
                let read = self.plan.delta + rounding;
                self.plan.judged.push(Judged {
                    id,
                    nth,
                    point: self.plan.points.len(),
                    predicted: at,
                    tol: err + read,
                    given,
                    rounding,
                    on_circle: circle.is_some(),
                    others: Vec::new(),
                    lines: Vec::new(),
                    step: self.taken,
                });
                // A point known by its length alone is known along its
                // circle only as well as the step places it.
                let known = if circle.is_some() { err + read } else { read };
                (given, known)
            }
            None => (at, err),
        };
        self.plan.points.push(PlanPoint {
            id,
            key: String::new(),
            label: (String::new(), String::new()),
            at,
            err,
        });
        self.plan.points.len() - 1
    }

    /// How close two places of one link are the same material point: a
    /// billionth of the link's own size, above the rounding of the
    /// coordinates (never a fraction of the whole sketch).
    #[inline]
    pub fn same_point(&self, link: usize, x: Point) -> f64 {
        ACCURACY.same_point * self.m().link_scale(link)
            + ACCURACY.tangency_roundings * f64::EPSILON * x.to_vec2().hypot()
    }

    pub fn register(&mut self, link: usize, x: Point, idx: usize) {
        let local = self.local(link, x);
        let tol = self.same_point(link, x);
        if self.plan.known_at(link, local, tol).is_none() {
            self.plan.body.push(Known {
                link,
                local,
                point: idx,
            });
        }
    }

    /// Lay off the real vector `v` from plan point `from`: the new plan
    /// point `id`.
    pub fn lay_off(
        &mut self,
        from: usize,
        v: Vec2,
        what: What,
        way: Way,
        id: PointId,
        value_err: f64,
    ) -> usize {
        let v = if self.making(Mistake::Slip) {
            v * self.variant.factor
        } else {
            v
        };
        let at = self.plan.points[from].at + v / self.plan.mu + self.pencil();
        let err = self.plan.points[from].err + self.plan.delta + value_err / self.plan.mu;
        let to = self.add_point(id, at, err);
        self.step(|| Act::LayOff {
            from,
            to,
            what,
            value: v.hypot(),
            way,
        });
        to
    }

    /// Lay off `v`, the normal component of `link` at X about J
    /// (`xj`) over its segment `seg`, the error of its magnitude `err`:
    /// the link's point n.
    pub fn normal(
        &mut self,
        from: usize,
        v: Vec2,
        link: usize,
        xj: Seg,
        seg: Seg,
        err: f64,
    ) -> usize {
        let (x, j) = xj;
        let is = Product::squared(Rate::Omega(link), seg);
        let what = What::Component { sup: 'n', x, j, is };
        let to = self.lay_off(
            from,
            v,
            what,
            Way::Toward(xj),
            PointId::Normal { link },
            err,
        );
        self.note_normal(link, to);
        to
    }

    pub fn line(&mut self, through: usize, unit: Vec2, way: Way) -> Ray {
        let shift = self.pencil().x;
        Ray {
            through,
            unit: unit.normalize(),
            way,
            err: self.plan.points[through].err + self.plan.delta,
            shift,
        }
    }

    /// The pencil's error of one operation: a random displacement within δ
    /// when emulating hand drafting, else zero.
    #[inline]
    pub fn pencil(&mut self) -> Vec2 {
        use rand::Rng;
        let delta = self.plan.delta;
        match &mut self.rng {
            None => Vec2::ZERO,
            Some(r) => loop {
                let v = Vec2::new(r.random_range(-1.0..=1.0), r.random_range(-1.0..=1.0));
                if v.hypot2() <= 1.0 {
                    break v * delta;
                }
            },
        }
    }

    /// Is this mistake being made at this decision? Counts the decisions
    /// of its kind and records the first step where it is made.
    #[inline]
    pub fn making(&mut self, m: Mistake) -> bool {
        if self.variant.on.is_some_and(|k| k != self.plan.kind) {
            return false;
        }
        if self.variant.also == Some(m) && self.variant.mistake != Some(m) {
            // A second mistake combined with the first, made everywhere.
            self.plan.mistake_step.get_or_insert(self.taken);
            return true;
        }
        if self.variant.mistake != Some(m) {
            return false;
        }
        let n = self.plan.decisions;
        self.plan.decisions += 1;
        let among = self.variant.among;
        if among != 0 {
            if n >= 64 || among & (1 << n) == 0 {
                return false;
            }
        } else if self.variant.at.is_some_and(|at| at != n) {
            return false;
        }
        self.plan.mistake_step.get_or_insert(self.taken);
        true
    }

    /// The sense of a normal component ω²·r laid off along r = X − J:
    /// −1 (toward the centre J), or +1 where the mistake of laying it off
    /// from the centre is being made at this decision.
    pub fn normal_sense(&mut self) -> f64 {
        if self.making(Mistake::NormalFromCentre) {
            1.0
        } else {
            -1.0
        }
    }

    /// The new plan point `id` where lines `a` and `b` meet.
    pub fn intersect(&mut self, a: Ray, b: Ray, id: PointId) -> Result<usize> {
        let drawn = |r: &Ray| Line {
            point: self.plan.points[r.through].at.to_point() + perp(r.unit) * r.shift,
            dir: r.unit,
        };
        let LineCut::Point { at, sin_angle } =
            crate::geom::intersect_lines(&drawn(&a), &drawn(&b), ACCURACY.min_line_sine)
        else {
            let (_, (letters, sub)) = key_label(id, self.plan.kind, self.m());
            return Err(Error::singular(
                describe_input(self.m(), &self.drives.coords()),
                format!(
                    "on the {} plan the lines for {letters}{sub} are parallel: the position is a dead point of the group",
                    self.kind_word(),
                ),
            ));
        };
        // The worst case of two lines each shifted by up to its error: the
        // corner of their parallelogram, √(e1² + e2² + 2·e1·e2·|cos θ|) /
        // sin θ (the sides' first-order √(e1² + e2²)/sin θ falls short
        // where the lines meet at a glancing angle: along them the point
        // moves by up to (e1 + e2·|cos θ|)/sin θ).
        let cos = (1.0 - sin_angle * sin_angle).max(0.0).sqrt();
        let err = (a.err * a.err + b.err * b.err + 2.0 * a.err * b.err * cos).sqrt() / sin_angle;
        let delta = self.plan.delta;
        let lines = [&a, &b].map(|r| {
            let l = drawn(r);
            (l.point.to_vec2(), l.dir, r.err + delta)
        });
        let out = self.add_point(id, at.to_vec2(), err);
        if let Some(j) = self.plan.judged.last_mut().filter(|j| j.point == out) {
            // A replay judges the student's point by the two lines: each
            // line's own error and the point read (to δ, typed to its
            // digits) off it.
            j.lines = lines.map(|(p, u, t)| (p, u, t + j.rounding)).to_vec();
            // A point known by its length alone lies where its circle
            // crosses the two lines' bands: along the circle, as far as
            // the narrower crossing lets it (a band crossed squarely pins
            // it), never farther than the meeting point's own error.
            if j.on_circle && j.given.hypot() > 0.0 {
                let t = perp(j.given / j.given.hypot());
                let along = j
                    .lines
                    .iter()
                    .map(|&(_, u, tol)| tol / t.cross(u).abs().max(1e-300))
                    .fold(f64::INFINITY, f64::min);
                let point = &mut self.plan.points[out];
                point.err = point.err.min(along);
            }
        }
        self.plan.worst_sin = self.plan.worst_sin.min(sin_angle);
        self.step(|| Act::Intersect {
            lines: [a, b],
            out,
            sin_angle,
        });
        Ok(out)
    }

    fn kind_word(&self) -> &'static str {
        if self.vel_kind() {
            "velocity"
        } else {
            "acceleration"
        }
    }

    /// Measure the relative segment from `from` to `to` (the tangential
    /// part for accelerations) of `link` between J and X: its rate.
    pub fn measure_rate(
        &mut self,
        link: usize,
        from: usize,
        to: usize,
        (jw, j): (Point, Name),
        (x, xn): (Point, Name),
    ) {
        let mu = self.plan.mu;
        let rel = (self.plan.points[to].at - self.plan.points[from].at) * mu;
        let r = x - jw;
        let len = r.hypot();
        let sign = r.cross(rel).signum();
        let value = sign * rel.hypot() / len;
        let err_mm = self.plan.points[to].err + self.plan.points[from].err + self.plan.delta;
        let err = err_mm * mu / len;
        // The sense is read from the side of the link's line the relative
        // segment's end lies on: within the drafting error of that line it
        // cannot be read (a plan drawn wrong has it there, and so has one
        // of a link that hardly turns), and the rate is known only in
        // magnitude.
        let sense_known = !(len > 0.0 && (r.cross(rel) / len).abs() / mu <= err_mm);
        self.plan.rate_sense[link] = sense_known;
        self.plan.rates[link] = Some((value, err));
        self.plan.rate_len[link] = len;
        self.plan.measured.push(Measured {
            of: Quantity::Rate(link),
            quantity: String::new(),
            from,
            to,
            mm: rel.hypot() / mu,
            value,
            bound: err,
        });
        self.step(|| Act::Measure {
            from,
            to,
            value: rel.hypot(),
            reading: Reading::Relative {
                link,
                j,
                x: xn,
                length: len,
                rate: value,
            },
        });
    }

    /// One vector equation of a group: X from a known point `base` through
    /// a rigid link or a slide, rotating or not.
    pub fn relation(&self, x: Name, base: Name, rigid: bool, link: usize) -> Relation {
        Relation {
            x,
            base,
            rigid,
            rotating: !self.t.nr[link],
            via: None,
        }
    }

    /// Links in a prismatic pair: `link` turns with `from`.
    pub fn same_rate(&mut self, link: usize, from: usize) {
        self.plan.rates[link] = self.plan.rates[from];
        self.plan.rate_sense[link] = self.plan.rate_sense[from];
        self.step(|| Act::Same {
            link,
            from_link: from,
        });
    }

    pub fn run(&mut self) -> Result<()> {
        let m = self.m();
        let frame = m.frame();
        // The pole and the fixed points.
        self.add_point(PointId::Pole, Vec2::ZERO, 0.0);
        self.step(|| Act::Pole);
        for &p in &m.links[frame].points {
            let x = self.world(frame, p);
            self.register(frame, x, 0);
            if self.t.reported_on[p].is_some() {
                self.plan.of_point[p] = Some(0);
            }
        }
        self.plan.rates[frame] = Some((0.0, 0.0));
        for &stage in &self.st.s.stages {
            let gi = match stage {
                Stage::Input(i) => {
                    let d = self.drives[i];
                    match self.st.s.roles[i] {
                        InputRole::Frame => self.input(i, (d.rate, d.rate2))?,
                        InputRole::Chained { known, pair } => {
                            self.chained(pair, known, (d.rate, d.rate2))
                        }
                        InputRole::InGroup { .. } => {}
                    }
                    continue;
                }
                Stage::Group(gi) => gi,
            };
            if !self.st.need[gi] {
                continue;
            }
            let g = &self.st.s.groups[gi];
            match g {
                AssurGroup::Dyad(d) => self.dyad(d)?,
                AssurGroup::Triad(t) => self.triad(t)?,
            }
            // The reported points of the group's links, in scene order
            // (`AssurGroup::links`, without its allocation).
            let mut links = [usize::MAX; 4];
            let n = match g {
                AssurGroup::Dyad(d) => {
                    links[..2].copy_from_slice(&d.links);
                    match d.cylinder {
                        Some(c) => {
                            links[2] = c.other;
                            3
                        }
                        None => 2,
                    }
                }
                AssurGroup::Triad(t) => {
                    links[..3].copy_from_slice(&t.leashes);
                    links[3] = t.base;
                    4
                }
            };
            links[..n].sort_unstable();
            for &l in &links[..n] {
                for &p in &m.links[l].points {
                    if self.t.reported_on[p] == Some(l) && self.plan.of_point[p].is_none() {
                        self.named(l, p);
                    }
                }
            }
        }
        // Measured absolute values of the reported points.
        for &p in self.st.points {
            let Some(i) = self.plan.of_point[p].filter(|&i| i != 0) else {
                continue;
            };
            let mm = self.plan.points[i].at.hypot();
            self.plan.measured.push(Measured {
                of: Quantity::Point(p),
                quantity: String::new(),
                from: 0,
                to: i,
                mm,
                value: mm * self.plan.mu,
                bound: (self.plan.points[i].err + self.plan.delta) * self.plan.mu,
            });
            let value = mm * self.plan.mu;
            self.step(|| Act::Measure {
                from: 0,
                to: i,
                value,
                reading: Reading::Point(p),
            });
        }
        Ok(())
    }
}

impl Tools {
    /// The first included link carrying `p` (in scene order), else the
    /// frame: the link a reported point is constructed on.
    fn carrier(st: &Setup, p: usize) -> usize {
        let m = st.m;
        (0..m.links.len())
            .find(|&l| st.include[l] && m.links[l].points.contains(&p))
            .unwrap_or(m.frame())
    }
}
