//! From the scene to rigid bodies: every link gets a local frame and the
//! local coordinates of its points (the rigid-shape rule of the contract),
//! every shared point becomes a revolute pair and every slider entry a
//! prismatic pair with its guide line fixed in the guide link's frame.

use crate::error::{Error, Issue, Result};
use crate::geom::{Line, Pose, perp, rotate};
use crate::model::scene::{Direction, Scene, Through};
use crate::model::shape::Placement;
use kurbo::{Point, Vec2};

/// Relative tolerance for a length between two frame points against their
/// coordinates ([`crate::accuracy::Accuracy::frame_length`]).
pub const LENGTH_REL_TOL: f64 = crate::accuracy::ACCURACY.frame_length;
/// How far off its guide a slider's point may be drawn in the sketch,
/// relative to the links that carry it
/// ([`crate::accuracy::Accuracy::sketch_off_guide`]).
pub const SKETCH_REL_TOL: f64 = crate::accuracy::ACCURACY.sketch_off_guide;

/// A rigid link: its points in its own frame.
#[derive(Clone, Debug)]
pub struct Link {
    pub id: String,
    pub points: Vec<usize>,
    /// Local coordinates, parallel to `points`.
    pub local: Vec<Vec2>,
    /// The pose that places the local frame on the sketch.
    pub sketch_pose: Pose,
    /// The link's own size: the largest distance of its points from its
    /// first. Tolerances about this link are relative to it, not to the
    /// size of the whole sketch.
    pub extent: f64,
}

impl Link {
    #[inline]
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
    /// Size of the sketch (diagonal of its bounding box): the scale of
    /// drawings and of the reported bounds of positions.
    pub size: f64,
    /// How each link's points were placed ([`crate::model::shape`]), parallel to
    /// `links`: the decisions a rebuild with changed data follows.
    pub placements: Vec<Vec<Placement>>,
}

impl Mechanism {
    pub fn new(scene: Scene) -> Result<Mechanism> {
        Mechanism::build(scene, None)
    }

    /// The same mechanism on other data (the data sensitivity check: the
    /// lengths and coordinates moved by a few units of rounding), its
    /// shapes built with this mechanism's decisions.
    pub fn with_data(&self, scene: Scene) -> Result<Mechanism> {
        Mechanism::build(scene, Some(&self.placements))
    }

