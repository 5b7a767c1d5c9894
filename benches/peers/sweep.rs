//! The sweep that `benches/peers/run.sh` times against Python peers.
//!
//! `cargo run --release --example peers_sweep -- FIXTURE N [CSV]`: the
//! fixture's crank is turned through N equal steps of a full turn from its
//! own angle; at each, the positions and route (a) (velocities and
//! accelerations by the closed vector contours, compiled for the
//! mechanism: `compiled::Program::solve_one`) are solved, and the place,
//! velocity and acceleration of every point are read off (SI units). Only
//! that solve is timed (the median of several sweeps). Then the whole
//! analysis (`Analysis::run`: both routes, the plans' construction, the
//! cross-check) is timed once on the same N positions. Prints one JSON
//! line; with CSV, writes `k,phi,point,x,y,vx,vy,ax,ay` rows for the
//! peers' results to be checked against.

use mechplan::analytic::{Drive, Order};
use mechplan::compiled::Program;
use mechplan::{Analysis, Scene};
use std::hint::black_box;
use std::io::Write as _;
use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (Some(path), Some(n)) = (args.first(), args.get(1)) else {
        return Err("usage: peers_sweep FIXTURE N [CSV]".into());
    };
    let n: usize = n.parse()?;
    let text = std::fs::read_to_string(path)?;
    let an = Analysis::new(Scene::from_json(&text)?)?;
    let m = &an.mech;
    let (rate, rate2) = m.scene.input.rates();
    let q0 = m.scene.input.coordinate();
    let qs: Vec<f64> = (0..n)
        .map(|k| q0 + std::f64::consts::TAU * k as f64 / n as f64)
        .collect();
    let carriers: Vec<(usize, usize)> = an.points.iter().map(|&p| (p, an.carrier(p))).collect();
    // (x, y, vx, vy, ax, ay) of every reported point at every position.
    let mut out = vec![[0.0f64; 6]; n * carriers.len()];
    let prog = Program::new(m, &an.structure, &an.need)?;
    let sweep = |out: &mut [[f64; 6]]| -> mechplan::Result<()> {
        let mut st = prog.state();
        for (k, &q) in qs.iter().enumerate() {
            prog.solve_one(&mut st, Drive { q, rate, rate2 }, Order::Acceleration)?;
            for (i, &(p, l)) in carriers.iter().enumerate() {
                let at = st.config.point(m, l, p);
                let x = st.motion[l].expect("solved link");
                let (v, a) = (x.velocity(at), x.acceleration(at));
                out[k * carriers.len() + i] = [at.x, at.y, v.x, v.y, a.x, a.y];
            }
        }
        Ok(())
    };
    sweep(&mut out)?; // warm-up
    let mut times = Vec::new();
    for _ in 0..15 {
        let t = Instant::now();
        sweep(black_box(&mut out))?;
        times.push(t.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    let route_a = times[times.len() / 2];

    // The whole analysis on the same positions (scene angles in degrees or
    // radians, as the fixture's units say).
    let mut v: serde_json::Value = serde_json::from_str(&text)?;
    let deg = v["units"]["angle"].as_str() != Some("rad");
    let angles: Vec<f64> = qs
        .iter()
        .map(|q| if deg { q.to_degrees() } else { *q })
        .collect();
    v["positions"] = serde_json::json!({ "angles": angles });
    let full = Analysis::new(Scene::from_json(&v.to_string())?)?;
    let t = Instant::now();
    let solved = full.run()?;
    let run = t.elapsed().as_secs_f64();
    assert_eq!(solved.len(), n);

    println!(
        "{{\"fixture\": {:?}, \"positions\": {n}, \"route_a_s\": {route_a:.6e}, \"route_a_per_position_s\": {:.6e}, \"run_s\": {run:.6e}, \"run_per_position_s\": {:.6e}}}",
        path,
        route_a / n as f64,
        run / n as f64
    );
    if let Some(csv) = args.get(2) {
        let mut f = std::io::BufWriter::new(std::fs::File::create(csv)?);
        writeln!(f, "k,phi,point,x,y,vx,vy,ax,ay")?;
        for (k, q) in qs.iter().enumerate() {
            for (i, &(p, _)) in carriers.iter().enumerate() {
                let r = out[k * carriers.len() + i];
                writeln!(
                    f,
                    "{k},{q:.17e},{},{:.17e},{:.17e},{:.17e},{:.17e},{:.17e},{:.17e}",
                    m.point_name(p),
                    r[0],
                    r[1],
                    r[2],
                    r[3],
                    r[4],
                    r[5]
                )?;
            }
        }
    }
    Ok(())
}
