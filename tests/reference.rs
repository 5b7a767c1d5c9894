//! The extended-precision reference: it agrees with route (a) to the last
//! digits of f64 on every fixture, and reproduces seed 004's Table 1 in
//! extended precision from the exact dimensions.

mod common;

use common::{FIXTURES, fixture, scene_with, solve, sweep};
use mechplan::reference::{Exact, Real, Reference};
use mechplan::{Analysis, Scene};

/// Largest relative difference between route (a) and the reference over
/// some positions of a fixture's sweep: places relative to the sketch
/// size, v and ω·size relative to the largest of them, a and ε·size too.
fn worst_against_route_a(name: &str) -> (f64, String) {
    let v = fixture(name);
    let sw = sweep(name, &v);
    let key = if sw.get("angles").is_some() {
        "angles"
    } else {
        "s"
    };
    let all = sw[key].as_array().unwrap().clone();
    let picked: Vec<_> = all.iter().step_by(all.len().div_ceil(7)).cloned().collect();
    let mut pos = serde_json::Map::new();
    pos.insert(key.into(), picked.into());
    let (an, solved) = solve(scene_with(v, pos.into()));
    let m = &an.mech;
    let mut re = Reference::new(&an).unwrap();
    let mut worst = (0.0f64, String::new());
    for s in &solved {
        let r = re.solve_f64(s.q).unwrap();
        let mut note = |d: f64, what: String| {
            if d > worst.0 || d.is_nan() {
                worst = (d, format!("{what} at q = {}", s.q));
            }
        };
        let (mut sv, mut sa) = (0.0f64, 0.0f64);
        for &p in &an.points {
            let st = s.point(&an, p);
            let (vv, aa) = st.rates.unwrap();
            sv = sv.max(vv.hypot());
            sa = sa.max(aa.hypot());
        }
        for l in (0..m.links.len()).filter(|&l| an.include[l]) {
            let mo = s.motion[l].unwrap();
            sv = sv.max(mo.omega.abs() * m.size);
            sa = sa.max(mo.epsilon.abs() * m.size);
        }
        for &p in &an.points {
            let st = s.point(&an, p);
            let rp = r.point(&an, p);
            let (vv, aa) = st.rates.unwrap();
            note(
                rp.at.dist_f64(st.at.to_vec2()) / m.size,
                format!("place of {}", m.point_name(p)),
            );
            note(rp.v.dist_f64(vv) / sv, format!("v of {}", m.point_name(p)));
            note(rp.a.dist_f64(aa) / sa, format!("a of {}", m.point_name(p)));
        }
        for l in (0..m.links.len()).filter(|&l| an.include[l]) {
            let mo = s.motion[l].unwrap();
            let rm = r.links[l].as_ref().unwrap();
            let d = |x: &Real, y: f64| (x - &Real::from_f64(y)).abs().to_f64();
            note(
                d(&rm.omega, mo.omega) * m.size / sv,
                format!("ω of {}", m.link_id(l)),
            );
            note(
                d(&rm.epsilon, mo.epsilon) * m.size / sa,
                format!("ε of {}", m.link_id(l)),
            );
        }
    }
    worst
}

#[test]
fn reference_agrees_with_route_a_on_every_fixture() {
    for name in FIXTURES {
        let (d, what) = worst_against_route_a(name);
        eprintln!("{name}: {d:.2e} ({what})");
        assert!(
            d < 2e-14,
            "{name}: route (a) differs from the reference by {d:.2e} ({what})"
        );
    }
}

fn sqrt(x: &Real) -> Real {
    x.sqrt()
}

