//! The plan of the mechanism at μ_l, with the symbols of kinematic schemes
//! (ГОСТ 2.770): fixed pivots with hatched bases, revolute pairs as small
//! circles, slider blocks on guides, links as lines or shaded ternary
//! links, link numbers, point labels, the input's ω1 (and ε1) arrows and
//! centres of mass.

use super::canvas::{Canvas, Class, FONT, Label, MAIN, SMALL, THIN};
use super::rate_arc::{obstacles, rate_arc};
use super::wall::{BLOCK, Block, Wall, crossing_at, draw_wall};
use crate::geom::perp;
use crate::kinematics::positions::Configuration;
use crate::kinematics::solve::Analysis;
use crate::model::mechanism::Mechanism;
use crate::model::scene::InputSpec;
use crate::pipeline::Solved;
use kurbo::{Point, Vec2};
use std::f64::consts::{FRAC_PI_2, FRAC_PI_4};

/// Hatching under a fixed base: a base line of width `w` perpendicular to
/// `down` at `at`, with short strokes at 45° on the far side.
pub fn hatch(c: &mut Canvas, at: Point, down: Vec2, w: f64) {
    let down = down.normalize();
    let along = perp(down);
    let (a, b) = (at - along * (w / 2.0), at + along * (w / 2.0));
    c.seg(a, b, Class::Main);
    let n = (w / 1.5).floor() as usize;
    for k in 0..=n {
        let p = a + (b - a) * (k as f64 / n.max(1) as f64);
        c.seg(p, p + (down - along) * 1.6, Class::Hatch);
    }
}

/// A fixed pivot: the pair's circle on a small triangle standing on a
/// hatched base; one symbol (a block in the DXF), turned from standing
/// upright.
fn pivot(c: &mut Canvas, at: Point, down: Vec2) {
    let down = down.normalize();
    let side = perp(down);
    let base = at + down * 4.0;
    c.symbol("pivot", at, down.atan2() + FRAC_PI_2, |c| {
        c.seg(at + down * 1.0 - side * 0.9, base - side * 2.5, Class::Main);
        c.seg(at + down * 1.0 + side * 0.9, base + side * 2.5, Class::Main);
        hatch(c, base, down, 8.0);
        c.circle(at, 1.2, "white", MAIN);
    });
}

/// A centre of mass: a circle with two opposite quarters filled; one
/// symbol (a block in the DXF).
pub(crate) fn centre_of_mass(c: &mut Canvas, at: Point) {
    let r = 1.4;
    c.symbol("mass", at, 0.0, |c| {
        c.circle(at, r, "white", THIN);
        for q in [0.0, std::f64::consts::PI] {
            let mut pts = vec![at];
            for k in 0..=6 {
                pts.push(at + Vec2::from_angle(q + FRAC_PI_2 * k as f64 / 6.0) * r);
            }
            c.poly(pts, "black", 0.0);
        }
    });
}

/// Draw the mechanism at position `s` with scale `mu_l` (m/mm).
pub fn draw(an: &Analysis, s: &Solved, c: &mut Canvas, mu_l: f64, with_labels: bool) {
    draw_over(an, s, &[], c, mu_l, with_labels);
}

/// [`draw`], with the fixed guides' walls long enough for the sliders in
/// every position of `stroke` too (the positions sheet).
pub fn draw_over(
    an: &Analysis,
    s: &Solved,
    stroke: &[&Configuration],
    c: &mut Canvas,
    mu_l: f64,
    with_labels: bool,
) {
    let sc = Scheme::new(an, s, mu_l);
    // The slots of guides on moving links (a kulisa), under the links; a
    // hydraulic cylinder (a driving slider on a moving guide) is drawn by
    // its own symbol instead.
    let cylinders = super::cylinder::pairs(an);
    let mut bodies = sc.slots(c, &cylinders);
    // The links' lines, known before the fixed guides are hatched, so that
    // a guide's hatching goes to the side fewer of them cross.
    sc.link_lines(&mut bodies);
    let blocks = sc.blocks(&cylinders);
    let centre = sc.centre();
    for wall in sc.walls(stroke) {
        draw_wall(c, wall, &bodies, &blocks, centre);
    }
    sc.links(c);
    for (_, q, corners) in &blocks {
        slider_block(c, *q, corners, None);
    }
    super::cylinder::draw(an, s, c, mu_l);
    let supports = sc.pairs(c, &bodies, with_labels);
    sc.inputs(c, &bodies, &supports);
    sc.rates(c, &bodies, &supports);
}

