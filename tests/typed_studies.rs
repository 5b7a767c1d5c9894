//! The studies as typed records (`Centres::positions`,
//! `Invariants::phases`): the same numbers as the JSON files, and right by
//! laws the test checks itself — an instant centre is where the two
//! links' relative velocity vanishes (v_A = ω × (A − P)), Kennedy's P13 of
//! a four-bar lies on the crank's and the rocker's lines, and the phases
//! of an output cover a revolution, in degrees as the files say.

use mechplan::Study;
use mechplan::study::records::{CentresAt, PhaseRecord};

fn study(name: &str) -> Study {
    let path = format!("{}/fixtures/{name}.json", env!("CARGO_MANIFEST_DIR"));
    Study::from_json(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// The intersection of lines p1p2 and q1q2.
fn meet(p1: [f64; 2], p2: [f64; 2], q1: [f64; 2], q2: [f64; 2]) -> [f64; 2] {
    let (d1, d2) = (
        [p2[0] - p1[0], p2[1] - p1[1]],
        [q2[0] - q1[0], q2[1] - q1[1]],
    );
    let den = d1[0] * d2[1] - d1[1] * d2[0];
    let t = ((q1[0] - p1[0]) * d2[1] - (q1[1] - p1[1]) * d2[0]) / den;
    [p1[0] + t * d1[0], p1[1] + t * d1[1]]
}

#[test]
fn four_bar_centres_typed_and_right() {
    let s = study("four_bar");
    let solution = s.solve().unwrap();
    let numbers: Vec<usize> = solution.iter().map(|p| p.number()).collect();
    let all = solution.clone().into_centres(None).unwrap();
    let typed: Vec<CentresAt> = all.positions();
    // The typed records are the file's records.
    assert_eq!(
        serde_json::to_value(&typed).unwrap(),
        all.to_json()["positions"]
    );
    assert_eq!(typed.len(), numbers.len());
    for at in &typed {
        let p = solution.position(at.position).unwrap();
        let xy = |n: &str| {
            let q = p.point(n).unwrap().place();
            [q.x, q.y]
        };
        let (o1, a, b, o3) = (xy("O1"), xy("A"), xy("B"), xy("O3"));
        // Links: 0 frame, 1 crank, 2 coupler, 3 rocker.
        let p13 = at.centres.iter().find(|c| c.name == "P02").unwrap();
        let want = meet(o1, a, o3, b);
        let got = p13
            .at
            .expect("a finite centre away from the parallel position");
        let size = 0.4;
        assert!(
            (got[0] - want[0]).hypot(got[1] - want[1]) <= 1e-9 * size / p13.sin_angle,
            "position {}: P02 at {got:?}, the lines meet at {want:?}",
            at.position
        );
        // The coupler turns about it: v_A = ω2 × (A − P), v_B likewise.
        let w2 = p.link("2").unwrap().omega().unwrap();
        for n in ["A", "B", "M"] {
            let r = p.point(n).unwrap();
            let v = r.velocity().unwrap();
            let q = r.place();
            let (rx, ry) = (q.x - got[0], q.y - got[1]);
            let expect = (-w2 * ry, w2 * rx);
            let scale = w2.abs() * (rx.hypot(ry)).max(size);
            assert!(
                (v.x - expect.0).hypot(v.y - expect.1) <= 1e-8 * scale,
                "position {}: v_{n} = {v:?}, ω2 × (r − P02) = {expect:?}",
                at.position
            );
        }
        // Each centre is named after its links, in ids.
        for c in &at.centres {
            assert_eq!(c.name, format!("P{}{}", c.links[0], c.links[1]));
            assert!(c.at.is_some() != c.infinity.is_some());
            assert!(c.sin_angle > 0.0 && c.sin_angle <= 1.0);
        }
    }
    // One position asked: its record alone, under its number.
    let one = solution.into_centres(Some(numbers[2])).unwrap().positions();
    assert_eq!(one.len(), 1);
    assert_eq!(one[0], typed[2]);
}

#[test]
fn phases_typed_in_degrees() {
    let s = study("dwell_six_link_003");
    let inv = s.invariants(None, 1e-3, 10.0, 720).unwrap();
    let phases: Vec<PhaseRecord> = inv.phases();
    assert_eq!(
        serde_json::to_value(&phases).unwrap(),
        inv.to_json()["phases"]
    );
    assert_eq!(phases.len(), inv.len());
    let total: f64 = phases.iter().map(|p| p.span_deg).sum();
    assert!((total - 360.0).abs() < 1e-6, "the phases span {total}°");
    for w in phases.windows(2) {
        let end = (w[0].start_deg + w[0].span_deg).rem_euclid(360.0);
        assert!(
            (end - w[1].start_deg).abs() < 1e-6,
            "{end} then {}",
            w[1].start_deg
        );
    }
    for p in &phases {
        assert!((0.0..360.0).contains(&p.start_deg));
        assert_eq!(p.peaks.is_some(), p.phase != "dwell", "{p:?}");
        if let Some(k) = p.peaks {
            // The peaks of any law that rises by its stroke in the phase:
            // B ≥ 1 (the mean velocity), D ≤ B·C.
            assert!(k.b >= 1.0 - 1e-9 && k.d <= k.b * k.c + 1e-9, "{k:?}");
        }
    }
}
