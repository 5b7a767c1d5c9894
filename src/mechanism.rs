//! From the scene to rigid bodies: every link gets a local frame and the
//! local coordinates of its points (the rigid-shape rule of the contract),
//! every shared point becomes a revolute pair and every slider entry a
//! prismatic pair with its guide line fixed in the guide link's frame.

use crate::error::{Error, Issue, Result};
use crate::geom::{Line, Pose, circle_circle, perp, rotate, sign_tol};
use crate::scene::{Direction, Scene, Through};
use kurbo::{Point, Vec2};

/// Relative tolerance for "equal" lengths in the scene (the contract's 1e-9).
pub const LENGTH_REL_TOL: f64 = 1e-9;
/// How far off its guide a slider's point may be drawn in the sketch,
/// relative to the size of the sketch: the sketch is a drawing.
pub const SKETCH_REL_TOL: f64 = 1e-3;

/// A rigid link: its points in its own frame.
#[derive(Clone, Debug)]
pub struct Link {
    pub id: String,
    pub points: Vec<usize>,
    /// Local coordinates, parallel to `points`.
    pub local: Vec<Vec2>,
    /// The pose that places the local frame on the sketch.
    pub sketch_pose: Pose,
}

impl Link {
    pub fn local_of(&self, point: usize) -> Option<Vec2> {
        self.points
            .iter()
            .position(|&p| p == point)
            .map(|i| self.local[i])
    }
}

/// A revolute pair at `point` joining links `a` and `b`.
#[derive(Clone, Debug)]
pub struct Revolute {
    pub point: usize,
    pub a: usize,
    pub b: usize,
}

/// A prismatic pair: link `slider` slides on a line fixed to link `guide`.
#[derive(Clone, Debug)]
pub struct Prismatic {
    pub slider: usize,
    pub guide: usize,
    pub point: usize,
    /// The slider's point in the slider's frame.
    pub slider_local: Vec2,
    /// A point of the guide line in the guide's frame.
    pub line_point: Vec2,
    /// Unit direction of the guide line in the guide's frame.
    pub line_dir: Vec2,
    /// θ_slider − θ_guide: the pair lets no relative rotation.
    pub delta: f64,
}

impl Prismatic {
    /// The guide line in the world for a guide pose.
    pub fn line(&self, guide: &Pose) -> Line {
        Line {
            point: guide.apply(self.line_point),
            dir: guide.dir(self.line_dir),
        }
    }
}

#[derive(Clone, Debug)]
pub struct Mechanism {
    pub scene: Scene,
    pub links: Vec<Link>,
    pub revolutes: Vec<Revolute>,
    pub prismatics: Vec<Prismatic>,
    /// Size of the sketch (diagonal of its bounding box), for tolerances.
    pub size: f64,
}

impl Mechanism {
    pub fn new(scene: Scene) -> Result<Mechanism> {
        let mut issues = Vec::new();
        let (lo, hi) = scene.points.iter().fold(
            (
                Point::new(f64::MAX, f64::MAX),
                Point::new(f64::MIN, f64::MIN),
            ),
            |(lo, hi), p| {
                (
                    Point::new(lo.x.min(p.sketch.x), lo.y.min(p.sketch.y)),
                    Point::new(hi.x.max(p.sketch.x), hi.y.max(p.sketch.y)),
                )
            },
        );
        let size = (hi - lo).hypot().max(f64::MIN_POSITIVE);
        let mut links = Vec::with_capacity(scene.links.len());
        // Links whose shape could not be built: checking them further would
        // only report the same problem again in other words.
        let mut broken = Vec::with_capacity(scene.links.len());
        for l in 0..scene.links.len() {
            let before = issues.len();
            links.push(rigid_link(&scene, l, size, &mut issues));
            broken.push(issues.len() > before);
        }
        check_lengths(&scene, &links, &broken, &mut issues);
        let revolutes = revolutes(&scene);
        let mut prismatics = Vec::new();
        for (k, s) in scene.sliders.iter().enumerate() {
            if broken[s.slider] || broken[s.guide] {
                continue;
            }
            if let Some(p) = prismatic(&scene, &links, k, size, &mut issues) {
                prismatics.push(p);
            } else if issues.is_empty() {
                // prismatic() always reports why it failed.
                unreachable!("slider {k} ({}) failed without an issue", s.point);
            }
        }
        if !issues.is_empty() {
            return Err(Error::Scene(issues));
        }
        Ok(Mechanism {
            scene,
            links,
            revolutes,
            prismatics,
            size,
        })
    }

    pub fn point_name(&self, p: usize) -> &str {
        &self.scene.points[p].name
    }
    pub fn link_id(&self, l: usize) -> &str {
        &self.links[l].id
    }
    pub fn frame(&self) -> usize {
        self.scene.frame
    }
    /// Local coordinates of `point` on `link` (the point must be on it).
    pub fn local(&self, link: usize, point: usize) -> Vec2 {
        self.links[link]
            .local_of(point)
            .expect("point belongs to link (checked by structure)")
    }
    /// Links carrying `point`, in scene order.
    pub fn links_of_point(&self, point: usize) -> Vec<usize> {
        self.scene.links_of_point(point)
    }
}

