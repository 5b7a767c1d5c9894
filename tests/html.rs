//! The step-by-step handout (`mechplan draw --html`), checked offline:
//! one self-contained file (nothing fetched from anywhere), every step's
//! sentence present in its plan, every step revealing something
//! (`data-step` values cover 1..=steps for each plan, the drawing steps in
//! the SVG itself). The page's behaviour in a browser is checked by
//! tests/html_handout.sh (headless Chromium).

mod common;
use common::*;
use mechplan::construction::{Op, Plan};
use mechplan::drawing::canvas::{Canvas, Prim};
use mechplan::drawing::html::{handout, rich};
use mechplan::drawing::plan::{draw_steps, made_at};
use mechplan::words::construction::{Lang, sentence};
use std::collections::BTreeSet;

fn fixture_handout(name: &str, lang: Lang) -> (Vec<(usize, mechplan::Solved)>, String) {
    let scene = mechplan::Scene::from_json(&fixture(name).to_string()).unwrap();
    let (an, s) = solve(scene);
    let h = handout(&an, &s, lang);
    // Each position with its number, as the handout shows it (a count
    // sweep from 0, given input values from 1).
    let numbered = s
        .into_iter()
        .enumerate()
        .map(|(k, s)| (an.numbering.number(k), s))
        .collect();
    (numbered, h)
}

/// The text between `start` (inclusive) and the next `end` after it.
fn between<'a>(s: &'a str, start: &str, end: &str) -> Option<&'a str> {
    let i = s.find(start)?;
    let j = s[i..].find(end)? + i;
    Some(&s[i..j + end.len()])
}

/// Text content: tags dropped, entities decoded.
fn text(html: &str) -> String {
    let mut out = String::new();
    let mut tag = false;
    for c in html.chars() {
        match c {
            '<' => tag = true,
            '>' if tag => tag = false,
            c if !tag => out.push(c),
            _ => {}
        }
    }
    out.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&amp;", "&")
}

/// A sentence compared by its letters: the notation's `_` and `^` become
/// sub- and superscripts on the page, and underlines are combining marks.
fn letters(s: &str) -> String {
    s.chars()
        .filter(|c| !matches!(c, '_' | '^' | '\u{300}'..='\u{36f}'))
        .collect()
}

/// Values of `attr="…"` in `html`.
fn attr_values(html: &str, attr: &str) -> Vec<String> {
    let pat = format!(" {attr}=\"");
    html.match_indices(&pat)
        .map(|(i, _)| {
            let rest = &html[i + pat.len()..];
            rest[..rest.find('"').unwrap()].to_string()
        })
        .collect()
}

/// The figure of a plan: `pos-0-v`, `pos-3-a` (by the position's number).
fn figure<'a>(h: &'a str, pos: usize, kind: &str) -> &'a str {
    between(h, &format!("id=\"pos-{pos}-{kind}\""), "</figure>")
        .unwrap_or_else(|| panic!("no figure pos-{pos}-{kind}"))
}

fn plans(s: &mechplan::Solved) -> Vec<(&'static str, &Plan)> {
    let p = s.plans.as_ref().unwrap();
    let mut v = vec![("v", &p.velocity)];
    if let Some(a) = &p.acceleration {
        v.push(("a", a));
    }
    v
}

/// Nothing outside the file: no web addresses but the SVG namespace, no
/// linked style sheets, scripts, images, frames, fonts or imports.
#[test]
fn handout_is_self_contained() {
    for name in FIXTURES {
        let (_, h) = fixture_handout(name, Lang::En);
        let rest = h.replace("http://www.w3.org/2000/svg", "");
        assert!(
            !rest.contains("http://") && !rest.contains("https://") && !rest.contains("//cdn"),
            "{name}: a web address in the handout"
        );
        for bad in [
            "<link",
            "src=",
            "href=",
            "@import",
            "url(",
            "<iframe",
            "<img",
            "<object",
            "<embed",
            "fetch(",
            "XMLHttpRequest",
            "import(",
        ] {
            assert!(!h.contains(bad), "{name}: the handout has {bad}");
        }
        assert!(h.starts_with("<!DOCTYPE html>") && h.ends_with("</html>\n"));
        assert_eq!(h.matches("<style>").count(), 1);
        // Every SVG inline, and ids unique in the page.
        let ids = attr_values(&h, "id");
        let unique: BTreeSet<&String> = ids.iter().collect();
        assert_eq!(unique.len(), ids.len(), "{name}: duplicate ids");
    }
}

