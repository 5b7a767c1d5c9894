//! Zhukovsky's lever as a sheet (docs/sheets.md): the velocity plan turned
//! by 90° counter-clockwise at its scale μ_v, pivoted at the pole; every
//! known force as an arrow at its turned point at the force scale μ_F (a
//! couple as its pair of forces), its arm from the pole as a thin dashed
//! perpendicular marked with its length in mm, the balancing force at
//! its point; a table of forces, arms and moments beside it and under the
//! figure the equation Σ M_p = 0 solved for the balancing value.

use crate::kinematics::construction::scale::Series;
use super::canvas::{Canvas, Class, FONT, Label, Line, SMALL};
use super::table::{Ruled, number};
use super::kind::SheetKind;
use crate::kinematics::construction::scale::standard_scale;
use crate::kinematics::solve::Analysis;
use crate::presentation::position_number;
use crate::kinetostatics::lever::{Lever, LeverForce, Part};
use crate::kinetostatics::{Balancing, Origin};
use crate::words::catalogue::LeverPhrases;
use crate::words::construction::Lang;
use kurbo::{Point, Vec2};

/// The longest force arrow, as a share of the lever's extent: forces
/// long enough to read, short enough not to hide the plan.
const FORCE_SHARE: f64 = 0.45;

/// An arm shorter than this (mm) is not drawn: it would be a dot on the
/// sheet (the table still lists it).
const VISIBLE: f64 = 0.8;

/// A force whose arrow is shorter than this (mm) is left to the table:
/// its arrow unreadable, its arm would only crowd the lever.
const SHORTEST: f64 = 1.5;

/// The lever's words in `lang` (its catalogue's).
pub(crate) fn words(lang: Lang) -> &'static LeverPhrases {
    &crate::words::catalogue(lang).lever
}

/// A unit in the language, the newton included (Н).
fn unit(u: &str, lang: Lang) -> String {
    let u = super::table::unit(u, lang);
    u.replace('N', &crate::words::catalogue(lang).force_plans.newton)
}

/// The name of a force on the lever in the course's notation, as the
/// force sheets write it (`presentation::force_notation`): Φ2 (inertia),
/// G2, F_M2 (a couple's pair), F5 (an external force on link 5).
fn name(an: &Analysis, f: &LeverForce) -> String {
    let link = an.mech.link_id(f.link);
    match (f.part, f.origin) {
        (Part::Couple { .. }, _) => format!("F_M{link}"),
        (Part::Force, Origin::Inertia) => format!("Φ_{link}"),
        (Part::Force, Origin::Gravity) => format!("G_{link}"),
        (Part::Force, Origin::External) => format!("F_{link}"),
    }
}

/// A name in the notation as a label: base letters, subscript.
fn label_of(s: &str) -> Label {
    match s.split_once('_') {
        Some((b, sub)) => Label::new(b, sub),
        None => {
            let cut = s.find(|c: char| c.is_ascii_digit()).unwrap_or(s.len());
            Label::new(&s[..cut], &s[cut..])
        }
    }
}

/// The force scale μ_F (N/mm): the standard value at which the largest
/// force, the balancing one included, is drawn at most [`FORCE_SHARE`] of
/// the lever's extent.
pub fn force_scale(l: &Lever) -> f64 {
    let extent = l
        .plan
        .points
        .iter()
        .map(|p| p.at.hypot())
        .fold(10.0, f64::max);
    let largest = l
        .forces
        .iter()
        .map(|f| f.f.hypot())
        .fold(l.f_b.abs(), f64::max);
    standard_scale(largest, FORCE_SHARE * extent)
}

/// The foot of the perpendicular from the pole to the line through `at`
/// along `f`.
fn foot(at: Vec2, f: Vec2) -> Point {
    let u = f.normalize();
    (at - u * at.dot(u)).to_point()
}

/// A force at `at` (mm on the lever) drawn at `mu_f`: its arrow from its
/// point, its label, its arm as a dashed perpendicular from the pole with
/// its length (once per foot: forces on one line share it); its line
/// carried on (thin dashed) to the arm's foot.
fn force(
    c: &mut Canvas,
    (at, f): (Vec2, Vec2),
    mu_f: f64,
    label: Label,
    feet: &mut Vec<Point>,
    lang: Lang,
) {
    let tail = at.to_point();
    let len = f.hypot() / mu_f;
    let tip = tail + f / mu_f;
    if len < SHORTEST {
        return;
    }
    c.vector(tail, tip, Class::Vector, None);
    c.label_later(tail.midpoint(tip), label, FONT, None);
    let h = at.cross(f).abs() / f.hypot();
    let ft = foot(at, f);
    if h >= VISIBLE && feet.iter().all(|q| (*q - ft).hypot() > 0.3) {
        feet.push(ft);
        // The force's line on to the foot, from the arrow's nearer end.
        let along = (ft - tail).dot(f.normalize());
        if along < 0.0 || along > len {
            let from = if along < 0.0 { tail } else { tip };
            c.path(vec![from, ft], Line::Dashed);
        }
        c.path(vec![Point::ORIGIN, ft], Line::Dashed);
        c.label_later(
            Point::ORIGIN.lerp(ft, 0.6),
            Label::new(number(h, lang), ""),
            SMALL,
            None,
        );
    }
}