/// Every point in k links makes k−1 revolute pairs, each joining the first
/// of those links (in scene order) to one of the others.
fn revolutes(scene: &Scene) -> Vec<Revolute> {
    let mut out = Vec::new();
    for p in 0..scene.points.len() {
        let ls = scene.links_of_point(p);
        for &b in ls.iter().skip(1) {
            out.push(Revolute {
                point: p,
                a: ls[0],
                b,
            });
        }
    }
    out
}

fn length_between(scene: &Scene, a: usize, b: usize) -> Option<f64> {
    scene
        .lengths
        .iter()
        .find(|l| (l.a == a && l.b == b) || (l.a == b && l.b == a))
        .map(|l| l.value)
}

fn sketch(scene: &Scene, p: usize) -> Point {
    scene.points[p].sketch
}

fn link_ptr(scene: &Scene, l: usize) -> String {
    format!("/links/{}", crate::json::escape(&scene.links[l].id))
}

/// Build one link's local shape by the contract's rule.
fn rigid_link(scene: &Scene, l: usize, size: f64, issues: &mut Vec<Issue>) -> Link {
    let spec = &scene.links[l];
    let pts = &spec.points;
    let id = spec.id.clone();
    if l == scene.frame {
        // The frame is exact: its local frame is the world.
        return Link {
            id,
            points: pts.clone(),
            local: pts.iter().map(|&p| sketch(scene, p).to_vec2()).collect(),
            sketch_pose: Pose::IDENTITY,
        };
    }
    let mut local = vec![Vec2::ZERO; pts.len()];
    let mut pose = Pose::new(sketch(scene, pts[0]), 0.0);
    if pts.len() == 1 {
        // A one-point link is a slider: its angle is its guide's direction.
        match scene.sliders.iter().position(|s| s.slider == l) {
            Some(k) => pose = Pose::new(pose.origin, sketch_guide_dir(scene, k).atan2()),
            None => issues.push(Issue {
                pointer: format!("{}/points", link_ptr(scene, l)),
                message: format!(
                    "link \"{}\" has a single point, so it must be the slider of a prismatic pair (an entry in /sliders)",
                    spec.id
                ),
            }),
        }
        return Link {
            id,
            points: pts.clone(),
            local,
            sketch_pose: pose,
        };
    }
    let (p0, p1) = (pts[0], pts[1]);
    let d01 = length_between(scene, p0, p1)
        .unwrap_or_else(|| sketch(scene, p0).distance(sketch(scene, p1)));
    if d01 <= LENGTH_REL_TOL * size {
        issues.push(Issue {
            pointer: format!("{}/points", link_ptr(scene, l)),
            message: format!(
                "zero-length link: its first two points \"{}\" and \"{}\" coincide",
                scene.points[p0].name, scene.points[p1].name
            ),
        });
        return Link {
            id,
            points: pts.clone(),
            local,
            sketch_pose: pose,
        };
    }
    pose = Pose::new(pose.origin, (sketch(scene, p1) - sketch(scene, p0)).atan2());
    local[1] = Vec2::new(d01, 0.0);
    for k in 2..pts.len() {
        let p = pts[k];
        // References: earlier points paired with p in `lengths` first, then the earliest others.
        let mut refs: Vec<usize> = (0..k)
            .filter(|&j| length_between(scene, p, pts[j]).is_some())
            .collect();
        refs.extend((0..k).filter(|&j| length_between(scene, p, pts[j]).is_none()));
        let (j1, j2) = (refs[0], refs[1]);
        let (q1, q2) = (pts[j1], pts[j2]);
        let dist = |a: usize, b: usize| {
            length_between(scene, a, b)
                .unwrap_or_else(|| sketch(scene, a).distance(sketch(scene, b)))
        };
        let (r1, r2) = (dist(p, q1), dist(p, q2));
        let (a, b) = (local[j1], local[j2]);
        let d = (b - a).hypot();
        let on_line = (r1 + r2 - d).abs() <= LENGTH_REL_TOL * d
            || ((r1 - r2).abs() - d).abs() <= LENGTH_REL_TOL * d;
        let s_cross =
            (sketch(scene, q2) - sketch(scene, q1)).cross(sketch(scene, p) - sketch(scene, q1));
        let side = sign_tol(s_cross, 1e-12 * size * size);
        if side == 0.0 && !on_line {
            issues.push(Issue {
                pointer: format!("{}/points/{k}", link_ptr(scene, l)),
                message: format!(
                    "point \"{}\" is drawn on the line through \"{}\" and \"{}\", but its distances make a triangle: draw it on the side it belongs",
                    scene.points[p].name, scene.points[q1].name, scene.points[q2].name
                ),
            });
            continue;
        }
        if on_line {
            // Exactly on the line QR: a tangency of the two circles would
            // put the point off the line by √ε of its distance.
            let x = (d * d + r1 * r1 - r2 * r2) / (2.0 * d);
            local[k] = a + (b - a) * (x / d);
            continue;
        }
        let tol = LENGTH_REL_TOL * d.max(r1).max(r2);
        match circle_circle(a.to_point(), r1, b.to_point(), r2, if side == 0.0 { 1.0 } else { side }, tol) {
            Some(x) => local[k] = x.to_vec2(),
            None => issues.push(Issue {
                pointer: format!("{}/points/{k}", link_ptr(scene, l)),
                message: format!(
                    "link \"{}\" cannot be rigid: point \"{}\" at {r1} from \"{}\" and {r2} from \"{}\", which are {d} apart (triangle inequality)",
                    spec.id, scene.points[p].name, scene.points[q1].name, scene.points[q2].name
                ),
            }),
        }
    }
    Link {
        id,
        points: pts.clone(),
        local,
        sketch_pose: pose,
    }
}

