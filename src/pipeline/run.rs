//! Solving every position asked for: the positions found in order by both
//! routes, then each one's rates, plans and cross-check.

use super::{Analysis, InputPosition, InputPositions, Position, RUN_CHUNK, Solved};
use crate::kinematics::solve::Motions;
use crate::error::{Error, Result};
use crate::geom::wrap_pi;
use crate::kinematics::analytic::constraint::{ConstraintSolver, Settings};
use crate::kinematics::analytic::{Coords, Drives, InputRates, Order, contour};
use crate::kinematics::compiled::{Program, State};
use super::switches::Kernel;
use crate::kinematics::construction::{Plans, build_plans, build_plans_numbers};
use crate::kinematics::positions::{Configuration, PositionSolver};
use crate::model::scene::InputSpec;
use crate::verification::crosscheck::{ChangedData, Costs, Residuals};
use std::time::Instant as Clock;

/// The change between two positions (a link's turn in rad, or its move
/// over the sketch's size) above which the fast path halves the span
/// between them to tell a quick motion from a jump of route (a).
const JUMP: f64 = 0.25;

/// A position found in order by both routes, before its rates.
#[derive(Clone)]
struct Placed<'a> {
    /// The position's number in the scene's order, from 0.
    index: usize,
    q: Coords,
    /// The rounding of q as the file writes it (rad or m).
    q_rounding: Coords,
    config: Configuration,
    /// Route (b) at this position (its state continues from the last);
    /// `None` on the fast path (no plans), which checks route (a)'s answer
    /// by route (b)'s equations instead.
    constraint: Option<ConstraintSolver<'a>>,
    /// Time of finding the position, seconds, by route (a) and route (b).
    contour_time: f64,
    constraint_time: f64,
    /// Where the result keeps no plans: the sweep kernel's plans of the
    /// position, numbers only, for the cross-check (`None` where it
    /// refused: the one-position build then gives the position's error),
    /// and their time, seconds.
    kernel: Option<(Option<Box<Plans>>, f64)>,
}

impl Analysis {
    /// Solve every position asked for, both routes, with the cross-check.
    ///
    /// The positions are found in order (both routes continue from one
    /// position to the next, which keeps them on the sketch's branch);
    /// then each position's velocities, accelerations, plans and checks are
    /// independent, and long sweeps do them in parallel
    /// ([`crate::progress::map_on`], a chunk at a time). The result, and
    /// the first error in the order of the positions, are those of a
    /// sequential run.
    ///
    /// Every position is held: a sweep of more than
    /// [`MAX_POSITIONS`](crate::model::scene::MAX_POSITIONS) is refused
    /// (naming `/positions/count`); [`Analysis::run_each`] takes any count.
    pub fn run(&self) -> Result<Vec<Solved>> {
        use crate::model::scene::MAX_POSITIONS;
        let n = self.mech.scene.positions.count();
        if n > MAX_POSITIONS {
            return Err(crate::error::Error::scene(
                "/positions/count",
                format!(
                    "{n} positions: Analysis::run holds every position and takes at most {MAX_POSITIONS}; Analysis::run_each hands each over as it is solved and takes any count"
                ),
            ));
        }
        let mut out = Vec::new();
        self.run_each(|s| {
            out.push(s);
            Ok(())
        })?;
        Ok(out)
    }

    /// As [`Analysis::run`], each solved position handed to `f` in order
    /// instead of kept: the positions are found and finished
    /// [`RUN_CHUNK`] at a time, so that memory does not grow with their
    /// number. The positions before the first error are handed over; an
    /// error of `f` stops the run and is returned.
    pub fn run_each(&self, f: impl FnMut(Solved) -> Result<()>) -> Result<()> {
        self.run_each_with(&crate::progress::Silent, f)
    }

    /// As [`Analysis::run_each`], telling `progress` of the sweep (its
    /// length, once the input values are found) and of each position (the
    /// caller's watcher: a terminal's bar, or none).
    pub fn run_each_with(
        &self,
        progress: &dyn crate::progress::Progress,
        f: impl FnMut(Solved) -> Result<()>,
    ) -> Result<()> {
        self.run_kept(progress, &|_| Vec::new(), f, |_| Ok(()))
    }

