//! The mechplan side of `benches/peers/million.sh`: a million positions
//! of the four-bar fixture, end to end, into a CSV file.
//!
//! `cargo run --release --example peers_million -- N OUT_DIR`: the crank
//! of `fixtures/four_bar.json` is turned through N equal steps of a full
//! turn from its own angle. Timed, one after the other:
//!
//! - `compiled_csv`: positions, velocities and accelerations by route (a)
//!   compiled for the mechanism (`compiled::Program::solve_one`), each
//!   position written as a CSV row to `OUT_DIR/mechplan.csv` as it is
//!   solved (the library writing CSV itself; `mechplan solve --format csv`
//!   is the checked command-line path, timed by the script);
//! - `closed_csv`: the hand-written closed form (`closed_form.rs`), the
//!   same rows to `OUT_DIR/closed_form.csv` (each CSV twice, alternating,
//!   the faster kept; `closed_csv_cpu_s` its thread's CPU time, the less
//!   of the two);
//! - `compiled` and `closed`: the same two without writing (a checksum of
//!   the results kept, so nothing is optimized away).
//!
//! The rows: `position,phi_1` then `x,y,vx,vy,ax,ay` of A, B, M and
//! `angle,omega,epsilon` of links 2 and 3 (SI units, degrees for angles),
//! the numbers as the shortest text that reads back to the same double:
//! the columns of `solve --format csv` for those points and links. Before
//! anything is timed the two are compared at every position (the largest
//! difference relative to the largest magnitude of each kind is printed);
//! `OUT_DIR/b.f64` keeps B's place, velocity and acceleration (six
//! little-endian doubles per position) for the script to check
//! pylinkage's against. Prints one JSON line of seconds.

#[path = "closed_form.rs"]
mod closed_form;

use closed_form::{FourBar, FourBarState};
use mechplan::analytic::{Drive, Order};
use mechplan::compiled::{Program, State};
use mechplan::{Analysis, Scene};
use std::io::Write;
use std::time::Instant;

/// One position's numbers in the rows' order: A, B, M (x, y, vx, vy, ax,
/// ay), links 2, 3 (angle in degrees, ω, ε).
type Row = [f64; 24];

/// The row of the compiled route's state.
fn row_of(an: &Analysis, st: &State, pts: &[(usize, usize)], links: &[usize]) -> Row {
    let m = &an.mech;
    let mut r = [0.0; 24];
    for (i, &(p, l)) in pts.iter().enumerate() {
        let mo = st.motion[l].expect("solved link");
        let at = mo.pose.apply(m.local(l, p));
        let (v, a) = (mo.velocity(at), mo.acceleration(at));
        r[6 * i..6 * i + 6].copy_from_slice(&[at.x, at.y, v.x, v.y, a.x, a.y]);
    }
    for (i, &l) in links.iter().enumerate() {
        let mo = st.motion[l].expect("solved link");
        let deg = mechplan::geom::wrap_pi(mo.pose.angle).to_degrees();
        r[18 + 3 * i..21 + 3 * i].copy_from_slice(&[deg, mo.omega, mo.epsilon]);
    }
    r
}

/// The row of the closed form's state.
fn row_closed(s: &FourBarState) -> Row {
    let mut r = [0.0; 24];
    for i in 0..3 {
        r[6 * i..6 * i + 6].copy_from_slice(&[
            s.p[i][0],
            s.p[i][1],
            s.v[i][0],
            s.v[i][1],
            s.acc[i][0],
            s.acc[i][1],
        ]);
    }
    for i in 0..2 {
        r[18 + 3 * i..21 + 3 * i].copy_from_slice(&[s.theta[i].to_degrees(), s.omega[i], s.eps[i]]);
    }
    r
}

const HEADER: &str = "position,phi_1,x_A,y_A,vx_A,vy_A,ax_A,ay_A,x_B,y_B,vx_B,vy_B,ax_B,ay_B,\
x_M,y_M,vx_M,vy_M,ax_M,ay_M,angle_2,omega_2,epsilon_2,angle_3,omega_3,epsilon_3";