/// Each plan's steps listed in order with their sentences, in the language asked.
#[test]
fn every_sentence_is_in_its_plan() {
    for name in ["six_link_fig2_10", "shaper_fig2_11"] {
        for lang in [Lang::En, Lang::Uk, Lang::Ru] {
            let (solved, h) = fixture_handout(name, lang);
            for (k, s) in &solved {
                for (kind, plan) in plans(s) {
                    let fig = figure(&h, *k, kind);
                    assert_eq!(
                        attr_values(fig, "data-steps"),
                        vec![plan.steps.len().to_string()]
                    );
                    for i in 0..plan.steps.len() {
                        let li = between(fig, &format!("<li data-step=\"{}\">", i + 1), "</li>")
                            .unwrap_or_else(|| panic!("{name} pos {k} {kind}: no step {}", i + 1));
                        let want = sentence(plan, i, lang);
                        assert_eq!(
                            letters(&text(li)),
                            letters(&want),
                            "{name} pos {k} {kind} step {}",
                            i + 1
                        );
                        assert!(li.contains(&rich(&want)));
                    }
                }
            }
        }
    }
}

/// Every step reveals something: `data-step` covers 1..=steps in each
/// plan's figure; in its SVG, every step that draws (all but the vector
/// equations and the shared ω/ε of a prismatic pair); `data-until` after
/// `data-step`.
#[test]
fn data_steps_cover_every_step() {
    for name in FIXTURES {
        let (solved, h) = fixture_handout(name, Lang::En);
        for (k, s) in &solved {
            for (kind, plan) in plans(s) {
                let at = format!("{name} pos {k} {kind}");
                let fig = figure(&h, *k, kind);
                let n = plan.steps.len();
                let all: BTreeSet<usize> = attr_values(fig, "data-step")
                    .iter()
                    .map(|v| v.parse().unwrap())
                    .collect();
                assert_eq!(all, (1..=n).collect(), "{at}");
                let svg = between(fig, "<svg", "</svg>").unwrap();
                let drawn: BTreeSet<usize> = attr_values(svg, "data-step")
                    .iter()
                    .map(|v| v.parse().unwrap())
                    .collect();
                for (i, step) in plan.steps.iter().enumerate() {
                    let draws = !matches!(step.op, Op::Equation { .. } | Op::Same { .. });
                    assert_eq!(drawn.contains(&(i + 1)), draws, "{at} step {}", i + 1);
                }
                // Each group's until comes after its step.
                for g in svg.split("<g ").skip(1) {
                    let head = &g[..g.find('>').unwrap()];
                    let s: usize = attr_values(&format!(" {head}"), "data-step")[0]
                        .parse()
                        .unwrap();
                    if let Some(u) = attr_values(&format!(" {head}"), "data-until").first() {
                        assert!(u.parse::<usize>().unwrap() > s, "{at}: {head}");
                    }
                }
            }
        }
    }
}

/// `draw_steps` tags every primitive with a step, and a point's dot is
/// never shown before the step that made the point; `draw` draws the same.
#[test]
fn draw_steps_tags_every_primitive() {
    for name in FIXTURES {
        let scene = mechplan::Scene::from_json(&fixture(name).to_string()).unwrap();
        let (an, solved) = solve(scene);
        for s in &solved {
            for (_, plan) in plans(s) {
                let mut c = Canvas::default();
                let tags = draw_steps(plan, &mut c, &an.points);
                assert_eq!(tags.len(), c.prims.len());
                assert!(tags.iter().all(|&t| t < plan.steps.len()));
                let made = made_at(plan);
                for (p, &t) in c.prims.iter().zip(&tags) {
                    if let Prim::Circle { id: Some(id), .. } = p {
                        let key = id.strip_prefix("pt-").unwrap();
                        let i = plan.points.iter().position(|q| q.key == key).unwrap();
                        assert!(made[i].is_none_or(|m| m <= t), "{name}: {id}");
                    }
                }
                let mut d = Canvas::default();
                mechplan::drawing::plan::draw(plan, &mut d, &an.points);
                let (mut a, mut b) = (String::new(), String::new());
                c.write(&mut a, 0.0, 0.0);
                d.write(&mut b, 0.0, 0.0);
                assert_eq!(a, b);
            }
        }
    }
}