    fn build(scene: Scene, decided: Option<&[Vec<Placement>]>) -> Result<Mechanism> {
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
        let mut placements = Vec::with_capacity(scene.links.len());
        // Links whose shape could not be built: checking them further would
        // only report the same problem again in other words.
        let mut broken = Vec::with_capacity(scene.links.len());
        for l in 0..scene.links.len() {
            let before = issues.len();
            let (link, placed) = rigid_link(&scene, l, decided.map(|d| &d[l][..]), &mut issues);
            links.push(link);
            placements.push(placed);
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
            return Err(Error::fields(issues));
        }
        Ok(Mechanism {
            scene,
            links,
            revolutes,
            prismatics,
            size,
            placements,
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
    #[inline]
    pub fn local(&self, link: usize, point: usize) -> Vec2 {
        self.links[link]
            .local_of(point)
            .expect("point belongs to link (checked by structure)")
    }

    /// The size that scales a link's angle into a length (its extent; a
    /// one-point link: the largest of its neighbours'): tolerances and
    /// scalings about a link are relative to it, not to the whole sketch.
    #[inline]
    pub fn link_scale(&self, l: usize) -> f64 {
        let own = self.links[l].extent;
        if own > 0.0 {
            return own;
        }
        self.neighbours_scale(l)
    }

    /// [`Mechanism::link_scale`] of a one-point link.
    #[cold]
    fn neighbours_scale(&self, l: usize) -> f64 {
        // A one-point link: the links that share its point, its guides and
        // what slides on it, and theirs.
        let mut near: Vec<usize> = vec![l];
        for _ in 0..2 {
            let mut next = near.clone();
            for &k in &near {
                next.extend(self.links_of_point(self.links[k].points[0]));
                for p in &self.prismatics {
                    if p.slider == k {
                        next.push(p.guide);
                    }
                    if p.guide == k {
                        next.push(p.slider);
                    }
                }
            }
            near = next;
        }
        let reach = near
            .into_iter()
            .filter(|&k| k != self.frame())
            .map(|k| self.links[k].extent)
            .fold(0.0, f64::max);
        if reach > 0.0 { reach } else { self.size }
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

fn sketch(scene: &Scene, p: usize) -> Point {
    scene.points[p].sketch
}

fn link_ptr(scene: &Scene, l: usize) -> String {
    format!("/links/{}", crate::json::escape(&scene.links[l].id))
}

/// Build one link's local shape by the contract's rule ([`crate::model::shape`]),
/// deciding its placements from the data or following `decided`.
fn rigid_link(
    scene: &Scene,
    l: usize,
    decided: Option<&[Placement]>,
    issues: &mut Vec<Issue>,
) -> (Link, Vec<Placement>) {
    let spec = &scene.links[l];
    let pts = &spec.points;
    let id = spec.id.clone();
    let link = |local: Vec<Vec2>, sketch_pose: Pose| Link {
        id: id.clone(),
        points: pts.clone(),
        extent: local
            .iter()
            .map(|v| (*v - local[0]).hypot())
            .fold(0.0, f64::max),
        local,
        sketch_pose,
    };
    if l == scene.frame {
        // The frame is exact: its local frame is the world.
        let local = pts.iter().map(|&p| sketch(scene, p).to_vec2()).collect();
        return (link(local, Pose::IDENTITY), Vec::new());
    }
    let origin = sketch(scene, pts[0]);
    if pts.len() == 1 {
        // A one-point link is a slider: its angle is its guide's direction.
        let pose = match scene.sliders.iter().position(|s| s.slider == l) {
            Some(k) => Pose::new(origin, sketch_guide_dir(scene, k).atan2()),
            None => {
                issues.push(Issue {
                    pointer: format!("{}/points", link_ptr(scene, l)),
                    message: format!(
                        "link \"{}\" has a single point, so it must be the slider of a prismatic pair (an entry in /sliders)",
                        spec.id
                    ),
                });
                Pose::new(origin, 0.0)
            }
        };
        return (link(vec![Vec2::ZERO], pose), Vec::new());
    }
    match crate::model::shape::shape(scene, l, decided) {
        Ok((placements, shape)) => (
            link(shape.local, Pose::new(origin, shape.sketch_angle)),
            placements,
        ),
        Err(found) => {
            for f in found {
                issues.push(Issue {
                    pointer: match f.point {
                        Some(k) => format!("{}/points/{k}", link_ptr(scene, l)),
                        None => format!("{}/points", link_ptr(scene, l)),
                    },
                    message: f.message,
                });
            }
            (
                link(vec![Vec2::ZERO; pts.len()], Pose::new(origin, 0.0)),
                Vec::new(),
            )
        }
    }
}

/// Every given length must hold in the rigid shape: between frame points
/// to the contract's 1e-9 (frame points are exact), on a moving link to
/// the rounding of the data (an over-determined shape that does not close
/// is an error, never a silent change).
fn check_lengths(scene: &Scene, links: &[Link], broken: &[bool], issues: &mut Vec<Issue>) {
    for len in &scene.lengths {
        for (l, link) in links.iter().enumerate().filter(|(l, _)| !broken[*l]) {
            let (Some(a), Some(b)) = (link.local_of(len.a), link.local_of(len.b)) else {
                continue;
            };
            if link.points.len() == 1 {
                continue;
            }
            let actual = (a - b).hypot();
            let frame = l == scene.frame;
            let slack = if frame {
                LENGTH_REL_TOL * len.value.max(actual)
            } else {
                crate::model::shape::length_slack(scene, &link.points, len.value, a, b)
            };
            if (actual - len.value).abs() > slack {
                issues.push(Issue {
                    pointer: format!("/lengths/{}", crate::json::escape(&len.key)),
                    message: format!(
                        "{} does not fit link \"{}\": its rigid shape gives {actual}{}",
                        len.value,
                        link.id,
                        if frame {
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
            let (sq, sr) = (sketch(scene, q).to_vec2(), sketch(scene, r).to_vec2());
            if v.hypot() <= 4.0 * f64::EPSILON * (sq.hypot() + sr.hypot()) {
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
    // The drawing's tolerance, relative to the links that carry the point
    // (a small linkage in a large sketch is judged by its own size).
    let own = scene
        .links_of_point(s.point)
        .into_iter()
        .filter(|&l| l != scene.frame)
        .map(|l| links[l].extent)
        .fold(0.0, f64::max);
    let reach = match own.max(links[s.guide].extent) {
        r if r > 0.0 => r,
        _ => size,
    };
    // A point drawn exactly on its guide is off it by the rounding of the
    // coordinates that draw the two.
    let rounding = 16.0
        * f64::EPSILON
        * (sk_through.to_vec2().hypot() + sketch(scene, s.point).to_vec2().hypot());
    if off.abs() > SKETCH_REL_TOL * reach + rounding {
        return fail(
            format!("{at}/point"),
            format!(
                "point \"{}\" is {} off its guide line in the sketch; a slider's point lies on its guide",
                scene.points[s.point].name,
                crate::format::format_quantity(off.abs(), "m")
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
