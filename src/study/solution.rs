//! A study's positions solved: all of them in memory ([`Solution`]) or
//! one at a time ([`Positions`], flat memory however many), each read by
//! name ([`PositionResult::point`], [`PositionResult::link`]).

use super::prepared::Watcher;
use super::{DrawRequest, SheetWriter, Study, Written, files};
use crate::error::{Error, Result};
use crate::kinematics::construction::{Plan, PlanKind};
use crate::kinematics::solve::Analysis;
use crate::pipeline::Solved;
use crate::presentation::drawing::{self, Sheet, SheetSize, Sweep};
use crate::presentation::report;
use crate::studies::sheet_data::{SheetData, SheetNeeds};
use kurbo::{Point, Vec2};
use std::borrow::Cow;
use std::sync::Arc;
use std::sync::mpsc::{Receiver, SyncSender, sync_channel};
use std::thread::JoinHandle;

/// The positions of a study, solved: both routes, the plans, their
/// cross-check and (with `dynamics`) the forces at every one.
#[derive(Clone, Debug)]
pub struct Solution<'a> {
    study: &'a Study,
    positions: Vec<Solved>,
}

impl<'a> Solution<'a> {
    pub(super) fn new(study: &'a Study, positions: Vec<Solved>) -> Solution<'a> {
        Solution { study, positions }
    }

    /// The study solved.
    pub fn study(&self) -> &'a Study {
        self.study
    }

    /// How many positions.
    pub fn len(&self) -> usize {
        self.positions.len()
    }

    /// Whether there are none (a scene always has at least one).
    pub fn is_empty(&self) -> bool {
        self.positions.is_empty()
    }

