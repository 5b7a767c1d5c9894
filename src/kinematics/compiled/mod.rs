//! Route (a) compiled per mechanism: the positions and the closed vector
//! contours of [`crate::kinematics::positions`] and
//! [`crate::kinematics::analytic::contour`], with everything that does
//! not depend on the position worked out once, at load.
//!
//! [`Program::new`] walks the structure's stages once and turns them into
//! two flat lists of typed steps over link and input indices: one that
//! places the links ([`Place`]: a crank, a slider, each kind of dyad, a
//! class III group) and one that finds their rates ([`Rate`]: the frame,
//! the inputs, each group's contours). What the interpreted route looks
//! up or recomputes at every position is a constant of the step: a point's
//! local coordinates on its links, a group's link lengths, the angle and
//! length of the segment a link is posed by, the sine and cosine of a
//! guide's fixed angle, which links a contour reads as known, the order in
//! which its walk reaches its links. A position then runs the steps on a
//! [`State`] whose buffers are made once: no maps, no allocation.
//!
//! The arithmetic is the interpreted route's, operation for operation, so
//! the numbers are the same to the bit (`tests/compiled.rs` checks every
//! fixture and every stress scene over their sweeps, the errors too). A
//! tolerance that only decides a failure (a tangency accepted to the
//! rounding of its numbers) is not computed on the way: where a step
//! cannot place its group by its plain closed form it hands the group to
//! the interpreted solver, which accepts the tangency or gives the same
//! error as the interpreted route. The singular contour is refused by the
//! same test ([`crate::accuracy::Accuracy::min_contour_determinant`]).
//!
//! The steps are made and run by kind: [`place`] holds the steps that
//! place the links (the closed form of each kind of dyad with its
//! constants), [`rates`] the compiled contours and the steps of the rates,
//! [`dyad3`] a dyad's contour written out in scalars; this module holds
//! the [`Program`], its [`State`] and the public calls.

mod twists;
mod dyad3;
mod place;
mod rates;

use crate::error::Result;
use crate::geom::Pose;
use crate::kinematics::analytic::contour::{self, driven_pair, dyad_contours, triad_contours};
use crate::kinematics::analytic::{Coords, Drive, Drives, Motion, Order};
use crate::kinematics::positions::{
    self, Branches, Configuration, CrankFrame, Tracking, crank_frame, sketch_input, triad_error,
};
use crate::model::mechanism::Mechanism;
use crate::model::scene::InputSpec;
use crate::model::structure::{AssurGroup, Step, Structure};
use kurbo::{Point, Vec2};
use dyad3::Dyad3;
use place::{Place, dyad_place};
use rates::{Rate, compile_contour};

/// Route (a) of one mechanism, compiled: the positions and the contours
/// as flat lists of typed steps ([`crate::kinematics::compiled`]).
#[derive(Clone, Debug)]
pub struct Program<'a> {
    m: &'a Mechanism,
    s: &'a Structure,
    place: Vec<Place>,
    rate: Vec<Rate>,
    /// The largest step of each input over which class III groups are
    /// tracked; empty when the program solves none.
    triad_step: Vec<f64>,
    /// The sketch's pose of each class III group's base, and its branches.
    branches: Branches,
}

/// The buffers one sweep of a [`Program`] works in: the poses and the
/// motions of the links (the links the program does not solve stay
/// `None`), the tracked class III groups and the last input coordinates.
#[derive(Clone, Debug)]
pub struct State {
    pub config: Configuration,
    pub motion: Vec<Option<Motion>>,
    triad_pose: Vec<Pose>,
    last_q: Coords,
}