#[test]
fn notation_as_on_the_board() {
    assert_eq!(rich("v_B3C"), "v<sub>B3C</sub>");
    assert_eq!(rich("a^n_BA"), "a<sup>n</sup><sub>BA</sub>");
    assert_eq!(rich("p_vb3 = 5"), "p<sub>v</sub>b<sub>3</sub> = 5");
    assert_eq!(rich("μ_a = 0.05"), "μ<sub>a</sub> = 0.05");
    assert_eq!(
        rich("ω3 = 1.5 rad/s, O2B"),
        "ω<sub>3</sub> = 1.5 rad/s, O<sub>2</sub>B"
    );
    assert_eq!(rich("a < b & c"), "a &lt; b &amp; c");
    // Doubly underlined (known) vectors keep their underlines.
    assert_eq!(
        rich("v\u{333}_\u{333}B\u{333}"),
        "v\u{333}<sub>B\u{333}</sub>"
    );
}

/// A number as the handout prints it (a decimal comma in uk/ru, the
/// minus sign U+2212) as a value.
fn printed(t: &str) -> f64 {
    t.replace('\u{2212}', "-")
        .replace(',', ".")
        .parse()
        .unwrap()
}

/// The number right after `mark` in `s` (digits, a decimal mark, a sign).
fn after<'a>(s: &'a str, mark: &str) -> &'a str {
    let i = s.find(mark).unwrap_or_else(|| panic!("no {mark:?} in {s}")) + mark.len();
    let rest = &s[i..];
    let n = rest
        .char_indices()
        .find(|&(j, c)| {
            !(c.is_ascii_digit()
                || (j > 0 && (c == '.' || c == ','))
                || c == '-'
                || c == '\u{2212}')
        })
        .map_or(rest.len(), |x| x.0);
    rest[..n].trim_end_matches(['.', ','])
}

/// A number written with a decimal point: a digit, '.', a digit.
fn decimal_points(text: &str) -> Vec<String> {
    let c: Vec<char> = text.chars().collect();
    (1..c.len().saturating_sub(1))
        .filter(|&i| c[i] == '.' && c[i - 1].is_ascii_digit() && c[i + 1].is_ascii_digit())
        .map(|i| {
            c[i.saturating_sub(30)..(i + 30).min(c.len())]
                .iter()
                .collect()
        })
        .collect()
}

