//! `mechplan serve`: a local web page on which a student (or a teacher)
//! grades a plan drawn on paper without writing a file — choose a scene,
//! open a photo, click the rectangle's corners and the plan's points, read
//! the verdict. The page is one embedded file (`serve.html`): nothing is
//! fetched from outside and nothing leaves the machine. The server is
//! tiny_http on a pool of worker threads, so several students grade at
//! once; every request is checked (its size, its JSON, an upload that is
//! no image) and answered with a message, and a request that fails never
//! stops the server.
//!
//! Grading goes through the same path as `mechplan check SCENE MARKS`
//! ([`mechplan::check_file`]): the page's marks are written as a marks
//! file beside the uploaded photo in the server's own folder, and checked.

use mechplan::{CheckRequest, PlanKind, Study};
use serde_json::{Value, json};
use std::io::Read;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use tiny_http::{Header, Method, Request, Response, Server};

/// The page: HTML, its style and script in one file.
const PAGE: &str = include_str!("serve.html");

/// The scenes the page offers without a file: the project's examples.
const BUNDLED: &[(&str, &str)] = &[
    (
        "six_link_fig2_10",
        include_str!("../fixtures/six_link_fig2_10.json"),
    ),
    ("four_bar", include_str!("../fixtures/four_bar.json")),
    (
        "offset_slider_crank",
        include_str!("../fixtures/offset_slider_crank.json"),
    ),
    (
        "shaper_fig2_11",
        include_str!("../fixtures/shaper_fig2_11.json"),
    ),
    (
        "compressor_fig2_12",
        include_str!("../fixtures/compressor_fig2_12.json"),
    ),
    (
        "rrp_rotating_guide_002",
        include_str!("../fixtures/rrp_rotating_guide_002.json"),
    ),
    (
        "prp_tangent_drive",
        include_str!("../fixtures/prp_tangent_drive.json"),
    ),
    ("class3_004", include_str!("../fixtures/class3_004.json")),
    (
        "dwell_six_link_003",
        include_str!("../fixtures/dwell_six_link_003.json"),
    ),
    (
        "slider_driven_rocker",
        include_str!("../fixtures/slider_driven_rocker.json"),
    ),
    (
        "boom_cylinder",
        include_str!("../fixtures/boom_cylinder.json"),
    ),
    (
        "arm_two_cylinders",
        include_str!("../fixtures/arm_two_cylinders.json"),
    ),
    (
        "five_bar_two_cranks",
        include_str!("../fixtures/five_bar_two_cranks.json"),
    ),
];

/// The largest JSON request (a scene and its marks), bytes.
const MAX_JSON: usize = 2 << 20;

/// The most pixels an uploaded photo may have (a 100-megapixel camera's
/// frame): a larger header is a decompression bomb, not a photo.
pub const MAX_PIXELS: u64 = 100_000_000;

/// What `serve` is started with.
pub struct Options {
    /// Where to listen (`127.0.0.1:8080`; port 0: any free port).
    pub listen: String,
    /// Scene files offered beside the bundled examples.
    pub scenes: Vec<PathBuf>,
    /// A teacher's folder: its subfolders of photos and marks may be
    /// graded into a gradebook from the page. None: no teacher's mode.
    pub teacher: Option<PathBuf>,
    /// The largest photo accepted, MB.
    pub max_upload_mb: usize,
    /// Worker threads (requests handled at once).
    pub workers: usize,
}

/// The server's state, shared by its workers.
struct State {
    /// The server's own folder: scenes written out, uploads, marks.
    dir: PathBuf,
    /// (name, title, path) of each scene offered.
    scenes: Vec<(String, String, PathBuf)>,
    teacher: Option<PathBuf>,
    max_upload: usize,
    counter: AtomicU64,
}

/// A request's failure: the HTTP status and the message the page shows.
struct Failure(u16, String);

impl From<mechplan::Error> for Failure {
    fn from(e: mechplan::Error) -> Failure {
        Failure(400, e.to_string())
    }
}

fn bad(message: impl Into<String>) -> Failure {
    Failure(400, message.into())
}

