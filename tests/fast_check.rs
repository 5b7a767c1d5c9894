//! The fast path's certification where nothing prints it (a table or CSV
//! sweep, `Analysis::printed_check` false): the conditioning only decided
//! (a lower bound from the Jacobian's inverse, the SVD only below the
//! thresholds it is compared with), no bounds built. Every decision must
//! be the SVD's: over the whole stress catalogue and the fixtures, position
//! by position as the file reaches it, the same positions answered with
//! the same numbers, the same ones refused with the same message, the same
//! choice of the data check (linearized or solved again).

use mechplan::analytic::constraint::ConstraintSolver;
use mechplan::scene::PositionsSpec;
use mechplan::{Analysis, Scene};
use std::path::Path;

fn scenes() -> Vec<std::path::PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut v = Vec::new();
    for dir in ["fixtures/stress", "fixtures"] {
        for e in std::fs::read_dir(root.join(dir)).unwrap() {
            let p = e.unwrap().path();
            if p.extension().is_some_and(|e| e == "json") {
                v.push(p);
            }
        }
    }
    v.sort();
    v
}

/// The fast path of `scene` (no plans) with the check printed or not: per
/// position, the CSV row and the data check's kind, or the refusal.
fn outcome(an: &Analysis, printed: bool) -> Result<Vec<(String, String)>, String> {
    let mut an = an.clone();
    an.printed_check = printed;
    let mut rows = Vec::new();
    let mut k = 0;
    an.run_each(|s| {
        let check = s.check.as_ref().unwrap();
        rows.push((
            mechplan::report::csv_row(&an, k, &s),
            format!(
                "{:?} {:e} {:e}",
                check.method,
                check.max_rel_diff,
                check.data_sensitivity.unwrap()
            ),
        ));
        k += 1;
        Ok(())
    })
    .map_err(|e| e.to_string())?;
    Ok(rows)
}

#[test]
fn decided_conditioning_decides_as_the_svd() {
    let mut compared = (0, 0);
    let mut failures = Vec::new();
    for path in scenes() {
        let name = path.file_stem().unwrap().to_string_lossy().into_owned();
        let text = std::fs::read_to_string(&path).unwrap();
        let Ok(mut scene) = Scene::from_json(&text) else {
            continue;
        };
        if scene.dynamics.is_some() {
            continue;
        }
        scene.want.plans = false;
        let Ok(an) = Analysis::new(scene.clone()) else {
            continue;
        };
        let Ok(inputs) = an.input_positions() else {
            continue;
        };
        let qs: Vec<f64> = inputs.iter().map(|p| p.value.first()).collect();
        if scene.several_inputs() {
            continue;
        }
        let rounding: Vec<f64> = inputs.iter().map(|p| p.rounding.first()).collect();
        // Each position after the ones answered before it, as a user
        // reaches it.
        let mut accepted: Vec<usize> = Vec::new();
        for k in 0..qs.len().min(40) {
            let path: Vec<usize> = accepted.iter().copied().chain([k]).collect();
            let mut one = scene.clone();
            one.positions = PositionsSpec::List(path.iter().map(|&i| qs[i]).collect());
            one.input_rounding = path.iter().map(|&i| rounding[i]).collect();
            let an = Analysis::new(one).unwrap();
            let (exact, decided) = (outcome(&an, true), outcome(&an, false));
            match (&exact, &decided) {
                (Ok(_), Ok(_)) => compared.0 += 1,
                (Err(_), Err(_)) => compared.1 += 1,
                _ => {}
            }
            if exact != decided {
                failures.push(format!(
                    "{name} position {}: with the SVD {exact:?}, decided {decided:?}",
                    k + 1
                ));
            }
            if exact.is_ok() {
                accepted.push(k);
            }
        }
    }
    eprintln!(
        "{} positions answered alike, {} refused alike",
        compared.0, compared.1
    );
    assert!(compared.0 > 300 && compared.1 > 10, "{compared:?}");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The lower bound the decision rests on: at most σ_min/σ_max, at least
/// that over n, at every answered position of the catalogue.
#[test]
fn conditioning_bound_brackets_the_svd() {
    let mut seen = 0;
    for path in scenes() {
        let text = std::fs::read_to_string(&path).unwrap();
        let Ok(mut scene) = Scene::from_json(&text) else {
            continue;
        };
        scene.want.plans = false;
        let Ok(an) = Analysis::new(scene) else {
            continue;
        };
        let cs = ConstraintSolver::new(&an.mech, &an.include, Default::default());
        let _ = an.run_each(|s| {
            let u = cs.unknowns(|l| s.config.pose(l), &s.motion, None);
            let (exact, bound, n) = cs.conditioning_both(&u);
            if let Some(bound) = bound {
                assert!(
                    bound <= exact && bound * n as f64 >= exact * (1.0 - 1e-9),
                    "{}: bound {bound:e}, σ_min/σ_max {exact:e}, n = {n}",
                    path.display()
                );
                seen += 1;
            }
            Ok(())
        });
    }
    assert!(seen > 300, "{seen}");
}
