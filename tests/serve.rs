//! `mechplan serve` (docs/serve.md) over real HTTP on 127.0.0.1: the page
//! and its API; a check through the page's route gives what `mechplan
//! check` gives for the same marks; 20 gradings at once, each the same;
//! bad uploads (no image, a 50 MB file, a decompression bomb's header, a
//! damaged JPEG, broken JSON, an unknown scene, a folder outside the
//! teacher's) each answered with a message, the server answering after
//! each; the teacher's mode grades a folder into a gradebook.

use serde_json::{Value, json};
use std::io::{BufRead, BufReader};
use std::process::{Child, Command, Stdio};

/// The server, stopped when dropped.
struct Served {
    child: Child,
    url: String,
}

impl Drop for Served {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn serve(args: &[&str]) -> Served {
    let mut child = Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .arg("serve")
        .args(["--listen", "127.0.0.1:0", "--max-upload-mb", "20"])
        .args(args)
        .stdout(Stdio::piped())
        .spawn()
        .unwrap();
    let mut line = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut line)
        .unwrap();
    let url = line
        .split_whitespace()
        .find(|w| w.starts_with("http://"))
        .unwrap_or_else(|| panic!("no address in {line:?}"))
        .trim_end_matches('/')
        .to_string();
    Served { child, url }
}

/// A request's status and JSON body (errors included).
fn answer(r: Result<ureq::Response, ureq::Error>) -> (u16, Value) {
    let resp = match r {
        Ok(r) => r,
        Err(ureq::Error::Status(_, r)) => r,
        Err(e) => panic!("{e}"),
    };
    let status = resp.status();
    let text = resp.into_string().unwrap();
    (
        status,
        serde_json::from_str(&text).unwrap_or(Value::String(text)),
    )
}

fn get(s: &Served, path: &str) -> (u16, Value) {
    answer(ureq::get(&format!("{}{path}", s.url)).call())
}

fn post_json(s: &Served, path: &str, body: &Value) -> (u16, Value) {
    answer(
        ureq::post(&format!("{}{path}", s.url))
            .set("Content-Type", "application/json")
            .send_string(&body.to_string()),
    )
}

fn post_bytes(s: &Served, path: &str, bytes: &[u8]) -> (u16, Value) {
    answer(ureq::post(&format!("{}{path}", s.url)).send_bytes(bytes))
}

/// The server still answers.
fn alive(s: &Served) {
    let (status, scenes) = get(s, "/api/scenes");
    assert_eq!(status, 200);
    assert!(scenes.as_array().is_some_and(|a| a.len() >= 13), "{scenes}");
}

/// The shaper's answer of docs/check.md's worked example (a wrong ω3).
fn shaper_marks() -> Value {
    json!({"plan":"acceleration","position":3,"mu":0.025,
        "velocity":{"mu":0.004,"values":{"omega3":"1.06 ccw","v_B3B2":0.152}},
        "points":{"b":[-48.0,-135.76],"n3":[-1.5,-17.72],"k3":[-35.16,-136.85],
                  "b3":[-24.92,-15.74],"d":[-34.63,-21.88],"s3":[-17.32,-10.94],"k":[-34.63,0.0]},
        "values":{"a_D":1.02}})
}