/// The lever on a canvas, the pole at the origin, with the caption under
/// it, its lines broken to be no wider than `width` mm; `mu_f` the force
/// scale.
pub fn draw(an: &Analysis, l: &Lever, c: &mut Canvas, (mu_f, width): (f64, f64), lang: Lang) {
    figure(an, l, c, mu_f, lang);
    let bottom = c.bounds().y0;
    let x = c.bounds().x0.min(0.0);
    let size = SMALL * super::canvas::lettering();
    let lines = caption(an, l, mu_f, lang)
        .iter()
        .flat_map(|t| super::canvas::wrap(t, width, size))
        .collect::<Vec<_>>();
    for (i, t) in lines.iter().enumerate() {
        c.rich(Point::new(x, bottom - 8.0 - 5.0 * i as f64), t, SMALL, "", "start");
    }
}

/// The lever alone, without its caption (the handout writes the caption
/// in words beside it), labels placed.
pub fn figure(an: &Analysis, l: &Lever, c: &mut Canvas, mu_f: f64, lang: Lang) {
    let w = words(lang);
    let plan = &l.plan;
    let turned = |i: usize| {
        let v = plan.points[i].at;
        Point::new(-v.y, v.x)
    };
    // Each moving link's known plan points: its segments (a shaded figure
    // for three and more), as the plan draws them, turned.
    let m = &an.mech;
    let mut used = vec![false; plan.points.len()];
    used[0] = true;
    for link in (0..m.links.len()).filter(|&j| j != m.frame()) {
        let mut pts: Vec<Point> = Vec::new();
        for k in plan.body.iter().filter(|k| k.link == link) {
            used[k.point] = true;
            let p = turned(k.point);
            if pts.iter().all(|q| (*q - p).hypot() > 0.05) {
                pts.push(p);
            }
        }
        match pts.len() {
            0 | 1 => {}
            2 => c.seg(pts[0], pts[1], Class::Main),
            _ => {
                let centre = pts.iter().fold(Vec2::ZERO, |s, p| s + p.to_vec2()) / pts.len() as f64;
                pts.sort_by(|a, b| {
                    let ang = |p: &Point| (p.to_vec2() - centre).atan2();
                    ang(a).total_cmp(&ang(b))
                });
                c.poly(pts, "#e3e3e3", super::canvas::MAIN);
            }
        }
    }
    // The rays from the pole: the turned absolute velocities.
    for (i, _) in used.iter().enumerate().filter(|(i, u)| **u && *i > 0) {
        let p = turned(i);
        if p.to_vec2().hypot() > VISIBLE {
            c.seg(Point::ORIGIN, p, Class::Thin);
        }
    }
    let mut feet = Vec::new();
    let fb = l.dir_b * l.f_b;
    if fb != Vec2::ZERO {
        let label = Label::new("F", &w.balancing[..]);
        force(c, (l.at_b, fb), mu_f, label, &mut feet, lang);
    }
    for f in &l.forces {
        let label = label_of(&name(an, f));
        force(c, (f.at, f.f), mu_f, label, &mut feet, lang);
    }
    // The points, labelled as on the plan (points at one place share one
    // label), placed last.
    let mut groups: Vec<(Point, Vec<usize>)> = Vec::new();
    for (i, _) in used.iter().enumerate().filter(|(_, u)| **u) {
        let p = turned(i);
        match groups.iter_mut().find(|g| (g.0 - p).hypot() < 0.05) {
            Some(g) => g.1.push(i),
            None => groups.push((p, vec![i])),
        }
    }
    for (p, members) in &groups {
        c.dot(*p, format!("pt-{}", plan.points[members[0]].key));
    }
    for (p, members) in groups {
        // Named as on the plan: d₅ alone for the ram, not "d₅, k′, m, t".
        let members = super::plan::named(plan, &members);
        let first = &plan.points[members[0]];
        let mut label = Label::new(first.label.0.clone(), first.label.1.clone());
        for &i in &members[1..] {
            let q = &plan.points[i];
            if (q.label.0.clone(), q.label.1.clone()) != (label.base.clone(), label.sub.clone())
                && !label.more.contains(&q.label)
            {
                label = label.and(q.label.0.clone(), q.label.1.clone());
            }
        }
        c.label(p, label, FONT, Some(format!("label-{}", first.key)));
    }
    c.place_pending();
}

