//! Bad answers are refused (bad input, status 2) with the field named,
//! never graded: a thing given twice under two spellings, a letter of no
//! plan or of the other plan, a number that is not finite or absurd, a
//! position the scene has not, an answer of another plan than it says
//! (docs/check.md, "The answer file"); an answer whose points fit another
//! position is graded, never refused.

mod common;
use common::*;
use mechplan::check::answer::from_json;
use mechplan::check::{check, resolve};
use mechplan::{Analysis, CheckRequest, PlanKind, Solved, Study};
use serde_json::{Value, json};
use std::process::Command;

/// A fixture as a study (its own 12 positions).
fn study(name: &str) -> Study {
    Study::from_json(&fixture(name).to_string()).unwrap()
}

/// A fixture's analysis and its positions.
fn solved(name: &str) -> (Analysis, Vec<Solved>) {
    solve(mechplan::Scene::from_json(&fixture(name).to_string()).unwrap())
}

/// The problems of a JSON answer (read, then checked) as text, one a line;
/// empty if it was accepted.
fn refusal(name: &str, answer: &Value) -> String {
    refusal_with(name, answer, &CheckRequest::default())
}

fn refusal_with(name: &str, answer: &Value, req: &CheckRequest) -> String {
    let s = study(name);
    let sol = s.solve().unwrap();
    match sol.check_answer(&answer.to_string(), "answer.json", false, req) {
        Ok(_) => String::new(),
        Err(e) => e.to_string(),
    }
}

/// Does `err` have the line `pointer: …message…`?
fn names(err: &str, pointer: &str, message: &str) -> bool {
    err.lines()
        .any(|l| l.starts_with(&format!("{pointer}: ")) && l.contains(message))
}

/// Where plan point `name` is on the standard plan `kind` at position
/// `k` (its number: these scenes count their positions from 0, as their
/// sheets do), mm from the pole.
fn place(solved: &[Solved], k: usize, kind: PlanKind, name: &str) -> [f64; 2] {
    let plans = solved[k].plans.as_ref().unwrap();
    let plan = match kind {
        PlanKind::Velocity => &plans.velocity,
        PlanKind::Acceleration => plans.acceleration.as_ref().unwrap(),
    };
    let p = plan.points[resolve(plan, name).unwrap()].at;
    [p.x, p.y]
}

fn standard_mu(solved: &[Solved], kind: PlanKind) -> f64 {
    let plans = solved[0].plans.as_ref().unwrap();
    match kind {
        PlanKind::Velocity => plans.velocity.mu,
        PlanKind::Acceleration => plans.acceleration.as_ref().unwrap().mu,
    }
}

/// An SVG plan: the pole labelled `pole` at (50, 150) on an A4 page (user
/// units are mm), a segment from it to each labelled end (`labels`: name,
/// x, y), and the text `scale` ("μ = 0.01").
fn svg(pole: &str, scale: &str, labels: &[(&str, f64, f64)]) -> String {
    let mut body =
        format!(r#"<text x="48" y="148">{pole}</text><text x="5" y="280">{scale}</text>"#);
    for (name, x, y) in labels {
        body.push_str(&format!(
            r#"<line x1="50" y1="150" x2="{x}" y2="{y}"/><text x="{}" y="{}">{name}</text>"#,
            x + 1.0,
            y - 1.0
        ));
    }
    format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="210mm" height="297mm" viewBox="0 0 210 297">{body}</svg>"#
    )
}

