//! Every sheet `mechplan draw` writes is named by its kind
//! (`mechplan::SheetKind`): the file's stem reads back as the kind that
//! writes it, so the names the drawing gives and the names the output
//! folder recognises cannot drift apart. The sheets of an earlier
//! version left in a folder are told, whatever their kind.

mod common;

use mechplan::SheetKind;
use std::collections::BTreeSet;
use std::path::Path;
use std::process::Command;

fn fixture(name: &str) -> String {
    format!("{}/fixtures/{name}", env!("CARGO_MANIFEST_DIR"))
}

/// `mechplan draw SCENE -o DIR ARGS`: its status and what it printed.
fn draw(scene: &str, dir: &Path, args: &[&str]) -> (i32, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .args(["draw", &fixture(scene), "-o"])
        .arg(dir)
        .args(args)
        .output()
        .unwrap();
    let text =
        String::from_utf8_lossy(&out.stdout).into_owned() + &String::from_utf8_lossy(&out.stderr);
    (out.status.code().unwrap_or(-1), text)
}

/// A kind without its numbers, to count which kinds were seen.
fn family(k: &SheetKind) -> &'static str {
    match k {
        SheetKind::Mechanism(_) => "mechanism",
        SheetKind::Velocity(_) => "velocity",
        SheetKind::Acceleration(_) => "acceleration",
        SheetKind::Positions => "positions",
        SheetKind::Diagrams => "diagrams",
        SheetKind::Course => "course",
        SheetKind::CourseForces => "course_forces",
        SheetKind::Forces(_) => "forces",
        SheetKind::ForcesPart { .. } => "forces of a group",
        SheetKind::Lever { input: None, .. } => "lever",
        SheetKind::Lever { input: Some(_), .. } => "lever of an input",
    }
}

#[test]
fn every_sheet_drawn_is_named_by_its_kind() {
    let mut seen = BTreeSet::new();
    for (scene, args) in [
        ("dynamics/arm_two_cylinders.json", &["--course"][..]),
        ("dynamics/six_link_fig2_10.json", &["--course"][..]),
        ("four_bar.json", &[][..]),
        // On the A4 asked for, the six-link's groups one to a sheet.
        (
            "dynamics/six_link_fig2_10.json",
            &["--sheet", "A4", "--title-block", "--position", "1"][..],
        ),
    ] {
        let dir = common::fresh("names", &scene.replace('/', "-"));
        let (code, out) = draw(scene, &dir, args);
        assert_eq!(code, 0, "{scene}: {out}");
        for e in std::fs::read_dir(&dir).unwrap() {
            let p = e.unwrap().path();
            if p.extension().is_none_or(|x| x != "svg") {
                continue;
            }
            let stem = p.file_stem().unwrap().to_str().unwrap().to_string();
            let kind = SheetKind::parse(&stem)
                .unwrap_or_else(|| panic!("{scene}: {stem}.svg is named by no sheet kind"));
            assert_eq!(kind.stem(), stem, "{scene}");
            seen.insert(family(&kind));
        }
    }
    let every = [
        "mechanism",
        "velocity",
        "acceleration",
        "positions",
        "course",
        "course_forces",
        "forces",
        "forces of a group",
        "lever",
        "lever of an input",
    ];
    for f in every {
        assert!(seen.contains(f), "no {f} sheet drawn: {seen:?}");
    }
}

#[test]
fn sheets_of_every_kind_not_from_this_run_are_told() {
    let dir = common::fresh("names", "stale");
    let old = [
        "velocity_99.svg",
        "forces_99.svg",
        "forces_99_2.svg",
        "lever_99_2.pdf",
        "course_forces.svg",
        "mechanism_99.dxf",
    ];
    for f in old.iter().chain(&["notes.svg", "velocity_x.svg"]) {
        std::fs::write(dir.join(f), "<svg/>").unwrap();
    }
    let (code, out) = draw("four_bar.json", &dir, &[]);
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("6 sheet file(s)"), "{out}");
    for f in old {
        assert!(out.contains(f), "{f} not told: {out}");
        assert!(dir.join(f).exists(), "{f} was not left as it was");
    }
    assert!(
        !out.contains("notes.svg") && !out.contains("velocity_x.svg"),
        "{out}"
    );
}
