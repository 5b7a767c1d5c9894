//! Plans on paper, photographed and marked (docs/check.md, "Plans on
//! paper: photos and marks"). The right plans come from the method's own
//! solver (tests/student), never from mechplan's construction; each is
//! put on an A4 sheet inside its frame, the sheet "photographed" by a
//! camera of this file's own (tilted up to 15°, turned, 8–12 px per mm),
//! and a marks file written with the frame's corners and the points where
//! the camera puts them, clicked carefully (each up to 0.15 mm off on the
//! sheet). Each marks file must get its JSON twin's verdict: the right
//! plan right, a mistaken one wrong with the same first mistake.

mod common;

mod student;

use kurbo::Vec2;
use mechplan::PlanKind;
use mechplan::check::answer::from_json;
use mechplan::check::{Grade, Report, check};
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use serde_json::{Map, Value, json};
use std::path::Path;
use student::drawing::{Drawing, Source, acceleration_plan, standard_mu, velocity_plan};
use student::rigid::{Model, Options};
use student::scenes;

/// The A4 sheet, mm, and its frame (20 mm left, 5 mm on the other sides).
pub const SHEET: [f64; 2] = [210.0, 297.0];
pub const FRAME_AT: [f64; 2] = [20.0, 5.0];
pub const FRAME: [f64; 2] = [185.0, 287.0];

/// A camera over the sheet: a pinhole at distance `d` (mm) above the
/// sheet's centre, the sheet tilted by `tilt` (radians about x) and `yaw`
/// (about y), the image turned by `turn` and shifted so that it is all in
/// view; `f` in px so that the sheet's centre is `scale` px per mm.
#[derive(Clone, Copy, Debug)]
pub struct Camera {
    pub tilt: f64,
    pub yaw: f64,
    pub turn: f64,
    pub scale: f64,
    pub d: f64,
    pub offset: [f64; 2],
}

impl Camera {
    /// A camera of random pose: each tilt up to 15°, any turn.
    pub fn random(rng: &mut StdRng) -> Camera {
        let deg = |x: f64| x.to_radians();
        let mut c = Camera {
            tilt: deg(rng.random_range(-15.0..15.0)),
            yaw: deg(rng.random_range(-15.0..15.0)),
            turn: deg(rng.random_range(-180.0..180.0)),
            scale: rng.random_range(8.0..12.0),
            d: 500.0,
            offset: [0.0, 0.0],
        };
        // Shift so that the sheet's corners are 40 px inside the image.
        let corners = [[0.0, 0.0], [SHEET[0], 0.0], SHEET, [0.0, SHEET[1]]];
        let px: Vec<[f64; 2]> = corners.iter().map(|&p| c.to_px(p)).collect();
        let lo = px
            .iter()
            .fold([f64::INFINITY; 2], |m, p| [m[0].min(p[0]), m[1].min(p[1])]);
        c.offset = [40.0 - lo[0], 40.0 - lo[1]];
        c
    }

    /// A flatbed scan at 300 dpi: the sheet flat on the glass (no
    /// perspective), laid up to 2° askew.
    pub fn scan(rng: &mut StdRng) -> Camera {
        let mut c = Camera {
            tilt: 0.0,
            yaw: 0.0,
            turn: rng.random_range(-2.0f64..2.0).to_radians(),
            scale: 300.0 / 25.4,
            d: 500.0,
            offset: [0.0, 0.0],
        };
        let corners = [[0.0, 0.0], [SHEET[0], 0.0], SHEET, [0.0, SHEET[1]]];
        let lo = corners
            .iter()
            .map(|&p| c.to_px(p))
            .fold([f64::INFINITY; 2], |m, p| [m[0].min(p[0]), m[1].min(p[1])]);
        c.offset = [40.0 - lo[0], 40.0 - lo[1]];
        c
    }

    /// The pixel (x right, y down, origin at the image's top-left corner)
    /// of sheet point `p` (mm, x right, y up, origin bottom-left).
    pub fn to_px(&self, p: [f64; 2]) -> [f64; 2] {
        let (x, y) = (p[0] - SHEET[0] / 2.0, p[1] - SHEET[1] / 2.0);
        // The sheet turned about x by tilt, then about y by yaw.
        let (ct, st) = (self.tilt.cos(), self.tilt.sin());
        let (y1, z1) = (y * ct, y * st);
        let (cy, sy) = (self.yaw.cos(), self.yaw.sin());
        let (x2, z2) = (x * cy + z1 * sy, -x * sy + z1 * cy);
        let z = self.d + z2;
        let f = self.scale * self.d;
        let (u, v) = (f * x2 / z, -f * y1 / z);
        let (cr, sr) = (self.turn.cos(), self.turn.sin());
        [
            u * cr - v * sr + self.offset[0],
            u * sr + v * cr + self.offset[1],
        ]
    }

    /// The image's size that holds the whole sheet with a margin.
    pub fn size(&self) -> [u32; 2] {
        let corners = [[0.0, 0.0], [SHEET[0], 0.0], SHEET, [0.0, SHEET[1]]];
        let hi = corners
            .iter()
            .map(|&p| self.to_px(p))
            .fold([0.0f64; 2], |m, p| [m[0].max(p[0]), m[1].max(p[1])]);
        [(hi[0] + 40.0).ceil() as u32, (hi[1] + 40.0).ceil() as u32]
    }

    /// The frame's corners in px: bottom-left, bottom-right, top-right,
    /// top-left of the upright sheet.
    pub fn frame_px(&self) -> [[f64; 2]; 4] {
        let [x, y] = FRAME_AT;
        let [w, h] = FRAME;
        [[x, y], [x + w, y], [x + w, y + h], [x, y + h]].map(|p| self.to_px(p))
    }
}