/// A dynamics scene's handout carries every position's force analysis:
/// one figure per Assur group and one for the input link, each with its
/// free body and its polygon, the μ_F it prints the force plan's own, its
/// steps the sentences of `solve --steps`; Zhukovsky's lever with the
/// balancing value the analysis found, to the printed digits; in uk no
/// number with a decimal point.
#[test]
fn a_dynamics_handout_has_the_force_analysis() {
    use mechplan::format::num;
    use mechplan::words::force_plans::{plan_head, plan_sentences};
    use mechplan::words::numbers::decimals;
    for (name, lang) in [
        ("dynamics/six_link_fig2_10", Lang::Uk),
        ("dynamics/shaper_fig2_11", Lang::Uk),
        ("dynamics/six_link_fig2_10", Lang::En),
    ] {
        let scene = mechplan::Scene::from_json(&fixture(name).to_string()).unwrap();
        let (an, solved) = solve(scene);
        let h = handout(&an, &solved, lang);
        for (k, s) in solved.iter().enumerate() {
            let pos = an.numbering.number(k);
            let at = format!("{name} {lang:?} position {pos}");
            let d = s.dynamics.as_ref().unwrap();
            let fp = d.force_plans.as_ref().unwrap();
            let section = between(&h, &format!("id=\"pos-{pos}\""), "</section>").unwrap();
            let forces = between(section, &format!("id=\"pos-{pos}-forces\""), "</section>")
                .unwrap_or_else(|| panic!("{at}: no force analysis"));
            // One polygon per group, and the input link's.
            assert_eq!(fp.plans.len(), an.structure.groups.len() + 1, "{at}");
            assert_eq!(
                forces.matches("<figure class=\"fig force\"").count(),
                fp.plans.len(),
                "{at}"
            );
            for (i, plan) in fp.plans.iter().enumerate() {
                let fig = between(forces, &format!("id=\"pos-{pos}-f{}\"", i + 1), "</figure>")
                    .unwrap_or_else(|| panic!("{at}: no figure of plan {}", i + 1));
                // The free body and the polygon, its vectors drawn.
                assert_eq!(fig.matches("<svg ").count(), 2, "{at} plan {}", i + 1);
                assert!(fig.contains("-vec-"), "{at} plan {}: no vectors", i + 1);
                // μ_F in the caption and in the plan's heading: the plan's.
                let caption = between(fig, "<figcaption>", "</figcaption>").unwrap();
                let mark = "μ<sub>F</sub> = ";
                let mu = printed(after(caption, mark));
                assert_eq!(mu, plan.mu, "{at} plan {}: μ_F", i + 1);
                let head = between(fig, "<p class=\"force-head\">", "</p>").unwrap();
                assert_eq!(printed(after(head, mark)), plan.mu, "{at}");
                assert_eq!(
                    letters(&text(head)),
                    letters(&decimals(&plan_head(&an, plan, lang), lang))
                );
                // The steps, in the words of `solve --steps`.
                let sentences = plan_sentences(&an, &d.loads, plan, lang);
                let items: Vec<&str> = fig.split("<li>").skip(1).collect();
                assert_eq!(items.len(), sentences.len(), "{at} plan {}", i + 1);
                for (li, want) in items.iter().zip(&sentences) {
                    let li = &li[..li.find("</li>").unwrap()];
                    assert_eq!(letters(&text(li)), letters(&decimals(want, lang)), "{at}");
                }
            }
            // The lever and its balancing value, the analysis's.
            let lever = between(forces, &format!("id=\"pos-{pos}-lever-1\""), "</figure>")
                .unwrap_or_else(|| panic!("{at}: no lever"));
            assert!(lever.contains("<svg "), "{at}: the lever is not drawn");
            let last = between(lever, "<li class=\"balancing\">", "</li>").unwrap();
            let last = text(last);
            let value = after(&last, &last[..last.rfind("= ").unwrap() + 2]);
            // To three significant digits, as the lever's table.
            let three = |x: f64| {
                let p = 10f64.powi(2 - x.abs().log10().floor() as i32);
                (x * p).round() / p
            };
            let want = three(d.balancing[0].value());
            let shown = decimals(&num(want).replace('-', "\u{2212}"), lang);
            assert_eq!(value, shown, "{at}: the balancing value");
            assert_eq!(
                num(printed(value)),
                num(three(d.lever[0])),
                "{at}: the lever's"
            );
            if lang == Lang::Uk {
                let bad = decimal_points(&text(forces));
                assert!(bad.is_empty(), "{at}: {bad:#?}");
            }
        }
    }
}

