//! The lecture's notation on the sheets, the steps and the tables (issue
//! 40's notation items), each against the lecture (seed `000`, Fig. 2.11).

mod common;

use common::*;
use mechplan::words::construction::Lang;

/// The shaper of Fig. 2.11 solved at its twelve positions.
fn shaper() -> (mechplan::Analysis, Vec<mechplan::Solved>) {
    let v = fixture("shaper_fig2_11");
    let positions = v["positions"].clone();
    solve(scene_with(v, positions))
}

/// Seed `000`, Fig. 2.11: "a^K_B3B = 2·ω3·v_B3B", its direction "v_B3B
/// turned by 90° in the sense of ω3": a capital K, and the angular
/// velocity of the guide (the kulisa 3 that slider 2 slides on), not of
/// the slider — in the steps of every language and in the plan's table.
#[test]
fn coriolis_is_capital_k_with_the_guides_omega() {
    let (an, solved) = shaper();
    for lang in [Lang::En, Lang::Uk, Lang::Ru] {
        let t = mechplan::report::to_steps(&an, &solved, lang);
        // The equations underline their vectors with combining marks.
        let t: String = t
            .chars()
            .filter(|c| !('\u{300}'..='\u{36f}').contains(c))
            .collect();
        assert!(t.contains("a^K_B3B2 = 2·ω3·v_B3B2"), "{t}");
        assert!(t.contains("a_B3 = a_B + a^K_B3B + a^r_B3B"), "{t}");
        assert!(!t.contains("a^k"), "a lower-case a^k in\n{t}");
        assert!(!t.contains("·ω2·"), "ω of the slider in\n{t}");
    }
    let t = mechplan::report::to_steps(&an, &solved, Lang::En);
    assert!(t.contains("v_B3B2 turned by 90° in the sense of ω3"), "{t}");
    let plan = solved[1]
        .plans
        .as_ref()
        .unwrap()
        .acceleration
        .clone()
        .unwrap();
    let rows = mechplan::drawing::table::plan_rows(&plan);
    let names: Vec<&str> = rows.iter().map(|r| r.quantity.as_str()).collect();
    assert!(names.contains(&"a^K_B3B2"), "{names:?}");
    assert!(names.contains(&"a^r_B3B2"), "{names:?}");
}

/// The shaper with its masses and cutting force drawn at its twelve
/// positions with the default options.
fn shaper_sheets() -> Vec<mechplan::drawing::Sheet> {
    let v = fixture("dynamics/shaper_fig2_11");
    let positions = v["positions"].clone();
    let (an, solved) = solve(scene_with(v, positions));
    sheets(&an, &solved, &mechplan::drawing::DrawOptions::default())
}

/// A label's text as the sheet shows it (its runs joined).
fn label_text(svg: &str, id: &str) -> Option<String> {
    let doc = roxmltree::Document::parse(svg).unwrap();
    let n = doc.descendants().find(|n| n.attribute("id") == Some(id))?;
    Some(
        n.descendants()
            .filter(|t| t.is_text())
            .filter_map(|t| t.text())
            .collect(),
    )
}

/// Seed `000`, Fig. 2.11 b: the plan of velocities shows d₅ for the ram
/// 5 (it translates: its K, M and T lie there too, as the steps say) and
/// the pole p_v alone; before, every shaper plan read "d₅, k′, m, t" and
/// "p_v, d₀" and drew p_v → k′, p_v → m, p_v → t over d₀ → d₅ (four
/// arrows in one).
#[test]
fn a_translating_links_points_are_not_named_again_on_the_plans() {
    let sheets = shaper_sheets();
    let plans: Vec<_> = sheets
        .iter()
        .filter(|s| s.name.starts_with("velocity_") || s.name.starts_with("acceleration_"))
        .collect();
    assert_eq!(plans.len(), 24);
    for s in plans {
        let pole = if s.name.starts_with("velocity") {
            "p_v"
        } else {
            "p_a"
        };
        let d5 = label_text(&s.svg, "label-d_5");
        if s.name.ends_with("_0") {
            // The dead centre: d₅ at the pole with b₃, d, s₃.
            let t = label_text(&s.svg, &format!("label-{pole}")).unwrap();
            assert!(
                !t.contains('k') && !t.contains('m') && !t.contains('t'),
                "{}: {t}",
                s.name
            );
            continue;
        }
        assert_eq!(d5.as_deref(), Some("d5"), "{}", s.name);
        assert_eq!(
            label_text(&s.svg, &format!("label-{pole}")).as_deref(),
            Some(&pole.replace('_', "")[..]),
            "{}",
            s.name
        );
        let doc = roxmltree::Document::parse(&s.svg).unwrap();
        let mut seen: Vec<[String; 4]> = Vec::new();
        for n in doc.descendants().filter(|n| n.has_tag_name("line")) {
            let e = ["x1", "y1", "x2", "y2"].map(|a| n.attribute(a).unwrap().to_string());
            assert!(
                !seen.contains(&e),
                "{}: a vector drawn twice: {e:?}",
                s.name
            );
            seen.push(e);
        }
    }
}