/// How the `i`-th plan is handed in: of every four, two photographed on
/// plain paper, one on millimetre paper, one scanned flat (plain and
/// millimetre paper by turns).
pub fn setting(i: usize, rng: &mut StdRng) -> (Paper, Camera, &'static str) {
    match i % 8 {
        2 | 6 => (
            Paper::Millimetre,
            Camera::random(rng),
            "millimetre paper, photo",
        ),
        3 => (Paper::Plain, Camera::scan(rng), "plain paper, scan"),
        7 => (
            Paper::Millimetre,
            Camera::scan(rng),
            "millimetre paper, scan",
        ),
        _ => (Paper::Plain, Camera::random(rng), "plain paper, photo"),
    }
}

/// A plan on the sheet: its points (mm from the pole) and the pole's
/// place on the sheet, the plan centred in the frame.
#[derive(Clone, Debug)]
pub struct OnSheet {
    pub points: Vec<(String, Vec2)>,
    pub pole: [f64; 2],
}

impl OnSheet {
    pub fn new(points: Vec<(String, Vec2)>) -> OnSheet {
        let (mut lo, mut hi) = (Vec2::ZERO, Vec2::ZERO);
        for (_, p) in &points {
            lo = Vec2::new(lo.x.min(p.x), lo.y.min(p.y));
            hi = Vec2::new(hi.x.max(p.x), hi.y.max(p.y));
        }
        let mid = (lo + hi) * 0.5;
        let centre = [FRAME_AT[0] + FRAME[0] / 2.0, FRAME_AT[1] + FRAME[1] / 2.0];
        OnSheet {
            points,
            pole: [centre[0] - mid.x, centre[1] - mid.y],
        }
    }
    /// Point `p` (mm from the pole) on the sheet.
    pub fn sheet(&self, p: Vec2) -> [f64; 2] {
        [self.pole[0] + p.x, self.pole[1] + p.y]
    }
}

/// A point `r` mm from `p` on the sheet in a random direction, as
/// clicked: its pixel.
pub fn click(cam: &Camera, p: [f64; 2], r: f64, rng: &mut StdRng) -> [f64; 2] {
    let a = rng.random_range(0.0..std::f64::consts::TAU);
    let q = cam.to_px([p[0] + r * a.cos(), p[1] + r * a.sin()]);
    // Clicks are read to a hundredth of a pixel.
    q.map(|x| (x * 100.0).round() / 100.0)
}

/// The answer's JSON twin: its points (mm from the pole, 0.01 mm).
pub fn twin(kind: PlanKind, position: usize, mu: f64, points: &[(String, Vec2)]) -> Value {
    let r = |x: f64| (x * 100.0).round() / 100.0;
    let pts: Map<String, Value> = points
        .iter()
        .map(|(k, p)| (k.clone(), json!([r(p.x), r(p.y)])))
        .collect();
    json!({
        "plan": if kind == PlanKind::Velocity { "velocity" } else { "acceleration" },
        "position": position, "mu": mu, "points": pts,
    })
}

/// The marks file of `plan` photographed by `cam`: the frame's corners
/// and each point (the pole `p_v` or `p_a`) clicked up to `off` mm from where it is.
pub fn marks(
    twin: &Value,
    plan: &OnSheet,
    cam: &Camera,
    off: (f64, f64),
    file: &str,
    rng: &mut StdRng,
) -> Value {
    let mut m = twin.clone();
    let o = m.as_object_mut().unwrap();
    let corners: Vec<Value> = cam
        .frame_px()
        .iter()
        .map(|c| {
            let r = rng.random_range(0.0..=off.0.min(0.15));
            let a = rng.random_range(0.0..std::f64::consts::TAU);
            let q = [
                c[0] + r * cam.scale * a.cos(),
                c[1] + r * cam.scale * a.sin(),
            ];
            json!([
                (q[0] * 100.0).round() / 100.0,
                (q[1] * 100.0).round() / 100.0
            ])
        })
        .collect();
    o.insert(
        "photo".into(),
        json!({ "file": file, "rectangle_px": corners, "rectangle_mm": FRAME }),
    );
    let mut pts = Map::new();
    let pole = click(cam, plan.pole, rng.random_range(off.0..=off.1), rng);
    // The pole by its plan's name: `p` may be a point of the scene (P).
    let pole_key = if twin["plan"] == "velocity" {
        "p_v"
    } else {
        "p_a"
    };
    pts.insert(pole_key.into(), json!(pole));
    for (k, p) in &plan.points {
        let at = click(cam, plan.sheet(*p), rng.random_range(off.0..=off.1), rng);
        pts.insert(k.clone(), json!(at));
    }
    o.insert("points".into(), Value::Object(pts));
    m
}

/// The verdict to compare: the grade and the first mistake (its step and
/// sentence, its measured numbers left out: "laid off 0.7307 times its
/// right length" is the same mistake read 0.7269).
fn verdict(r: &Report) -> (Grade, Option<(usize, Option<String>)>) {
    let first = r.steps.as_ref().and_then(|s| s.mistakes.first()).map(|f| {
        let words = f.mistake.as_ref().map(|m| {
            m.chars()
                .filter(|c| !c.is_ascii_digit() && *c != '.')
                .collect::<String>()
        });
        (f.step.0, words)
    });
    (r.grade(), first)
}