/// Run the server until the process ends: print its address, then serve.
pub fn run(o: Options) -> Result<(), mechplan::Error> {
    let fail = |what: &str, e: &dyn std::fmt::Display| {
        mechplan::Error::scene("listen", format!("{what}: {e}"))
    };
    let dir = std::env::temp_dir().join(format!("mechplan-serve-{}", std::process::id()));
    std::fs::create_dir_all(dir.join("uploads")).map_err(|e| fail("its folder", &e))?;
    let mut scenes = Vec::new();
    for (name, text) in BUNDLED {
        let path = dir.join(format!("{name}.json"));
        std::fs::write(&path, text).map_err(|e| fail("its folder", &e))?;
        scenes.push((name.to_string(), title_of(text), path));
    }
    for path in &o.scenes {
        let text = mechplan::study::read(path)?;
        // A scene that does not solve is refused before the page offers it.
        Study::named(&text, &path.display().to_string())?.solve()?;
        let name = path
            .file_stem()
            .map_or("scene".into(), |s| s.to_string_lossy().into_owned());
        scenes.insert(0, (name, title_of(&text), path.clone()));
    }
    let server = Server::http(&o.listen).map_err(|e| fail(&o.listen, &e))?;
    let addr = server
        .server_addr()
        .to_ip()
        .ok_or_else(|| fail(&o.listen, &"not an IP address"))?;
    println!("mechplan serve: http://{addr}/ (Ctrl-C stops it)");
    use std::io::Write;
    let _ = std::io::stdout().flush();
    let state = Arc::new(State {
        dir,
        scenes,
        teacher: o.teacher,
        max_upload: o.max_upload_mb.max(1) << 20,
        counter: AtomicU64::new(0),
    });
    let server = Arc::new(server);
    let workers: Vec<_> = (0..o.workers.max(1))
        .map(|_| {
            let (server, state) = (server.clone(), state.clone());
            std::thread::spawn(move || {
                while let Ok(rq) = server.recv() {
                    serve_one(&state, rq);
                }
            })
        })
        .collect();
    for w in workers {
        let _ = w.join();
    }
    Ok(())
}

/// A scene's title (its name when it has none).
fn title_of(text: &str) -> String {
    serde_json::from_str::<Value>(text)
        .ok()
        .and_then(|v| v["title"].as_str().map(str::to_string))
        .unwrap_or_default()
}

fn header(name: &str, value: &str) -> Header {
    Header::from_bytes(name.as_bytes(), value.as_bytes()).expect("a valid header")
}

/// Answer one request; a panic in grading is caught and answered as an
/// internal error, the worker going on.
fn serve_one(state: &State, mut rq: Request) {
    let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| route(state, &mut rq)));
    let response = match result {
        Ok(Ok((body, kind))) => Response::from_data(body).with_header(header("Content-Type", kind)),
        Ok(Err(Failure(code, message))) => {
            Response::from_data(json!({ "error": message }).to_string().into_bytes())
                .with_status_code(code)
                .with_header(header("Content-Type", "application/json"))
        }
        Err(_) => Response::from_data(
            json!({ "error": "internal error: the request could not be graded" })
                .to_string()
                .into_bytes(),
        )
        .with_status_code(500)
        .with_header(header("Content-Type", "application/json")),
    };
    // Nothing of the page comes from elsewhere, and it is never framed.
    let response = response
        .with_header(header(
            "Content-Security-Policy",
            "default-src 'self'; img-src 'self' blob: data:; style-src 'unsafe-inline'; script-src 'unsafe-inline'",
        ))
        .with_header(header("X-Frame-Options", "DENY"));
    let _ = rq.respond(response);
}

type Reply = Result<(Vec<u8>, &'static str), Failure>;

fn reply_json(v: &Value) -> Reply {
    Ok((v.to_string().into_bytes(), "application/json"))
}

fn route(state: &State, rq: &mut Request) -> Reply {
    let url = rq.url().to_string();
    let (path, query) = url.split_once('?').unwrap_or((&url, ""));
    match (rq.method(), path) {
        (Method::Get, "/") => Ok((PAGE.as_bytes().to_vec(), "text/html; charset=utf-8")),
        (Method::Get, "/api/scenes") => reply_json(&json!(
            state
                .scenes
                .iter()
                .map(|(name, title, _)| json!({ "name": name, "title": title }))
                .collect::<Vec<_>>()
        )),
        (Method::Get, "/api/plan") => plan(state, query),
        (Method::Post, "/api/photo") => photo(state, rq),
        (Method::Post, "/api/check") => {
            let body = read_json(rq)?;
            check(state, &body)
        }
        (Method::Post, "/api/grade") => {
            let body = read_json(rq)?;
            grade(state, &body)
        }
        (_, "/" | "/api/scenes" | "/api/plan" | "/api/photo" | "/api/check" | "/api/grade") => Err(
            Failure(405, format!("{} {path}: not this method", rq.method())),
        ),
        _ => Err(Failure(404, format!("{path}: no such page"))),
    }
}

/// The request's body, at most `limit` bytes (413 beyond).
fn body(rq: &mut Request, limit: usize) -> Result<Vec<u8>, Failure> {
    if rq.body_length().is_some_and(|n| n > limit) {
        return Err(Failure(
            413,
            format!("the upload is larger than {} MB", limit >> 20),
        ));
    }
    let mut bytes = Vec::new();
    rq.as_reader()
        .take(limit as u64 + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| bad(format!("the upload could not be read: {e}")))?;
    if bytes.len() > limit {
        return Err(Failure(
            413,
            format!("the upload is larger than {} MB", limit >> 20),
        ));
    }
    Ok(bytes)
}

fn read_json(rq: &mut Request) -> Result<Value, Failure> {
    let bytes = body(rq, MAX_JSON)?;
    serde_json::from_slice(&bytes).map_err(|e| bad(format!("the request is no JSON: {e}")))
}

/// A query's parameter.
fn param<'a>(query: &'a str, key: &str) -> Option<&'a str> {
    query
        .split('&')
        .filter_map(|kv| kv.split_once('='))
        .find(|(k, _)| *k == key)
        .map(|(_, v)| v)
}