/// Every text element of a sheet, its runs joined, in order.
fn texts(svg: &str) -> Vec<String> {
    let doc = roxmltree::Document::parse(svg).unwrap();
    doc.descendants()
        .filter(|n| n.has_tag_name("text"))
        .map(|n| {
            n.descendants()
                .filter(|t| t.is_text())
                .filter_map(|t| t.text())
                .collect()
        })
        .collect()
}

/// Zhukovsky's lever gives F_b one way in its table and in its caption's
/// ΣM_p = 0: its magnitude, the arrow drawn as it acts, the convention
/// stated on the sheet. Before, a balancing force against its assumed
/// direction read 45.83 in the table and −45.83 in the caption
/// (positions 7 and 11 of the shaper).
#[test]
fn the_balancing_force_has_one_sign_on_the_lever_sheet() {
    for s in shaper_sheets()
        .iter()
        .filter(|s| s.name.starts_with("lever_"))
    {
        let t = texts(&s.svg);
        let row = t.iter().position(|x| x == "Fb (B)").unwrap();
        let in_table = &t[row + 1];
        let sum = t.iter().find(|x| x.starts_with("ΣMp")).unwrap();
        let in_caption = sum.rsplit("Fb = ").next().unwrap().trim_end_matches(" N");
        // Both to three significant digits: one number, written alike.
        assert_eq!(in_caption, in_table, "{}: {sum}", s.name);
        assert!(!in_caption.starts_with('−'), "{}: {sum}", s.name);
        assert!(
            t.iter()
                .any(|x| x.starts_with("Fb in the table and in ΣMp")),
            "{}",
            s.name
        );
    }
}

/// The plan of the mechanism shows the angular velocity of every link
/// that turns, as the plan of velocities measured it, not ω1 alone (seed
/// `000`, Fig. 2.11: "ω3 направлена у той же бік", the kulisa's ω3 drawn
/// on the scheme): the shaper's kulisa 3; not its slider blocks 2 and 4
/// (they turn with their guides) nor the ram 5 (it translates). The
/// six-link's coupler 2, rocker 3 and connecting rod 4 each have theirs.
#[test]
fn the_plan_of_the_mechanism_shows_every_turning_links_omega() {
    let ids = |sheets: &[mechplan::drawing::Sheet], name: &str| -> Vec<String> {
        let s = sheets.iter().find(|s| s.name == name).unwrap();
        let doc = roxmltree::Document::parse(&s.svg).unwrap();
        doc.descendants()
            .filter_map(|n| n.attribute("id"))
            .filter(|id| id.starts_with("omega-") || id.starts_with("input-"))
            .map(String::from)
            .collect()
    };
    let sh = shaper_sheets();
    for k in 1..12 {
        let got = ids(&sh, &format!("mechanism_{k}"));
        assert!(
            got.contains(&"omega-3".to_string()),
            "mechanism_{k}: {got:?}"
        );
        for l in ["omega-2", "omega-4", "omega-5", "omega-1"] {
            assert!(!got.contains(&l.to_string()), "mechanism_{k}: {got:?}");
        }
        let s = sh
            .iter()
            .find(|s| s.name == format!("mechanism_{k}"))
            .unwrap();
        assert!(texts(&s.svg).iter().any(|t| t == "ω3"), "mechanism_{k}");
    }
    let v = fixture("six_link_fig2_10");
    let positions = v["positions"].clone();
    let (an, solved) = solve(scene_with(v, positions));
    let six = sheets(&an, &solved, &mechplan::drawing::DrawOptions::default());
    let got = ids(&six, "mechanism_2");
    for l in ["omega-2", "omega-3", "omega-4", "input-ω"] {
        assert!(got.contains(&l.to_string()), "{got:?}");
    }
}