/// What `mechplan check` says of `marks` on `scene`: its text and status.
fn cli_check(scene: &str, marks: &Value) -> (String, i32) {
    let dir = std::env::temp_dir().join(format!("mechplan-serve-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("marks.json");
    std::fs::write(&file, marks.to_string()).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .args(["check", &format!("fixtures/{scene}.json")])
        .arg(&file)
        .output()
        .unwrap();
    (
        String::from_utf8_lossy(&out.stdout).into_owned(),
        out.status.code().unwrap(),
    )
}

#[test]
fn the_page_and_its_plan() {
    let s = serve(&[]);
    let page = ureq::get(&format!("{}/", s.url)).call().unwrap();
    assert!(
        page.header("Content-Security-Policy")
            .is_some_and(|c| c.contains("default-src 'self'")),
        "nothing is fetched from outside"
    );
    let html = page.into_string().unwrap();
    assert!(html.contains("<title>mechplan") && html.contains("/api/check"));
    assert!(
        !html.contains("http://") && !html.contains("https://"),
        "no outside address in the page"
    );
    let (status, plan) = get(&s, "/api/plan?scene=four_bar&plan=velocity&position=3");
    assert_eq!(status, 200, "{plan}");
    assert_eq!(plan["first"], 0);
    assert_eq!(plan["positions"], 12);
    let letters: Vec<&str> = plan["letters"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l.as_str().unwrap())
        .collect();
    assert_eq!(letters[0], "p_v", "the pole first: {letters:?}");
    assert!(
        letters.contains(&"a") && letters.contains(&"b"),
        "{letters:?}"
    );
    let (status, e) = get(&s, "/api/plan?scene=four_bar&plan=velocity&position=12");
    assert_eq!(status, 400);
    assert!(e["error"].as_str().unwrap().contains("position"), "{e}");
    let (status, _) = get(&s, "/nothing");
    assert_eq!(status, 404);
}

#[test]
fn a_check_through_the_page_is_the_commands() {
    let s = serve(&[]);
    let marks = shaper_marks();
    let (status, r) = post_json(
        &s,
        "/api/check",
        &json!({"scene": "shaper_fig2_11", "marks": marks}),
    );
    assert_eq!(status, 200, "{r}");
    let (text, code) = cli_check("shaper_fig2_11", &marks);
    assert_eq!(r["status"], code);
    assert_eq!(code, 1, "the worked example is wrong");
    assert_eq!(r["text"].as_str().unwrap(), text);
    assert!(
        r["overlay"].as_str().unwrap().starts_with("<svg")
            || r["overlay"].as_str().unwrap().starts_with("<?xml")
    );
    assert_eq!(r["report"]["status"], 1);
}

#[test]
fn twenty_students_at_once() {
    let s = serve(&[]);
    let (text, code) = cli_check("shaper_fig2_11", &shaper_marks());
    let url = s.url.clone();
    let started = std::time::Instant::now();
    let threads: Vec<_> = (0..20)
        .map(|k| {
            let url = url.clone();
            std::thread::spawn(move || {
                let mut marks = shaper_marks();
                marks["title"] = json!(format!("student {k}"));
                let body = json!({"scene": "shaper_fig2_11", "marks": marks});
                answer(
                    ureq::post(&format!("{url}/api/check"))
                        .set("Content-Type", "application/json")
                        .send_string(&body.to_string()),
                )
            })
        })
        .collect();
    for t in threads {
        let (status, r) = t.join().unwrap();
        assert_eq!(status, 200, "{r}");
        assert_eq!(r["status"], code);
        // The title is the only difference: the report's body is the same.
        let body = |t: &str| {
            t.lines()
                .skip_while(|l| !l.starts_with("Grade"))
                .collect::<Vec<_>>()
                .join("\n")
        };
        assert_eq!(body(r["text"].as_str().unwrap()), body(&text));
    }
    eprintln!(
        "20 concurrent gradings in {:.2} s",
        started.elapsed().as_secs_f64()
    );
    alive(&s);
}

#[test]
fn bad_uploads_are_answered_and_the_server_goes_on() {
    let s = serve(&[]);
    // Not an image.
    let (status, e) = post_bytes(&s, "/api/photo", b"GIF89a not a photo at all");
    assert_eq!(status, 400);
    assert!(e["error"].as_str().unwrap().contains("no photo"), "{e}");
    alive(&s);
    // 50 MB: over the limit.
    let mut big = vec![0u8; 50 << 20];
    big[..3].copy_from_slice(&[0xFF, 0xD8, 0xFF]);
    let (status, e) = post_bytes(&s, "/api/photo", &big);
    assert_eq!(status, 413, "{e}");
    assert!(e["error"].as_str().unwrap().contains("20 MB"), "{e}");
    alive(&s);
    // A PNG header that claims 100 000 × 100 000 pixels: a bomb.
    let mut ihdr = b"IHDR".to_vec();
    ihdr.extend(100_000u32.to_be_bytes());
    ihdr.extend(100_000u32.to_be_bytes());
    ihdr.extend([8, 2, 0, 0, 0]);
    let mut png = b"\x89PNG\r\n\x1a\n\0\0\0\x0d".to_vec();
    png.extend(&ihdr);
    png.extend(crc32fast::hash(&ihdr).to_be_bytes());
    // An empty IDAT and the end: a whole file, but for its pixels.
    for chunk in [&b"IDAT"[..], &b"IEND"[..]] {
        png.extend(0u32.to_be_bytes());
        png.extend(chunk);
        png.extend(crc32fast::hash(chunk).to_be_bytes());
    }
    let (status, e) = post_bytes(&s, "/api/photo", &png);
    assert_eq!(status, 400);
    assert!(e["error"].as_str().unwrap().contains("megapixels"), "{e}");
    alive(&s);
    // A JPEG cut short before its frame header.
    let (status, e) = post_bytes(
        &s,
        "/api/photo",
        &[0xFF, 0xD8, 0xFF, 0xE0, 0x00, 0x10, b'J'],
    );
    assert_eq!(status, 400);
    assert!(e["error"].as_str().unwrap().contains("damaged"), "{e}");
    alive(&s);
    // Broken JSON, an unknown scene, marks that are no object, a photo id
    // that is a path.
    let (status, e) =
        answer(ureq::post(&format!("{}/api/check", s.url)).send_string("{\"scene\": "));
    assert_eq!(status, 400);
    assert!(e["error"].as_str().unwrap().contains("no JSON"), "{e}");
    let (status, e) = post_json(&s, "/api/check", &json!({"scene": "nowhere", "marks": {}}));
    assert_eq!(status, 400);
    assert!(
        e["error"].as_str().unwrap().contains("unknown scene"),
        "{e}"
    );
    let (status, e) = post_json(
        &s,
        "/api/check",
        &json!({"scene": "four_bar", "marks": [1]}),
    );
    assert_eq!(status, 400);
    assert!(e["error"].as_str().unwrap().contains("/marks"), "{e}");
    let (status, e) = post_json(
        &s,
        "/api/check",
        &json!({"scene": "four_bar", "marks": {"plan": "velocity"}, "photo": "../../etc/passwd"}),
    );
    assert_eq!(status, 400);
    assert!(e["error"].as_str().unwrap().contains("/photo"), "{e}");
    // Marks the checker refuses: its message, naming the field.
    let (status, e) = post_json(
        &s,
        "/api/check",
        &json!({"scene": "four_bar", "marks": {"plan": "velocity", "position": 1, "mu": -1, "points": {}}}),
    );
    assert_eq!(status, 400);
    assert!(e["error"].as_str().unwrap().contains("/mu"), "{e}");
    // The teacher's mode is off without --teacher.
    let (status, _) = post_json(
        &s,
        "/api/grade",
        &json!({"scene": "four_bar", "folder": "x"}),
    );
    assert_eq!(status, 403);
    alive(&s);
}

#[test]
fn the_teachers_folder_is_graded_into_a_gradebook() {
    let root = std::env::temp_dir().join(format!("mechplan-serve-teacher-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&root);
    std::fs::create_dir_all(root.join("group41")).unwrap();
    let mut wrong = shaper_marks();
    std::fs::write(root.join("group41/ivanenko.json"), wrong.to_string()).unwrap();
    wrong["velocity"]["values"]["omega3"] = json!("1.467 ccw");
    std::fs::write(root.join("group41/petrenko.json"), wrong.to_string()).unwrap();
    let s = serve(&["--teacher", root.to_str().unwrap()]);
    let (status, r) = post_json(
        &s,
        "/api/grade",
        &json!({"scene": "shaper_fig2_11", "folder": "group41"}),
    );
    assert_eq!(status, 200, "{r}");
    let book = r["gradebook"].as_str().unwrap();
    assert!(
        book.contains("ivanenko") && book.contains("petrenko"),
        "{book}"
    );
    assert_eq!(book.lines().count(), 3, "a header and a row each: {book}");
    let (status, e) = post_json(
        &s,
        "/api/grade",
        &json!({"scene": "shaper_fig2_11", "folder": "../"}),
    );
    assert_eq!(status, 400);
    assert!(
        e["error"]
            .as_str()
            .unwrap()
            .contains("inside the teacher's folder"),
        "{e}"
    );
    alive(&s);
    let _ = std::fs::remove_dir_all(&root);
}