/// How far the twin's first wrong step is beyond its tolerance, mm; a
/// mistake within 0.5 mm of it (the clicks move each point by up to
/// 0.15 mm, the pole too, and the steps' own points with them) is on
/// the edge, where a careful reading may fall either side.
fn margin(r: &Report) -> Option<f64> {
    let s = r.steps.as_ref()?;
    s.steps
        .iter()
        .find(|v| v.judgement == mechplan::check::Judgement::Wrong)
        .map(|v| v.off - v.tolerance)
}

/// One plan to photograph: the scene, its answer's JSON twin and the
/// plan on the sheet; `right`: whether it is the right plan.
pub struct Trial {
    pub case: usize,
    pub title: String,
    pub twin: Value,
    pub plan: OnSheet,
    pub right: bool,
    /// The pencil lines: pairs of points, mm from the pole.
    pub lines: Vec<(Vec2, Vec2)>,
}

/// The lines a velocity or acceleration plan is drawn with: a ray from the
/// pole to every point, and every two points of one link joined.
fn lines_of(m: &Model, d: &Drawing) -> Vec<(Vec2, Vec2)> {
    let mut out: Vec<(Vec2, Vec2)> = d.0.iter().map(|(_, _, p)| (Vec2::ZERO, *p)).collect();
    for (l, body) in m.links.iter().enumerate() {
        if l == m.frame {
            continue;
        }
        let mut pts: Vec<Vec2> = body
            .points
            .iter()
            .filter(|&&p| d.0.iter().any(|x| x.1 == Source::Named(p)))
            .map(|&p| d.of_point(p))
            .collect();
        pts.extend(d.0.iter().filter_map(|(_, s, p)| match s {
            Source::On { link, .. } if *link == l => Some(*p),
            _ => None,
        }));
        for i in 0..pts.len() {
            for j in i + 1..pts.len() {
                out.push((pts[i], pts[j]));
            }
        }
    }
    out.retain(|(a, b)| (*a - *b).hypot() > 1.0);
    out
}

/// Every fixture at its three positions, both plans at the standard
/// scale: the right plan, the plan turned through the pole (the input's
/// velocity or acceleration reversed), and the right plan with its last
/// point 6 mm off.
pub fn trials() -> (Vec<scenes::Case>, Vec<Trial>) {
    let cases = scenes::fixtures();
    let mut out = Vec::new();
    for (ci, case) in cases.iter().enumerate() {
        for (k, s) in case.solved.iter().enumerate() {
            let m = Model::new(&case.json, &case.an, s);
            let Some(vel) = m.velocities(&Options::default()) else {
                continue;
            };
            let Some(acc) = m.accelerations(&vel, &vel.omega, &Options::default()) else {
                continue;
            };
            for kind in [PlanKind::Velocity, PlanKind::Acceleration] {
                let vectors = match kind {
                    PlanKind::Velocity => velocity_plan(&m, &vel),
                    PlanKind::Acceleration => acceleration_plan(&m, &acc),
                };
                let mu = standard_mu(vectors.largest());
                let d = vectors.at_scale(mu);
                if d.0.is_empty() {
                    continue;
                }
                let lines = lines_of(&m, &d);
                let pts: Vec<(String, Vec2)> =
                    d.0.iter().map(|(k, _, p)| (k.clone(), *p)).collect();
                let reversed: Vec<(String, Vec2)> =
                    pts.iter().map(|(k, p)| (k.clone(), -*p)).collect();
                let mut moved = pts.clone();
                let last = moved.len() - 1;
                let p = moved[last].1;
                let perp = if p.hypot() > 1e-9 {
                    Vec2::new(-p.y, p.x) / p.hypot()
                } else {
                    Vec2::new(1.0, 0.0)
                };
                moved[last].1 = p + perp * 6.0;
                let moved_lines: Vec<(Vec2, Vec2)> = lines
                    .iter()
                    .map(|&(a, b)| {
                        let f = |x: Vec2| {
                            if (x - p).hypot() < 1e-9 {
                                moved[last].1
                            } else {
                                x
                            }
                        };
                        (f(a), f(b))
                    })
                    .collect();
                let neg: Vec<(Vec2, Vec2)> = lines.iter().map(|&(a, b)| (-a, -b)).collect();
                for (tag, points, lines, right) in [
                    ("right", pts.clone(), lines.clone(), true),
                    ("reversed", reversed, neg, false),
                    ("last point off", moved, moved_lines, false),
                ] {
                    out.push(Trial {
                        case: ci,
                        title: format!("{} position {} {kind:?}: {tag}", case.name, k + 1),
                        twin: twin(kind, k + 1, mu, &points),
                        plan: OnSheet::new(points),
                        right,
                        lines,
                    });
                }
            }
        }
    }
    (cases, out)
}

/// Grade an answer's JSON text, or a marks file's (read without its
/// photo).
fn grade(case: &scenes::Case, text: &str) -> Result<Report, String> {
    let ans = if text.contains("\"photo\"") {
        mechplan::check::photo::from_marks(text, None).map(|(a, _)| a)
    } else {
        from_json(text)
    }
    .map_err(|e| format!("{e}"))?;
    check(&case.an, &case.solved, &ans).map_err(|e| format!("{e}"))
}

fn rng_for(title: &str) -> StdRng {
    let seed = title.bytes().fold(0xcbf29ce484222325u64, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x100000001b3)
    });
    StdRng::seed_from_u64(seed)
}