#[test]
fn reproduces_table_1_of_seed_004_in_extended_precision() {
    let text = std::fs::read_to_string(format!(
        "{}/fixtures/class3_004.json",
        env!("CARGO_MANIFEST_DIR")
    ))
    .unwrap();
    let an = Analysis::new(Scene::from_json(&text).unwrap()).unwrap();
    let n = |x: f64| Real::from_f64(x);
    let s3 = sqrt(&n(3.0));
    // The exact mechanism the file can only round: O = (−1−√3, 1),
    // F = (1+√3/2, 1/2), AB = √3.
    let exact = Exact {
        points: vec![
            ("O".into(), -(n(1.0) + &s3), n(1.0)),
            ("F".into(), n(1.0) + &s3 / n(2.0), n(0.5)),
        ],
        lengths: vec![("A-B".into(), s3.clone())],
    };
    let mut re = Reference::with_exact(&an, &exact).unwrap();
    let st = re.solve(&Real::from_degrees(&n(30.0))).unwrap();
    let sc = &an.mech.scene;
    let point = |name: &str| st.point(&an, sc.point_index(name).unwrap());
    let link = |id: &str| st.links[sc.link_index(id).unwrap()].clone().unwrap();
    let close = |what: &str, got: &Real, want: &Real| {
        let d = (got - want).abs().to_f64();
        eprintln!("{what}: |difference| = {d:.1e}");
        assert!(
            d < 1e-25,
            "{what}: {} against {} ({d:.1e})",
            got.to_f64(),
            want.to_f64()
        );
    };
    let b = point("B");
    close("|v_B| = 2", &b.v.norm(), &n(2.0));
    close(
        "|a_B| = √(192+108√3)",
        &b.a.norm(),
        &sqrt(&(n(192.0) + n(108.0) * &s3)),
    );
    let c = point("C");
    close("|v_C| = 1", &c.v.norm(), &n(1.0));
    close(
        "|a_C| = √(85+48√3)",
        &c.a.norm(),
        &sqrt(&(n(85.0) + n(48.0) * &s3)),
    );
    let d = point("D");
    close("|v_D| = 2", &d.v.norm(), &n(2.0));
    close(
        "|a_D| = √(100+48√3)",
        &d.a.norm(),
        &sqrt(&(n(100.0) + n(48.0) * &s3)),
    );
    let a = point("A");
    close("|v_A| = 1", &a.v.norm(), &n(1.0));
    close("|a_A| = 1", &a.a.norm(), &n(1.0));
    close("ω2 = ω1", &link("2").omega, &n(1.0));
    close("ω3 = −√3·ω1", &link("3").omega, &-&s3);
    close("ω4 = ω1", &link("4").omega, &n(1.0));
    close("ω5 = 2ω1", &link("5").omega, &n(2.0));
    close(
        "ε2 = 6+10√3/3",
        &link("2").epsilon,
        &(n(6.0) + n(10.0) * &s3 / n(3.0)),
    );
    close(
        "ε3 = −(5+3√3)",
        &link("3").epsilon,
        &-(n(5.0) + n(3.0) * &s3),
    );
    close("ε4 = 6+4√3", &link("4").epsilon, &(n(6.0) + n(4.0) * &s3));
    close("ε5 = 6+4√3", &link("5").epsilon, &(n(6.0) + n(4.0) * &s3));
    // Extended precision really is extended: the f64 scene's reference
    // differs from the exact mechanism's by the file's rounding of √3.
    let mut plain = Reference::new(&an).unwrap();
    let p = plain.solve(&Real::from_degrees(&n(30.0))).unwrap();
    let dv = (p.point(&an, sc.point_index("B").unwrap()).a.norm() - b.a.norm())
        .abs()
        .to_f64();
    assert!(dv > 1e-20 && dv < 1e-13, "rounding of the file: {dv:.1e}");
}

#[test]
fn decimal_numerals_and_degrees() {
    let x = Real::from_decimal("-12.5e-1").unwrap();
    assert_eq!(x.to_f64(), -1.25);
    let tenth = Real::from_decimal("0.1").unwrap();
    // 0.1 in extended precision is not the f64 0.1.
    assert!((tenth.clone() - Real::from_f64(0.1)).abs().to_f64() > 1e-18);
    let (s, _) = Real::from_degrees(&Real::from_f64(30.0)).sin_cos();
    assert!((s - Real::from_f64(0.5)).abs().to_f64() < 1e-50);
}

/// A rigid shape's point on the line of two others (coupler point M on AB
/// extended), with lengths that make the line only to rounding: A-M is
/// 0.4499999999999999, so in extended precision the two circles about A
/// and B overlap by 1e-16 and their intersection lies √ε·|AM| ≈ 5e-9 m off
/// the line (where the reference put it before). Like `mechanism.rs`, the reference projects onto the line:
/// M lies on AB and at the distance the exact construction gives,
/// x = (AB² + AM² − BM²) / (2·AB) from A, both to 1e-25.
#[test]
fn collinear_shape_point_lies_on_its_line_in_extended_precision() {
    let mut v = fixture("four_bar");
    let p = |k: &str, i: usize| v["points"][k][i].as_f64().unwrap();
    let (ax, ay, bx, by) = (p("A", 0), p("A", 1), p("B", 0), p("B", 1));
    let k = 0.45 / 0.35;
    v["points"]["M"] = serde_json::json!([ax + (bx - ax) * k, ay + (by - ay) * k]);
    let am = 0.4499999999999999f64;
    v["lengths"]["A-M"] = am.into();
    v["lengths"]["B-M"] = 0.1.into();
    let an = Analysis::new(scene_with(v, serde_json::json!({ "angles": [45.0] }))).unwrap();
    let sc = &an.mech.scene;
    let mut re = Reference::new(&an).unwrap();
    let st = re.solve_f64(45f64.to_radians()).unwrap();
    let at = |name: &str| st.point(&an, sc.point_index(name).unwrap()).at;
    let (a, b, mp) = (at("A"), at("B"), at("M"));
    let ab = b.sub(&a);
    let off_line = (ab.cross(&mp.sub(&a)) / ab.norm()).abs().to_f64();
    // The scene is in metres: its numbers are taken as the binary values.
    let (d, r1, r2) = (
        Real::from_f64(0.35),
        Real::from_f64(am),
        Real::from_f64(0.1),
    );
    let x = (d.square() + r1.square() - r2.square()) / (Real::from_f64(2.0) * &d);
    let along = (mp.sub(&a).norm() - x).abs().to_f64();
    eprintln!("M off the line AB by {off_line:.1e} m, from the exact distance by {along:.1e} m");
    assert!(off_line < 1e-25, "M is {off_line:.1e} m off the line AB");
    assert!(
        along < 1e-25,
        "M is {along:.1e} m from the exact construction along AB"
    );
}