/// The corners of a slider block of half length `a` and half width `b`
/// about `q`, its length along the unit `u`.
pub(crate) fn block_corners(q: Point, u: Vec2, a: f64, b: f64) -> [Point; 4] {
    let n = perp(u);
    [
        q - u * a - n * b,
        q + u * a - n * b,
        q + u * a + n * b,
        q - u * a + n * b,
    ]
}

/// A slider block about `q` with its `corners` (from [`block_corners`]),
/// as one symbol (a block in the DXF) turned as its guide; `id` for the
/// checks to find it by.
pub(crate) fn slider_block(c: &mut Canvas, q: Point, corners: &[Point; 4], id: Option<String>) {
    let angle = (corners[1] - corners[0]).atan2();
    c.symbol("slider", q, angle, |c| match id {
        Some(id) => c.poly_id(corners.to_vec(), "white", MAIN, id),
        None => c.poly(corners.to_vec(), "white", MAIN),
    });
}

/// The points of link `l` that make its body: all but its centres of
/// mass (a point of this link alone named S…), in the link's order.
pub(crate) fn body_points(m: &Mechanism, l: usize) -> Vec<usize> {
    m.links[l]
        .points
        .iter()
        .copied()
        .filter(|&p| m.links_of_point(p).len() >= 2 || !m.point_name(p).starts_with('S'))
        .collect()
}

/// A link's body through its points `xy` (centres of mass left out): a
/// shaded polygon for three points or more, a line for two.
pub(crate) fn link_body(c: &mut Canvas, xy: &[Point]) {
    if xy.len() >= 3 {
        c.poly(xy.to_vec(), "#d9d9d9", MAIN);
    } else if xy.len() == 2 {
        c.seg(xy[0], xy[1], Class::Main);
    }
}

/// Whether `q` lies on the line of a two-point link's body `xy`.
pub(crate) fn on_body(xy: &[Point], q: Point) -> bool {
    (xy[1] - xy[0]).cross(q - xy[0]).abs() <= 1e-6 * (xy[1] - xy[0]).hypot2()
}

/// A point of a moving link: a revolute pair's circle, a centre of mass
/// (each one symbol, a block in the DXF), or a dot.
pub(crate) fn point_symbol(c: &mut Canvas, at: Point, joint: bool, mass: bool) {
    if joint {
        c.symbol("joint", at, 0.0, |c| c.circle(at, 1.2, "white", MAIN));
    } else if mass {
        centre_of_mass(c, at);
    } else {
        c.circle(at, 0.6, "black", 0.0);
    }
}

/// A point's name at `at`, its letters and their index apart ("O1" as O
/// with 1 under it, "S_2" as S with 2).
pub(crate) fn point_label(c: &mut Canvas, at: Point, name: &str, id: String) {
    let split = name
        .find(|ch: char| ch.is_ascii_digit() || ch == '_')
        .unwrap_or(name.len());
    c.label_later(
        at,
        Label::new(&name[..split], name[split..].trim_start_matches('_')),
        FONT,
        Some(id),
    );
}

/// The mechanism at one position as its scheme draws it: the places of
/// its points on the sheet (mm) and which points are pairs.
struct Scheme<'a> {
    an: &'a Analysis,
    s: &'a Solved,
    m: &'a Mechanism,
    frame: usize,
    mu_l: f64,
    /// Per point: a pair of two links or more.
    joints: Vec<bool>,
}

