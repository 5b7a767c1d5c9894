//! `check`'s answers at their limits: a file too large, elements nested too
//! deep (refused with a clear message and status 2, fast, instead of a
//! stack overflow), a large SVG read in linear time, and `--position`
//! outside the scene's positions (numbered from 1).

use std::path::PathBuf;
use std::process::{Command, Output};
use std::time::{Duration, Instant};

const EXE: &str = env!("CARGO_BIN_EXE_mechplan");

fn six_link() -> String {
    format!(
        "{}/fixtures/six_link_fig2_10.json",
        env!("CARGO_MANIFEST_DIR")
    )
}

fn temp(name: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("mechplan-limits-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

fn run(args: &[&str]) -> (Output, Duration) {
    let t = Instant::now();
    let o = Command::new(EXE).args(args).output().unwrap();
    (o, t.elapsed())
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// A velocity plan: the pole p_v, one segment to b, the scale; `depth`
/// nested groups around it (each shifting by 0.01 user units), and `fill`
/// more labelled segments (c and d, wrong places) up to about `bytes`.
fn plan_svg(depth: usize, bytes: usize) -> String {
    let mut s = String::from(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="210mm" height="297mm" viewBox="0 0 210 297">"#,
    );
    s.push('\n');
    for _ in 0..depth {
        s.push_str(r#"<g transform="translate(0.01,0)">"#);
    }
    s.push_str(
        "\n<line x1=\"50\" y1=\"50\" x2=\"90\" y2=\"30\"/>\n<text x=\"48\" y=\"48\">p_v</text>\n<text x=\"90\" y=\"28\">b</text>\n<text x=\"5\" y=\"280\">μ = 0.01</text>\n",
    );
    // A fixed pseudo-random scatter (a linear congruential sequence).
    let mut r: u64 = 12345;
    let mut next = || {
        r = r
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (r >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut k = 0;
    while s.len() < bytes {
        let (x, y) = (200.0 * next(), 280.0 * next());
        s.push_str(&format!(
            "<path d=\"M {x:.3} {y:.3} L {:.3} {:.3}\"/><text x=\"{:.3}\" y=\"{:.3}\">{}</text>\n",
            x + 5.0,
            y + 5.0,
            x + 5.5,
            y + 5.5,
            ["c", "d"][k % 2]
        ));
        k += 1;
    }
    for _ in 0..depth {
        s.push_str("</g>");
    }
    s.push_str("</svg>\n");
    s
}

#[test]
fn deeply_nested_groups_are_refused_not_a_stack_overflow() {
    let scene = six_link();
    let deep = temp("deep.svg", &plan_svg(20_000, 0));
    let (o, t) = run(&["check", &scene, deep.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("nested more than 256 deep") && stderr(&o).contains("deep.svg"),
        "{}",
        stderr(&o)
    );
    assert!(t < Duration::from_secs(5), "{t:?}");
    // At the limit the file is read (in a test thread's small stack too).
    let at_limit = plan_svg(mechplan::check::svg::MAX_DEPTH - 2, 0);
    let over = plan_svg(mechplan::check::svg::MAX_DEPTH - 1, 0);
    std::thread::Builder::new()
        .stack_size(256 << 10)
        .spawn(move || {
            let a = mechplan::check::svg::from_svg(&at_limit, None, None, 0.5, 1).unwrap();
            assert_eq!(a.items.len(), 1);
            let e = mechplan::check::svg::from_svg(&over, None, None, 0.5, 1).unwrap_err();
            assert!(e.to_string().contains("nested more than"), "{e}");
        })
        .unwrap()
        .join()
        .unwrap();
}

#[test]
fn a_huge_answer_is_refused_before_it_is_read() {
    let scene = six_link();
    let max = mechplan::check::answer::MAX_ANSWER_BYTES;
    for (name, text) in [
        ("huge.svg", " ".repeat(max + 1)),
        ("huge.json", " ".repeat(max + 1) + "{}"),
    ] {
        let p = temp(name, &text);
        let (o, t) = run(&["check", &scene, p.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
        assert!(
            stderr(&o).contains(&format!("at most {max}")) && stderr(&o).contains(name),
            "{}",
            stderr(&o)
        );
        assert!(t < Duration::from_secs(5), "{t:?}");
    }
    let e =
        mechplan::check::svg::from_svg(&" ".repeat(max + 1), Some(0.01), None, 0.5, 1).unwrap_err();
    assert!(e.to_string().contains("at most"), "{e}");
}

/// 3 MB of labelled segments in groups nested 250 deep: the per-element
/// walk over its ancestors and the search of every line end for every label
/// made this 47 s (13 s without the nesting); now it is linear. Its
/// thousands of labels c and d at different line ends give each point
/// thousands of places: refused (status 2) as given many times, in one
/// message per point, found in linear time too.
#[test]
fn a_large_svg_answer_is_read_in_linear_time() {
    let scene = six_link();
    let big = temp("big.svg", &plan_svg(250, 3_000_000));
    let (o, t) = run(&["check", &scene, big.to_str().unwrap(), "--plan", "velocity"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(t < Duration::from_secs(10), "{t:?}");
    let err = stderr(&o);
    assert!(
        err.contains("svg: label c: point c is given")
            && err.contains("svg: label d: point d is given")
            && err.lines().count() == 2,
        "{err}"
    );
}

#[test]
fn position_outside_the_scene_is_bad_input() {
    let scene = six_link();
    // The six-link fixture has 12 positions, counted from 0 as its sheets
    // count them; `--positions-from 1` reads them from 1, as mechplan
    // numbered them before.
    let svg = temp("plan.svg", &plan_svg(1, 0));
    let json = temp(
        "plan.json",
        r#"{ "plan": "velocity", "mu": 0.01, "points": { "b": [40, 20] } }"#,
    );
    for answer in [&svg, &json] {
        let a = answer.to_str().unwrap();
        for (p, from, range) in [
            ("12", None, "from 0 to 11"),
            ("13", None, "from 0 to 11"),
            ("0", Some("1"), "from 1 to 12"),
            ("13", Some("1"), "from 1 to 12"),
        ] {
            let mut args = vec!["check", &scene, a, "--position", p];
            args.extend(from.iter().flat_map(|f| ["--positions-from", f]));
            let (o, _) = run(&args);
            assert_eq!(o.status.code(), Some(2), "{a} {p}: {}", stderr(&o));
            let err = stderr(&o);
            assert!(
                err.contains("--position")
                    && err.contains(&format!("position {p} "))
                    && err.contains(range),
                "{a} {p} {from:?}: {err}"
            );
        }
        for (p, from) in [
            ("0", None),
            ("11", None),
            ("1", Some("1")),
            ("12", Some("1")),
        ] {
            let mut args = vec!["check", &scene, a, "--position", p];
            args.extend(from.iter().flat_map(|f| ["--positions-from", f]));
            let (o, _) = run(&args);
            assert!(
                matches!(o.status.code(), Some(0 | 1)),
                "{a} {p}: {}",
                stderr(&o)
            );
            assert!(String::from_utf8_lossy(&o.stdout).contains(&format!("position {p},")));
        }
    }
    // The answer file's own position, outside the scene's.
    let far = temp(
        "far.json",
        r#"{ "plan": "velocity", "position": 12, "mu": 0.01, "points": { "b": [40, 20] } }"#,
    );
    let (o, _) = run(&["check", &scene, far.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("/position") && stderr(&o).contains("from 0 to 11"),
        "{}",
        stderr(&o)
    );
    for p in ["12", "13"] {
        let (o, _) = run(&["centres", &scene, "--position", p]);
        assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
        assert!(
            stderr(&o).contains("--position") && stderr(&o).contains("from 0 to 11"),
            "{}",
            stderr(&o)
        );
    }
}