    /// [`Analysis::run_each_with`], the positions `keep` names (of their
    /// number; from 0) kept as found; when every position is handed over,
    /// `then` is given what finishes a kept one again as another analysis
    /// (this one with other scales) would.
    pub(super) fn run_kept(
        &self,
        progress: &dyn crate::progress::Progress,
        keep: &dyn Fn(usize) -> Vec<usize>,
        mut f: impl FnMut(Solved) -> Result<()>,
        then: impl FnOnce(&mut dyn FnMut(&Analysis, usize) -> Result<Solved>) -> Result<()>,
    ) -> Result<()> {
        let inputs: InputPositions = self.input_positions()?;
        let m = &self.mech;
        let mut ps = PositionSolver::new(m, &self.structure, self.need.clone())?;
        let route = self.route()?;
        // Route (b) follows the positions where the plans are built; the
        // fast path evaluates its equations at route (a)'s answers.
        let mut cs = self
            .plans
            .then(|| ConstraintSolver::new(m, &self.include, Settings::default()));
        let changed = self.changed_data();
        let eqs = (!self.plans).then(|| self.residual_equations(&changed));
        // The fast path: the orientation of the assembly at the last
        // position checked (the sketch's before the first).
        let mut orientation = eqs
            .as_ref()
            .and_then(|e| e.sketch_orientation)
            .map(|o| (o, None));
        // … and route (a)'s answers one continuous motion: closed forms of
        // class II groups (a class III group is tracked in small steps).
        let mut motion = (eqs.is_some() && !ps.has_triads()).then(|| (ps.clone(), None));
        progress.start(inputs.len(), "positions");
        let keep = keep(inputs.len());
        let checks = Checks {
            changed: &changed,
            residuals: eqs.as_ref(),
        };
        let Route {
            program,
            mut state,
            mut kernel,
        } = route;
        let program = program.as_ref();
        let mut hand = |s: Solved| {
            self.same_orientation(&mut orientation, &s)?;
            if let Some((probe, last)) = &mut motion {
                self.continuous(probe, last, &s)?;
            }
            f(s)
        };
        // Chunk after chunk: its positions found in order (route (a)'s
        // state and route (b)'s path run on), then finished — in parallel
        // when long. Where the overlap is allowed a thread of its own finds
        // and finishes the chunks while this one hands the finished ones
        // over in order (writing a sweep's results overlaps checking it;
        // a few chunks may wait finished, so that the pool is never idle
        // while they are written). Not where each position keeps its plans
        // (a chunk of them is tens of MB): there a chunk is handed over
        // before the next is found. Nor from within a thread pool's worker
        // (a run among runs in parallel): there the chunk is finished on
        // the caller's own pool, which a waiting worker keeps working for.
        let overlap = !(self.plans && self.keep_plans) && rayon::current_thread_index().is_none();
        let checks = &checks;
        // Finds and finishes every chunk in order, each given to `emit`
        // with the error that stopped it; stops when `emit` says so.
        let mut chunks = |emit: &mut Emit| {
            let mut kept: Vec<Placed> = Vec::new();
            // One buffer for a chunk's results, handed back emptied.
            let mut finished = Vec::new();
            // The input values made a chunk at a time, none kept.
            let mut values = inputs.iter();
            for from in (0..inputs.len()).step_by(RUN_CHUNK) {
                let chunk: Vec<InputPosition> = values.by_ref().take(RUN_CHUNK).collect();
                let route = (program, &mut state, &mut kernel);
                let (placed, stop) = self.place_chunk((from, &chunk), &mut ps, route, &mut cs);
                kept.extend(Placed::kept(&placed, &keep));
                let finish = |st: &mut Option<State>, p: &Placed| self.finish(p, checks, program, st);
                crate::progress::map_into_with(&placed, progress, || None, finish, &mut finished);
                let last = stop.is_some();
                match emit(std::mem::take(&mut finished), stop) {
                    Some(back) if !last => finished = back,
                    _ => break,
                }
            }
            kept
        };
        let mut handed = move |finished: &mut Finished, stop: Option<Error>| -> Result<()> {
            for s in finished.drain(..) {
                hand(s?)?;
            }
            stop.map_or(Ok(()), Err)
        };
        let (kept, done) = if overlap {
            overlapped(chunks, handed)
        } else {
            let mut outcome = Ok(());
            let kept = chunks(&mut |mut done, stop| {
                outcome = handed(&mut done, stop);
                outcome.is_ok().then_some(done)
            });
            (kept, outcome)
        };
        progress.finish();
        done?;
        then(&mut |an: &Analysis, k: usize| {
            let p = kept.iter().find(|p| p.index == k);
            let p = p.ok_or_else(|| Error::Internal(format!("position {k} was not kept")))?;
            an.finish(p, checks, program, &mut None)
        })
    }