/// Where a link's ω arc may go: its centre, the directions taken there
/// (with their half widths, rad), the direction wished.
type Try = (Point, Vec<(f64, f64)>, f64);

impl<'a> Scheme<'a> {
    fn new(an: &'a Analysis, s: &'a Solved, mu_l: f64) -> Scheme<'a> {
        let m = &an.mech;
        let joints: Vec<bool> = (0..m.scene.points.len())
            .map(|p| m.links_of_point(p).len() >= 2)
            .collect();
        Scheme {
            an,
            s,
            m,
            frame: m.frame(),
            mu_l,
            joints,
        }
    }

    /// A real place (m) on the sheet (mm).
    fn to(&self, p: Point) -> Point {
        Point::new(p.x / self.mu_l, p.y / self.mu_l)
    }

    /// Point `p` of link `l` on the sheet.
    fn place(&self, l: usize, p: usize) -> Point {
        self.to(self.s.config.point(self.m, l, p))
    }

    /// Point `p` on the sheet, as the first drawn link holding it has it.
    fn at_point(&self, p: usize) -> Point {
        let l = self
            .m
            .links_of_point(p)
            .into_iter()
            .find(|&l| self.an.link(l))
            .unwrap_or(self.frame);
        self.place(l, p)
    }

    /// A centre of mass: a point of one link named S….
    fn is_mass(&self, p: usize) -> bool {
        !self.joints[p] && self.m.point_name(p).starts_with('S')
    }

    /// The moving links drawn, with their indices.
    fn moving(&self) -> impl Iterator<Item = (usize, &'a crate::model::mechanism::Link)> + '_ {
        (self.m.links.iter().enumerate()).filter(|&(l, _)| l != self.frame && self.an.link(l))
    }

    /// The places of link `l`'s points but its centres of mass: the
    /// corners of its body.
    fn body(&self, l: usize) -> Vec<Point> {
        self.m.links[l]
            .points
            .iter()
            .filter(|&&p| !self.is_mass(p))
            .map(|&p| self.place(l, p))
            .collect()
    }

    /// The middle of the points drawn.
    fn centre(&self) -> Point {
        let m = self.m;
        let shown: Vec<Point> = (0..m.scene.points.len())
            .filter(|&p| m.links_of_point(p).iter().any(|&l| self.an.link(l)))
            .map(|p| self.at_point(p))
            .collect();
        Point::new(
            shown.iter().map(|p| p.x).sum::<f64>() / shown.len().max(1) as f64,
            shown.iter().map(|p| p.y).sum::<f64>() / shown.len().max(1) as f64,
        )
    }

    /// Draw the slots of the guides on moving links (but the cylinders');
    /// returns them as the first lines drawn.
    fn slots(&self, c: &mut Canvas, cylinders: &[usize]) -> Vec<(Point, Point)> {
        let (m, an) = (self.m, self.an);
        let mut bodies: Vec<(Point, Point)> = Vec::new();
        for (k, pr) in m.prismatics.iter().enumerate() {
            if !an.link(pr.slider)
                || !an.link(pr.guide)
                || pr.guide == self.frame
                || cylinders.contains(&k)
            {
                continue;
            }
            let q = self.place(pr.slider, pr.point);
            let u = self.s.config.pose(pr.guide).dir(pr.line_dir);
            // A one-point link carrying a slot (a sliding yoke) is drawn as
            // the slot itself, reaching its own point, so that the slot and
            // the yoke read as one link.
            let (mut lo, mut hi) = (-10.0f64, 10.0f64);
            if m.links[pr.guide].points.len() == 1 {
                let t = (self.place(pr.guide, m.links[pr.guide].points[0]) - q).dot(u);
                lo = lo.min(t - 3.0);
                hi = hi.max(t + 3.0);
            }
            c.seg(q + u * lo, q + u * hi, Class::Main);
            bodies.push((q + u * lo, q + u * hi));
        }
        bodies
    }

    /// The lines between every two points of each moving link, into
    /// `bodies`.
    fn link_lines(&self, bodies: &mut Vec<(Point, Point)>) {
        for (l, _) in self.moving() {
            let xy = self.body(l);
            for i in 0..xy.len() {
                for j in i + 1..xy.len() {
                    bodies.push((xy[i], xy[j]));
                }
            }
        }
    }

    /// Slider blocks: those on the frame's guides first; a block at the
    /// point of one already placed (the two blocks of a PRP group, pinned
    /// together) nests inside it, smaller, instead of crossing it. Known
    /// before the walls are hatched, drawn over the links.
    fn blocks(&self, cylinders: &[usize]) -> Vec<Block> {
        let (m, an, frame) = (self.m, self.an, self.frame);
        let mut order: Vec<&crate::model::mechanism::Prismatic> = m
            .prismatics
            .iter()
            .enumerate()
            .filter(|(k, pr)| an.link(pr.slider) && an.link(pr.guide) && !cylinders.contains(k))
            .map(|(_, pr)| pr)
            .collect();
        order.sort_by_key(|pr| pr.guide != frame);
        let mut blocks: Vec<Block> = Vec::new();
        for pr in order {
            let q = self.place(pr.slider, pr.point);
            let u = self.s.config.pose(pr.guide).dir(pr.line_dir);
            let inner = blocks.iter().filter(|b| (b.1 - q).hypot() < 1e-6).count();
            let k = 0.55f64.powi(inner as i32);
            let (a, b) = (BLOCK.0 * k, BLOCK.1 * k);
            blocks.push((pr.slider, q, block_corners(q, u, a, b)));
        }
        blocks
    }

    /// The frame's guides: one line and one hatched wall for all the
    /// sliders on one line (two pistons in one cylinder share their wall),
    /// with the sliders' places in every position of `stroke` too.
    fn walls(&self, stroke: &[&Configuration]) -> Vec<Wall> {
        let m = self.m;
        let mut walls: Vec<Wall> = Vec::new();
        for pr in &m.prismatics {
            if !self.an.link(pr.slider) || pr.guide != self.frame {
                continue;
            }
            let q = self.place(pr.slider, pr.point);
            let u = self.s.config.pose(pr.guide).dir(pr.line_dir);
            let i = match walls
                .iter()
                .position(|w| w.1.cross(u).abs() < 1e-9 && w.1.cross(q - w.0).abs() < 1e-6)
            {
                Some(i) => i,
                None => {
                    walls.push((q, u, Vec::new()));
                    walls.len() - 1
                }
            };
            walls[i].2.push((pr.slider, q));
            for o in stroke {
                let p = o.point(m, pr.slider, pr.point);
                walls[i].2.push((pr.slider, self.to(p)));
            }
        }
        walls
    }

    /// Draw the moving links: bodies, the lines to their centres of mass
    /// and the links' numbers.
    fn links(&self, c: &mut Canvas) {
        for (l, link) in self.moving() {
            let xy = self.body(l);
            link_body(c, &xy);
            // Centres of mass lie on their links: draw the link to them.
            for &p in &link.points {
                if self.is_mass(p) && xy.len() == 2 {
                    let q = self.place(l, p);
                    if !on_body(&xy, q) {
                        c.seg(xy[0], q, Class::Main);
                    }
                }
            }
            // Link number beside the middle of its first segment.
            let mid = if xy.len() >= 2 {
                xy[0].midpoint(xy[1])
            } else {
                xy.first().copied().unwrap_or(Point::ORIGIN) + Vec2::new(0.0, 4.0)
            };
            c.label_later(
                mid,
                Label::new(link.id.clone(), ""),
                SMALL,
                Some(format!("link-{}", link.id)),
            );
        }
    }

    /// The unit directions of the moving links leaving point `p` (to their
    /// other points).
    fn leaving(&self, p: usize) -> Vec<Vec2> {
        let at = self.at_point(p);
        self.m
            .links_of_point(p)
            .into_iter()
            .filter(|&l| l != self.frame && self.an.link(l))
            .flat_map(|l| self.m.links[l].points.iter().map(move |&q| (l, q)))
            .filter(|&(_, q)| q != p)
            .map(|(l, q)| self.place(l, q) - at)
            .filter(|d| d.hypot() > 1e-9)
            .map(|d| d.normalize())
            .collect()
    }

    /// Draw the pairs and points (fixed pivots on their bases), named when
    /// `with_labels`; returns each fixed pivot's support as drawn.
    fn pairs(
        &self,
        c: &mut Canvas,
        bodies: &[(Point, Point)],
        with_labels: bool,
    ) -> Vec<Option<Vec2>> {
        let (m, frame) = (self.m, self.frame);
        let mut supports: Vec<Option<Vec2>> = vec![None; m.scene.points.len()];
        for (p, &joint) in self.joints.iter().enumerate() {
            let ls = m.links_of_point(p);
            let moving = ls.iter().any(|&l| self.an.link(l) && l != frame);
            if !(moving || ls.contains(&frame) && joint) {
                continue;
            }
            let at = self.at_point(p);
            if ls.contains(&frame) && joint {
                let down = base_direction(&self.leaving(p), at, bodies);
                supports[p] = Some(down);
                pivot(c, at, down);
            } else {
                point_symbol(c, at, joint, self.is_mass(p));
            }
            if with_labels {
                let name = m.point_name(p);
                point_label(c, at, name, format!("point-{name}"));
            }
        }
        supports
    }

    /// The inputs' motion: ω1 (and ε1) as arcs about each crank's pivot,
    /// clear of the links there (`bodies`) and of its support.
    fn inputs(&self, c: &mut Canvas, bodies: &[(Point, Point)], supports: &[Option<Vec2>]) {
        let m = self.m;
        for (i, spec) in m.scene.inputs().enumerate() {
            let InputSpec::Crank {
                link, pivot: pv, ..
            } = *spec
            else {
                continue;
            };
            let (w, e) = (self.s.drives[i].rate, self.s.drives[i].rate2);
            let o = self.at_point(pv);
            let other = m.links[link]
                .points
                .iter()
                .copied()
                .find(|&p| p != pv)
                .unwrap();
            let crank = (self.place(link, other) - o).atan2();
            let busy = self.busy_about(pv, o, bodies, supports);
            let (mid, room) = free_arc(&busy, crank + std::f64::consts::PI);
            for (k, (val, name)) in [(w, "ω"), (e, "ε")].into_iter().enumerate() {
                if val == 0.0 {
                    continue;
                }
                // On the far side of the pivot from the crank, as textbooks
                // draw it, when that side is free.
                let id = if i == 0 {
                    format!("input-{name}")
                } else {
                    format!("input-{name}{}", m.link_id(link))
                };
                let label = Label::new(name, m.link_id(link));
                rate_arc(c, (o, 6.0 + 3.5 * k as f64), (mid, room), val, label, id);
            }
        }
    }

    /// The angular velocities of the other links that turn, as the plan
    /// of velocities measured them (seed `000`, Fig. 2.11: ω3 of the
    /// kulisa drawn on the scheme, "ω3 направлена у той же бік"): an arc
    /// about the link's fixed pivot, or about the middle of a coupler,
    /// clear of the lines there. A one-point link (a slider block) turns
    /// with its guide and is left to the guide's arc.
    fn rates(&self, c: &mut Canvas, bodies: &[(Point, Point)], supports: &[Option<Vec2>]) {
        let m = self.m;
        let Some(plans) = &self.s.plans else { return };
        let cranks: Vec<usize> = (m.scene.inputs())
            .filter_map(|i| match *i {
                InputSpec::Crank { link, .. } => Some(link),
                _ => None,
            })
            .collect();
        let tiny = 1e-9 * self.s.drives.iter().map(|d| d.rate.abs()).fold(1.0, f64::max);
        let obstacles = obstacles(c);
        for (l, link) in self.moving() {
            let Some(Some((w, _))) = plans.velocity.rates.get(l) else { continue };
            if cranks.contains(&l) || w.abs() < tiny || link.points.len() < 2 {
                continue;
            }
            let body = self.body(l);
            let pivot = link.points.iter().copied().find(|p| m.links[self.frame].points.contains(p));
            // Where the arc may go: about the fixed pivot, else along a
            // coupler from its middle; each side of it.
            let mut tries: Vec<Try> = Vec::new();
            if let Some(pv) = pivot {
                let o = self.at_point(pv);
                let away = body.iter().map(|&q| q - o).find(|d| d.hypot() > 1e-9);
                let wish = away.map_or(0.0, |d| d.atan2() + std::f64::consts::PI);
                let busy = self.busy_about(pv, o, bodies, supports);
                tries.push((o, busy.clone(), wish));
                tries.push((o, busy, wish + std::f64::consts::PI));
            } else if body.len() >= 2 {
                let (a, b) = (body[0], body[1]);
                let d = (b - a).atan2();
                let busy = vec![(d, 0.35), (d + std::f64::consts::PI, 0.35)];
                for t in [0.5, 0.35, 0.65, 0.2, 0.8] {
                    for side in [1.0, -1.0] {
                        let wish = d + side * std::f64::consts::FRAC_PI_2;
                        tries.push((a + (b - a) * t, busy.clone(), wish));
                    }
                }
            }
            let clear = tries.into_iter().map(|(o, busy, wish)| (o, free_arc(&busy, wish))).find(
                |&(o, (mid, room))| {
                    let sweep = room.min(1.6);
                    (0..=16).all(|k| {
                        let a = mid - sweep / 2.0 + sweep * k as f64 / 16.0;
                        !obstacles.iter().any(|q| q(o + Vec2::from_angle(a) * 6.0))
                    })
                },
            );
            let Some((o, (mid, room))) = clear else { continue };
            let label = Label::new("ω", m.link_id(l));
            rate_arc(c, (o, 6.0), (mid, room), *w, label, format!("omega-{}", m.link_id(l)));
        }
    }

    /// The directions taken about pivot `pv` at `o` (with their half
    /// widths, rad), where the input's arcs must not go: the links there,
    /// the support and its hatching, other lines passing by.
    fn busy_about(
        &self,
        pv: usize,
        o: Point,
        bodies: &[(Point, Point)],
        supports: &[Option<Vec2>],
    ) -> Vec<(f64, f64)> {
        let mut busy: Vec<(f64, f64)> =
            self.leaving(pv).iter().map(|d| (d.atan2(), 0.35)).collect();
        if let Some(down) = supports[pv] {
            busy.push((down.atan2(), 0.95));
        }
        // Other lines passing where the arcs would go.
        for &(p, q) in bodies {
            for k in 0..=48 {
                let x = p + (q - p) * (k as f64 / 48.0);
                let r = (x - o).hypot();
                if (4.0..=11.0).contains(&r) {
                    busy.push(((x - o).atan2(), 0.2));
                }
            }
        }
        busy
    }
}