/// One CSV row: the shortest text of each double, no `-0`.
fn write_row(w: &mut impl Write, k: usize, phi: f64, r: &Row) -> std::io::Result<()> {
    write!(w, "{}", k + 1)?;
    for &x in std::iter::once(&phi).chain(r.iter()) {
        let x = if x == 0.0 { 0.0 } else { x };
        write!(w, ",{x}")?;
    }
    w.write_all(b"\n")
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let n: usize = args.first().map_or(Ok(1_000_000), |a| a.parse())?;
    let out = std::path::PathBuf::from(args.get(1).map_or("target/peers", |s| s.as_str()));
    std::fs::create_dir_all(&out)?;
    let root = env!("CARGO_MANIFEST_DIR");
    let text = std::fs::read_to_string(format!("{root}/fixtures/four_bar.json"))?;
    let an = Analysis::new(Scene::from_json(&text)?)?;
    let fb = FourBar::from_scene(&serde_json::from_str(&text)?);
    let m = &an.mech;
    let (rate, rate2) = m.scene.input.rates();
    let q0 = m.scene.input.coordinate();
    let q = |k: usize| q0 + std::f64::consts::TAU * k as f64 / n as f64;
    let point = |name: &str| m.scene.points.iter().position(|p| p.name == name).unwrap();
    let link = |id: &str| m.scene.links.iter().position(|l| l.id == id).unwrap();
    let pts: Vec<(usize, usize)> = ["A", "B", "M"]
        .iter()
        .map(|&p| (point(p), an.carrier(point(p))))
        .collect();
    let links = [link("2"), link("3")];
    let prog = Program::new(m, &an.structure, &an.need)?;
    let drive = |k: usize| Drive {
        q: q(k),
        rate,
        rate2,
    };

    // The two agree at every position, before anything is timed.
    let mut st = prog.state();
    let mut worst = [0.0f64; 4];
    let mut scale = [0.0f64; 4];
    let mut b = std::io::BufWriter::new(std::fs::File::create(out.join("b.f64"))?);
    // The kinds of a row's numbers: place, velocity, acceleration, link angle/rates.
    let kind = |j: usize| if j >= 18 { 3 } else { (j % 6) / 2 };
    for k in 0..n {
        prog.solve_one(&mut st, drive(k), Order::Acceleration)?;
        let (x, y) = (row_of(&an, &st, &pts, &links), row_closed(&fb.solve(q(k))));
        for j in 0..24 {
            let d = if j >= 18 && j % 3 == 0 {
                mechplan::geom::wrap_pi((x[j] - y[j]).to_radians()).to_degrees()
            } else {
                x[j] - y[j]
            };
            worst[kind(j)] = worst[kind(j)].max(d.abs());
            scale[kind(j)] = scale[kind(j)].max(y[j].abs());
        }
        for v in &x[6..12] {
            b.write_all(&v.to_le_bytes())?;
        }
    }
    b.flush()?;
    b.get_ref().sync_all()?;
    let rel: Vec<f64> = worst.iter().zip(&scale).map(|(w, s)| w / s).collect();
    let agree = rel.iter().copied().fold(0.0, f64::max);
    assert!(
        agree < 1e-9,
        "mechplan and the closed form disagree: {rel:?}"
    );

    let timed = |f: &mut dyn FnMut() -> std::io::Result<f64>| -> std::io::Result<(f64, f64)> {
        let t = Instant::now();
        let sum = f()?;
        Ok((t.elapsed().as_secs_f64(), sum))
    };
    let csv = |name: &str| -> std::io::Result<std::io::BufWriter<std::fs::File>> {
        let mut w =
            std::io::BufWriter::with_capacity(1 << 20, std::fs::File::create(out.join(name))?);
        writeln!(w, "{HEADER}")?;
        Ok(w)
    };
    let deg = |k: usize| q(k).to_degrees();

    // Each CSV twice, alternating, the faster run kept; each file synced
    // to the disk after its timing (not in it), so that the write-back of
    // one writer's half a gigabyte does not fall into the next writer's
    // time, and removed before it: a new file each time (ext4 writes a
    // file that replaces another back at once, in the writer's time: about
    // 35 ms for these 50 MB).
    let synced = |name: &str| std::fs::File::open(out.join(name))?.sync_all();
    let fresh = |name: &str| match std::fs::remove_file(out.join(name)) {
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => Err(e),
        _ => Ok(()),
    };
    let (mut compiled_csv, mut closed_csv) = (f64::INFINITY, f64::INFINITY);
    let mut closed_csv_cpu = f64::INFINITY;
    for _ in 0..2 {
        let mut st = prog.state();
        fresh("mechplan.csv")?;
        let (t, _) = timed(&mut || {
            let mut w = csv("mechplan.csv")?;
            for k in 0..n {
                prog.solve_one(&mut st, drive(k), Order::Acceleration)
                    .map_err(std::io::Error::other)?;
                write_row(&mut w, k, deg(k), &row_of(&an, &st, &pts, &links))?;
            }
            w.flush()?;
            Ok(0.0)
        })?;
        compiled_csv = compiled_csv.min(t);
        synced("mechplan.csv")?;
        fresh("closed_form.csv")?;
        let cpu0 = thread_cpu_s();
        let (t, _) = timed(&mut || {
            let mut w = csv("closed_form.csv")?;
            for k in 0..n {
                write_row(&mut w, k, deg(k), &row_closed(&fb.solve(q(k))))?;
            }
            w.flush()?;
            Ok(0.0)
        })?;
        closed_csv = closed_csv.min(t);
        closed_csv_cpu = closed_csv_cpu.min(thread_cpu_s() - cpu0);
        synced("closed_form.csv")?;
    }
    let mut st = prog.state();
    let (compiled, _) = timed(&mut || {
        let mut sum = 0.0;
        for k in 0..n {
            prog.solve_one(&mut st, drive(k), Order::Acceleration)
                .map_err(std::io::Error::other)?;
            sum += row_of(&an, &st, &pts, &links).iter().sum::<f64>();
        }
        Ok(std::hint::black_box(sum))
    })?;
    let (closed, _) = timed(&mut || {
        Ok(std::hint::black_box(
            (0..n)
                .map(|k| row_closed(&fb.solve(q(k))).iter().sum::<f64>())
                .sum(),
        ))
    })?;
    let size = |name: &str| {
        std::fs::metadata(out.join(name))
            .map(|m| m.len())
            .unwrap_or(0)
    };
    println!(
        "{{\"positions\": {n}, \"compiled_csv_s\": {compiled_csv:.6}, \"closed_csv_s\": {closed_csv:.6}, \
\"closed_csv_cpu_s\": {closed_csv_cpu:.6}, \
\"compiled_s\": {compiled:.6}, \"closed_s\": {closed:.6}, \"csv_bytes\": {}, \
\"max_rel_diff\": {agree:.2e}}}",
        size("mechplan.csv"),
    );
    Ok(())
}

/// The CPU time of this thread so far, seconds: the first field of
/// `/proc/thread-self/schedstat` (ns on the CPU; Linux); NaN elsewhere.
fn thread_cpu_s() -> f64 {
    std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse::<f64>().ok())
        .map_or(f64::NAN, |ns| ns * 1e-9)
}