/// The kinematic diagrams write each ordinate's name (s, s′, s″) at the
/// upper end of its axis, as axes are labelled, not at the origin beside
/// the abscissa; φ1's name at the abscissa's arrow; and where φ1 counts
/// from: the start of the working stroke (node 0).
#[test]
fn diagram_axes_are_named_at_their_ends_and_phi1_has_its_origin() {
    let dir = fresh("notation", "diagrams");
    let scene = format!(
        "{}/fixtures/six_link_fig2_10.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let (code, _, err) = run(&["diagram", &scene, "-o", dir.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    let svg = std::fs::read_to_string(dir.join("diagrams.svg")).unwrap();
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let y = |n: roxmltree::Node| -> f64 { n.attribute("y").unwrap().parse().unwrap() };
    let joined = |n: roxmltree::Node| -> String {
        n.descendants()
            .filter(|t| t.is_text())
            .filter_map(|t| t.text())
            .collect()
    };
    let mut abscissas: Vec<f64> = doc
        .descendants()
        .filter(|n| n.has_tag_name("text") && joined(*n) == "φ1")
        .map(y)
        .collect();
    abscissas.sort_by(f64::total_cmp);
    assert_eq!(abscissas.len(), 3, "{abscissas:?}");
    for (i, (name, at)) in [
        ("s", abscissas[0]),
        ("s′", abscissas[1]),
        ("s″", abscissas[2]),
    ]
    .into_iter()
    .enumerate()
    {
        let n = doc
            .descendants()
            .find(|n| n.attribute("id") == Some(&format!("axis-{i}")[..]))
            .unwrap_or_else(|| panic!("no axis-{i}"));
        assert_eq!(joined(n), name);
        assert!(
            y(n) < at - 8.0,
            "{name} at y = {} beside its origin (abscissa at {at})",
            y(n)
        );
    }
    assert!(
        texts(&svg)
            .iter()
            .any(|t| t.contains("(the start of the working stroke)")),
        "no φ1 origin"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// The lever's result table gives its numbers to three significant
/// digits (before: 419283, 0.8569, 137.1 on the shaper's sheets).
#[test]
fn the_lever_table_has_three_significant_digits() {
    for s in shaper_sheets()
        .iter()
        .filter(|s| s.name.starts_with("lever_"))
    {
        let t = texts(&s.svg);
        let from = t.iter().position(|x| x == "F·h, N·mm").unwrap() + 1;
        for cell in t[from..]
            .iter()
            .filter(|x| x.starts_with(|c: char| c.is_ascii_digit() || c == '−'))
        {
            let digits = cell.trim_start_matches(['−', '0', '.']).replace('.', "");
            let significant = digits.trim_end_matches('0').len();
            assert!(significant <= 3, "{}: {cell}", s.name);
        }
    }
}

/// A plan drawn with `--table` gives its numbers to what a reading of the
/// plan supports: the segments to 0.1 mm, the values to three significant
/// digits (the old tables printed four: 0.8569, 137.1).
#[test]
fn plan_tables_give_three_significant_digits() {
    let dir = std::env::temp_dir().join(format!("mechplan-notation-table-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let scene = format!(
        "{}/fixtures/six_link_fig2_10.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .args(["draw", &scene, "--table", "-o"])
        .arg(&dir)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let mut cells = 0;
    for sheet in ["velocity_3.svg", "acceleration_3.svg"] {
        let svg = std::fs::read_to_string(dir.join(sheet)).unwrap();
        for line in svg.lines().filter(|l| l.contains("class=\"table\"")) {
            let text: String = {
                let mut t = String::new();
                let mut inside = false;
                for ch in line.chars() {
                    match ch {
                        '<' => inside = true,
                        '>' => inside = false,
                        c if !inside => t.push(c),
                        _ => {}
                    }
                }
                t
            };
            // A value with its unit ("0.935 m/s", "19.1 ↺ rad/s") or a length.
            let Some(first) = text.split_whitespace().next() else {
                continue;
            };
            let Ok(x) = first.replace('−', "-").parse::<f64>() else {
                continue;
            };
            let digits = first
                .chars()
                .filter(|c| c.is_ascii_digit())
                .collect::<String>();
            let significant = digits.trim_start_matches('0').len();
            if text.contains('/') {
                assert!(significant <= 3, "{sheet}: {text} ({x})");
            } else {
                let decimals = first.split('.').nth(1).map_or(0, str::len);
                assert!(decimals <= 1, "{sheet}: a length {text} beyond 0.1 mm");
            }
            cells += 1;
        }
    }
    assert!(cells > 20, "{cells} numbers read");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Zhukovsky's lever names its points as the plan of velocities does:
/// the shaper's ram by d₅ alone, not "d₅, k′, m, t" (its K, M and T lie
/// there: it translates), the pole p_v alone.
#[test]
fn the_lever_names_a_translating_links_point_once() {
    let sheets = shaper_sheets();
    let levers: Vec<_> = sheets
        .iter()
        .filter(|s| s.name.starts_with("lever_"))
        .collect();
    assert!(levers.len() >= 10, "{} lever sheets", levers.len());
    let mut seen = 0;
    for s in levers {
        if let Some(d5) = label_text(&s.svg, "label-d_5") {
            assert_eq!(d5, "d5", "{}", s.name);
            seen += 1;
        }
        if let Some(p) = label_text(&s.svg, "label-p_v") {
            assert!(
                !p.contains("d0"),
                "{}: the frame's d₀ named at the pole: {p}",
                s.name
            );
        }
    }
    assert!(seen >= 10, "d₅ named on {seen} levers");
}

/// ГОСТ 2.770's cylinder with a piston: the barrel closed at both ends
/// (its bottom at the pivot, the end cap the rod passes through), each a
/// main line across the axis as wide as the barrel; the rod crosses the
/// cap. Read from the boom's plans of the mechanism, the group
/// `cylinder-1`.
#[test]
fn the_cylinders_barrel_is_closed_at_both_ends() {
    let v = fixture("boom_cylinder");
    let positions = v["positions"].clone();
    let (an, solved) = solve(scene_with(v, positions));
    let sheets = sheets(&an, &solved, &mechplan::drawing::DrawOptions::default());
    let mut checked = 0;
    for s in sheets.iter().filter(|s| s.name.starts_with("mechanism_")) {
        let doc = roxmltree::Document::parse(&s.svg).unwrap();
        let g = doc
            .descendants()
            .find(|n| n.attribute("id") == Some("cylinder-1"))
            .unwrap_or_else(|| panic!("{}: no cylinder-1", s.name));
        let segs: Vec<[f64; 4]> = g
            .descendants()
            .filter(|n| n.has_tag_name("line"))
            .map(|n| ["x1", "y1", "x2", "y2"].map(|a| n.attribute(a).unwrap().parse().unwrap()))
            .collect();
        let len = |e: &[f64; 4]| (e[2] - e[0]).hypot(e[3] - e[1]);
        let dir = |e: &[f64; 4]| ((e[2] - e[0]) / len(e), (e[3] - e[1]) / len(e));
        // The barrel's two walls: the two longest parallel lines.
        let mut by_len = segs.clone();
        by_len.sort_by(|a, b| len(b).total_cmp(&len(a)));
        let wall = by_len
            .iter()
            .find(|e| {
                by_len.iter().any(|f| {
                    f != *e
                        && (len(f) - len(e)).abs() < 0.05
                        && (dir(f).0 * dir(e).1 - dir(f).1 * dir(e).0).abs() < 1e-3
                })
            })
            .unwrap_or_else(|| panic!("{}: no barrel walls in {segs:?}", s.name));
        let u = dir(wall);
        // Lines across the axis (⊥ the walls) at the walls' two ends.
        let across: Vec<&[f64; 4]> = segs
            .iter()
            .filter(|e| {
                (dir(e).0 * u.0 + dir(e).1 * u.1).abs() < 1e-2 && (len(e) - 4.4).abs() < 0.05
            })
            .collect();
        let at = |x: f64, y: f64| (x - wall[0]) * u.0 + (y - wall[1]) * u.1;
        let ends: Vec<f64> = across.iter().map(|e| at(e[0], e[1])).collect();
        for t in [0.0, len(wall)] {
            assert!(
                ends.iter().any(|e| (e - t).abs() < 0.05),
                "{}: the barrel not closed at {t:.1} mm of its {:.1} (lines across at {ends:?})",
                s.name,
                len(wall)
            );
        }
        checked += 1;
    }
    assert!(checked >= 10, "{checked} plans of the mechanism");
}

/// ГОСТ 2.304's least size is 2.5 mm: every word of an A4 sheet's title
/// block (`--title-block`), the columns' words included (they were 2 mm),
/// is at least that, narrowed to its cell where it is wider.
#[test]
fn title_block_words_are_at_least_2_5_mm() {
    let dir = std::env::temp_dir().join(format!("mechplan-notation-tb-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let scene = format!(
        "{}/fixtures/dynamics/shaper_fig2_11.json",
        env!("CARGO_MANIFEST_DIR")
    );
    for lang in ["en", "uk", "ru"] {
        let out = dir.join(lang);
        let o = std::process::Command::new(env!("CARGO_BIN_EXE_mechplan"))
            .args([
                "draw",
                &scene,
                "--title-block",
                "--sheet",
                "A4",
                "--lang",
                lang,
                "-o",
            ])
            .arg(&out)
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let svg = std::fs::read_to_string(out.join("velocity_1.svg")).unwrap();
        let sizes: Vec<f64> = svg
            .lines()
            .filter(|l| l.starts_with("<text class=\"title-block"))
            .map(|l| {
                let at = l.find("font-size=\"").unwrap() + 11;
                l[at..].split('"').next().unwrap().parse().unwrap()
            })
            .collect();
        assert!(
            sizes.len() >= 12,
            "{lang}: {} title-block texts",
            sizes.len()
        );
        assert!(sizes.iter().all(|&s| s >= 2.5), "{lang}: sizes {sizes:?}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