/// Careful clicks (each up to 0.15 mm off on the sheet) through a tilted,
/// turned camera: a plan its twin finds right is right, one its twin
/// finds wrong (beyond the edge, [`margin`]) is wrong with the same first
/// mistake; a twin that cannot judge is never made wrong.
#[test]
fn careful_clicks_get_the_twins_verdict() {
    let (cases, trials) = trials();
    let (mut n, mut same, mut right_right, mut wrong_wrong, mut edge, mut undecided) =
        (0, 0, 0, 0, 0, 0);
    let mut differ = Vec::new();
    for (i, t) in trials.iter().enumerate() {
        let case = &cases[t.case];
        let Ok(twin_report) = grade(case, &t.twin.to_string()) else {
            continue;
        };
        let mut rng = rng_for(&t.title);
        let (_, cam, _) = setting(i, &mut rng);
        let m = marks(&t.twin, &t.plan, &cam, (0.0, 0.15), "plan.jpg", &mut rng);
        let r = grade(case, &m.to_string()).unwrap_or_else(|e| panic!("{}: {e}", t.title));
        n += 1;
        let (a, b) = (verdict(&twin_report), verdict(&r));
        if a == b {
            same += 1;
            right_right += usize::from(t.right && a.0 == Grade::Right);
            wrong_wrong += usize::from(!t.right && a.0 == Grade::Wrong);
            continue;
        }
        let on_edge = margin(&twin_report).is_some_and(|d| d < 0.5);
        let fine = match a.0 {
            Grade::CannotJudge => b.0 != Grade::Wrong,
            Grade::Wrong if on_edge => true,
            _ => false,
        };
        if fine {
            if a.0 == Grade::CannotJudge {
                undecided += 1;
            } else {
                edge += 1;
            }
            continue;
        }
        let off = |r: &Report| {
            r.steps.as_ref().map(|s| {
                s.steps
                    .iter()
                    .map(|v| format!("{} {:.2}/{:.2}", v.point, v.off, v.tolerance))
                    .collect::<Vec<_>>()
                    .join(", ")
            })
        };
        differ.push(format!(
            "{}: twin {a:?}, photo {b:?}\n  twin steps {:?}\n  photo steps {:?}",
            t.title,
            off(&twin_report),
            off(&r)
        ));
    }
    eprintln!(
        "careful clicks: {n} marks files, {same} with the twin's verdict ({right_right} right plans right, {wrong_wrong} mistaken ones wrong); {undecided} the twin cannot judge and the photo does not call wrong; {edge} wrong within 0.5 mm of the tolerance read otherwise"
    );
    assert!(n >= 200, "only {n} cases");
    assert!(differ.is_empty(), "{}", differ.join("\n"));
}

const SCENE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/fixtures/six_link_fig2_10.json"
);

/// A marks file of the six-link's right velocity plan at position 1 (the
/// first trial), its photo's name `plan.jpg`.
fn six_link_marks() -> Value {
    let (_, trials) = trials();
    let t = trials
        .iter()
        .find(|t| {
            t.title
                .starts_with("six_link_fig2_10 position 1 Velocity: right")
        })
        .unwrap();
    let mut rng = rng_for(&t.title);
    let cam = Camera::random(&mut rng);
    let mut m = marks(&t.twin, &t.plan, &cam, (0.0, 0.1), "plan.jpg", &mut rng);
    // The fixture's own positions (the scene file as it is).
    m.as_object_mut().unwrap().remove("position");
    m
}

fn write(dir: &Path, name: &str, v: &Value) -> String {
    let p = dir.join(name);
    std::fs::write(&p, v.to_string()).unwrap();
    p.display().to_string()
}

/// The command reads a marks file, finds its photo beside it and states
/// the photo's scale.
#[test]
fn the_command_reads_a_marks_file() {
    let dir = common::fresh("photo", "cli");
    std::fs::write(dir.join("plan.jpg"), b"not read without snap").unwrap();
    let m = six_link_marks();
    let f = write(&dir, "marks.json", &m);
    let (code, out, err) = common::run(&["check", SCENE, &f]);
    assert!(code == 0 || code == 1 || code == 4, "{err}");
    assert!(out.contains("px per mm"), "{out}");
    let (_, json_out, err) = common::run(&["check", SCENE, &f, "--format", "json"]);
    let v: Value = serde_json::from_str(&json_out).unwrap_or_else(|e| panic!("{e}: {err}"));
    let s = v["photo"]["px_per_mm"].as_f64().unwrap();
    assert!((7.0..14.0).contains(&s), "{s}");
    // The photo is found against the marks file's folder.
    std::fs::remove_file(dir.join("plan.jpg")).unwrap();
    let (code, _, err) = common::run(&["check", SCENE, &f]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("/photo/file"), "{err}");
}