/// A handout without `dynamics` is as it was before the force analysis
/// came (its SHA-256 in tests/golden/handout; UPDATE_GOLDEN=1 writes it):
/// no force section, no force style.
#[test]
fn a_handout_without_dynamics_is_unchanged() {
    use sha2::{Digest, Sha256};
    // As `mechplan draw --html` writes it.
    let dir = std::env::temp_dir().join(format!("mechplan-handout-{}", std::process::id()));
    let scene = format!(
        "{}/fixtures/six_link_fig2_10.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .args(["draw", &scene, "--html", "-o", dir.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(out.status.success());
    let h = std::fs::read_to_string(dir.join("handout.html")).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    assert!(!h.contains("class=\"forces\""));
    assert!(!h.contains(".forces "));
    let got = format!("{:x}\n", Sha256::digest(h.as_bytes()));
    let path = format!(
        "{}/tests/golden/handout/six_link_fig2_10_en.sha256",
        env!("CARGO_MANIFEST_DIR")
    );
    if std::env::var_os("UPDATE_GOLDEN").is_some() {
        std::fs::create_dir_all(std::path::Path::new(&path).parent().unwrap()).unwrap();
        std::fs::write(&path, &got).unwrap();
        return;
    }
    let want = std::fs::read_to_string(&path).unwrap();
    assert_eq!(got, want, "the handout of six_link_fig2_10 changed");
}

/// Every number a Ukrainian or Russian handout shows is written with the
/// decimal comma: headings, tabs, result tables (values, drafting bounds,
/// the plans' worst angle and δ), captions and sentences. The scene's
/// title is the user's text ("Fig. 2.10") and is left out.
#[test]
fn a_uk_or_ru_handout_writes_no_decimal_point() {
    for name in ["six_link_fig2_10", "shaper_fig2_11"] {
        for lang in [Lang::Uk, Lang::Ru] {
            let mut v = fixture(name);
            v["title"] = serde_json::json!("");
            let (an, s) = solve(mechplan::Scene::from_json(&v.to_string()).unwrap());
            let h = handout(&an, &s, lang);
            let body = &h[h.find("<body").unwrap()..];
            let body = body.split("<script").next().unwrap();
            let points = decimal_points(&text(body));
            assert!(points.is_empty(), "{name} {lang:?}: {points:?}");
            // It has numbers at all: a comma between digits.
            assert!(
                text(body).contains(",5") || text(body).contains(",0"),
                "{name} {lang:?}"
            );
        }
    }
}

/// The board's caption names the position whose tab is current: for every
/// tab of a Ukrainian handout (a `count` sweep numbered from 0, given
/// angles from 1), the plans the board steps through under that tab (the
/// figures with the tab's `data-pos`) carry a caption (`data-title`, the
/// text the page's script writes on the board) ending in "положення N"
/// with N the tab's number, as the position's heading does; and the script
/// writes the board from that caption alone and marks the tab of the same
/// figure's `data-pos` (no number of its own made from an index).
#[test]
fn the_boards_caption_is_the_number_of_its_tab() {
    let js = include_str!("../src/presentation/drawing/handout.js");
    for needle in [
        "pos: +fig.getAttribute('data-pos')",
        "title: fig.getAttribute('data-title')",
        "where.textContent = P.title + ",
        "showPos(P.pos);",
        "+t.getAttribute('data-pos') === pos",
    ] {
        assert!(js.contains(needle), "handout.js no longer has {needle:?}");
    }
    let board: Vec<&str> = js
        .lines()
        .filter(|l| l.contains("where.textContent"))
        .collect();
    assert_eq!(
        board.len(),
        1,
        "the board's caption written once: {board:?}"
    );
    assert!(
        !board[0].contains("pos") && !board[0].contains("+ 1"),
        "the board's caption makes a number of its own: {}",
        board[0]
    );
    for (name, first) in [("six_link_fig2_10", 0usize), ("prp_tangent_drive", 1)] {
        let dir = fresh("html-board", name);
        let scene = format!("{}/fixtures/{name}.json", env!("CARGO_MANIFEST_DIR"));
        let (code, _, err) = run(&[
            "draw",
            &scene,
            "-o",
            dir.to_str().unwrap(),
            "--html",
            "--lang",
            "uk",
        ]);
        assert_eq!(code, 0, "{name}: {err}");
        let h = std::fs::read_to_string(dir.join("handout.html")).unwrap();
        let tag = r#"<button type="button" class="tab" data-pos=""#;
        let tabs: Vec<(usize, usize)> = h
            .match_indices(tag)
            .map(|(i, _)| {
                let rest = &h[i + tag.len()..];
                let pos = rest[..rest.find('"').unwrap()].parse().unwrap();
                let shown = &rest[rest.find('>').unwrap() + 1..];
                let shown = shown[..shown.find(' ').unwrap()].parse().unwrap();
                (pos, shown)
            })
            .collect();
        assert!(tabs.len() >= 7, "{name}: {} tabs", tabs.len());
        assert_eq!(tabs[0].0, first, "{name}: the first tab");
        let figures: Vec<&str> = h
            .match_indices(r#"<figure class="fig plan""#)
            .map(|(i, _)| &h[i..i + h[i..].find('>').unwrap()])
            .collect();
        let attr = |el: &str, a: &str| {
            let key = format!(" {a}=\"");
            let i = el.find(&key).unwrap() + key.len();
            el[i..i + el[i..].find('"').unwrap()].to_string()
        };
        for &(pos, shown) in &tabs {
            assert_eq!(
                pos, shown,
                "{name}: the tab of position {pos} shows {shown}"
            );
            let under: Vec<String> = figures
                .iter()
                .filter(|f| attr(f, "data-pos") == pos.to_string())
                .map(|f| attr(f, "data-title"))
                .collect();
            assert!(!under.is_empty(), "{name}: no plan under tab {pos}");
            for title in &under {
                assert!(
                    title.ends_with(&format!("положення {pos}")),
                    "{name}: the board says {title:?} above tab {pos}"
                );
            }
            assert!(
                h.contains(&format!(
                    "<section class=\"position\" id=\"pos-{pos}\" data-pos=\"{pos}\">\n<h2>Положення {pos}: "
                )),
                "{name}: the heading of position {pos}"
            );
        }
        // Every plan is under a tab.
        for f in &figures {
            let pos: usize = attr(f, "data-pos").parse().unwrap();
            assert!(
                tabs.iter().any(|t| t.0 == pos),
                "{name}: a plan of position {pos} without a tab"
            );
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
}
