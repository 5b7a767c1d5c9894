//! A photographed plan's clicks moved to the points its pencil lines
//! mark (`"snap": true` in a marks file, docs/check.md): a click is a
//! millimetre or so off, the vertex the student drew is where the point
//! is. Around each click, the dark pixels of the photo (against the
//! paper's own brightness there; a millimetre grid's colour reads as
//! paper) are found as straight lines by a Hough transform, each line
//! refined by a least-squares fit to the pixels along it and its ends
//! found along the pencil, and the click moved to the nearest place
//! where lines end together (a plan's points are where its vectors end),
//! else to a crossing, a line's end or onto the nearest line, if one
//! lies within the radius ([`vertex`]).

use crate::error::{Error, Result};
use image::{DynamicImage, GrayImage, ImageDecoder, ImageReader};
use std::io::Cursor;

/// Two lines meeting at less than this are no crossing a click can be
/// moved to: along nearly parallel lines the crossing slides far with a
/// pixel's error.
const MIN_CROSSING_DEG: f64 = 15.0;

/// How far beyond the snapping radius the lines are looked for, mm: a
/// crossing at the radius's edge still has this much of its lines seen.
const MARGIN_MM: f64 = 2.0;

/// The shortest line found, mm: shorter dark strokes are a letter, a
/// smudge or noise.
const MIN_LINE_MM: f64 = 1.5;

/// The most lines looked for around one click (a pole may have many).
const MAX_LINES: usize = 8;

/// The photo as displayed: its file's bytes decoded (JPEG or PNG) with
/// its EXIF orientation applied, each pixel as bright as its brightest
/// colour channel. Graphite is dark in every channel, while the printed
/// grid of millimetre paper (orange, green or blue) is bright in its own
/// colour's channel: so the grid reads as paper and only the pencil as
/// lines. A grey photo is its own grey.
pub fn load(bytes: &[u8]) -> Result<GrayImage> {
    let bad = |why: String| {
        Error::scene(
            "/photo/file",
            format!("the photo cannot be decoded: {why}"),
        )
    };
    let reader = ImageReader::new(Cursor::new(bytes))
        .with_guessed_format()
        .map_err(|e| bad(e.to_string()))?;
    let mut decoder = reader.into_decoder().map_err(|e| bad(e.to_string()))?;
    let orientation = decoder
        .orientation()
        .unwrap_or(image::metadata::Orientation::NoTransforms);
    let mut img = DynamicImage::from_decoder(decoder).map_err(|e| bad(e.to_string()))?;
    img.apply_orientation(orientation);
    let rgb = img.to_rgb8();
    Ok(GrayImage::from_fn(rgb.width(), rgb.height(), |x, y| {
        let p = rgb.get_pixel(x, y).0;
        image::Luma([p[0].max(p[1]).max(p[2])])
    }))
}

/// A line fitted to dark pixels: a point on it and its unit direction,
/// and where its pixels begin and end along it (from `at`).
#[derive(Clone, Copy, Debug)]
struct Line {
    at: [f64; 2],
    dir: [f64; 2],
    ends: [f64; 2],
}

impl Line {
    /// The point `t` along it.
    fn point(&self, t: f64) -> [f64; 2] {
        [self.at[0] + t * self.dir[0], self.at[1] + t * self.dir[1]]
    }
}