/// The caption: the scales, and Σ M_p = 0 solved with numbers.
pub(crate) fn caption(an: &Analysis, l: &Lever, mu_f: f64, lang: Lang) -> Vec<String> {
    let w = words(lang);
    // Three significant digits, as the table: the arms are read on the
    // lever to a tenth of a millimetre.
    let n = |x: f64| number(super::pack::round3(x), lang);
    let u = |s: &str| unit(s, lang);
    let b = &w.balancing;
    let sum: f64 = l.forces.iter().map(|f| f.moment).sum();
    let mut out = vec![
        format!(
            "{}: μ_v = {} ({})/{}, μ_F = {} {}/{}",
            &w.turned,
            n(l.mu_v),
            u("m/s"),
            u("mm"),
            n(mu_f),
            u("N"),
            u("mm")
        ),
        format!(
            "ΣM_p = Σ F·h + F_{b}·h_{b} = 0:  {} {} + F_{b}·{} {} = 0,  F_{b} = {} {}",
            n(sum),
            u("N·mm"),
            {
                // The arm of F_b as it acts (the arrow drawn), so that F_b
                // is its magnitude, as in the table.
                let h = l.at_b.cross(l.dir_b) * l.f_b.signum();
                if h < 0.0 { format!("({})", n(h)) } else { n(h) }
            },
            u("mm"),
            n(l.f_b.abs()),
            u("N")
        ),
        w.convention.replace("{b}", b),
    ];
    let m = &an.mech;
    match l.balancing {
        Balancing::Moment(mb) => {
            let spec = m.scene.input_at(l.input);
            // The crank's length from the mechanism (not M_b / F_b, which
            // is 0/0 where nothing loads the crank).
            let (pivot, arm) = match *spec {
                crate::model::scene::InputSpec::Crank { pivot, link, .. } => (
                    m.point_name(pivot),
                    (m.local(link, l.point_b) - m.local(link, pivot)).hypot(),
                ),
                crate::model::scene::InputSpec::Slider { .. } => ("", mb / l.f_b),
            };
            // M_b signed, counter-clockwise positive; F_b a magnitude.
            let sign = if mb < 0.0 { "−" } else { "" };
            out.push(format!(
                "M_{b} = {sign}F_{b}·l_{pivot}{} = {sign}{}·{} = {} {}",
                m.point_name(l.point_b),
                n(l.f_b.abs()),
                n(arm),
                n(mb),
                u("N·m")
            ));
        }
        Balancing::Force(fb) => {
            out[1] = out[1].replace(&format!("F_{b} = {} {}", n(l.f_b.abs()), u("N")), "");
            out.push(format!("F_{b} = {} {} ({})", n(fb), u("N"), w.along));
        }
    }
    out
}

/// The table beside the lever: every force, its magnitude, arm and
/// moment about the pole (counter-clockwise positive), the balancing
/// force last; three significant digits, as a course project's result
/// table gives them (and the caption's equation).
pub fn table(an: &Analysis, l: &Lever, lang: Lang) -> Ruled {
    use super::pack::round3;
    let w = words(lang);
    let mut rows: Vec<Vec<String>> = l
        .forces
        .iter()
        .map(|f| {
            let at = f.point.map(|p| an.mech.point_name(p)).unwrap_or("·");
            vec![
                format!("{} ({at})", name(an, f)),
                number(round3(f.f.hypot()), lang),
                number(round3(f.arm), lang),
                number(round3(f.moment), lang),
            ]
        })
        .collect();
    rows.push(vec![
        format!("F_{} ({})", w.balancing, an.mech.point_name(l.point_b)),
        number(round3(l.f_b.abs()), lang),
        number(round3(l.arm_b), lang),
        number(round3(l.moment_b), lang),
    ]);
    Ruled {
        head: w.heads.iter().map(|s| s.to_string()).collect(),
        rows,
    }
}

/// "input 2" of a scene with several inputs, for the sheet's heading.
pub(crate) fn input_text(l: &Lever, lang: Lang) -> String {
    format!("{} {}", words(lang).input, l.input + 1)
}

