//! The plans drawn, scene by scene: the four-bar (crank, one RRR group,
//! a coupler point M off AB), the six-link of Fig. 2.10 (RRR with the
//! triangular rocker, then RRP on the frame's guide: the frame's d0 at
//! the pole), the crank with a rotating guide (RRP whose slider slides
//! on the crank: the Coriolis acceleration with the crank's ω1) and the
//! shaper (a rocking guide: RPR with the Coriolis acceleration with the
//! rocker's ω3, then the ram that translates: k′ and m at d5).

use super::hand::{Kind, Route, Sheet};
use super::scenes::{Ctx, How, Read, Values};
use kurbo::Vec2;
use mechplan::construction::PointId;

const POLE: Vec2 = Vec2::ZERO;

/// The rate of a link as the judge reads it off the typed points: from j
/// (on an acceleration plan from the link's normal end n: typed, or laid
/// off from the typed j with the judge's ω) to x.
fn judged_rate(
    c: &Ctx,
    sh: &Sheet,
    v: Option<&Values>,
    (j, jn): (Vec2, &str),
    (x, xn): (Vec2, &str),
    link: &str,
) -> f64 {
    let start = match v {
        None => j,
        Some(v) => {
            let w = v.judge_w(c.link(link));
            let r = c.p(xn) - c.p(jn);
            sh.typed(c.normal(link)).unwrap_or(j - r * (w * w) / sh.mu)
        }
    };
    c.typed_rate(sh, (start, x), (jn, xn))
}

/// A known point of a link: where it is on the sheet, its name on the
/// mechanism, and which plan point it is (the pole: `None`).
type Known<'a> = (Vec2, &'a str, Option<PointId>);

/// Draw point `xn` of a link (its known points `a`, `b`, the link's
/// rate as the student read it, with ω on an acceleration plan) and
/// hand it in; for a relative vector, with the place the judge's own
/// reading of the typed points gives (where both known points are the
/// pole or handed in).
#[allow(clippy::too_many_arguments)]
fn third(
    c: &Ctx,
    sh: &mut Sheet,
    how: How,
    (a, an, ia): Known,
    (b, bn, ib): Known,
    xn: &str,
    (rate, omega): (f64, Option<f64>),
    (link, v): (&str, Option<&Values>),
) -> Vec2 {
    let (x, kind) = c.point_of(sh, how, (a, an), (b, bn), xn, (rate, omega));
    sh.hand_in(c.named(xn), x, kind, false);
    let typed = |id: Option<PointId>| id.map_or(Some(POLE), |id| sh.typed(id));
    let route = match (kind, typed(ia), typed(ib)) {
        (Kind::Relation, Some(ta), Some(tb)) => {
            let rate_t = judged_rate(c, sh, v, (ta, an), (tb, bn), link);
            let w = v.map(|v| v.judge_w(c.link(link)));
            let place = |rate| c.relation_place(sh, (ta, an), xn, (rate, w));
            Some(Route::Relation(place(rate_t), place(0.0)))
        }
        (Kind::Relation, ..) => None,
        _ => {
            let (ab, ax) = (c.p(bn) - c.p(an), c.p(xn) - c.p(an));
            let ratio = Vec2::new(ax.dot(ab), ab.cross(ax)) / ab.hypot2();
            Some(Route::Figure(ia, ib, ratio))
        }
    };
    sh.handed.last_mut().expect("handed in").route = route;
    x
}

pub fn four_bar_v(c: &Ctx, sh: &mut Sheet, how: How) -> Read {
    let a = c.crank_point(sh, ("O1", "A"), "1", true);
    let (l1, _) = c.rigid(sh, (a, "A"), "B", None);
    let (l2, _) = c.rigid(sh, (POLE, "O3"), "B", None);
    let b = sh.meet(l1, l2);
    sh.hand_in(c.named("B"), b, Kind::Lines, false);
    let w2 = sh.rate(a, b, (c.p("A"), c.p("B")));
    let w3 = sh.rate(POLE, b, (c.p("O3"), c.p("B")));
    third(
        c,
        sh,
        how,
        (a, "A", Some(c.named("A"))),
        (b, "B", Some(c.named("B"))),
        "M",
        (w2, None),
        ("2", None),
    );
    Read {
        omega: vec![(c.link("2"), w2), (c.link("3"), w3)],
        slide: Vec::new(),
    }
}

pub fn four_bar_a(c: &Ctx, sh: &mut Sheet, how: How, v: &Values) {
    let (w2, w3) = (v.w(c.link("2")), v.w(c.link("3")));
    let a = c.crank_point(sh, ("O1", "A"), "1", false);
    let (l1, n2) = c.rigid(sh, (a, "A"), "B", Some((w2, "2")));
    let (l2, _) = c.rigid(sh, (POLE, "O3"), "B", Some((w3, "3")));
    let b = sh.meet(l1, l2);
    sh.hand_in(c.named("B"), b, Kind::Lines, false);
    let e2 = sh.rate(n2, b, (c.p("A"), c.p("B")));
    third(
        c,
        sh,
        how,
        (a, "A", Some(c.named("A"))),
        (b, "B", Some(c.named("B"))),
        "M",
        (e2, Some(w2)),
        ("2", Some(v)),
    );
}