/// The crossing of pencil lines nearest `click` (px) within `radius`
/// px, where `px_per_mm` is the photo's scale there; `None` where there
/// is none.
pub fn crossing(img: &GrayImage, click: [f64; 2], radius: f64, px_per_mm: f64) -> Option<[f64; 2]> {
    let reach = radius + MARGIN_MM * px_per_mm;
    let (w, h) = (img.width() as i64, img.height() as i64);
    let x0 = ((click[0] - reach).floor() as i64).clamp(0, w);
    let x1 = ((click[0] + reach).ceil() as i64).clamp(0, w);
    let y0 = ((click[1] - reach).floor() as i64).clamp(0, h);
    let y1 = ((click[1] + reach).ceil() as i64).clamp(0, h);
    if x1 - x0 < 3 || y1 - y0 < 3 {
        return None;
    }
    // The window's pixels within reach of the click (centres at +0.5).
    let mut px: Vec<([f64; 2], f64)> = Vec::new();
    for y in y0..y1 {
        for x in x0..x1 {
            let c = [x as f64 + 0.5, y as f64 + 0.5];
            if (c[0] - click[0]).hypot(c[1] - click[1]) <= reach {
                px.push((c, f64::from(img.get_pixel(x as u32, y as u32)[0])));
            }
        }
    }
    // Darkness against the paper's brightness here (the window's
    // median: most of it is paper), kept above 40 % of the darkest.
    let mut values: Vec<f64> = px.iter().map(|p| p.1).collect();
    values.sort_by(f64::total_cmp);
    let paper = values[values.len() / 2];
    let darkest = values[values.len() / 100];
    if paper - darkest < 30.0 {
        return None;
    }
    let cut = 0.4 * (paper - darkest);
    let mut dark: Vec<([f64; 2], f64)> = px
        .iter()
        .filter(|p| paper - p.1 > cut)
        .map(|p| (p.0, paper - p.1))
        .collect();
    let all = dark.clone();
    let mut lines = Vec::new();
    let min_pixels = MIN_LINE_MM * px_per_mm;
    let band = (0.25 * px_per_mm).max(1.5);
    while lines.len() < MAX_LINES {
        let Some(mut line) = hough_peak(&dark, click, reach, min_pixels) else {
            break;
        };
        // Refine: fit the pixels along it, twice.
        for _ in 0..2 {
            let near: Vec<([f64; 2], f64)> =
                dark.iter().copied().filter(|p| distance(&line, p.0) <= band).collect();
            match fit(&near) {
                Some(l) => line = l,
                None => break,
            }
        }
        // Its ends among all the pencil's pixels, not only those no
        // line found before has taken: where two lines meet at a few
        // degrees, the first takes the second's pixels near their
        // common end, and the rest would seem to end where they part.
        line.ends = ends(&all, &line, band, 0.5 * px_per_mm);
        let before = dark.len();
        dark.retain(|p| distance(&line, p.0) > band * 1.5);
        if before - dark.len() < min_pixels as usize {
            break;
        }
        lines.push(line);
    }
    vertex(&lines, click, radius, px_per_mm)
}

/// Where the pencil along `line` begins and ends (from `line.at`): the
/// longest run of the pixels within `band` of it with no gap wider than
/// `gap` px, so that a stroke merely crossing its extension beyond its
/// end does not lengthen it.
fn ends(pts: &[([f64; 2], f64)], line: &Line, band: f64, gap: f64) -> [f64; 2] {
    let mut along: Vec<f64> = pts
        .iter()
        .filter(|p| distance(line, p.0) <= band)
        .map(|p| (p.0[0] - line.at[0]) * line.dir[0] + (p.0[1] - line.at[1]) * line.dir[1])
        .collect();
    along.sort_by(f64::total_cmp);
    let Some(&first) = along.first() else {
        return [0.0, 0.0];
    };
    let (mut best, mut start, mut count, mut most) = ([first, first], first, 0usize, 0usize);
    for w in along.windows(2) {
        count += 1;
        if w[1] - w[0] > gap {
            start = w[1];
            count = 0;
        }
        if count >= most {
            most = count;
            best = [start, w[1]];
        }
    }
    best
}

/// How close to a crossing a line's end is to make it a vertex, mm.
const END_NEAR_MM: f64 = 0.6;