impl<'a> Program<'a> {
    /// Compile the positions and route (a) of the groups `need` asks for,
    /// on the branches the sketch shows (refused as
    /// [`crate::kinematics::positions::PositionSolver::new`] refuses).
    pub fn new(m: &'a Mechanism, s: &'a Structure, need: &[bool]) -> Result<Program<'a>> {
        let branches = Branches::from_sketch(m, s)?;
        let mut solved = vec![false; m.links.len()];
        solved[m.frame()] = true;
        let mut place = Vec::new();
        let mut rate = vec![Rate::Frame];
        let mut triads = false;
        for step in s.steps(m) {
            match step {
                Step::Frame { input, link } => {
                    let (p, r) = input_steps(m, input);
                    solved[link] = true;
                    place.push(p);
                    rate.push(r);
                }
                Step::Chained(ch) => {
                    if solved[ch.known] {
                        solved[ch.other] = true;
                        place.push(Place::Chained(ch));
                        rate.push(Rate::Chained(ch));
                    }
                }
                Step::Group { index, .. } if !need[index] => {}
                Step::Group { index, group } => {
                    let (p, r) = group_steps(m, index, group, branches.sign[index], &solved);
                    triads |= matches!(group, AssurGroup::Triad(_));
                    place.push(p);
                    rate.push(r);
                    for l in group.links() {
                        solved[l] = true;
                    }
                }
            }
        }
        let triad_step = if triads {
            (0..m.scene.input_count())
                .map(|i| positions::triad_step(m, s, need, i))
                .collect()
        } else {
            Vec::new()
        };
        Ok(Program {
            m,
            s,
            place,
            rate,
            triad_step,
            branches,
        })
    }

    /// A state to run this program in: the sketch's positions tracked from.
    pub fn state(&self) -> State {
        let n = self.m.links.len();
        State {
            config: Configuration {
                poses: vec![None; n],
            },
            motion: vec![None; n],
            triad_pose: self.branches.triad_pose.clone(),
            last_q: sketch_input(self.m),
        }
    }

    /// Positions at the input coordinates `q`, reached continuously from
    /// the last solved position (class III groups tracked in small
    /// steps), as [`crate::kinematics::positions::PositionSolver::solve_coords`].
    pub fn positions_coords(&self, st: &mut State, q: Coords) -> Result<()> {
        if !self.triad_step.is_empty() {
            for qk in Tracking::new(self.m, st.last_q, &q, |i| self.triad_step[i]) {
                self.place(st, &qk)?;
            }
        }
        self.place(st, &q)?;
        st.last_q = q;
        Ok(())
    }

    /// Velocities (and accelerations when `order` asks) of every solved
    /// link at the positions in `st`, as
    /// [`crate::kinematics::analytic::contour::solve`] gives them.
    pub fn rates(&self, st: &mut State, drive: impl Into<Drives>, order: Order) -> Result<()> {
        self.rates_of(st, &drive.into(), order)
    }

    /// Positions at `drive`'s coordinate (tracked from the last) and their
    /// rates, one step of a sweep of a mechanism with one input, without
    /// gathering the inputs into [`Drives`] and [`Coords`].
    #[inline]
    #[cfg(feature = "internals")]
    pub fn solve_one(&self, st: &mut State, drive: Drive, order: Order) -> Result<()> {
        assert_eq!(self.m.scene.input_count(), 1, "a mechanism with one input");
        if self.triad_step.is_empty() {
            self.place(st, &[drive.q])?;
            st.last_q = Coords::one(drive.q);
        } else {
            self.positions_coords(st, Coords::one(drive.q))?;
        }
        self.rates_of(st, &[drive], order)
    }
}

/// The steps of an input on the frame: its place and its rate.
fn input_steps(m: &Mechanism, i: usize) -> (Place, Rate) {
    match *m.scene.input_at(i) {
        InputSpec::Crank { link, pivot, .. } => {
            let CrankFrame { at, local, offset } = crank_frame(m, link, pivot);
            (
                Place::Crank {
                    input: i,
                    link,
                    at,
                    local,
                    offset,
                },
                Rate::Crank {
                    input: i,
                    link,
                    pivot: m.local(m.frame(), pivot),
                },
            )
        }
        InputSpec::Slider { link, pair, .. } => {
            let pr = &m.prismatics[pair];
            let line = pr.line(&Pose::IDENTITY);
            let (sin, cos) = pr.delta.sin_cos();
            (
                Place::Slider {
                    input: i,
                    link,
                    q0: positions::sketch_slider_ref(m, pair),
                    dir: line.dir,
                    local: pr.slider_local,
                    delta: pr.delta,
                    turn: (cos, sin),
                },
                Rate::Slider {
                    input: i,
                    link,
                    dir: pr.line_dir,
                },
            )
        }
    }
}

/// The steps of group `gi` (on its branch `sign`, the links `solved`
/// known before it): its place and its rate.
fn group_steps(
    m: &Mechanism,
    gi: usize,
    g: &AssurGroup,
    sign: f64,
    solved: &[bool],
) -> (Place, Rate) {
    match g {
        AssurGroup::Dyad(d) => {
            let driven = driven_pair(d).map(|(conn, input, on)| (conn, input, on.then_some(0)));
            let on = dyad_contours(d);
            let g = compile_contour::<3>(m, gi, &on, &d.placed_links(), driven, solved);
            let rate = match Dyad3::of(&g) {
                Some(d3) => Rate::Dyad3(Box::new(d3)),
                None => Rate::Dyad(Box::new(g)),
            };
            (dyad_place(m, gi, d, sign), rate)
        }
        AssurGroup::Triad(t) => {
            let on = triad_contours(t);
            let g = compile_contour::<6>(m, gi, &on, &t.placed_links(), None, solved);
            let rate = Rate::Triad(Box::new(g));
            (Place::Triad { group: gi }, rate)
        }
    }
}