/// Bad marks are refused (status 2) with a message naming the field.
#[test]
fn bad_marks_are_refused_naming_the_field() {
    let dir = common::fresh("photo", "bad");
    std::fs::write(dir.join("plan.jpg"), b"x").unwrap();
    let good = six_link_marks();
    let c = good["photo"]["rectangle_px"].clone();
    let edit = |f: &dyn Fn(&mut Value)| {
        let mut m = good.clone();
        f(&mut m);
        m
    };
    let cases: Vec<(&str, Value, &str)> = vec![
        (
            "crossed corners",
            edit(&|m| m["photo"]["rectangle_px"] = json!([c[0], c[2], c[1], c[3]])),
            "/photo/rectangle_px",
        ),
        (
            "mirrored corners",
            edit(&|m| m["photo"]["rectangle_px"] = json!([c[1], c[0], c[3], c[2]])),
            "/photo/rectangle_px",
        ),
        (
            "three corners on a line",
            edit(&|m| {
                let mid = json!([
                    (c[0][0].as_f64().unwrap() + c[2][0].as_f64().unwrap()) / 2.0,
                    (c[0][1].as_f64().unwrap() + c[2][1].as_f64().unwrap()) / 2.0
                ]);
                m["photo"]["rectangle_px"] = json!([c[0], mid, c[2], c[3]]);
            }),
            "/photo/rectangle_px",
        ),
        (
            "a corner repeated",
            edit(&|m| m["photo"]["rectangle_px"] = json!([c[0], c[0], c[2], c[3]])),
            "/photo/rectangle_px",
        ),
        (
            "three corners",
            edit(&|m| m["photo"]["rectangle_px"] = json!([c[0], c[1], c[2]])),
            "/photo/rectangle_px",
        ),
        (
            "a flat rectangle",
            edit(&|m| m["photo"]["rectangle_mm"] = json!([185, 0])),
            "/photo/rectangle_mm",
        ),
        (
            "a negative rectangle",
            edit(&|m| m["photo"]["rectangle_mm"] = json!([-185, 287])),
            "/photo/rectangle_mm",
        ),
        (
            "no pole",
            edit(&|m| {
                m["points"].as_object_mut().unwrap().remove("p_v");
            }),
            "/points",
        ),
        (
            "the pole twice",
            edit(&|m| m["points"]["π"] = m["points"]["p_v"].clone()),
            "/points/π",
        ),
        (
            "a coordinate not a number",
            edit(&|m| m["points"]["b"] = json!(["NaN", 3])),
            "/points/b/0",
        ),
        (
            "a corner not a number",
            edit(&|m| m["photo"]["rectangle_px"][2][1] = json!(null)),
            "/photo/rectangle_px/2/1",
        ),
        (
            "an unknown field of the photo",
            edit(&|m| m["photo"]["dpi"] = json!(300)),
            "/photo/dpi",
        ),
        (
            "an unknown field",
            edit(&|m| m["rotation"] = json!(90)),
            "/rotation",
        ),
        (
            "no photo file",
            edit(&|m| m["photo"]["file"] = json!("elsewhere.jpg")),
            "/photo/file",
        ),
        (
            "the photo not an object",
            edit(&|m| m["photo"] = json!("plan.jpg")),
            "/photo",
        ),
    ];
    for (what, m, field) in cases {
        let f = write(&dir, "bad.json", &m);
        let (code, _, err) = common::run(&["check", SCENE, &f]);
        assert_eq!(code, 2, "{what}: {err}");
        assert!(err.contains(field), "{what}: {err}");
        assert!(!err.contains("panicked"), "{what}: {err}");
    }
    // A literal NaN or an overflowing number is no JSON number.
    let text = good.to_string().replacen(
        "\"rectangle_mm\":[185.0,287.0]",
        "\"rectangle_mm\":[1e999,287.0]",
        1,
    );
    assert!(text.contains("1e999"), "{text}");
    std::fs::write(dir.join("big.json"), text).unwrap();
    let (code, _, err) = common::run(&["check", SCENE, &path(&dir.join("big.json"))]);
    assert_eq!(code, 2, "{err}");
}

fn path(p: &Path) -> String {
    p.display().to_string()
}

/// A small rectangle far from the plan is said to be badly conditioned.
#[test]
fn a_small_rectangle_far_from_the_plan_is_badly_conditioned() {
    let dir = common::fresh("photo", "cond");
    std::fs::write(dir.join("plan.jpg"), b"x").unwrap();
    let mut m = six_link_marks();
    // A 10 mm square at the frame's bottom-left corner, by the same
    // camera: the corners' pixels recomputed from the frame's map.
    let c: Vec<[f64; 2]> = serde_json::from_value(m["photo"]["rectangle_px"].clone()).unwrap();
    let lerp = |s: f64, t: f64| {
        // Bilinear on the frame's corners: close enough for a small square
        // that is itself the rectangle (its own corners define the map).
        let b = [
            c[0][0] + (c[1][0] - c[0][0]) * s,
            c[0][1] + (c[1][1] - c[0][1]) * s,
        ];
        let tp = [
            c[3][0] + (c[2][0] - c[3][0]) * s,
            c[3][1] + (c[2][1] - c[3][1]) * s,
        ];
        [b[0] + (tp[0] - b[0]) * t, b[1] + (tp[1] - b[1]) * t]
    };
    let (s, t) = (10.0 / FRAME[0], 10.0 / FRAME[1]);
    m["photo"]["rectangle_px"] = json!([lerp(0.0, 0.0), lerp(s, 0.0), lerp(s, t), lerp(0.0, t)]);
    m["photo"]["rectangle_mm"] = json!([10, 10]);
    let f = write(&dir, "small.json", &m);
    let (code, out, err) = common::run(&["check", SCENE, &f]);
    assert!(code != 2, "{err}");
    assert!(out.contains("badly conditioned"), "{out}");
    let good = write(&dir, "good.json", &six_link_marks());
    let (_, out, _) = common::run(&["check", SCENE, &good]);
    assert!(!out.contains("badly conditioned"), "{out}");
}

/// A pencil line's width on the sheet, mm, and how much darker than the
/// paper it is (of 255).
const PENCIL_MM: f64 = 0.35;
const PENCIL_DARK: f64 = 120.0;

/// The paper a plan is drawn on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Paper {
    /// White paper with the frame drawn in pencil.
    Plain,
    /// Millimetre paper: an orange grid printed over the frame (lines
    /// every millimetre, bolder every 5 and 10 mm), its border the
    /// rectangle.
    Millimetre,
}