    /// Position `number`, in the study's numbering ([`Study::numbering`]:
    /// a `count` sweep from 0, given input values from 1), as the sheets,
    /// the result files and `--position` number it; an error naming the
    /// range if there is none.
    ///
    /// # Errors
    ///
    /// [`Error::Input`] at `position` when the study has no position
    /// `number`, with the range it has.
    ///
    /// # Examples
    ///
    /// ```
    /// let study = mechplan::Study::default_scene();
    /// let solution = study.solve()?;
    /// let b = solution.position(3)?.point("B")?;
    /// assert!(b.velocity().is_some());
    /// let e = solution.position(12).unwrap_err().to_string();
    /// assert!(e.contains("from 0 to 11"), "{e}");
    /// # Ok::<(), mechplan::Error>(())
    /// ```
    pub fn position(&self, number: usize) -> Result<PositionResult<'_>> {
        let k = super::prepared::position_index(self.an().numbering, number, self.positions.len())
            .map_err(|m| Error::scene("position", m))?;
        let s = &self.positions[k];
        Ok(PositionResult {
            an: &self.study.analysis,
            solved: Cow::Borrowed(s),
            index: k,
        })
    }

    /// Every position, in order.
    pub fn iter(&self) -> impl Iterator<Item = PositionResult<'_>> {
        self.positions
            .iter()
            .enumerate()
            .map(|(k, s)| PositionResult {
                an: &self.study.analysis,
                solved: Cow::Borrowed(s),
                index: k,
            })
    }

    /// The solved positions themselves (the internals, for the project's
    /// own tests).
    #[cfg(feature = "internals")]
    pub fn solved(&self) -> &[Solved] {
        &self.positions
    }

    pub(super) fn an(&self) -> &'a Analysis {
        &self.study.analysis
    }

    pub(super) fn all(&self) -> &[Solved] {
        &self.positions
    }

    /// The result file (`mechplan solve --format json`).
    pub fn to_json(&self) -> serde_json::Value {
        report::to_json(self.an(), &self.positions)
    }

    /// The sheets `req` asks for, as SVG text (nothing written; see
    /// [`Solution::draw`] for files): each plan at its own scale (chosen for
    /// the sheet the study was prepared for, [`Study::for_sheets`]), the
    /// other figures at the largest standard scale that fills their sheet.
    /// A sheet size asked for is the only one
    /// tried; else A4, or (for a μ_l the scene fixes) the smallest sheet
    /// that holds the mechanism's drawings at it, the second of the pair.
    ///
    /// ```
    /// let study = mechplan::Study::default_scene();
    /// let (sheets, _size) = study.solve()?.sheets(&mechplan::DrawRequest::default())?;
    /// assert!(sheets.iter().any(|s| s.name == "velocity_1"));
    /// assert!(sheets[0].svg.starts_with("<svg"));
    /// # Ok::<(), mechplan::Error>(())
    /// ```
    pub fn sheets(&self, req: &DrawRequest) -> Result<(Vec<Sheet>, SheetSize)> {
        let mut sheets = Vec::new();
        let size = self.sheets_each(req, &mut |s| {
            sheets.push(s);
            Ok(())
        })?;
        Ok((sheets, size))
    }

    /// [`Solution::sheets`], each sheet handed to `sink` as soon as it is
    /// drawn (and dropped there: what [`Solution::draw`] writes as it
    /// goes); the sheet size used.
    pub fn sheets_each(
        &self,
        req: &DrawRequest,
        sink: &mut dyn FnMut(Sheet) -> Result<()>,
    ) -> Result<SheetSize> {
        let solved: &[Solved] = &self.positions;
        let data = |needs| SheetData::solve(self.an(), solved, needs);
        sheets_of(self.study, &solved, &data, req, sink)
    }

    /// Draw the sheets (or the handout) into `req.dir`: the files written
    /// and the notes for the user.
    ///
    /// # Errors
    ///
    /// [`Error::Input`] for a request that does not fit the scene (a
    /// position it has not, a fixed μ_l no sheet holds, naming the
    /// smallest that fits); those of [`Study::solve`]; [`Error::Write`]
    /// where a file cannot be written (what was there is kept: each file
    /// is written whole and renamed).
    ///
    /// # Examples
    ///
    /// ```
    /// let study = mechplan::Study::default_scene();
    /// let dir = std::env::temp_dir().join("mechplan-doc-draw");
    /// let req = mechplan::DrawRequest {
    ///     dir: dir.clone(),
    ///     positions: vec![3],
    ///     ..mechplan::DrawRequest::default()
    /// };
    /// let written = study.solve()?.draw(&req)?;
    /// assert!(written.files.iter().any(|f| f.ends_with("velocity_3.svg")));
    /// # Ok::<(), mechplan::Error>(())
    /// ```
    pub fn draw(&self, req: &DrawRequest) -> Result<Written> {
        match self.staged(req)? {
            Staged::Done(written) => Ok(written),
            Staged::Sheets(writer, notes) => finish(*writer, notes),
        }
    }

    /// [`Solution::draw`], the positions dropped before the files are
    /// put into place (the manifest, the renames: a long sweep's peak).
    pub(super) fn draw_dropped(self, req: &DrawRequest) -> Result<Written> {
        let staged = self.staged(req)?;
        drop(self);
        match staged {
            Staged::Done(written) => Ok(written),
            Staged::Sheets(writer, notes) => finish(*writer, notes),
        }
    }

    /// The files of [`Solution::draw`] written (the handout), or the
    /// sheets staged, with the notes on them, to be put into place.
    fn staged(&self, req: &DrawRequest) -> Result<Staged> {
        req.validate()?;
        let an = self.an();
        if req.html {
            let lang = req.lang.unwrap_or_else(|| self.study.lang());
            std::fs::create_dir_all(&req.dir)
                .map_err(|e| files::write_error(&req.dir.display().to_string(), e))?;
            let path = req.dir.join("handout.html");
            let page = drawing::html::handout(an, &self.positions, lang);
            files::write_files_atomically(&[(path.clone(), page.as_bytes())])?;
            return Ok(Staged::Done(Written {
                files: vec![path],
                notes: Vec::new(),
            }));
        }
        let solved: &[Solved] = &self.positions;
        let data = |needs| SheetData::solve(an, solved, needs);
        let (writer, notes) = staged_sheets(self.study, &solved, &data, req)?;
        Ok(Staged::Sheets(Box::new(writer), notes))
    }
}

/// The sheets `req` asks for of the positions `sweep` of `study` (held,
/// or solved again as they are read), each handed to `sink` as it is
/// drawn; `data`: what they draw beyond the positions, solved for the
/// needs given ([`SheetData::solve`]). The sheet size used.
pub(super) fn sheets_of(
    study: &Study,
    sweep: &dyn Sweep,
    data: &dyn Fn(SheetNeeds) -> Result<SheetData>,
    req: &DrawRequest,
    sink: &mut dyn FnMut(Sheet) -> Result<()>,
) -> Result<SheetSize> {
    req.validate()?;
    let an = &*study.analysis;
    let only = req
        .positions
        .iter()
        .map(|&k| super::prepared::position_index(an.numbering, k, sweep.len()))
        .collect::<std::result::Result<Vec<usize>, String>>()
        .map_err(|m| Error::scene("position", m))?;
    let sizes = match req.sheet {
        Some(s) => vec![s],
        None => SheetSize::ALL.to_vec(),
    };
    let opt = req.options(study.lang());
    // What the sheets draw beyond the positions (trajectories, extreme
    // positions, the chosen positions, the diagrams) solved here, only
    // for the sheets drawn: presentation never solves.
    let data = data(drawing::sweep_needs(an, sweep, &opt, only.is_empty()))?;
    drawing::sheets_on_each(an, sweep, &data, &opt, (&sizes, &only), sink)
}