    /// How a run finds its positions ([`Route`]): route (a) compiled for
    /// the mechanism (issue 24) — the rates at every position, and on the
    /// fast path its positions in order (the full path finds them by the
    /// interpreted solver, whose tracked state route (b)'s probes of the
    /// way start from) — and the sweep's kernel where plans are only
    /// checked and it is asked for (`sweep_kernel`).
    fn route(&self) -> Result<Route<'_>> {
        let m = &self.mech;
        let program = match self.reference() {
            false => Some(Program::new(m, &self.structure, &self.need)?),
            true => None,
        };
        let kernel = self.kernel();
        let state = if self.plans {
            None
        } else {
            program.as_ref().map(Program::state)
        };
        Ok(Route {
            program,
            state,
            kernel,
        })
    }

    /// The positions of one chunk of [`Analysis::run_each`] (the number
    /// of its first position, its input values with how far each may be
    /// from the one meant) found in order: route
    /// (a)'s places (compiled where `program`, on its `state`), route
    /// (b)'s path run on, the kernel's plans; the first error stops the
    /// chunk and is returned with the positions before it.
    fn place_chunk<'a>(
        &'a self,
        (from, values): (usize, &[InputPosition]),
        ps: &mut PositionSolver,
        (program, state, kernel): (Option<&Program<'a>>, &mut Option<State>, &mut Option<Kernel>),
        cs: &mut Option<ConstraintSolver<'a>>,
    ) -> (Vec<Placed<'a>>, Option<Error>) {
        let mut placed = Vec::with_capacity(values.len());
        for (i, &InputPosition { value: q, rounding: q_rounding }) in values.iter().enumerate() {
            let t0 = Clock::now();
            let config = match (program, &mut *state) {
                (Some(prog), Some(st)) => prog.positions_coords(st, q).map(|()| st.config.clone()),
                _ => ps.solve_coords(q),
            };
            let config = match config {
                Ok(c) => c,
                Err(e) => return (placed, Some(e)),
            };
            // One reading of the clock ends route (a)'s time and starts
            // route (b)'s.
            let t1 = Clock::now();
            let contour_time = (t1 - t0).as_secs_f64();
            // Route (b) along the positions (none on the fast path: no time).
            let mut constraint_time = 0.0;
            if let Some(cs) = cs.as_mut() {
                let span = self.path_span(ps, cs.last_inputs(), q);
                if let Err(e) = cs.solve_positions_along(q, span) {
                    // Route (a)'s rates come first at a position: its
                    // error, if it has one here, is the one a sequential
                    // run reports.
                    let e = self.contour_error(q, &config).unwrap_or(e);
                    return (placed, Some(e));
                }
                constraint_time = t1.elapsed().as_secs_f64();
            }
            let kernel = match (kernel.as_mut(), self.order) {
                (Some(k), Some(order)) => {
                    let (plans, time) = self.kernel_plans(k, &config, (q, from + i), order);
                    Some((plans.map(Box::new), time))
                }
                _ => None,
            };
            placed.push(Placed {
                index: from + i,
                q,
                q_rounding,
                config,
                constraint: cs.clone(),
                contour_time,
                constraint_time,
                kernel,
            });
        }
        (placed, None)
    }

    /// The fast path's check of the assembly: the orientation of route
    /// (a)'s answer at `s` (the sign of det Φ_q) is the one at the
    /// position before (`last`: its sign and inputs, none for the
    /// sketch), as route (b)'s path following would keep it; it changes
    /// only through a singular position, which route (b) cannot pass.
    fn same_orientation(&self, last: &mut Option<(f64, Option<Coords>)>, s: &Solved) -> Result<()> {
        let Some(o) = s.check.as_ref().and_then(|c| c.orientation) else {
            return Ok(());
        };
        let q = s.drives.coords();
        if let Some((before, at)) = *last
            && before != o
        {
            let m = &self.mech;
            let from = match at {
                Some(at) => crate::kinematics::positions::describe_input(m, &at),
                None => "the sketch".to_string(),
            };
            return Err(Error::singular(
                crate::kinematics::positions::describe_input(m, &q),
                format!(
                    "between {from} and this position the mechanism passes a singular position (the orientation of its assembly, the sign of det Φ_q, changes): no motion from the sketch reaches route (a)'s answer here"
                ),
            ));
        }
        *last = Some((o, Some(q)));
        Ok(())
    }

    /// The fast path's check that route (a)'s answers are one continuous
    /// motion, as route (b)'s path following would find: its closed forms
    /// keep the sketch's branch by a sign, and a branch point that leaves
    /// det Φ_q's sign alone (a slider's pin passing through its rotating
    /// guide's pivot) turns their answer by 180° at one input value. Where
    /// a link turns or moves much between two positions (0.25 rad, a
    /// quarter of the sketch's size), the span is halved, route (a) solved
    /// at the middle, and each half judged again: a continuous motion's
    /// change shrinks with its span, a jump does not and is refused.
    fn continuous(
        &self,
        probe: &mut PositionSolver,
        last: &mut Option<(Coords, Configuration)>,
        s: &Solved,
    ) -> Result<()> {
        let q = s.drives.coords();
        match last {
            Some((q0, c0)) => {
                // The way between (a probe every 5° of a crank) only where
                // a link moved much: a fine sweep pays one comparison.
                if self.change(c0, &s.config) > JUMP {
                    let span = self.path_span(probe, *q0, q);
                    self.no_jump(probe, *q0, c0, span, &s.config, 0)?;
                }
                *q0 = q;
                c0.poses.clone_from(&s.config.poses);
            }
            None => *last = Some((q, s.config.clone())),
        }
        Ok(())
    }

    /// How much the links turn (rad) or move (over the sketch's size) from
    /// `c0` to `c1`, the most of any.
    fn change(&self, c0: &Configuration, c1: &Configuration) -> f64 {
        let m = &self.mech;
        (0..m.links.len())
            .filter(|&l| l != m.frame() && self.link(l))
            .filter_map(|l| Some((c0.poses[l]?, c1.poses[l]?)))
            .map(|(a, b)| {
                wrap_pi(b.angle - a.angle)
                    .abs()
                    .max((b.origin - a.origin).hypot() / m.size)
            })
            .fold(0.0f64, f64::max)
    }

    /// [`Analysis::continuous`] over `span` from `q0` (configuration `c0`)
    /// to the configuration `c1`, at bisection depth `depth`.
    fn no_jump(
        &self,
        probe: &mut PositionSolver,
        q0: Coords,
        c0: &Configuration,
        span: Coords,
        c1: &Configuration,
        depth: usize,
    ) -> Result<()> {
        let m = &self.mech;
        let change = self.change(c0, c1);
        if change <= JUMP {
            return Ok(());
        }
        let wide = span
            .iter()
            .zip(q0.iter())
            .any(|(d, x)| d.abs() > 1e-12 * (1.0 + x.abs()));
        if !wide || depth >= 64 {
            let mut at = q0;
            for (x, d) in at.iter_mut().zip(span.iter()) {
                *x += d;
            }
            return Err(Error::singular(
                crate::kinematics::positions::describe_input(m, &at),
                format!(
                    "route (a)'s answer jumps here (a link turns or moves by {change:.3} at one input value): a branch point its closed forms pass without a continuous motion; with plans (want.plans) route (b) follows the motion and says where it stops"
                ),
            ));
        }
        let (mut mid, mut half) = (q0, span);
        for ((x, h), d) in mid.iter_mut().zip(half.iter_mut()).zip(span.iter()) {
            *h = d / 2.0;
            *x += *h;
        }
        let cm = probe.solve_at_coords(mid).map_err(|e| {
            Error::singular(
                crate::kinematics::positions::describe_input(m, &mid),
                format!("the mechanism does not assemble between two positions of the sweep ({e}): no continuous motion joins them"),
            )
        })?;
        self.no_jump(probe, q0, c0, half, &cm, depth + 1)?;
        self.no_jump(probe, mid, &cm, half, c1, depth + 1)
    }

    /// Which way the inputs go from `from` to `to`: a slider straight; a
    /// crank the short way round, unless (a single crank) the mechanism
    /// does not assemble on it (a crank that only rocks) and does the
    /// other way. Route (a)'s closed forms, tried every 5°, tell; route
    /// (b) then continues along that way, so a valid sequence of a rocking
    /// crank is never refused.
    fn path_span(&self, ps: &PositionSolver, from: Coords, to: Coords) -> Coords {
        if self.mech.scene.several_inputs() {
            return crate::kinematics::positions::span(&self.mech, &from, &to);
        }
        let (from, to) = (from.first(), to.first());
        Coords::one(self.path_span_one(ps, from, to))
    }

    /// [`Analysis::path_span`] of a single input.
    fn path_span_one(&self, ps: &PositionSolver, from: f64, to: f64) -> f64 {
        let InputSpec::Crank { .. } = self.mech.scene.input else {
            return to - from;
        };
        let short = wrap_pi(to - from);
        let assembles = |span: f64| {
            let mut probe = ps.clone();
            let n = (span.abs() / 5f64.to_radians()).ceil().max(1.0) as usize;
            (1..n).all(|i| probe.solve_at(from + span * i as f64 / n as f64).is_ok())
        };
        if short == 0.0 || assembles(short) {
            return short;
        }
        let long = short - std::f64::consts::TAU.copysign(short);
        if assembles(long) { long } else { short }
    }

    /// Every input's (rate, rate of rate), in the scene's order.
    pub fn input_rates(&self) -> InputRates {
        self.mech.scene.inputs().map(|i| i.rates()).collect()
    }

    /// Every input's drive at the input coordinates `q`.
    pub fn drives_at(&self, q: &[f64]) -> Drives {
        Drives::at(q, &self.input_rates())
    }

    /// Route (a)'s error at a position, if its contours are singular there.
    fn contour_error(&self, q: Coords, config: &Configuration) -> Option<Error> {
        let order = self.order?;
        contour::solve(
            &self.mech,
            &self.structure,
            &self.need,
            config,
            self.drives_at(&q),
            order,
        )
        .err()
    }

    /// One placed position: both routes' rates, the plans, the cross-check
    /// (on the fast path: route (a)'s rates and their check); route (a)
    /// by `program` (`None`: interpreted, the reference), in the state
    /// `scratch` (made at the first position a thread finishes, reused).
    fn finish(
        &self,
        p: &Placed,
        checks: &Checks,
        program: Option<&Program>,
        scratch: &mut Option<State>,
    ) -> Result<Solved> {
        let m = &self.mech;
        let rates = self.input_rates();
        let (q, config) = (p.q, p.config.clone());
        let drives = self.drives_at(&q);
        let w = drives.len();
        let t0 = Clock::now();
        // Route (a)'s state for the rates: the scratch of the thread's
        // part of the sweep (its rates all written anew at each position).
        let mut st = program.map(|prog| {
            let st = scratch.get_or_insert_with(|| prog.state());
            st.config.clone_from(&config);
            (prog, st)
        });
        let mut run = |d: Drives, order: Order| match st.as_mut() {
            Some((prog, st)) => prog.rates(st, d, order).map(|()| st.motion.clone()),
            None => contour::solve(m, &self.structure, &self.need, &config, d, order),
        };
        let none = || vec![None; m.links.len()];
        let (mut motion, mut analogue) = (none(), none());
        let (mut more_analogues, mut mixed) = (Vec::new(), Vec::new());
        if let Some(order) = self.order {
            motion = run(drives, order)?;
            analogue = run(drives.unit(0, None), order)?;
            for i in 1..w {
                more_analogues.push(run(drives.unit(i, None), order)?);
            }
            if order == Order::Acceleration {
                for i in 0..w {
                    for j in i + 1..w {
                        mixed.push(run(drives.unit(i, Some(j)), order)?);
                    }
                }
            }
        }
        // One reading of the clock ends route (a)'s time and starts the
        // check's.
        let t1 = Clock::now();
        let contour_time = p.contour_time + (t1 - t0).as_secs_f64();
        #[cfg(feature = "internals")]
        let config = {
            let mut config = config;
            self.corrupt(&mut config, &mut motion);
            config
        };
        let motions = Motions {
            motion,
            analogue,
            more_analogues,
            mixed,
        };
        let Some(cs) = &p.constraint else {
            let mut solved = Solved::from(Position::new(drives, config, motions, None));
            let eqs = checks.residuals.expect("the fast path's equations");
            solved.check = Some(self.residual_check(
                &solved,
                eqs,
                (contour_time, t1),
                p.q_rounding,
                checks.changed,
            )?);
            solved.dynamics = crate::kinetostatics::analyse(self, &solved, p.index)?.map(Box::new);
            return Ok(if self.lean { solved.lean() } else { solved });
        };
        let mut cs = cs.clone();
        let t1 = Clock::now();
        let other = cs.solve_rates_of(&rates, self.order.unwrap_or(Order::Velocity))?;
        let constraint_time = p.constraint_time + t1.elapsed().as_secs_f64();
        let t2 = Clock::now();
        // Where the result keeps no plans they are only checked: built
        // numbers only (the same plans to the bit), or by the sweep's
        // kernel (`Analysis::sweep_kernel`; where it refused, on their own).
        let lean = !self.keep_plans && !self.reference();
        let checked = p.kernel.as_ref().and_then(|k| k.0.as_deref());
        let (setup, d) = (self.setup(), self.drafting_at(p.index));
        let plans = match self.order {
            Some(order) if checked.is_none() => Some(match lean {
                true => build_plans_numbers(&setup, &config, drives, order, d)?,
                false => build_plans(&setup, &config, drives, order, d)?,
            }),
            _ => None,
        };
        let (plans, lean) = if lean { (None, plans) } else { (plans, None) };
        let plan_time = t2.elapsed().as_secs_f64() + p.kernel.as_ref().map_or(0.0, |k| k.1);
        let mut solved = Solved::from(Position::new(drives, config, motions, plans));
        let costs = Costs {
            contour_time,
            constraint_time,
            plan_time,
            conditioning: cs.conditioning,
        };
        let plans = solved.plans.as_deref().or(lean.as_ref()).or(checked);
        solved.check =
            Some(self.cross_check(&solved, &other, plans, costs, p.q_rounding, checks.changed)?);
        solved.dynamics = crate::kinetostatics::analyse(self, &solved, p.index)?.map(Box::new);
        Ok(if self.lean { solved.lean() } else { solved })
    }
}