/// The orange of a millimetre grid's ink (R, G, B) and how strongly
/// (of 1) each of its lines is printed: 1 mm, 5 mm, 10 mm and border.
const GRID_INK: [f32; 3] = [236.0, 140.0, 70.0];
const GRID_LINES: [(f64, f64, f32); 4] = [
    (1.0, 0.08, 0.45),
    (5.0, 0.12, 0.7),
    (10.0, 0.2, 0.9),
    (0.0, 0.4, 1.0),
];

/// The sheet of `t` on `paper` seen by `cam`: the table around it, the
/// paper (lit a little unevenly), the frame or the grid, and the plan's
/// lines in pencil (antialiased, each `PENCIL_MM` wide), then blurred (a
/// 3 px box, once each way), with noise (±8 levels in each channel).
pub fn photograph(t: &Trial, cam: &Camera, paper: Paper, rng: &mut StdRng) -> image::RgbImage {
    let [w, h] = cam.size();
    let (wu, hu) = (w as usize, h as usize);
    let mut v = vec![[70.0f32, 66.0, 60.0]; wu * hu];
    let sheet = [[0.0, 0.0], [SHEET[0], 0.0], SHEET, [0.0, SHEET[1]]].map(|p| cam.to_px(p));
    let inside = |p: [f64; 2]| {
        let s: Vec<f64> = (0..4)
            .map(|i| {
                let (a, b) = (sheet[i], sheet[(i + 1) % 4]);
                (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
            })
            .collect();
        s.iter().all(|&x| x <= 0.0) || s.iter().all(|&x| x >= 0.0)
    };
    for y in 0..hu {
        for x in 0..wu {
            let c = [x as f64 + 0.5, y as f64 + 0.5];
            if inside(c) {
                let b = (222.0 + 18.0 * c[0] / w as f64) as f32;
                v[y * wu + x] = [b, b, b - 4.0];
            }
        }
    }
    // A segment's ink over the pixels it covers: `mix` of 1 paints the
    // colour, pencil darkens by its own amount.
    let stroke = |v: &mut Vec<[f32; 3]>,
                  a: [f64; 2],
                  b: [f64; 2],
                  width_mm: f64,
                  ink: Option<([f32; 3], f32)>| {
        let half = 0.5 * width_mm * cam.scale;
        let (lo, hi) = (
            [a[0].min(b[0]) - half - 2.0, a[1].min(b[1]) - half - 2.0],
            [a[0].max(b[0]) + half + 2.0, a[1].max(b[1]) + half + 2.0],
        );
        let d = [b[0] - a[0], b[1] - a[1]];
        let len2 = d[0] * d[0] + d[1] * d[1];
        // Each row only where the stroke's band crosses it (a long
        // slanting grid line's box is most of the photo).
        let len = len2.sqrt();
        let n = [-d[1] / len, d[0] / len];
        let r = half + 2.0;
        for y in (lo[1].max(0.0) as usize)..(hi[1].min(h as f64) as usize) {
            let cy = y as f64 + 0.5 - a[1];
            let (mut x0, mut x1) = (lo[0], hi[0]);
            if n[0].abs() > 1e-9 {
                let (p, q) = ((-r - n[1] * cy) / n[0], (r - n[1] * cy) / n[0]);
                x0 = x0.max(a[0] + p.min(q) - 1.0);
                x1 = x1.min(a[0] + p.max(q) + 1.0);
            }
            for x in (x0.max(0.0) as usize)..(x1.min(w as f64).max(0.0) as usize) {
                let c = [x as f64 + 0.5, y as f64 + 0.5];
                let s = (((c[0] - a[0]) * d[0] + (c[1] - a[1]) * d[1]) / len2).clamp(0.0, 1.0);
                let dist = (c[0] - a[0] - s * d[0]).hypot(c[1] - a[1] - s * d[1]);
                let cover = (half + 0.5 - dist).clamp(0.0, 1.0) as f32;
                let p = &mut v[y * wu + x];
                match ink {
                    Some((colour, mix)) => {
                        for (c, ink) in p.iter_mut().zip(colour) {
                            *c += (ink.min(*c) - *c) * mix * cover;
                        }
                    }
                    None => {
                        for c in p.iter_mut() {
                            *c -= PENCIL_DARK as f32 * cover;
                        }
                    }
                }
            }
        }
    };
    let f = cam.frame_px();
    match paper {
        Paper::Plain => {
            for i in 0..4 {
                stroke(&mut v, f[i], f[(i + 1) % 4], PENCIL_MM, None);
            }
        }
        Paper::Millimetre => {
            for (every, width, mix) in GRID_LINES {
                let at = |x: f64, y: f64| cam.to_px([FRAME_AT[0] + x, FRAME_AT[1] + y]);
                let (nx, ny) = if every > 0.0 {
                    ((FRAME[0] / every) as usize, (FRAME[1] / every) as usize)
                } else {
                    (1, 1)
                };
                let step = if every > 0.0 { every } else { FRAME[0] };
                for i in 0..=nx {
                    let x = i as f64 * step;
                    stroke(
                        &mut v,
                        at(x, 0.0),
                        at(x, FRAME[1]),
                        width,
                        Some((GRID_INK, mix)),
                    );
                }
                let step = if every > 0.0 { every } else { FRAME[1] };
                for j in 0..=ny {
                    let y = j as f64 * step;
                    stroke(
                        &mut v,
                        at(0.0, y),
                        at(FRAME[0], y),
                        width,
                        Some((GRID_INK, mix)),
                    );
                }
            }
        }
    }
    for (a, b) in &t.lines {
        stroke(
            &mut v,
            cam.to_px(t.plan.sheet(*a)),
            cam.to_px(t.plan.sheet(*b)),
            PENCIL_MM,
            None,
        );
    }
    // A 3 px box blur, along x then along y.
    let mut b = v.clone();
    for y in 0..hu {
        for x in 1..wu - 1 {
            let i = y * wu + x;
            b[i] = [0, 1, 2].map(|k| (v[i - 1][k] + v[i][k] + v[i + 1][k]) / 3.0);
        }
    }
    for y in 1..hu - 1 {
        for x in 0..wu {
            let i = y * wu + x;
            v[i] = [0, 1, 2].map(|k| (b[i - wu][k] + b[i][k] + b[i + wu][k]) / 3.0);
        }
    }
    image::RgbImage::from_fn(w, h, |x, y| {
        let p = v[y as usize * wu + x as usize];
        image::Rgb([0, 1, 2].map(|k| {
            let n: f32 = rng.random_range(-8.0..8.0);
            (p[k] + n).clamp(0.0, 255.0) as u8
        }))
    })
}

/// `img` written as JPEG (quality 85) to `path`; with `turned`, stored
/// turned a quarter left with EXIF orientation 6 (a viewer turns it a
/// quarter right: displayed as `img`), as a phone held sideways stores
/// it.
pub fn write_jpeg(img: &image::RgbImage, path: &Path, turned: bool) {
    use image::ImageEncoder;
    let mut out = Vec::new();
    let mut enc = image::codecs::jpeg::JpegEncoder::new_with_quality(&mut out, 85);
    let stored = if turned {
        // A TIFF header, one IFD entry: Orientation (0x0112), SHORT, 6.
        let exif = vec![
            0x49, 0x49, 0x2a, 0, 8, 0, 0, 0, 1, 0, 0x12, 0x01, 3, 0, 1, 0, 0, 0, 6, 0, 0, 0, 0, 0,
            0, 0,
        ];
        enc.set_exif_metadata(exif).unwrap();
        image::imageops::rotate270(img)
    } else {
        img.clone()
    };
    enc.write_image(
        stored.as_raw(),
        stored.width(),
        stored.height(),
        image::ExtendedColorType::Rgb8,
    )
    .unwrap();
    std::fs::write(path, out).unwrap();
}

/// Rough clicks (each 0.8–1.5 mm off on the sheet) snapped to the
/// photo's pencil crossings: the twin's verdict in at least 90 % of the
/// marks files (the aim is 95 %, not yet met: docs/check.md), a mistaken plan its twin finds wrong never right (a
/// point 6 mm off that its twin finds right is no mistake the photo must
/// find); every fifth photo stored
/// turned with its EXIF orientation.
#[test]
fn rough_clicks_snapped_get_the_twins_verdict() {
    use rayon::prelude::*;
    let (cases, trials) = trials();
    let dir = common::fresh("photo", "snap");
    type Done = (bool, bool, String, Vec<Option<f64>>, Vec<f64>, &'static str);
    let results: Vec<Option<Done>> = trials
        .par_iter()
        .enumerate()
        .map(|(i, t)| {
            let case = &cases[t.case];
            let twin_report = grade(case, &t.twin.to_string()).ok()?;
            // SNAPSEED=K draws another set of photos and clicks.
            let seed = std::env::var("SNAPSEED").unwrap_or_default();
            let mut rng = rng_for(&format!("snap{seed} {}", t.title));
            let (paper, cam, how) = setting(i, &mut rng);
            let img = photograph(t, &cam, paper, &mut rng);
            let file = dir.join(format!("plan{i}.jpg"));
            write_jpeg(&img, &file, i % 5 == 0);
            let mut m = marks(&t.twin, &t.plan, &cam, (0.8, 1.5), &path(&file), &mut rng);
            // Corners clicked carefully: they are not snapped.
            let careful = marks(&t.twin, &t.plan, &cam, (0.0, 0.15), &path(&file), &mut rng);
            m["photo"] = careful["photo"].clone();
            m["snap"] = json!(true);
            let read = |f: &str| std::fs::read(f).map_err(|e| e.to_string());
            let (ans, reading) = mechplan::check::photo::from_marks(&m.to_string(), Some(&read))
                .unwrap_or_else(|e| panic!("{}: {e}", t.title));
            let r = check(&case.an, &case.solved, &ans).unwrap();
            let (a, b) = (verdict(&twin_report), verdict(&r));
            let fine = a == b
                || (a.0 == Grade::CannotJudge && b.0 != Grade::Wrong)
                || (a.0 == Grade::Wrong && margin(&twin_report).is_some_and(|d| d < 0.5));
            let accepted_wrong = !t.right && a.0 == Grade::Wrong && b.0 == Grade::Right;
            let moves = reading
                .snapped
                .unwrap()
                .moves
                .into_iter()
                .map(|m| m.1)
                .collect();
            // Where each point was read, against where it is drawn.
            let left: Vec<f64> = ans
                .items
                .iter()
                .filter_map(|it| match &it.given {
                    mechplan::check::answer::Given::Point { name, at } => {
                        let p = t.plan.points.iter().find(|p| p.0 == *name)?.1;
                        Some((at[0] - p.x).hypot(at[1] - p.y))
                    }
                    _ => None,
                })
                .collect();
            Some((
                fine,
                accepted_wrong,
                format!("{} ({how}): twin {a:?}, photo {b:?}", t.title),
                moves,
                left,
                how,
            ))
        })
        .collect();
    let done: Vec<_> = results.into_iter().flatten().collect();
    let n = done.len();
    let same = done.iter().filter(|d| d.0).count();
    let accepted: Vec<&String> = done.iter().filter(|d| d.1).map(|d| &d.2).collect();
    let moves: Vec<f64> = done
        .iter()
        .flat_map(|d| d.3.iter().flatten().copied())
        .collect();
    let kept = done
        .iter()
        .flat_map(|d| d.3.iter())
        .filter(|m| m.is_none())
        .count();
    let quantiles = |mut v: Vec<f64>| {
        v.sort_by(f64::total_cmp);
        let q = |f: f64| {
            v.get(((v.len() as f64 - 1.0) * f) as usize)
                .copied()
                .unwrap_or(0.0)
        };
        format!(
            "median {:.2} mm, 95th percentile {:.2}, most {:.2}",
            q(0.5),
            q(0.95),
            q(1.0)
        )
    };
    let left: Vec<f64> = done.iter().flat_map(|d| d.4.iter().copied()).collect();
    eprintln!(
        "rough clicks snapped: {n} photos, {same} with the twin's verdict ({:.1} %); {} points moved ({}), {kept} kept where clicked; each point (from the pole) then off where drawn by {}",
        100.0 * same as f64 / n as f64,
        moves.len(),
        quantiles(moves.clone()),
        quantiles(left),
    );
    for how in [
        "plain paper, photo",
        "millimetre paper, photo",
        "plain paper, scan",
        "millimetre paper, scan",
    ] {
        let of: Vec<_> = done.iter().filter(|d| d.5 == how).collect();
        let same = of.iter().filter(|d| d.0).count();
        eprintln!("  {how}: {same} of {}", of.len());
    }
    for d in done.iter().filter(|d| !d.0) {
        eprintln!("  {}", d.2);
    }
    assert!(n >= 200, "only {n} photos");
    assert!(accepted.is_empty(), "mistaken plans accepted: {accepted:?}");
    assert!(same * 100 >= 95 * n, "{same} of {n}");
}

/// The circles of `colour` in an overlay SVG: their centres (px).
fn circles(svg: &str, colour: &str) -> Vec<[f64; 2]> {
    svg.split("<circle")
        .skip(1)
        .map(|c| c.split('>').next().unwrap())
        .filter(|c| c.contains(&format!("stroke=\"{colour}\"")))
        .map(|c| {
            let attr = |name: &str| -> f64 {
                let from = c.find(&format!(" {name}=\"")).unwrap() + name.len() + 3;
                c[from..].split('"').next().unwrap().parse().unwrap()
            };
            [attr("cx"), attr("cy")]
        })
        .collect()
}

/// `check --photo-overlay` draws over the photo in its own perspective:
/// the student's points where the camera put them, and the wrong step's
/// right place where the camera shows the right plan's point (the test's
/// own camera model, not the engine's homography), the photo linked by
/// its name beside the overlay.
#[test]
fn the_photo_overlay_is_drawn_in_the_photos_perspective() {
    let (cases, trials) = trials();
    let find = |tag: &str| {
        trials
            .iter()
            .find(|t| t.title == format!("four_bar position 2 Velocity: {tag}"))
            .unwrap()
    };
    let (wrong, right) = (find("last point off"), find("right"));
    let dir = common::fresh("photo", "overlay");
    let mut rng = rng_for("overlay");
    let cam = Camera::random(&mut rng);
    let img = photograph(wrong, &cam, Paper::Plain, &mut rng);
    write_jpeg(&img, &dir.join("plan.jpg"), false);
    let m = marks(
        &wrong.twin,
        &wrong.plan,
        &cam,
        (0.0, 0.0),
        "plan.jpg",
        &mut rng,
    );
    let marks_file = write(&dir, "marks.json", &m);
    let scene = write(&dir, "scene.json", &cases[wrong.case].json);
    let out = dir.join("overlay.svg");
    let (code, report, err) =
        common::run(&["check", &scene, &marks_file, "--photo-overlay", &path(&out)]);
    assert_eq!(code, 1, "{report}{err}");
    let svg = std::fs::read_to_string(&out).unwrap();
    assert!(
        svg.contains("href=\"plan.jpg\""),
        "the photo beside it, by its name"
    );
    assert!(
        svg.contains(&format!("width=\"{}\"", img.width())),
        "the photo's size"
    );
    // Every point the student clicked, where the camera shows it.
    let blue = circles(&svg, "#1f5fbf");
    for (name, p) in &wrong.plan.points {
        let px = cam.to_px(wrong.plan.sheet(*p));
        let near = blue
            .iter()
            .map(|c| (c[0] - px[0]).hypot(c[1] - px[1]))
            .fold(f64::INFINITY, f64::min);
        assert!(
            near < 0.5,
            "{name}: {near} px from where the camera shows it"
        );
    }
    // The wrong step's right place: the right plan's point as the camera
    // shows it (from the same pole).
    let red = circles(&svg, "#c62828");
    assert_eq!(red.len(), 1, "one wrong step: {report}");
    let (name, p) = right.plan.points.last().unwrap();
    let px = cam.to_px(wrong.plan.sheet(*p));
    let d = (red[0][0] - px[0]).hypot(red[0][1] - px[1]);
    assert!(d < 1.0, "{name}'s right place is {d} px off in the overlay");
    // Not a marks file: refused, naming the option.
    let twin = write(&dir, "twin.json", &wrong.twin);
    let (code, _, err) = common::run(&["check", &scene, &twin, "--photo-overlay", &path(&out)]);
    assert_eq!(code, 2);
    assert!(err.contains("photo-overlay"), "{err}");
}
