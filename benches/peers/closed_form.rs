//! The hand-written closed form of the four-bar fixture
//! (`fixtures/four_bar.json`): the practical limit of a position with its
//! velocities and accelerations. Shared by `benches/speed.rs` (`limit/*`)
//! and `benches/peers/million.rs`; both check it against mechplan before
//! timing it.

/// The hand-written closed form of the four-bar fixture: crank O1A, coupler
/// AB with the coupler point M, rocker O3B. Everything is precomputed that
/// does not depend on the crank angle.
#[derive(Clone, Copy, Debug)]
pub struct FourBar {
    o1: [f64; 2],
    o3: [f64; 2],
    a: f64,
    b: f64,
    c: f64,
    /// M in the coupler's frame (x along AB), relative to A.
    m: [f64; 2],
    sign: f64,
    omega1: f64,
    eps1: f64,
}

/// Angles, ω, ε of coupler and rocker; place, velocity, acceleration of A,
/// B, M.
#[derive(Clone, Copy, Debug, Default)]
pub struct FourBarState {
    pub theta: [f64; 2],
    pub omega: [f64; 2],
    pub eps: [f64; 2],
    pub p: [[f64; 2]; 3],
    pub v: [[f64; 2]; 3],
    pub acc: [[f64; 2]; 3],
}

impl FourBar {
    /// From the four-bar fixture's scene (`fixtures/four_bar.json`).
    pub fn from_scene(v: &serde_json::Value) -> FourBar {
        let pt = |n: &str| {
            [
                v["points"][n][0].as_f64().unwrap(),
                v["points"][n][1].as_f64().unwrap(),
            ]
        };
        let len = |n: &str| v["lengths"][n].as_f64().unwrap();
        let (o1, a, b, m, o3) = (pt("O1"), pt("A"), pt("B"), pt("M"), pt("O3"));
        let ab = [b[0] - a[0], b[1] - a[1]];
        let l = ab[0].hypot(ab[1]);
        let e = [ab[0] / l, ab[1] / l];
        let am = [m[0] - a[0], m[1] - a[1]];
        // The branch: the side of B from the directed line A → O3.
        let ad = [o3[0] - a[0], o3[1] - a[1]];
        FourBar {
            o1,
            o3,
            a: len("O1-A"),
            b: len("A-B"),
            c: len("O3-B"),
            m: [am[0] * e[0] + am[1] * e[1], -am[0] * e[1] + am[1] * e[0]],
            sign: (ad[0] * ab[1] - ad[1] * ab[0]).signum(),
            omega1: v["input"]["omega"].as_f64().unwrap(),
            eps1: v["input"]["epsilon"].as_f64().unwrap(),
        }
    }

    #[inline(never)]
    pub fn solve(&self, phi: f64) -> FourBarState {
        let perp = |r: [f64; 2]| [-r[1], r[0]];
        let dot = |p: [f64; 2], q: [f64; 2]| p[0] * q[0] + p[1] * q[1];
        let (s, c) = phi.sin_cos();
        let ra = [self.a * c, self.a * s];
        let pa = [self.o1[0] + ra[0], self.o1[1] + ra[1]];
        // B = circle (A, b) ∩ circle (O3, c) on the sketch's side.
        let d = [self.o3[0] - pa[0], self.o3[1] - pa[1]];
        let l2 = dot(d, d);
        let l = l2.sqrt();
        let x = (self.b * self.b - self.c * self.c + l2) / (2.0 * l);
        let h = self.sign * (self.b * self.b - x * x).max(0.0).sqrt();
        let pb = [
            pa[0] + (d[0] * x - d[1] * h) / l,
            pa[1] + (d[1] * x + d[0] * h) / l,
        ];
        let r2 = [pb[0] - pa[0], pb[1] - pa[1]];
        let r3 = [pb[0] - self.o3[0], pb[1] - self.o3[1]];
        let e2 = [r2[0] / self.b, r2[1] / self.b];
        let rm = [
            self.m[0] * e2[0] - self.m[1] * e2[1],
            self.m[0] * e2[1] + self.m[1] * e2[0],
        ];
        let pm = [pa[0] + rm[0], pa[1] + rm[1]];
        // Velocities: ω2·k×r2 − ω3·k×r3 = −v_A.
        let w1 = self.omega1;
        let va = [-w1 * ra[1], w1 * ra[0]];
        let d23 = dot(perp(r2), r3);
        let w2 = -dot(va, r3) / d23;
        let w3 = -dot(va, r2) / d23;
        let vb = [va[0] - w2 * r2[1], va[1] + w2 * r2[0]];
        let vm = [va[0] - w2 * rm[1], va[1] + w2 * rm[0]];
        // Accelerations: ε2·k×r2 − ε3·k×r3 = −a_A + ω2²·r2 − ω3²·r3.
        let aa = [
            -self.eps1 * ra[1] - w1 * w1 * ra[0],
            self.eps1 * ra[0] - w1 * w1 * ra[1],
        ];
        let rhs = [
            -aa[0] + w2 * w2 * r2[0] - w3 * w3 * r3[0],
            -aa[1] + w2 * w2 * r2[1] - w3 * w3 * r3[1],
        ];
        let e2r = dot(rhs, r3) / d23;
        let e3r = dot(rhs, r2) / d23;
        let ab = [
            aa[0] - e2r * r2[1] - w2 * w2 * r2[0],
            aa[1] + e2r * r2[0] - w2 * w2 * r2[1],
        ];
        let am = [
            aa[0] - e2r * rm[1] - w2 * w2 * rm[0],
            aa[1] + e2r * rm[0] - w2 * w2 * rm[1],
        ];
        FourBarState {
            theta: [r2[1].atan2(r2[0]), r3[1].atan2(r3[0])],
            omega: [w2, w3],
            eps: [e2r, e3r],
            p: [pa, pb, pm],
            v: [va, vb, vm],
            acc: [aa, ab, am],
        }
    }
}