/// The same plan point, segment or value under two spellings in one
/// answer is refused at the second, naming the first; a JSON key twice
/// too. One rule for JSON and SVG: two labels of one point at different
/// line ends are refused, the same label twice at one end is harmless.
#[test]
fn a_thing_given_twice_is_refused_naming_both() {
    let acc = json!({ "plan": "acceleration", "mu": 0.1,
        "points": { "n2": [1, 2], "n_2": [1, 2] } });
    let e = refusal("six_link_fig2_10", &acc);
    assert!(
        names(
            &e,
            "/points/n_2",
            "point n2 is given twice (also /points/n2)"
        ),
        "{e}"
    );
    let vel = json!({ "plan": "velocity", "mu": 0.01,
        "points": { "p_v": [0, 0], "p": [0, 0], "b": [1, 2], "B": [1, 2] },
        "segments": { "p_v b": 3, "b p_v": 3, "ab": 2 },
        "angles": { "ab": 10, "b-a": 190 },
        "values": { "v_B": 0.4, "vB": 0.4, "omega2": 1, "ω2": 1, "w3": 2 } });
    let e = refusal("six_link_fig2_10", &vel);
    for (pointer, message) in [
        ("/points/p", "point p_v is given twice (also /points/p_v)"),
        ("/points/B", "point b is given twice (also /points/b)"),
        (
            "/segments/b p_v",
            "segment p_v b is given twice (also /segments/p_v b)",
        ),
        (
            "/angles/b-a",
            "the direction of a b is given twice (also /angles/ab)",
        ),
        ("/values/vB", "v_B is given twice (also /values/v_B)"),
        ("/values/ω2", "ω2 is given twice (also /values/omega2)"),
    ] {
        assert!(names(&e, pointer, message), "{pointer}: {e}");
    }
    assert_eq!(e.lines().count(), 6, "{e}");
    // The ω of the velocity plan an acceleration answer was drawn from.
    let e = refusal(
        "six_link_fig2_10",
        &json!({ "plan": "acceleration", "mu": 0.1,
            "velocity": { "values": { "omega2": 1, "ω2": 1.1 } },
            "values": { "a_B": 1 } }),
    );
    assert!(
        names(
            &e,
            "/velocity/values/ω2",
            "ω2 is given twice (also /velocity/values/omega2)"
        ),
        "{e}"
    );
    // A key twice: serde_json would keep the last silently.
    let e = Study::default_scene()
        .check_answer(
            r#"{ "plan": "velocity", "mu": 0.01, "points": { "b": [1, 2], "b": [3, 4] } }"#,
            "answer.json",
            false,
        )
        .unwrap_err()
        .to_string();
    assert!(e.contains("/points/b: the name \"b\" is repeated"), "{e}");

    // A drawing: b labelled at two line ends is refused with both places;
    // b labelled twice at one end (and B there too) is one point b.
    let (an, solved) = solved("six_link_fig2_10");
    let twice = svg(
        "p_v",
        "μ = 0.01",
        &[("b", 100.0, 110.0), ("b", 130.0, 150.0), ("c", 90.0, 100.0)],
    );
    let ans = mechplan::check::svg::from_svg(&twice, None, None, 0.5, 1).unwrap();
    let e = check(&an, &solved, &ans).unwrap_err().to_string();
    assert!(
        names(
            &e,
            "svg: label b",
            "point b is given twice, by labels at different line ends: (50, 40), (80, 0) mm from the pole"
        ),
        "{e}"
    );
    let once = svg(
        "p_v",
        "μ = 0.01",
        &[
            ("b", 100.0, 110.0),
            ("b", 100.0, 110.0),
            ("B", 100.0, 110.0),
            ("c", 90.0, 100.0),
        ],
    );
    let ans = mechplan::check::svg::from_svg(&once, None, None, 0.5, 1).unwrap();
    let r = check(&an, &solved, &ans).unwrap();
    assert_eq!(r.verdicts.len(), 2, "b, b and B at one end (b once), c");
    // The pole labelled at two ends: which is the pole?
    let poles = svg(
        "p_v",
        "μ = 0.01",
        &[("b", 100.0, 110.0), ("p_v", 130.0, 150.0)],
    );
    let e = mechplan::check::svg::from_svg(&poles, None, None, 0.5, 1)
        .unwrap_err()
        .to_string();
    assert!(
        names(&e, "svg: label p_v", "the pole is given twice"),
        "{e}"
    );
}