/// The distance between two points.
fn dist(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// The crossing of lines `a` and `b`, with the sine of their angle.
fn cross(a: &Line, b: &Line) -> ([f64; 2], f64) {
    let s = a.dir[0] * b.dir[1] - a.dir[1] * b.dir[0];
    if s == 0.0 {
        return ([f64::NAN; 2], 0.0);
    }
    let d = [b.at[0] - a.at[0], b.at[1] - a.at[1]];
    let t = (d[0] * b.dir[1] - d[1] * b.dir[0]) / s;
    ([a.at[0] + t * a.dir[0], a.at[1] + t * a.dir[1]], s)
}

/// The plan's point the click means, within `radius` of it. A plan's
/// points are where its vectors end (the rays from the pole, the lines
/// between a link's points), so, in this order of preference:
/// 1. where two or more lines end together (the nearest such place):
///    their crossing where two of them meet at 15° or more, else the mean
///    of their ends (rays from a pole toward points in much the same
///    direction meet at a few degrees, where a crossing slides);
/// 2. a crossing at 15° or more where one line ends (a point marked on
///    a line by the ray that ends there);
/// 3. any crossing at 15° or more; 4. a line's end alone;
/// 5. the foot of the click on the nearest line (a point in the middle
///    of a line, as a plan at a dead centre has: the line says where the
///    point is across it, the click along it);
///
/// otherwise the click stays (`None`).
fn vertex(lines: &[Line], click: [f64; 2], radius: f64, px_per_mm: f64) -> Option<[f64; 2]> {
    let min_sin = MIN_CROSSING_DEG.to_radians().sin();
    let near = END_NEAR_MM * px_per_mm;
    // Each line's ends, with the line they belong to.
    let ends: Vec<([f64; 2], usize)> = lines
        .iter()
        .enumerate()
        .flat_map(|(i, l)| [(l.point(l.ends[0]), i), (l.point(l.ends[1]), i)])
        .collect();
    // The lines ending within `near` of `x`.
    let ending_at = |x: [f64; 2]| -> Vec<usize> {
        let mut v: Vec<usize> = ends
            .iter()
            .filter(|e| dist(e.0, x) <= near)
            .map(|e| e.1)
            .collect();
        v.sort_unstable();
        v.dedup();
        v
    };
    let nearest = |c: &mut Vec<[f64; 2]>| -> Option<[f64; 2]> {
        c.retain(|x| x[0].is_finite() && dist(*x, click) <= radius);
        c.iter().copied().min_by(|a, b| dist(*a, click).total_cmp(&dist(*b, click)))
    };
    // 1. Places where two or more lines end together.
    let mut together: Vec<[f64; 2]> = Vec::new();
    for (e, _) in &ends {
        let group = ending_at(*e);
        if group.len() < 2 {
            continue;
        }
        let sharp = group
            .iter()
            .flat_map(|&i| group.iter().map(move |&j| (i, j)))
            .filter(|(i, j)| i < j)
            .map(|(i, j)| cross(&lines[i], &lines[j]))
            .filter(|(x, s)| s.abs() >= min_sin && dist(*x, *e) <= near)
            .max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()));
        together.push(match sharp {
            Some((x, _)) => x,
            None => {
                let mine: Vec<[f64; 2]> = ends
                    .iter()
                    .filter(|f| group.contains(&f.1) && dist(f.0, *e) <= near)
                    .map(|f| f.0)
                    .collect();
                let n = mine.len() as f64;
                mine.iter().fold([0.0, 0.0], |m, f| [m[0] + f[0] / n, m[1] + f[1] / n])
            }
        });
    }
    if let Some(x) = nearest(&mut together) {
        return Some(x);
    }
    // 2 and 3. Crossings, where a line ends first.
    let mut crossings: Vec<([f64; 2], bool)> = Vec::new();
    for i in 0..lines.len() {
        for j in i + 1..lines.len() {
            let (x, s) = cross(&lines[i], &lines[j]);
            if s.abs() >= min_sin {
                crossings.push((x, !ending_at(x).is_empty()));
            }
        }
    }
    let mut ended: Vec<[f64; 2]> = crossings.iter().filter(|c| c.1).map(|c| c.0).collect();
    if let Some(x) = nearest(&mut ended) {
        return Some(x);
    }
    let mut any: Vec<[f64; 2]> = crossings.iter().map(|c| c.0).collect();
    if let Some(x) = nearest(&mut any) {
        return Some(x);
    }
    // 4. A line's end alone.
    let mut alone: Vec<[f64; 2]> = ends.iter().map(|e| e.0).collect();
    if let Some(x) = nearest(&mut alone) {
        return Some(x);
    }
    // 5. The foot on the nearest line, where the line is drawn.
    let mut feet: Vec<[f64; 2]> = lines
        .iter()
        .filter_map(|l| {
            let t = (click[0] - l.at[0]) * l.dir[0] + (click[1] - l.at[1]) * l.dir[1];
            (t >= l.ends[0] && t <= l.ends[1]).then(|| l.point(t))
        })
        .collect();
    nearest(&mut feet)
}