/// [`sheets_of`] staged into `req.dir` ([`SheetWriter`]), with the notes
/// for the user, to be put into place ([`finish`]).
pub(super) fn staged_sheets(
    study: &Study,
    sweep: &dyn Sweep,
    data: &dyn Fn(SheetNeeds) -> Result<SheetData>,
    req: &DrawRequest,
) -> Result<(SheetWriter, Vec<String>)> {
    let an = &*study.analysis;
    let mut writer = SheetWriter::new(&req.dir, req.format, req.dpi)?;
    if !req.positions.is_empty() {
        writer = writer.partial();
    }
    let sheet = sheets_of(study, sweep, data, req, &mut |s| writer.put(s))?;
    let mut notes = Vec::new();
    let asked = req.sheet.unwrap_or(SheetSize::A4);
    if sheet != asked {
        notes.push(format!(
            "the drawing of the mechanism at μ_l = {} m/mm (want.scales.mu_l) does not fit sheet {asked:?}: drawn on {sheet:?}",
            an.mech.scene.want.scales.mu_l.unwrap_or(an.mu_l),
        ));
    }
    Ok((writer, notes))
}

/// What [`Solution::draw`] has done before the files are put into place.
enum Staged {
    /// Written (the handout).
    Done(Written),
    /// The sheets staged, and the notes on them.
    Sheets(Box<SheetWriter>, Vec<String>),
}

/// The sheets staged put into place ([`SheetWriter::finish`]), `notes`
/// before the writer's own.
pub(super) fn finish(writer: SheetWriter, mut notes: Vec<String>) -> Result<Written> {
    let mut written = writer.finish()?;
    notes.append(&mut written.notes);
    written.notes = notes;
    Ok(written)
}

/// One solved position, read by name.
#[derive(Clone, Debug)]
pub struct PositionResult<'a> {
    an: &'a Analysis,
    solved: Cow<'a, Solved>,
    /// Its index in the sweep, from 0.
    index: usize,
}