/// A letter no plan has is refused naming the field and listing the
/// plan's letters (or its values, its rates); a letter of the other plan
/// is refused saying so, and where the answer says its plan.
#[test]
fn a_letter_not_in_the_plan_is_refused_listing_the_plans() {
    let e = refusal(
        "shaper_fig2_11",
        &json!({ "plan": "velocity", "mu": 0.005,
            "points": { "q": [1, 2] }, "segments": { "p_v q": 3 }, "angles": { "q b": 3 },
            "values": { "v_Q": 1, "omega9": 2 } }),
    );
    let letters = "(this plan has: p_v, b, b3, d, s3, d0, d5, k′, m)";
    for (pointer, message) in [
        ("/points/q", format!("unknown plan point \"q\" {letters}")),
        (
            "/segments/p_v q",
            format!("unknown plan point \"q\" {letters}"),
        ),
        ("/angles/q b", format!("unknown plan point \"q\" {letters}")),
        (
            "/values/v_Q",
            "unknown point \"Q\" (this plan gives: v_A, v_B, v_C".to_string(),
        ),
        (
            "/values/omega9",
            "unknown link \"9\" (this plan gives: ω0, ω1, ω2, ω3".to_string(),
        ),
    ] {
        assert!(names(&e, pointer, &message), "{pointer}: {e}");
    }
    // The shaper's Coriolis point and the acceleration plan's pole in a
    // velocity answer, the velocity plan's pole in an acceleration answer.
    let e = refusal(
        "shaper_fig2_11",
        &json!({ "plan": "velocity", "mu": 0.005,
            "points": { "k3": [1, 2] }, "segments": { "p_a b": 3 } }),
    );
    assert!(
        names(
            &e,
            "/points/k3",
            "\"k3\" belongs to the acceleration plan (a Coriolis point), but /plan says \"velocity\""
        ),
        "{e}"
    );
    assert!(
        names(
            &e,
            "/segments/p_a b",
            "\"p_a\" belongs to the acceleration plan (its pole), but /plan says \"velocity\""
        ),
        "{e}"
    );
    let e = refusal(
        "six_link_fig2_10",
        &json!({ "plan": "acceleration", "mu": 0.1, "points": { "p_v": [0, 0], "b": [1, 1] } }),
    );
    assert!(
        names(
            &e,
            "/points/p_v",
            "\"p_v\" belongs to the velocity plan (its pole), but /plan says \"acceleration\""
        ),
        "{e}"
    );
    let e = refusal(
        "six_link_fig2_10",
        &json!({ "plan": "velocity", "mu": 0.01, "points": { "n_2": [1, 2] } }),
    );
    assert!(
        names(
            &e,
            "/points/n_2",
            "belongs to the acceleration plan (the end of a normal component)"
        ),
        "{e}"
    );
}