/// The distance of `p` from line `l`.
fn distance(l: &Line, p: [f64; 2]) -> f64 {
    ((p[0] - l.at[0]) * l.dir[1] - (p[1] - l.at[1]) * l.dir[0]).abs()
}

/// The strongest straight line among the dark pixels (weighted by their
/// darkness), if enough pixels lie on it: a Hough transform over 1°
/// directions and 1 px offsets from the click.
fn hough_peak(dark: &[([f64; 2], f64)], click: [f64; 2], reach: f64, min_pixels: f64) -> Option<Line> {
    const ANGLES: usize = 180;
    let rho_bins = (2.0 * reach).ceil() as usize + 3;
    let trig: Vec<(f64, f64)> = (0..ANGLES)
        .map(|k| (k as f64).to_radians().sin_cos())
        .collect();
    let mut acc = vec![0.0f64; ANGLES * rho_bins];
    let mut count = vec![0u32; ANGLES * rho_bins];
    for (p, w) in dark {
        let (x, y) = (p[0] - click[0], p[1] - click[1]);
        for (k, (s, c)) in trig.iter().enumerate() {
            let rho = x * c + y * s + reach + 1.0;
            let r = rho.round() as usize;
            if r < rho_bins {
                acc[k * rho_bins + r] += w;
                count[k * rho_bins + r] += 1;
            }
        }
    }
    let (i, _) = acc
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.total_cmp(b.1))?;
    if f64::from(count[i]) < min_pixels {
        return None;
    }
    let (k, r) = (i / rho_bins, i % rho_bins);
    let (s, c) = trig[k];
    let rho = r as f64 - reach - 1.0;
    Some(Line {
        at: [click[0] + rho * c, click[1] + rho * s],
        dir: [-s, c],
        ends: [0.0, 0.0],
    })
}

/// The line through weighted pixels by total least squares (the
/// principal axis of their spread); `None` for too few.
fn fit(pts: &[([f64; 2], f64)]) -> Option<Line> {
    let sw: f64 = pts.iter().map(|p| p.1).sum();
    if pts.len() < 3 || sw <= 0.0 {
        return None;
    }
    let m = pts.iter().fold([0.0, 0.0], |m, (p, w)| {
        [m[0] + p[0] * w / sw, m[1] + p[1] * w / sw]
    });
    let (mut sxx, mut sxy, mut syy) = (0.0, 0.0, 0.0);
    for (p, w) in pts {
        let (dx, dy) = (p[0] - m[0], p[1] - m[1]);
        sxx += w * dx * dx;
        sxy += w * dx * dy;
        syy += w * dy * dy;
    }
    let theta = 0.5 * (2.0 * sxy).atan2(sxx - syy);
    Some(Line {
        at: m,
        dir: [theta.cos(), theta.sin()],
        ends: [0.0, 0.0],
    })
}