/// The path of the scene the page names.
fn scene_path<'a>(state: &'a State, name: &str) -> Result<&'a Path, Failure> {
    state
        .scenes
        .iter()
        .find(|(n, ..)| n == name)
        .map(|(.., p)| p.as_path())
        .ok_or_else(|| bad(format!("unknown scene \"{name}\"")))
}

/// What the page needs to mark a plan: the scene's positions, the plan's
/// points in the order of its construction (the letters to click), and
/// where the right plan has them (mm from the pole at its μ), to draw it
/// over the photo.
fn plan(state: &State, query: &str) -> Reply {
    let scene = param(query, "scene").ok_or_else(|| bad("no scene"))?;
    let kind = match param(query, "plan").unwrap_or("velocity") {
        "velocity" => PlanKind::Velocity,
        "acceleration" => PlanKind::Acceleration,
        other => return Err(bad(format!("unknown plan \"{other}\""))),
    };
    let study = Study::from_path(scene_path(state, scene)?)?;
    let solution = study.solve()?;
    let first = study.numbering().first();
    let number = match param(query, "position") {
        Some(p) => p
            .parse::<usize>()
            .map_err(|_| bad(format!("position \"{p}\" is no number")))?,
        None => first,
    };
    let result = solution.position(number)?.to_json();
    let name = if kind == PlanKind::Velocity {
        "velocity"
    } else {
        "acceleration"
    };
    let p = &result["plans"][name];
    if p.is_null() {
        return Err(bad(format!(
            "the scene does not draw the {name} plan (want.plans)"
        )));
    }
    let pole = if kind == PlanKind::Velocity {
        "p_v"
    } else {
        "p_a"
    };
    let mut letters = vec![pole.to_string()];
    letters.extend(
        p["points"]
            .as_object()
            .into_iter()
            .flatten()
            .map(|(k, _)| k.clone()),
    );
    reply_json(&json!({
        "positions": solution.len(),
        "first": first,
        "letters": letters,
        "mu": p["mu"],
        "points": p["points"],
    }))
}

/// Store an uploaded photo: a JPEG or PNG of at most the size limit and
/// [`MAX_PIXELS`], its id for the check.
fn photo(state: &State, rq: &mut Request) -> Reply {
    let bytes = body(rq, state.max_upload)?;
    let ext = if bytes.starts_with(&[0xFF, 0xD8, 0xFF]) {
        "jpg"
    } else if bytes.starts_with(b"\x89PNG\r\n\x1a\n") {
        "png"
    } else {
        return Err(bad(
            "the upload is no photo: a JPEG or PNG file is expected",
        ));
    };
    let (w, h) = dimensions(&bytes).ok_or_else(|| {
        bad(format!(
            "the {ext} file is damaged: its size cannot be read"
        ))
    })?;
    if u64::from(w) * u64::from(h) > MAX_PIXELS || w == 0 || h == 0 {
        return Err(bad(format!(
            "the photo's {w}×{h} pixels are more than a camera takes ({} megapixels at most)",
            MAX_PIXELS / 1_000_000
        )));
    }
    let id = format!(
        "{}.{ext}",
        state.counter.fetch_add(1, Ordering::Relaxed) + 1
    );
    std::fs::write(state.dir.join("uploads").join(&id), &bytes)
        .map_err(|e| Failure(500, format!("the photo could not be stored: {e}")))?;
    reply_json(&json!({ "id": id, "width": w, "height": h }))
}