/// Which way a fixed pivot's base stands, given the unit directions of the
/// links leaving it and the lines drawn near (`bodies`): down, upright as
/// on the board, unless a link leaves within 50° of down or a line crosses
/// the base; then the one of left, right, up (or down) that no line
/// crosses, farthest from every link.
pub fn base_direction(links: &[Vec2], at: Point, bodies: &[(Point, Point)]) -> Vec2 {
    let clearance = |d: Vec2| {
        links
            .iter()
            .map(|l| l.dot(d).clamp(-1.0, 1.0).acos())
            .fold(std::f64::consts::PI, f64::min)
    };
    // The lines crossing the base's place (its triangle's foot and the
    // hatching), in the direction `d`.
    let hits = |d: Vec2| {
        let side = perp(d) * 4.5;
        let (a, b) = (at + d * 2.0, at + d * 6.0);
        let edges = [
            (a - side, b - side),
            (b - side, b + side),
            (b + side, a + side),
            (a + side, a - side),
        ];
        bodies
            .iter()
            .filter(|&&(p, q)| {
                edges
                    .iter()
                    .any(|&(e0, e1)| crossing_at(p, q, e0, e1).is_some())
            })
            .count()
    };
    let down = Vec2::new(0.0, -1.0);
    if clearance(down) >= 50f64.to_radians() && hits(down) == 0 {
        return down;
    }
    // Upright or on its side first; tilted by 45° only when every upright
    // place is crossed.
    let best = |ds: &mut dyn Iterator<Item = Vec2>| {
        ds.map(|d| (d, hits(d), clearance(d)))
            .fold((down, usize::MAX, -1.0), |best, (d, h, c)| {
                if h < best.1 || h == best.1 && c > best.2 + 1e-9 {
                    (d, h, c)
                } else {
                    best
                }
            })
    };
    let square = best(&mut (0..4).map(|k| Vec2::from_angle(-FRAC_PI_2 + k as f64 * FRAC_PI_2)));
    if square.1 == 0 {
        return square.0;
    }
    let slant = best(&mut (0..4).map(|k| Vec2::from_angle(-FRAC_PI_4 + k as f64 * FRAC_PI_2)));
    if slant.1 < square.1 {
        slant.0
    } else {
        square.0
    }
}