/// The lever sheets of position `s` (the `k`-th), one per input, each at
/// the μ_v that fills its field beside its table (the scene's μ_v where
/// it fixes one for a single input).
pub(super) fn pending(
    an: &Analysis,
    s: &crate::pipeline::Solved,
    k: usize,
    opt: &super::DrawOptions,
) -> crate::error::Result<Vec<super::Pending>> {
    use crate::kinematics::construction::Naming;
    use crate::kinetostatics::lever::lever_at;
    let loads = s.dynamics.as_ref().map_or(&[][..], |d| &d.loads[..]);
    let pos = super::position_text(an, s, k, opt.lang);
    let w = words(opt.lang);
    let several = an.mech.scene.several_inputs();
    let mut out = Vec::new();
    for input in 0..an.mech.scene.input_count() {
        let first = lever_at(an, s, loads, input, Naming::Full, None)?;
        let right = |l: &Lever| table(an, l, opt.lang).size().0 + super::sheet::PAD;
        // The caption's lines broken to the field beside the table (less a
        // margin: the breaking estimates a line's width as plain text, the
        // sheet measures its subscripts).
        let width = super::field_size(opt, right(&first)).0 - 3.0;
        let figure = |l: &Lever| {
            let mu_f = force_scale(l);
            let mut c = Canvas::default();
            draw(an, l, &mut c, (mu_f, width), opt.lang);
            (c, mu_f)
        };
        let fixed = !several && an.drafting.mu_v.is_some();
        let (l, (c, mu_f)) = if fixed {
            let f = figure(&first);
            (first, f)
        } else {
            let field = super::field_size(opt, right(&first));
            let e = first.plan.points.iter().fold(kurbo::Rect::ZERO, |r, p| {
                r.union_pt(Point::new(-p.at.y, p.at.x))
            });
            let lower = super::lower_scale(e.width() * first.mu_v, e.height() * first.mu_v, field);
            let rebuild = |mu: f64| {
                let l = lever_at(an, s, loads, input, Naming::Full, Some(mu)).ok()?;
                let f = figure(&l);
                Some((l, f))
            };
            match super::fill(Series::Plans, lower, field, rebuild, |(_, (c, _))| c.bounds()) {
                Some((_, x)) => x,
                None => {
                    let f = figure(&first);
                    (first, f)
                }
            }
        };
        let t = table(an, &l, opt.lang);
        let (name, title) = if several {
            (
                SheetKind::Lever {
                    position: position_number(an, k),
                    input: Some(input),
                }
                .stem(),
                format!("{}, {}, {pos}", w.title, input_text(&l, opt.lang)),
            )
        } else {
            let sheet = SheetKind::Lever {
                position: position_number(an, k),
                input: None,
            };
            (sheet.stem(), format!("{}, {pos}", w.title))
        };
        out.push(super::Pending {
            sheet: None,
            name,
            title,
            scale: Some(format!(
                "{}, μ_F = {} {}/{}",
                super::scale_text("v", l.mu_v, "m/s", opt.lang),
                number(mu_f, opt.lang),
                unit("N", opt.lang),
                unit("mm", opt.lang)
            )),
            scales: vec![("mu_v", l.mu_v), ("mu_F", mu_f)],
            canvas: c,
            centre_on: None,
            table: Some(t),
        });
    }
    Ok(out)
}

/// The levers of position `s` (one per input) as `solve --steps` says
/// them: each lever, its caption's first line (the scales) and its items
/// (every force's arm and moment, ΣM_p = 0 solved, the balancing value),
/// without their full stops; numbers with the decimal point (the caller
/// writes them in the language's mark). Empty where no lever is built.
pub fn lines(
    an: &Analysis,
    s: &crate::pipeline::Solved,
    loads: &[crate::kinetostatics::Load],
    lang: Lang,
) -> Vec<(Lever, String, Vec<String>)> {
    use crate::kinematics::construction::Naming;
    let Ok(levers) = crate::kinetostatics::lever::levers(an, s, loads, Naming::Full) else {
        return Vec::new();
    };
    let w = &crate::words::catalogue(lang).lever;
    let units = &crate::words::catalogue(lang).force_plans;
    let arm = &w.arm;
    let mut out = Vec::new();
    for l in levers {
        let mu_f = force_scale(&l);
        let caption = caption(an, &l, mu_f, lang);
        let mut items = Vec::new();
        for row in &table(an, &l, lang).rows {
            let row: Vec<String> = row.iter().map(|c| points(c)).collect();
            items.push(format!(
                "{} = {} {}, {arm} h = {} {}: {}·h = {} {}",
                row[0],
                row[1],
                units.newton,
                row[2],
                units.mm,
                row[0].split(' ').next().unwrap_or(""),
                row[3],
                units.newton_millimetre,
            ));
        }
        items.extend(caption[1..].iter().map(|line| points(line)));
        let head = points(&caption[0]);
        out.push((l, head, items));
    }
    out
}

/// A decimal comma between digits (the sheets' Ukrainian and Russian
/// numbers) as the steps' decimal point, so that one text writes one way.
fn points(s: &str) -> String {
    let c: Vec<char> = s.chars().collect();
    (0..c.len())
        .map(|i| {
            let digit = |j: Option<&char>| j.is_some_and(|c| c.is_ascii_digit());
            if c[i] == ',' && i > 0 && digit(c.get(i - 1)) && digit(c.get(i + 1)) {
                '.'
            } else {
                c[i]
            }
        })
        .collect()
}
