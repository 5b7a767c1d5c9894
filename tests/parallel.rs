//! Long sweeps run in parallel (`mechplan::progress`): their results, and
//! their first error, are those of a sequential run.

mod common;
use common::*;
use mechplan::Analysis;
use mechplan::reference::Reference;
use serde_json::{Value, json};

/// The result file without its wall times (the only thing that may differ).
fn without_times(mut v: Value) -> Value {
    for p in v["positions"].as_array_mut().unwrap() {
        if let Some(c) = p.get_mut("crosscheck").and_then(Value::as_object_mut) {
            c.remove("time_s");
        }
    }
    v
}

fn on_threads<R: Send>(n: usize, f: impl FnOnce() -> R + Send) -> R {
    rayon::ThreadPoolBuilder::new()
        .num_threads(n)
        .build()
        .unwrap()
        .install(f)
}

/// Every fixture over its 1° sweep (more positions than the parallel
/// threshold): one thread and two threads give the same result file.
#[test]
fn parallel_run_equals_sequential_run_on_every_fixture() {
    for name in FIXTURES {
        let v = fixture(name);
        let an = Analysis::new(scene_with(v.clone(), sweep(name, &v))).unwrap();
        assert!(an.input_values().unwrap().len() >= mechplan::progress::PARALLEL_FROM);
        let one = on_threads(1, || an.run().unwrap());
        let two = on_threads(2, || an.run().unwrap());
        assert_eq!(
            without_times(mechplan::report::to_json(&an, &one)),
            without_times(mechplan::report::to_json(&an, &two)),
            "{name}"
        );
    }
}

/// A sweep that runs into the class III group's dead point (near 34.6°)
/// after many good positions: the same refusal either way.
#[test]
fn parallel_run_reports_the_first_error_in_order() {
    let v = fixture("class3_004");
    let angles: Vec<f64> = (0..=200).map(|k| -90.0 + k as f64).collect();
    let an = Analysis::new(scene_with(v, json!({ "angles": angles }))).unwrap();
    let one = on_threads(1, || an.run().unwrap_err().to_string());
    let two = on_threads(2, || an.run().unwrap_err().to_string());
    assert_eq!(one, two);
    assert!(one.contains("φ = 3") || one.contains("φ = 2"), "{one}");
}

/// The extended-precision reference refined in parallel from its ordered
/// starts equals the one solved position by position.
#[test]
fn reference_refined_in_parallel_equals_sequential() {
    let v = fixture("six_link_fig2_10");
    let an = Analysis::new(scene_with(v.clone(), sweep("six_link_fig2_10", &v))).unwrap();
    let qs: Vec<f64> = an.input_values().unwrap().into_iter().step_by(9).collect();
    let mut seq = Reference::new(&an).unwrap();
    let want: Vec<String> = qs
        .iter()
        .map(|&q| format!("{:?}", seq.solve_f64(q).unwrap().links))
        .collect();
    let mut re = Reference::new(&an).unwrap();
    let starts: Vec<_> = qs.iter().copied().zip(re.starts(&qs).unwrap()).collect();
    let got = on_threads(2, || {
        mechplan::progress::map(
            &starts,
            "reference",
            &mechplan::progress::Silent,
            |(q, c)| {
                let q = mechplan::reference::Real::from_f64(*q);
                format!("{:?}", re.refine(&q, c).unwrap().links)
            },
        )
    });
    assert_eq!(want, got);
}

/// Runs themselves run in parallel on the global pool (a study of many
/// scenes): a long fast-path sweep finishes there — its chunks finished
/// on the caller's pool, not on a thread of their own that the waiting
/// workers could never help (a deadlock once every worker waited) — and
/// in a one-thread pool. Judged within a minute, so that a deadlock fails
/// instead of hanging.
#[test]
fn runs_inside_a_thread_pool_finish_on_it() {
    use rayon::prelude::*;
    let mut v = fixture("four_bar");
    v["positions"] = json!({ "count": 2000 });
    v["want"] = json!({ "plans": [] });
    let an = Analysis::new(scene_with(v.clone(), v["positions"].clone())).unwrap();
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let lens: Vec<usize> = (0..8)
            .into_par_iter()
            .map(|_| an.run().unwrap().len())
            .collect();
        let threads = on_threads(1, || an.run().unwrap().len());
        tx.send((lens, threads)).unwrap();
    });
    let (lens, one) = rx
        .recv_timeout(std::time::Duration::from_secs(60))
        .expect("runs on the global pool did not finish within a minute");
    assert_eq!(lens, vec![2000; 8]);
    assert_eq!(one, 2000);
}