impl<'a> Placed<'a> {
    /// The positions of `placed` that `keep` names, kept to be finished
    /// again one on its own (not by the sweep's kernel, which built their
    /// plans at the run's scales).
    fn kept(placed: &[Placed<'a>], keep: &[usize]) -> Vec<Placed<'a>> {
        let kept = placed.iter().filter(|p| keep.contains(&p.index));
        kept.map(|p| Placed {
            kernel: None,
            ..p.clone()
        })
        .collect()
    }
}

/// Route (a) of a run: the program compiled for the mechanism (`None`:
/// the interpreted reference, [`Analysis::reference`]), and on the fast
/// path the state its positions are tracked in; and the sweep's
/// construction kernel where the result keeps no plans.
struct Route<'a> {
    program: Option<Program<'a>>,
    state: Option<State>,
    kernel: Option<Kernel>,
}

/// `chunks` run on a thread of its own, each chunk it finishes handed
/// over by `handed` on this one, in order, while the next are found and
/// finished ([`FINISHED_AHEAD`] of them may wait); the first error of
/// `handed` stops both. What `chunks` returns, and how the handing ended.
fn overlapped<K: Send>(
    chunks: impl FnOnce(&mut Emit) -> K + Send,
    mut handed: impl FnMut(&mut Finished, Option<Error>) -> Result<()>,
) -> (K, Result<()>) {
    std::thread::scope(|scope| {
        let (to_hand, finished) = std::sync::mpsc::sync_channel(FINISHED_AHEAD);
        let (to_fill, emptied) = std::sync::mpsc::channel();
        let finding = scope.spawn(move || {
            chunks(&mut |done, stop| {
                to_hand.send((done, stop)).ok()?;
                Some(emptied.try_recv().unwrap_or_default())
            })
        });
        let mut outcome = Ok(());
        for (mut done, stop) in finished {
            outcome = handed(&mut done, stop);
            if outcome.is_err() {
                // The finding thread stops at its next chunk.
                break;
            }
            // Its room for another chunk (none wanted after the last).
            let _ = to_fill.send(done);
        }
        let kept = finding.join().expect("finding the chunks does not panic");
        (kept, outcome)
    })
}

/// A chunk's finished positions, in order.
type Finished = Vec<Result<Solved>>;

/// Where [`Analysis::run_each`]'s chunks go as they are finished, each
/// with the error that stopped it: its buffer back to be filled again,
/// `None` to stop.
type Emit<'e> = dyn FnMut(Finished, Option<Error>) -> Option<Finished> + 'e;

/// How many finished chunks may wait to be handed over while the next
/// are found and finished ([`Analysis::run_each`]'s overlap): enough that
/// the pool finishing them does not wait on the writing.
const FINISHED_AHEAD: usize = 2;

/// The checks of a run, made once: the scene with its data changed, and
/// (on the fast path) route (b)'s equations of it and of them.
struct Checks<'a> {
    changed: &'a ChangedData,
    residuals: Option<&'a Residuals<'a>>,
}