pub fn six_link_v(c: &Ctx, sh: &mut Sheet, how: How) -> Read {
    let a = c.crank_point(sh, ("O1", "A"), "1", true);
    let (l1, _) = c.rigid(sh, (a, "A"), "B", None);
    let (l2, _) = c.rigid(sh, (POLE, "O2"), "B", None);
    let b = sh.meet(l1, l2);
    sh.hand_in(c.named("B"), b, Kind::Lines, false);
    let w2 = sh.rate(a, b, (c.p("A"), c.p("B")));
    let w3 = sh.rate(POLE, b, (c.p("O2"), c.p("B")));
    third(
        c,
        sh,
        how,
        (a, "A", Some(c.named("A"))),
        (b, "B", Some(c.named("B"))),
        "S2",
        (w2, None),
        ("2", None),
    );
    let cc = third(
        c,
        sh,
        how,
        (POLE, "O2", None),
        (b, "B", Some(c.named("B"))),
        "C",
        (w3, None),
        ("3", None),
    );
    sh.hand_in(c.on("D", "0"), POLE, Kind::Coincide, true);
    let (l3, _) = c.rigid(sh, (cc, "C"), "D", None);
    let l4 = sh.line(POLE, c.guide("D"));
    let d = sh.meet(l3, l4);
    sh.hand_in(c.named("D"), d, Kind::Lines, false);
    let w4 = sh.rate(cc, d, (c.p("C"), c.p("D")));
    third(
        c,
        sh,
        how,
        (cc, "C", Some(c.named("C"))),
        (d, "D", Some(c.named("D"))),
        "S4",
        (w4, None),
        ("4", None),
    );
    Read {
        omega: vec![(c.link("2"), w2), (c.link("3"), w3), (c.link("4"), w4)],
        slide: Vec::new(),
    }
}

pub fn six_link_a(c: &Ctx, sh: &mut Sheet, how: How, v: &Values) {
    let w = |l: &str| v.w(c.link(l));
    let a = c.crank_point(sh, ("O1", "A"), "1", false);
    let (l1, n2) = c.rigid(sh, (a, "A"), "B", Some((w("2"), "2")));
    let (l2, n3) = c.rigid(sh, (POLE, "O2"), "B", Some((w("3"), "3")));
    let b = sh.meet(l1, l2);
    sh.hand_in(c.named("B"), b, Kind::Lines, false);
    let e2 = sh.rate(n2, b, (c.p("A"), c.p("B")));
    let e3 = sh.rate(n3, b, (c.p("O2"), c.p("B")));
    third(
        c,
        sh,
        how,
        (a, "A", Some(c.named("A"))),
        (b, "B", Some(c.named("B"))),
        "S2",
        (e2, Some(w("2"))),
        ("2", Some(v)),
    );
    let cc = third(
        c,
        sh,
        how,
        (POLE, "O2", None),
        (b, "B", Some(c.named("B"))),
        "C",
        (e3, Some(w("3"))),
        ("3", Some(v)),
    );
    sh.hand_in(c.on("D", "0"), POLE, Kind::Coincide, true);
    let (l3, n4) = c.rigid(sh, (cc, "C"), "D", Some((w("4"), "4")));
    let l4 = sh.line(POLE, c.guide("D"));
    let d = sh.meet(l3, l4);
    sh.hand_in(c.named("D"), d, Kind::Lines, false);
    let e4 = sh.rate(n4, d, (c.p("C"), c.p("D")));
    third(
        c,
        sh,
        how,
        (cc, "C", Some(c.named("C"))),
        (d, "D", Some(c.named("D"))),
        "S4",
        (e4, Some(w("4"))),
        ("4", Some(v)),
    );
}

/// C as a point of the crank's guide: on the line O1 K, dividing it.
fn on_crank(c: &Ctx, sh: &mut Sheet, k: Vec2) -> Vec2 {
    let (o, kk, cc) = (c.p("O1"), c.p("K"), c.p("C"));
    let t = (cc - o).dot(kk - o) / (kk - o).hypot2();
    let c1 = sh.divide(POLE, k, t);
    sh.hand_in(c.on("C", "1"), c1, Kind::Division, true);
    c1
}