impl PositionResult<'_> {
    /// The position's number, in the study's numbering
    /// ([`Study::numbering`]): a `count` sweep's positions from 0 (the
    /// sheets' "position 0" is the extreme position that starts the
    /// working stroke), given input values' from 1.
    pub fn number(&self) -> usize {
        self.an.numbering.number(self.index)
    }

    /// Every input's coordinate (a crank's angle in rad, a slider's or a
    /// cylinder's displacement in m), in the scene's order of inputs.
    pub fn inputs(&self) -> Vec<f64> {
        self.solved.drives.iter().map(|d| d.q).collect()
    }

    /// Point `name` of the scene at this position; an error naming it if
    /// the scene has no such point or does not report it (a point on no
    /// link the scene's output needs).
    pub fn point(&self, name: &str) -> Result<PointResult> {
        let m = &self.an.mech;
        let unknown = || Error::scene("point", format!("the scene has no point \"{name}\""));
        let p = m.scene.point_index(name).ok_or_else(unknown)?;
        if !self.an.points.contains(&p) {
            return Err(Error::scene(
                "point",
                format!(
                    "point \"{name}\" is on no link the scene's output needs: it is not solved"
                ),
            ));
        }
        let st = self.solved.point(self.an, p);
        let plans = self.solved.plans.as_ref();
        Ok(PointResult {
            place: st.at,
            rates: st.rates,
            analogue: st.analogue,
            measured: (
                plans.and_then(|pl| pl.velocity.value_of(p)),
                plans.and_then(|pl| pl.acceleration.as_ref()?.value_of(p)),
            ),
        })
    }

    /// Link `id` of the scene at this position; an error naming it if the
    /// scene has no such link or does not solve it.
    pub fn link(&self, id: &str) -> Result<LinkResult> {
        let m = &self.an.mech;
        let l = m
            .scene
            .link_index(id)
            .ok_or_else(|| Error::scene("link", format!("the scene has no link \"{id}\"")))?;
        if !self.an.link(l) {
            return Err(Error::scene(
                "link",
                format!("link \"{id}\" is not needed for the scene's output: it is not solved"),
            ));
        }
        let motion = self.solved.motion.get(l).copied().flatten();
        Ok(LinkResult {
            angle: self.solved.config.pose(l).angle,
            rates: motion.map(|mo| (mo.omega, mo.epsilon)),
        })
    }

    /// The plan of `kind` as the construction drew it at this position:
    /// its scale μ ([`Plan::mu`], real value per mm), its points in mm
    /// from the pole by name ([`Plan::points`]: [`PlanPoint::key`],
    /// [`PlanPoint::at`] and the drafting error [`PlanPoint::err`]), its
    /// lines and its steps; `None` where the scene asks for no such plan
    /// (no accelerations asked, or a position whose plans could not be
    /// built).
    ///
    /// # Examples
    ///
    /// ```
    /// use mechplan::{PlanKind, Study};
    /// use mechplan::study::plan::Plan;
    ///
    /// let study = Study::from_json(mechplan::DEFAULT_SCENE)?;
    /// let solution = study.solve()?;
    /// let position = solution.position(3)?;
    /// let plan: &Plan = position.plan(PlanKind::Velocity).expect("velocities are asked");
    /// let b = plan.points.iter().find(|p| p.key == "b").expect("b is drawn");
    /// // b's length on the plan times μ_v is v_B.
    /// let v_b = position.point("B")?.velocity().unwrap().hypot();
    /// assert!((b.at.hypot() * plan.mu - v_b).abs() < 1e-9 * v_b);
    /// # Ok::<(), mechplan::Error>(())
    /// ```
    ///
    /// [`PlanPoint::key`]: crate::study::plan::PlanPoint::key
    /// [`PlanPoint::at`]: crate::study::plan::PlanPoint::at
    /// [`PlanPoint::err`]: crate::study::plan::PlanPoint::err
    pub fn plan(&self, kind: PlanKind) -> Option<&Plan> {
        let plans = self.solved.plans.as_ref()?;
        match kind {
            PlanKind::Velocity => Some(&plans.velocity),
            PlanKind::Acceleration => plans.acceleration.as_ref(),
        }
    }

    /// The balancing moment (N·m, of a crank) or force (N, of a slider or
    /// cylinder) of every input, by the links' equilibrium; `None` without
    /// the scene's `dynamics`.
    pub fn balancing(&self) -> Option<Vec<f64>> {
        let d = self.solved.dynamics.as_ref()?;
        Some(d.balancing.iter().map(|b| b.value()).collect())
    }

    /// The position's object of the result file (a line of
    /// `--format jsonl`).
    pub fn to_json(&self) -> serde_json::Value {
        report::position_json(self.an, self.index, &self.solved)
    }

    /// The solved position itself (the internals, for the project's own
    /// tests).
    #[cfg(feature = "internals")]
    pub fn solved(&self) -> &Solved {
        &self.solved
    }
}

/// A point at one position: its place, velocity and acceleration by the
/// analytic route, and as measured on the plans.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointResult {
    place: Point,
    rates: Option<(Vec2, Vec2)>,
    analogue: Option<(Vec2, Vec2)>,
    measured: (Option<Vec2>, Option<Vec2>),
}

impl PointResult {
    /// Where the point is, m.
    pub fn place(&self) -> Point {
        self.place
    }
    /// Its velocity, m/s; `None` where the scene asks for no velocities.
    pub fn velocity(&self) -> Option<Vec2> {
        self.rates.map(|r| r.0)
    }
    /// Its acceleration, m/s²; `None` where the scene asks for none.
    pub fn acceleration(&self) -> Option<Vec2> {
        self.rates.map(|r| r.1)
    }
    /// Its velocity analogue dP/dq (of the first input): the velocity at
    /// unit input rate.
    pub fn velocity_analogue(&self) -> Option<Vec2> {
        self.analogue.map(|r| r.0)
    }
    /// Its velocity as measured on the velocity plan (segment × μ_v), as
    /// the construction drew it; `None` without plans.
    pub fn measured_velocity(&self) -> Option<Vec2> {
        self.measured.0
    }
    /// Its acceleration as measured on the acceleration plan (segment ×
    /// μ_a); `None` without that plan.
    pub fn measured_acceleration(&self) -> Option<Vec2> {
        self.measured.1
    }
}

/// A link at one position: its angle and rates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LinkResult {
    angle: f64,
    rates: Option<(f64, f64)>,
}

impl LinkResult {
    /// The angle its frame has turned through from the x axis, rad.
    pub fn angle(&self) -> f64 {
        self.angle
    }
    /// Its angular velocity ω, rad/s, counter-clockwise positive; `None`
    /// where the scene asks for no velocities.
    pub fn omega(&self) -> Option<f64> {
        self.rates.map(|r| r.0)
    }
    /// Its angular acceleration ε, rad/s².
    pub fn epsilon(&self) -> Option<f64> {
        self.rates.map(|r| r.1)
    }
}