/// Numbers that are not finite (NaN, Infinity, 1e999 as JSON numbers or as
/// text) or absurd for what they are are refused, each at its field.
#[test]
fn numbers_not_finite_or_absurd_are_refused_at_their_field() {
    let s = Study::default_scene();
    let text = |t: &str| {
        s.check_answer(t, "answer.json", false)
            .err()
            .map(|e| e.to_string())
            .unwrap_or_default()
    };
    // Not JSON numbers: located by their field all the same.
    for (t, at) in [
        (
            r#"{ "plan": "velocity", "mu": 0.01, "points": { "b": [NaN, 2] } }"#,
            "/points/b/0: non-finite number NaN",
        ),
        (
            r#"{ "plan": "velocity", "mu": 0.01, "segments": { "p_v b": 1e999 } }"#,
            "/segments/p_v b: non-finite number 1e999",
        ),
        (
            r#"{ "plan": "velocity", "mu": Infinity, "values": { "v_B": 1 } }"#,
            "/mu: non-finite number Infinity",
        ),
    ] {
        let e = text(t);
        assert!(e.contains(at), "{t}: {e}");
    }
    let v = |extra: Value| {
        let mut a = json!({ "plan": "velocity", "mu": 0.01, "values": { "v_B": 0.5 } });
        for (k, x) in extra.as_object().unwrap() {
            a[k] = x.clone();
        }
        text(&a.to_string())
    };
    for (extra, pointer, message) in [
        (
            json!({ "points": { "b": ["inf", 2] } }),
            "/points/b/0",
            "expected a finite number, found the text \"inf\"",
        ),
        (
            json!({ "points": { "b": [1e300, 2] } }),
            "/points/b/0",
            "1e300 mm is off any sheet: a plan point is at most 10000 mm from the pole",
        ),
        (
            json!({ "segments": { "p_v b": -3 } }),
            "/segments/p_v b",
            "cannot be negative",
        ),
        (
            json!({ "segments": { "p_v b": 2e5 } }),
            "/segments/p_v b",
            "200000 mm is longer than any sheet",
        ),
        (
            json!({ "angles": { "p_v b": 1e10 } }),
            "/angles/p_v b",
            "1e10° is not a direction as written",
        ),
        (
            json!({ "values": { "v_B": 1e20 } }),
            "/values/v_B",
            "1e20 is absurd",
        ),
        (
            json!({ "values": { "omega2": "NaN cw" } }),
            "/values/omega2",
            "cannot read \"NaN cw\"",
        ),
        (json!({ "mu": 0 }), "/mu", "a scale must be positive"),
        (
            json!({ "mu": 1e300 }),
            "/mu",
            "μ = 1e300 is not a plan's scale",
        ),
        (json!({ "delta": 0 }), "/delta", "must be positive"),
        (
            json!({ "delta": 50 }),
            "/delta",
            "δ = 50 mm is not a pencil's precision: it is more than 0 and at most 10 mm",
        ),
        (
            json!({ "plan": "acceleration", "values": { "a_B": 1 }, "velocity": { "mu": 1e9 } }),
            "/velocity/mu",
            "μ = 1e9 is not a plan's scale",
        ),
        (
            json!({ "plan": "acceleration", "values": { "a_B": 1 },
                    "velocity": { "values": { "omega2": 1e13 } } }),
            "/velocity/values/omega2",
            "1e13 is absurd",
        ),
        (
            json!({ "position": -1 }),
            "/position",
            "expected a whole position number, found -1",
        ),
        (
            json!({ "position": 1.5 }),
            "/position",
            "expected a whole position number, found 1.5",
        ),
        (
            json!({ "position": 1e30 }),
            "/position",
            "expected a whole position number, found 1e+30",
        ),
        (
            json!({ "position": "2" }),
            "/position",
            "expected a whole position number, found \"2\"",
        ),
        // The default scene counts 12 positions from 0, as its sheets do.
        (
            json!({ "position": 99999 }),
            "/position",
            "position 99999 is not one of the scene's positions: they are numbered from 0 to 11",
        ),
        (
            json!({ "position": 12 }),
            "/position",
            "position 12 is not one of the scene's positions: they are numbered from 0 to 11",
        ),
        // In the older numbering the answer states, the range is its own.
        (
            json!({ "position": 0, "positions_from": 1 }),
            "/position",
            "position 0 is not one of the scene's positions: they are numbered from 1 to 12",
        ),
        (
            json!({ "positions_from": 2 }),
            "/positions_from",
            "expected 0 or 1, the number of the scene's first position in this answer, found 2",
        ),
        (
            json!({ "positions_from": "1" }),
            "/positions_from",
            "expected 0 or 1, the number of the scene's first position in this answer, found \"1\"",
        ),
    ] {
        let e = v(extra.clone());
        assert!(names(&e, pointer, message), "{extra}: {e}");
    }
    // The command line's δ and μ, and a drawing's μ.
    let answer = json!({ "plan": "velocity", "mu": 0.01, "values": { "v_B": 0.5 } });
    let req = CheckRequest {
        delta: Some(20.0),
        ..CheckRequest::default()
    };
    let e = refusal_with("six_link_fig2_10", &answer, &req);
    assert!(
        names(&e, "delta", "δ = 20 mm is not a pencil's precision"),
        "{e}"
    );
    let drawing = svg("p_v", "μ = 0", &[("b", 100.0, 110.0)]);
    for (mu, pointer) in [(None, "svg: label μ"), (Some(-1.0), "mu")] {
        let req = CheckRequest {
            mu,
            ..CheckRequest::default()
        };
        let e = study("six_link_fig2_10")
            .solve()
            .unwrap()
            .check_answer(&drawing, "plan.svg", true, &req)
            .unwrap_err()
            .to_string();
        assert!(names(&e, pointer, "is not a plan's scale"), "{e}");
    }
}