pub fn rotating_guide_v(c: &Ctx, sh: &mut Sheet, how: How) -> Read {
    let k = c.crank_point(sh, ("O1", "K"), "1", true);
    let c1 = on_crank(c, sh, k);
    let (l1, _) = c.rigid(sh, (POLE, "B"), "C", None);
    let u = c.guide("C");
    let l2 = sh.line(c1, u);
    let cc = sh.meet(l1, l2);
    sh.hand_in(c.named("C"), cc, Kind::Lines, false);
    let w2 = sh.rate(POLE, cc, (c.p("B"), c.p("C")));
    let vrel = sh.along(c1, cc, u);
    third(
        c,
        sh,
        how,
        (POLE, "B", None),
        (cc, "C", Some(c.named("C"))),
        "S2",
        (w2, None),
        ("2", None),
    );
    Read {
        omega: vec![(c.link("2"), w2)],
        slide: vec![("C", vrel)],
    }
}

pub fn rotating_guide_a(c: &Ctx, sh: &mut Sheet, how: How, v: &Values) {
    let (w1, _) = c.crank();
    let w2 = v.w(c.link("2"));
    let k = c.crank_point(sh, ("O1", "K"), "1", false);
    let c1 = on_crank(c, sh, k);
    let u = c.guide("C");
    let kc = sh.lay(c1, super::hand::perp(u * v.slide("C")) * (2.0 * w1));
    sh.hand_in(c.coriolis("3"), kc, Kind::Coriolis, true);
    let (l1, n2) = c.rigid(sh, (POLE, "B"), "C", Some((w2, "2")));
    let l2 = sh.line(kc, u);
    let cc = sh.meet(l1, l2);
    sh.hand_in(c.named("C"), cc, Kind::Lines, false);
    let e2 = sh.rate(n2, cc, (c.p("B"), c.p("C")));
    third(
        c,
        sh,
        how,
        (POLE, "B", None),
        (cc, "C", Some(c.named("C"))),
        "S2",
        (e2, Some(w2)),
        ("2", Some(v)),
    );
}

/// The ram's group: d5 where the line ∥ the ram's guide through d meets
/// the line ∥ the frame's guide through d0 (at the pole); k′ and m at d5.
fn ram(c: &Ctx, sh: &mut Sheet, d: Vec2) {
    sh.hand_in(c.on("D", "0"), POLE, Kind::Coincide, true);
    let l1 = sh.line(d, c.guide_of("4", "5"));
    let l2 = sh.line(POLE, c.guide_of("5", "0"));
    let d5 = sh.meet(l1, l2);
    sh.hand_in(c.on("D", "5"), d5, Kind::Lines, true);
    sh.hand_in(c.named("K"), d5, Kind::Coincide, false);
    sh.hand_in(c.named("M"), d5, Kind::Coincide, false);
}

pub fn shaper_v(c: &Ctx, sh: &mut Sheet, how: How) -> Read {
    let b = c.crank_point(sh, ("A", "B"), "1", true);
    let (l1, _) = c.rigid(sh, (POLE, "C"), "B", None);
    let u = c.guide_of("2", "3");
    let l2 = sh.line(b, u);
    let b3 = sh.meet(l1, l2);
    sh.hand_in(c.on("B", "3"), b3, Kind::Lines, true);
    let w3 = sh.rate(POLE, b3, (c.p("C"), c.p("B")));
    let vrel = sh.along(b, b3, u);
    let d = third(
        c,
        sh,
        how,
        (POLE, "C", None),
        (b3, "B", Some(c.on("B", "3"))),
        "D",
        (w3, None),
        ("3", None),
    );
    third(
        c,
        sh,
        how,
        (POLE, "C", None),
        (b3, "B", Some(c.on("B", "3"))),
        "S3",
        (w3, None),
        ("3", None),
    );
    ram(c, sh, d);
    Read {
        omega: vec![(c.link("3"), w3)],
        slide: vec![("B", vrel)],
    }
}

pub fn shaper_a(c: &Ctx, sh: &mut Sheet, how: How, v: &Values) {
    let w3 = v.w(c.link("3"));
    let b = c.crank_point(sh, ("A", "B"), "1", false);
    let (l1, n3) = c.rigid(sh, (POLE, "C"), "B", Some((w3, "3")));
    let u = c.guide_of("2", "3");
    // 2·ω2 × v_B3B2, ω2 = ω3: v_rel turned by 90° in the sense of ω.
    let k3 = sh.lay(b, super::hand::perp(u * v.slide("B")) * (2.0 * w3));
    sh.hand_in(c.coriolis("3"), k3, Kind::Coriolis, true);
    let l2 = sh.line(k3, u);
    let b3 = sh.meet(l1, l2);
    sh.hand_in(c.on("B", "3"), b3, Kind::Lines, true);
    let e3 = sh.rate(n3, b3, (c.p("C"), c.p("B")));
    let d = third(
        c,
        sh,
        how,
        (POLE, "C", None),
        (b3, "B", Some(c.on("B", "3"))),
        "D",
        (e3, Some(w3)),
        ("3", Some(v)),
    );
    third(
        c,
        sh,
        how,
        (POLE, "C", None),
        (b3, "B", Some(c.on("B", "3"))),
        "S3",
        (e3, Some(w3)),
        ("3", Some(v)),
    );
    ram(c, sh, d);
}