/// The positions of a study, solved one at a time as they are read: a
/// worker thread solves them (in parallel a chunk at a time) at most a
/// chunk ahead of the reader, so memory stays flat however many positions
/// the scene sweeps ([`Study::positions`]). The first position that
/// cannot be solved comes as an error, and ends the iteration. Dropping
/// the iterator stops the worker.
pub struct Positions<'a> {
    study: &'a Study,
    next: usize,
    rx: Option<Receiver<Result<Solved>>>,
    worker: Option<JoinHandle<()>>,
}

impl Study {
    /// Solve every position, all kept in memory (for a long sweep, see
    /// [`Study::positions`], which keeps none).
    ///
    /// # Errors
    ///
    /// [`Error::Unsolvable`] naming the input value where the mechanism
    /// cannot be assembled (lengths that do not reach:
    /// [`Unsolvable::Assembly`](crate::error::Unsolvable::Assembly)) or where its equations have no unique
    /// solution (a dead centre, the routes' disagreement beyond their
    /// bound: [`Unsolvable::Singular`](crate::error::Unsolvable::Singular)).
    ///
    /// # Examples
    ///
    /// ```
    /// let study = mechplan::Study::default_scene();
    /// let solution = study.solve()?;
    /// assert_eq!(solution.len(), 12);
    /// // The crank of the lecture's six-link turns clockwise at 10 rad/s
    /// // (ω1 = −10 rad/s, counterclockwise positive).
    /// let crank = solution.position(0)?.link("1")?;
    /// assert_eq!(crank.omega(), Some(-10.0));
    /// # Ok::<(), mechplan::Error>(())
    /// ```
    pub fn solve(&self) -> Result<Solution<'_>> {
        Ok(Solution::new(self, self.solved()?))
    }

    /// Every position solved, in order.
    pub(super) fn solved(&self) -> Result<Vec<Solved>> {
        self.held()?;
        let an = &*self.analysis;
        let mut out = Vec::with_capacity(an.mech.scene.positions.count());
        self.each_of(an, |s| {
            out.push(s);
            Ok(())
        })?;
        Ok(out)
    }

    /// Every position, solved as it is read (flat memory; see
    /// [`Positions`]).
    ///
    /// ```
    /// let study = mechplan::Study::default_scene();
    /// let mut fastest = 0.0_f64;
    /// for position in study.positions() {
    ///     let d = position?.point("D")?;
    ///     fastest = fastest.max(d.velocity().unwrap().hypot());
    /// }
    /// assert!(fastest > 0.0);
    /// # Ok::<(), mechplan::Error>(())
    /// ```
    pub fn positions(&self) -> Positions<'_> {
        let (tx, rx) = sync_channel(crate::pipeline::RUN_CHUNK);
        let an = Arc::clone(&self.analysis);
        let watcher = self.watcher.clone();
        let worker = std::thread::spawn(move || run_into(&an, &watcher, &tx));
        Positions {
            study: self,
            next: 0,
            rx: Some(rx),
            worker: Some(worker),
        }
    }
}

/// The worker of [`Positions`]: every position sent in order, then the
/// error that stopped the run (none when the reader has gone).
fn run_into(an: &Analysis, watcher: &Watcher, tx: &SyncSender<Result<Solved>>) {
    let gone = || Error::Internal("the reader of the positions has gone".into());
    let done = an.run_each_with(watcher.get(), |s| tx.send(Ok(s)).map_err(|_| gone()));
    if let Err(e) = done {
        // Sending fails only when the reader has gone: nobody to tell.
        let _ = tx.send(Err(e));
    }
}

impl<'a> Iterator for Positions<'a> {
    type Item = Result<PositionResult<'a>>;

    fn next(&mut self) -> Option<Self::Item> {
        let got = self.rx.as_ref()?.recv().ok();
        match got {
            Some(Ok(s)) => {
                self.next += 1;
                Some(Ok(PositionResult {
                    an: &self.study.analysis,
                    solved: Cow::Owned(s),
                    index: self.next - 1,
                }))
            }
            Some(Err(e)) => {
                self.rx = None;
                Some(Err(e))
            }
            None => {
                self.rx = None;
                None
            }
        }
    }
}

impl Drop for Positions<'_> {
    fn drop(&mut self) {
        // The worker's next send fails and the run stops there.
        self.rx = None;
        if let Some(w) = self.worker.take() {
            let _ = w.join();
        }
    }
}

impl std::fmt::Debug for Positions<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Positions")
            .field("next", &self.next)
            .finish_non_exhaustive()
    }
}