impl Program<'_> {
    /// Positions at the coordinates `q` from the current tracked state,
    /// without stepping.
    pub(super) fn place(&self, st: &mut State, q: &[f64]) -> Result<()> {
        let (m, s) = (self.m, self.s);
        let c = &mut st.config;
        c.poses[m.frame()] = Some(Pose::IDENTITY);
        for step in &self.place {
            match step {
                Place::Crank {
                    input,
                    link,
                    at,
                    local,
                    offset,
                } => c.poses[*link] = Some(Pose::through(*at, *local, q[*input] - offset)),
                Place::Slider {
                    input,
                    link,
                    q0,
                    dir,
                    local,
                    delta,
                    turn,
                } => {
                    c.poses[*link] = Some(Pose::through_turned(
                        *q0 + *dir * q[*input],
                        *local,
                        *delta,
                        *turn,
                    ))
                }
                Place::Chained(ch) => {
                    let kp = c.pose(ch.known);
                    c.poses[ch.other] = Some(positions::place_across(
                        m,
                        ch.pair,
                        ch.known,
                        &kp,
                        q[ch.input],
                    ));
                }
                Place::Rrr(g) => {
                    if !g.place(c) {
                        self.dyad(c, g.group, q)?;
                    }
                }
                Place::Rrp(g) => {
                    if !g.place(c) {
                        self.dyad(c, g.group, q)?;
                    }
                }
                Place::Rpr(g) => {
                    if !g.place(c) {
                        self.dyad(c, g.group, q)?;
                    }
                }
                Place::Dyad { group } => self.dyad(c, *group, q)?,
                Place::Triad { group } => {
                    let AssurGroup::Triad(t) = &s.groups[*group] else {
                        unreachable!("a class III group")
                    };
                    let pose = positions::solve_triad(m, t, st.triad_pose[*group], c)
                        .map_err(|why| triad_error(m, s, *group, q, why))?;
                    st.triad_pose[*group] = pose;
                }
            }
        }
        Ok(())
    }

    /// Dyad `gi` by the interpreted closed form (its tolerances, its errors).
    #[cold]
    fn dyad(&self, c: &mut Configuration, gi: usize, q: &[f64]) -> Result<()> {
        let (m, s) = (self.m, self.s);
        let AssurGroup::Dyad(d) = &s.groups[gi] else {
            unreachable!("a class II group")
        };
        positions::solve_group_dyad(m, s, gi, d, self.branches.sign[gi], q, c)
    }
}
impl Program<'_> {
    /// [`Program::rates`], the drives by reference.
    pub(super) fn rates_of(&self, st: &mut State, drives: &[Drive], order: Order) -> Result<()> {
        let m = self.m;
        let (c, out) = (&st.config, &mut st.motion);
        for step in &self.rate {
            match step {
                Rate::Frame => {
                    out[m.frame()] = Some(Motion::from_point(
                        c.pose(m.frame()),
                        Point::ORIGIN,
                        Vec2::ZERO,
                        Vec2::ZERO,
                        0.0,
                        0.0,
                    ))
                }
                Rate::Crank { input, link, pivot } => {
                    let d = drives[*input];
                    let o = c.pose(m.frame()).apply(*pivot);
                    out[*link] = Some(Motion::from_point(
                        c.pose(*link),
                        o,
                        Vec2::ZERO,
                        Vec2::ZERO,
                        d.rate,
                        d.rate2,
                    ));
                }
                Rate::Slider { input, link, dir } => {
                    let d = drives[*input];
                    let pose = c.pose(*link);
                    let u = c.pose(m.frame()).dir(*dir);
                    out[*link] = Some(Motion::from_point(
                        pose,
                        pose.origin,
                        u * d.rate,
                        u * d.rate2,
                        0.0,
                        0.0,
                    ));
                }
                Rate::Chained(ch) => {
                    let kmo = out[ch.known].expect("solved before");
                    out[ch.other] =
                        Some(contour::chained_motion(m, c, *ch, &kmo, drives[ch.input]));
                }
                Rate::Dyad3(g) => {
                    if g.run(c, out, order).is_none() {
                        return Err(self.singular(g.group, drives));
                    }
                }
                Rate::Dyad(g) => {
                    if g.run(c, out, drives, order).is_none() {
                        return Err(self.singular(g.group, drives));
                    }
                }
                Rate::Triad(g) => {
                    if g.run(c, out, drives, order).is_none() {
                        return Err(self.singular(g.group, drives));
                    }
                }
            }
        }
        Ok(())
    }

    #[cold]
    fn singular(&self, gi: usize, drives: &[Drive]) -> crate::error::Error {
        contour::singular(self.m, &self.s.groups[gi], &Drives::new(drives))
    }
}