/// A drawing whose pole's label says the other plan than the one asked
/// is refused naming the plan. An answer whose points fit another
/// position of the scene well, and not the stated one, is never refused:
/// it is graded at the position it states (wrong), its report naming the
/// position it fits (tests/numbering.rs has the reversed crank). Answers
/// that fit their own position, or no position, are judged as before,
/// without the note.
#[test]
fn an_answer_of_another_plan_is_refused_one_of_another_position_graded() {
    let drawing = svg("p_a", "μ = 0.1", &[("b", 100.0, 110.0)]);
    let req = CheckRequest {
        plan: Some(PlanKind::Velocity),
        ..CheckRequest::default()
    };
    let e = study("six_link_fig2_10")
        .solve()
        .unwrap()
        .check_answer(&drawing, "plan.svg", true, &req)
        .unwrap_err()
        .to_string();
    assert!(
        names(
            &e,
            "plan",
            "the plan asked is the velocity plan, but the drawing's pole is labelled \"p_a\""
        ),
        "{e}"
    );

    let (an, solved) = solved("six_link_fig2_10");
    for kind in [PlanKind::Velocity, PlanKind::Acceleration] {
        let mu = standard_mu(&solved, kind);
        let at = |k: usize| {
            let mut points = serde_json::Map::new();
            for n in ["b", "c", "d"] {
                points.insert(n.into(), json!(place(&solved, k, kind, n)));
            }
            Value::Object(points)
        };
        let plan = if kind == PlanKind::Velocity {
            "velocity"
        } else {
            "acceleration"
        };
        let answer = |stated: usize, drawn: usize| {
            from_json(
                &json!({ "plan": plan, "mu": mu, "position": stated, "points": at(drawn) })
                    .to_string(),
            )
            .unwrap()
        };
        // Drawn at position 4, said to be position 1: graded at 1, wrong,
        // the report naming position 4.
        let r = check(&an, &solved, &answer(1, 4)).unwrap();
        assert_eq!(r.position, 1, "{kind:?}");
        assert!(r.wrong() > 0, "{kind:?}");
        assert_eq!(r.status(), 1, "{kind:?}");
        let e = r.elsewhere.expect("the position it fits");
        assert_eq!((e.position, e.reversed), (Some(4), false), "{kind:?}");
        let text = mechplan::presentation::verdict::to_text(&r);
        assert!(
            text.contains(
                "Note: your points fit position 4, not position 1 that the answer states; it is graded at position 1."
            ),
            "{kind:?}: {text}"
        );
        // Drawn and said at position 4: right, no note.
        let r = check(&an, &solved, &answer(4, 4)).unwrap();
        assert_eq!(r.wrong(), 0, "{kind:?}");
        assert_eq!(r.elsewhere, None, "{kind:?}");
        // Wrong everywhere (b 40 mm off): judged wrong, no position named.
        let mut far = answer(4, 4);
        for it in &mut far.items {
            if let mechplan::check::answer::Given::Point { name, at } = &mut it.given
                && name == "b"
            {
                at[0] += 40.0;
            }
        }
        let r = check(&an, &solved, &far).unwrap();
        assert!(r.wrong() > 0, "{kind:?}");
        assert_eq!(r.elsewhere, None, "{kind:?}");
    }
}

fn run(args: &[&str]) -> (i32, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap(),
        String::from_utf8_lossy(&out.stderr).into(),
    )
}

fn temp(name: &str, text: &str) -> String {
    let dir = std::env::temp_dir().join(format!("mechplan-check-bad-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.display().to_string()
}

/// Through the command: status 2, the field on standard error (an option
/// as the option).
#[test]
fn the_command_refuses_bad_answers_with_status_2() {
    let scene = format!(
        "{}/fixtures/six_link_fig2_10.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let (_, solved) = solved("six_link_fig2_10");
    let b4 = place(&solved, 4, PlanKind::Velocity, "b");
    let c4 = place(&solved, 4, PlanKind::Velocity, "c");
    let twice = temp(
        "twice.json",
        r#"{ "plan": "acceleration", "mu": 0.1, "points": { "n2": [1, 2], "n_2": [1, 2] } }"#,
    );
    let nan = temp(
        "nan.json",
        r#"{ "plan": "velocity", "mu": 0.01, "points": { "b": [NaN, 2] } }"#,
    );
    let pole = temp("pole.svg", &svg("p_a", "μ = 0.1", &[("b", 100.0, 110.0)]));
    let good = temp(
        "good.json",
        &json!({ "plan": "velocity", "mu": 0.01, "points": { "b": b4, "c": c4 } }).to_string(),
    );
    for (args, expect) in [
        (
            vec!["check", &scene, &twice],
            "/points/n_2: point n2 is given twice (also /points/n2)",
        ),
        (
            vec!["check", &scene, &nan],
            "/points/b/0: non-finite number NaN",
        ),
        (
            vec!["check", &scene, &pole, "--plan", "velocity"],
            "--plan: the plan asked is the velocity plan, but the drawing's pole is labelled \"p_a\"",
        ),
        (
            vec!["check", &scene, &good, "--position", "4", "--delta", "50"],
            "--delta: δ = 50 mm is not a pencil's precision",
        ),
    ] {
        let (code, err) = run(&args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(err.contains(expect), "{args:?}: {err}");
    }
    // The same points at their position are judged; at another position
    // (the answer states none: the first, position 0) graded wrong, with
    // the note naming the position they fit.
    let (code, err) = run(&["check", &scene, &good, "--position", "4"]);
    assert_eq!(code, 0, "{err}");
    let out = Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .args(["check", &scene, &good])
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{text}");
    assert!(
        text.contains("Note: your points fit position 4, not position 0 that the answer states"),
        "{text}"
    );
}