/// A JPEG's or PNG's width and height from its header (the image
/// crate reads the header only, never the pixels).
fn dimensions(bytes: &[u8]) -> Option<(u32, u32)> {
    image::ImageReader::new(std::io::Cursor::new(bytes))
        .with_guessed_format()
        .ok()?
        .into_dimensions()
        .ok()
}

/// Grade the page's marks: the photo copied beside where their marks
/// file would be, checked as `mechplan check` checks it; the report
/// as text and JSON, the exit status `check` would give, the overlay.
fn check(state: &State, body: &Value) -> Reply {
    let scene = body["scene"]
        .as_str()
        .ok_or_else(|| bad("/scene: the scene's name is missing"))?;
    let scene = scene_path(state, scene)?;
    let mut marks = body["marks"].clone();
    let Some(m) = marks.as_object_mut() else {
        return Err(bad("/marks: the marks are a JSON object"));
    };
    let n = state.counter.fetch_add(1, Ordering::Relaxed) + 1;
    let dir = state.dir.join(format!("check-{n}"));
    std::fs::create_dir_all(&dir).map_err(|e| Failure(500, e.to_string()))?;
    if let Some(id) = body["photo"].as_str() {
        // An id the server gave: digits and its extension, no path.
        let ok = id.split_once('.').is_some_and(|(d, e)| {
            !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit()) && ["jpg", "png"].contains(&e)
        });
        let from = state.dir.join("uploads").join(id);
        if !ok || !from.is_file() {
            return Err(bad(format!("/photo: no uploaded photo \"{id}\"")));
        }
        let to = dir.join(format!("photo.{}", id.rsplit('.').next().unwrap_or("jpg")));
        std::fs::copy(&from, &to).map_err(|e| Failure(500, e.to_string()))?;
        if let Some(p) = m.get_mut("photo").and_then(Value::as_object_mut) {
            p.insert(
                "file".into(),
                json!(to.file_name().unwrap().to_string_lossy()),
            );
        }
    }
    // Graded once, as `check` grades a marks file of this name: its photo
    // found beside it.
    let lang = body["lang"].as_str().and_then(mechplan::Lang::parse);
    let req = CheckRequest {
        lang,
        ..CheckRequest::default()
    };
    let name = dir.join("marks.json").display().to_string();
    let checked = Study::from_path(scene).and_then(|study| {
        study
            .solve()?
            .check_answer(&marks.to_string(), &name, false, &req)
    });
    let _ = std::fs::remove_dir_all(&dir);
    let checked = checked?;
    let (status, text, report) = (checked.status(), checked.to_text(), checked.to_json());
    let svg = checked.overlay().unwrap_or_default();
    reply_json(&json!({
        "status": status,
        "text": text,
        "report": report,
        "overlay": svg,
        "marks": marks,
    }))
}

/// The teacher's mode: a subfolder of the teacher's folder (its answers:
/// marks files with their photos, JSON, SVG or DXF answers) graded into a
/// gradebook, as `mechplan check SCENE DIR` grades it.
fn grade(state: &State, body: &Value) -> Reply {
    let Some(root) = &state.teacher else {
        return Err(Failure(
            403,
            "the teacher's mode is off: start the server with --teacher DIR".into(),
        ));
    };
    let scene = body["scene"]
        .as_str()
        .ok_or_else(|| bad("/scene: the scene's name is missing"))?;
    let scene = scene_path(state, scene)?;
    let folder = body["folder"].as_str().unwrap_or("");
    // Only a folder inside the teacher's: no .., no absolute path.
    if Path::new(folder)
        .components()
        .any(|c| !matches!(c, std::path::Component::Normal(_)))
    {
        return Err(bad(format!(
            "/folder: \"{folder}\" is not a folder inside the teacher's folder"
        )));
    }
    let answers = root.join(folder);
    let n = state.counter.fetch_add(1, Ordering::Relaxed) + 1;
    let out = state.dir.join(format!("grade-{n}"));
    let req = CheckRequest::default();
    let graded = mechplan::check_group(scene, &[answers], &req, &out, &mechplan::Silent)?;
    let book = std::fs::read_to_string(out.join("gradebook.csv")).unwrap_or_default();
    reply_json(&json!({
        "status": graded.status(),
        "text": graded.to_text(),
        "gradebook": book,
        "report": graded.to_json(),
    }))
}