/// Every given length must hold in the rigid shape (frame: in its coordinates).
fn check_lengths(scene: &Scene, links: &[Link], broken: &[bool], issues: &mut Vec<Issue>) {
    for len in &scene.lengths {
        for (link, _) in links.iter().zip(broken).filter(|(_, b)| !**b) {
            let (Some(a), Some(b)) = (link.local_of(len.a), link.local_of(len.b)) else {
                continue;
            };
            if link.points.len() == 1 {
                continue;
            }
            let actual = (a - b).hypot();
            if (actual - len.value).abs() > LENGTH_REL_TOL * len.value.max(actual) {
                issues.push(Issue {
                    pointer: format!("/lengths/{}", crate::json::escape(&len.key)),
                    message: format!(
                        "{} does not fit link \"{}\": its rigid shape gives {actual}{}",
                        len.value,
                        link.id,
                        if link.sketch_pose == Pose::IDENTITY && links[scene.frame].id == link.id {
                            " (frame points are exact)"
                        } else {
                            " (over-determined: see the rigid-shape rule in docs/scene-format.md)"
                        }
                    ),
                });
            }
        }
    }
}

/// The direction of slider `k`'s guide line, in the sketch.
fn sketch_guide_dir(scene: &Scene, k: usize) -> Vec2 {
    match scene.sliders[k].line.direction {
        Direction::Angle(a) => Vec2::from_angle(a),
        Direction::Along(q, r) => (sketch(scene, r) - sketch(scene, q)).normalize(),
    }
}

fn prismatic(
    scene: &Scene,
    links: &[Link],
    k: usize,
    size: f64,
    issues: &mut Vec<Issue>,
) -> Option<Prismatic> {
    let s = &scene.sliders[k];
    let at = format!("/sliders/{k}");
    let g = &links[s.guide];
    let gpose = g.sketch_pose;
    let mut fail = |pointer: String, message: String| {
        issues.push(Issue { pointer, message });
        None::<Prismatic>
    };
    // The guide line in the guide's frame.
    let through_local = match s.line.through {
        Through::Point(p) => g.local_of(p)?,
        Through::Coords(c) => c.to_vec2(),
    };
    let dir_local = match s.line.direction {
        Direction::Angle(a) => rotate(Vec2::from_angle(a), -gpose.angle),
        Direction::Along(q, r) => {
            let v = g.local_of(r)? - g.local_of(q)?;
            if v.hypot() <= LENGTH_REL_TOL * size {
                return fail(
                    format!("{at}/line/along"),
                    "the two points coincide: no direction".into(),
                );
            }
            v.normalize()
        }
    };
    let line_point = through_local + perp(dir_local) * s.line.offset;
    // The sketch must show the slider's point on the guide.
    let sk_dir = sketch_guide_dir(scene, k);
    let sk_through = match s.line.through {
        Through::Point(p) => sketch(scene, p),
        Through::Coords(c) => c,
    } + perp(sk_dir) * s.line.offset;
    let off = Line::new(sk_through, sk_dir).signed_distance(sketch(scene, s.point));
    if off.abs() > SKETCH_REL_TOL * size {
        return fail(
            format!("{at}/point"),
            format!(
                "point \"{}\" is {:.6} m off its guide line in the sketch; a slider's point lies on its guide",
                scene.points[s.point].name,
                off.abs()
            ),
        );
    }
    let slider = &links[s.slider];
    let slider_local = slider.local_of(s.point)?;
    Some(Prismatic {
        slider: s.slider,
        guide: s.guide,
        point: s.point,
        slider_local,
        line_point,
        line_dir: dir_local,
        delta: slider.sketch_pose.angle - gpose.angle,
    })
}