/// The free direction for the input's arcs about a pivot: `busy` holds
/// directions taken (by a link, by the support) with their half-widths
/// (rad). Returns the arc's middle, as near `wish` as the largest free
/// gap allows, and the sweep that fits there.
fn free_arc(busy: &[(f64, f64)], wish: f64) -> (f64, f64) {
    use std::f64::consts::TAU;
    if busy.is_empty() {
        return (wish, TAU);
    }
    // Taken intervals as [start, end) on the circle, from the first start.
    let mut taken: Vec<(f64, f64)> = busy
        .iter()
        .map(|&(a, w)| ((a - w).rem_euclid(TAU), 2.0 * w))
        .collect();
    taken.sort_by(|a, b| a.0.total_cmp(&b.0));
    // The gaps between consecutive taken intervals (merging overlaps).
    let mut gaps: Vec<(f64, f64)> = Vec::new();
    let origin = taken[0].0;
    let mut end = origin + taken[0].1;
    for &(a, w) in &taken[1..] {
        let a = if a < origin { a + TAU } else { a };
        if a > end {
            gaps.push((end, a));
        }
        end = end.max(a + w);
    }
    if origin + TAU > end {
        gaps.push((end, origin + TAU));
    }
    let Some(&(g0, g1)) = gaps
        .iter()
        .max_by(|a, b| (a.1 - a.0).total_cmp(&(b.1 - b.0)))
    else {
        // Everything taken: where it was wished, small.
        return (wish, 0.6);
    };
    let margin = 0.1;
    let room = (g1 - g0 - 2.0 * margin).max(0.3);
    let half = room.min(1.6) / 2.0;
    let (lo, hi) = (g0 + half + margin, g1 - half - margin);
    if lo > hi {
        return ((g0 + g1) / 2.0, room);
    }
    // The wish on the gap's turn of the circle, kept inside the gap (at
    // the nearer end when it lies outside).
    let w = g0 + (wish - g0).rem_euclid(TAU);
    let mid = if w <= g1 {
        w.clamp(lo, hi)
    } else if w - g1 < g0 + TAU - w {
        hi
    } else {
        lo
    };
    (mid, room)
}
