#!/usr/bin/env python3
"""mpref -- an independent high-precision reference solver for mechplan scenes.

Written only from the scene format's description (docs/scene-format.md); it
shares no code and no formulas with mechplan.  mechplan solves group by group
(Assur groups, closed forms, plans); this solver knows nothing of groups:

  * the scene is read exactly: every JSON number is kept as its decimal text
    and becomes a Fraction (mm -> m exactly); degrees -> radians at the
    working precision;
  * every link's shape (local coordinates of its points) is built by the
    contract's rigid-shape rule at twice the working precision, deciding
    "on the line" exactly (Cayley-Menger determinant of the rational squared
    distances);
  * every moving link is a pose (x, y, theta); every revolute pair is two
    equations (the point seen from both links coincides), every prismatic
    pair two (relative angle fixed, the slider's point on the guide's line),
    the input one; Newton's method on the square system, the Jacobian by
    forward-mode automatic differentiation of the residual (no difference
    quotients anywhere);
  * the branch is the sketch's: a homotopy from the sketch's own shapes (at
    which the sketch's poses assemble exactly; a slider point's small gap
    from its guide in the sketch is carried as a fading term) to the data's
    shapes, then a continuation in the input through the positions in order,
    each leg the short way round (the other way if the short way meets a
    limit position), a driving slider straight;
  * continuation: an order-8 Taylor predictor of the solution curve, the step
    half the series' radius of convergence (root test), Newton corrector;
    a step is halved when the corrector fails, lands farther from the
    prediction than a tenth of the step, or changes the sign of det J (a
    singular position crossed: a gap jumped, or a neck crossed onto the
    other assembly).  A leg whose step falls below 10^-(dps-5) ends at a
    limit position: "no assembly";
  * transfer functions: Taylor coefficients of x(q) order by order,
    J c_k = -[t^k] Phi(x + c_1 t + ... + c_(k-1) t^(k-1), q + t), the
    right-hand sides exact in truncated Taylor arithmetic: x' = c_1,
    x'' = 2 c_2; then v = omega1 P', a = omega1^2 P'' + eps1 P'.

Accuracy (why the error is below 1e-25): every step above is exact up to
rounding at W digits, so the error of every reported number is a fixed
amplification of 10^-W (of the order kappa * 10^-W for positions and
first derivatives and kappa^2 * 10^-W for second ones, kappa the condition
number of the scaled Jacobian, reported as "cond").  The whole solution is
computed at W = dps + 20 and at W + 20 (and W + 40 ... while needed) until
two levels agree to 10^-(dps/2 + 5) at every position; the higher level is
reported, and "accuracy" is the difference of the last two levels (an upper
bound of the lower level's error; the reported level is ~20 digits better).
On the stress catalogue the largest "accuracy" is 5e-42 (kappa = 1e18).
--selftest checks closed forms (offset slider-crank, four-bar with a
coupler point) to 1e-30 and finite differences against the transfer
functions.

Usage:
  mpref.py SCENE.json [--dps 50] [--draws 4] [--seed 1] [--inputs a,b,...] -o OUT.json
  mpref.py --selftest
  mpref.py --compare OURS.json MECHPLAN.json         (worst agreement per kind)
  mpref.py --against-mechplan SCENE.json OURS.json [--mechplan BIN]
"""

import argparse
import hashlib
import json
import math
import os
import random
import subprocess
import sys
import tempfile
import time
from fractions import Fraction

from mpmath import mp, mpf

GUARD = 20                      # guard digits carried over --dps
EPS53 = Fraction(1, 2 ** 53)    # the unit roundoff of an IEEE double: "the rounding of the decimals"
EXACT = object()                # the homotopy parameter's value "the data exactly" (lambda = 1)


class Rejected(Exception):
    """The scene cannot be built (the reader would reject it)."""


class Datum(str):
    """A JSON number kept as its literal text, so that it is read exactly."""


def read_scene_text(text):
    return json.loads(text, parse_float=Datum, parse_int=Datum)


def to_mpf(fr):
    return mpf(fr.numerator) / fr.denominator


# ---------------------------------------------------------------------------
# Arithmetic: sparse first-order automatic differentiation (for Jacobians) and
# truncated Taylor series in one parameter (the path predictor; x', x'').

class AD:
    """value + sparse gradient {unknown index: d value / d unknown}."""
    __slots__ = ('v', 'g')

    def __init__(self, v, g):
        self.v, self.g = v, g

    def __add__(self, o):
        if isinstance(o, AD):
            g = dict(self.g)
            for k, c in o.g.items():
                g[k] = g[k] + c if k in g else c
            return AD(self.v + o.v, g)
        return AD(self.v + o, self.g)
    __radd__ = __add__

    def __neg__(self):
        return AD(-self.v, {k: -c for k, c in self.g.items()})

    def __sub__(self, o):
        return self + (-o)

    def __rsub__(self, o):
        return (-self) + o

    def __mul__(self, o):
        if isinstance(o, AD):
            g = {k: c * o.v for k, c in self.g.items()}
            for k, c in o.g.items():
                g[k] = g[k] + c * self.v if k in g else c * self.v
            return AD(self.v * o.v, g)
        return AD(self.v * o, {k: c * o for k, c in self.g.items()})
    __rmul__ = __mul__

    def cos_sin(self):
        c, s = mp.cos_sin(self.v)
        return (AD(c, {k: -s * d for k, d in self.g.items()}),
                AD(s, {k: c * d for k, d in self.g.items()}))


class Taylor:
    """A truncated Taylor series c[0] + c[1] t + ... + c[n] t^n in one parameter."""
    __slots__ = ('c',)

    def __init__(self, c):
        self.c = c

    def __add__(self, o):
        if isinstance(o, Taylor):
            return Taylor([a + b for a, b in zip(self.c, o.c)])
        return Taylor([self.c[0] + o] + self.c[1:])
    __radd__ = __add__

    def __neg__(self):
        return Taylor([-a for a in self.c])

    def __sub__(self, o):
        return self + (-o)

    def __rsub__(self, o):
        return (-self) + o

    def __mul__(self, o):
        if isinstance(o, Taylor):
            a, b = self.c, o.c
            return Taylor([sum(a[j] * b[k - j] for j in range(k + 1)) for k in range(len(a))])
        return Taylor([a * o for a in self.c])
    __rmul__ = __mul__

    def cos_sin(self):
        u = self.c
        c0, s0 = mp.cos_sin(u[0])
        cs, sn = [c0], [s0]
        for k in range(1, len(u)):
            sk = sum(j * u[j] * cs[k - j] for j in range(1, k + 1)) / k
            ck = -sum(j * u[j] * sn[k - j] for j in range(1, k + 1)) / k
            sn.append(sk)
            cs.append(ck)
        return Taylor(cs), Taylor(sn)


def series(value, rate, order):
    """value + rate t as a Taylor series of the given order."""
    return Taylor([value, rate] + [mpf(0)] * (order - 1))


def cos_sin(a):
    if isinstance(a, (AD, Taylor)):
        return a.cos_sin()
    if isinstance(a, int):
        return mp.cos(a), mp.sin(a)
    return mp.cos_sin(a)


# ---------------------------------------------------------------------------
# Small dense linear algebra at the working precision.

class Singular(Exception):
    pass


def lu_factor(A):
    n = len(A)
    A = [list(r) for r in A]
    perm = list(range(n))
    sign = 1
    for k in range(n):
        p = max(range(k, n), key=lambda i: abs(A[i][k]))
        if A[p][k] == 0:
            raise Singular()
        if A[p][k] < 0:
            sign = -sign
        if p != k:
            A[k], A[p] = A[p], A[k]
            perm[k], perm[p] = perm[p], perm[k]
            sign = -sign
        piv = A[k][k]
        for i in range(k + 1, n):
            m = A[i][k] / piv
            if m:
                A[i][k] = m
                Ai, Ak = A[i], A[k]
                for j in range(k + 1, n):
                    Ai[j] -= m * Ak[j]
            else:
                A[i][k] = m
    return A, perm, sign


def lu_solve(fac, b):
    """Solve with a factorization (LU, permutation, sign of the determinant)."""
    A, perm, _ = fac
    n = len(A)
    y = [b[perm[i]] for i in range(n)]
    for i in range(n):
        s = y[i]
        Ai = A[i]
        for j in range(i):
            s -= Ai[j] * y[j]
        y[i] = s
    for i in reversed(range(n)):
        s = y[i]
        Ai = A[i]
        for j in range(i + 1, n):
            s -= Ai[j] * y[j]
        y[i] = s / Ai[i]
    return y


# ---------------------------------------------------------------------------
# Reading the scene.

class Model:
    pass


def exact_reader(seed=None):
    """Returns num(path, datum) -> Fraction: the datum exactly, or (a draw of
    the data-sensitivity check) moved by half an ulp of its double, with a
    random sign fixed by (seed, path)."""
    def num(path, d):
        if not isinstance(d, Datum):
            raise Rejected(f"{path}: expected a number")
        fr = Fraction(str(d))
        if seed is None:
            return fr
        f = float(str(d))
        if not math.isfinite(f):
            raise Rejected(f"{path}: non-finite number")
        sign = 1 if random.Random(f"{seed}|{path}").random() < 0.5 else -1
        return fr + sign * Fraction(math.ulp(f)) / 2
    return num


def wrap_pi(a):
    """a into (-pi, pi]."""
    two_pi = 2 * mp.pi
    a = a - two_pi * mp.floor(a / two_pi + mpf(1) / 2)
    if a <= -mp.pi:
        a += two_pi
    if a > mp.pi:
        a -= two_pi
    return a


def build_model(scene, inputs_override, num):
    """Shapes, pairs, input and positions of a scene, read exactly (num)."""
    M = Model()
    if str(scene.get('mechplan')) != '1':
        raise Rejected("/mechplan: the format version must be 1")
    units = scene.get('units') or {}
    lu = units.get('length', 'm')
    au = units.get('angle', 'deg')
    if lu not in ('m', 'mm'):
        raise Rejected("/units/length: must be m or mm")
    if au not in ('deg', 'rad'):
        raise Rejected("/units/angle: must be deg or rad")
    M.len_unit = Fraction(1) if lu == 'm' else Fraction(1, 1000)
    M.ang_unit = au

    def length(path, d):
        return num(path, d) * M.len_unit

    def angle(path, d):
        v = to_mpf(num(path, d))
        return v * mp.pi / 180 if au == 'deg' else v

    # points (sketch), exact, in metres
    pts = scene.get('points')
    if not isinstance(pts, dict) or not pts:
        raise Rejected("/points: required")
    M.sketch = {}
    for name, xy in pts.items():
        if not isinstance(xy, list) or len(xy) != 2:
            raise Rejected(f"/points/{name}: expected [x, y]")
        M.sketch[name] = (length(f"points/{name}/0", xy[0]), length(f"points/{name}/1", xy[1]))
    M.points = list(pts.keys())
    xs = [p[0] for p in M.sketch.values()]
    ys = [p[1] for p in M.sketch.values()]
    diag2 = (max(xs) - min(xs)) ** 2 + (max(ys) - min(ys)) ** 2
    M.S_p = mp.sqrt(to_mpf(diag2)) if diag2 > 0 else mpf(1)

    # links
    links = scene.get('links')
    if not isinstance(links, dict) or '0' not in {str(k) for k in links}:
        raise Rejected("/links: required, with the frame \"0\"")
    M.links = {}
    for lid, body in links.items():
        ps = body.get('points') if isinstance(body, dict) else None
        if not isinstance(ps, list) or not ps:
            raise Rejected(f"/links/{lid}/points: required")
        for i, p in enumerate(ps):
            if p not in M.sketch:
                raise Rejected(f"/links/{lid}/points/{i}: unknown point \"{p}\"")
        if len(set(ps)) != len(ps):
            raise Rejected(f"/links/{lid}/points: a point repeated")
        M.links[str(lid)] = list(ps)
    M.order = list(M.links.keys())
    M.moving = [L for L in M.order if L != '0']
    for p in M.points:
        if not any(p in ps for ps in M.links.values()):
            raise Rejected(f"/points/{p}: belongs to no link")

    # lengths
    M.lengths = {}
    for key, d in (scene.get('lengths') or {}).items():
        parts = key.split('-')
        if len(parts) != 2 or parts[0] == parts[1] or any(p not in M.sketch for p in parts):
            raise Rejected(f"/lengths/{key}: expected \"P-Q\" of two different known points")
        v = length(f"lengths/{key}", d)
        if v < 0:
            raise Rejected(f"/lengths/{key}: negative")
        pair = frozenset(parts)
        if not any(pair <= set(ps) for ps in M.links.values()):
            raise Rejected(f"/lengths/{key}: the two points share no link")
        M.lengths[pair] = v

    shapes(M)

    # sliders and guide lines
    M.pairs = []
    for k, sl in enumerate(scene.get('sliders') or []):
        M.pairs.append(read_slider(M, k, sl, length, angle))
    sketch_pose_of_sliders(M)
    for pr in M.pairs:
        finish_line(M, pr)
    for L in M.moving:
        if len(M.links[L]) == 1 and not any(pr['slider'] == L for pr in M.pairs):
            raise Rejected(f"/links/{L}: a one-point link must be the slider of a prismatic pair")

    # revolute pairs: a point in k links gives k-1 pairs
    M.revolutes = []
    for p in M.points:
        ls = [L for L in M.order if p in M.links[L]]
        for L2 in ls[1:]:
            M.revolutes.append((p, ls[0], L2))

    read_input(M, scene, num, length, angle)
    read_positions(M, scene, inputs_override, num, length, angle)

    n_unknowns = 3 * len(M.moving)
    n_equations = 2 * len(M.revolutes) + 2 * len(M.pairs) + 1
    if n_unknowns != n_equations:
        raise Rejected(f"/links: the mobility is {n_unknowns - n_equations + 1}, not the 1 of one input "
                       f"({len(M.moving)} moving links, {len(M.revolutes)} revolute and "
                       f"{len(M.pairs)} prismatic pairs)")
    M.index = {L: 3 * i for i, L in enumerate(M.moving)}
    sketch_start(M)
    return M


def shapes(M):
    """Local coordinates of every link's points: M.dat (the data's shape, by
    the rigid-shape rule) and M.sk (the sketch's own shape), and the sketch
    pose M.th_sk / M.org_sk of every link with two or more points."""
    M.dat, M.sk, M.th_sk, M.org_sk = {}, {}, {}, {}
    sk = {p: (to_mpf(x), to_mpf(y)) for p, (x, y) in M.sketch.items()}
    M.sk_global = sk
    for L in M.order:
        ps = M.links[L]
        if L == '0':
            M.dat[L] = {p: sk[p] for p in ps}
            M.sk[L] = dict(M.dat[L])
            M.th_sk[L], M.org_sk[L] = mpf(0), (mpf(0), mpf(0))
            for pair, v in M.lengths.items():
                if pair <= set(ps):
                    a, b = tuple(pair)
                    d = mp.sqrt(to_mpf(sketch_d2(M, a, b)))
                    if abs(d - to_mpf(v)) > mpf('1e-9') * max(to_mpf(v), d):
                        raise Rejected(f"/lengths/{a}-{b}: frame points {a}, {b} are {mp.nstr(d, 17)} m apart, "
                                       f"not {mp.nstr(to_mpf(v), 17)}")
            continue
        if len(ps) == 1:
            M.dat[L] = {ps[0]: (mpf(0), mpf(0))}
            M.sk[L] = {ps[0]: (mpf(0), mpf(0))}
            continue
        with mp.extradps(mp.dps):
            shape_of_link(M, L, ps, sk)
    for L in M.order:
        for P in M.dat[L]:
            M.dat[L][P] = (+M.dat[L][P][0], +M.dat[L][P][1])
            M.sk[L][P] = (+M.sk[L][P][0], +M.sk[L][P][1])


def sketch_d2(M, a, b):
    (ax, ay), (bx, by) = M.sketch[a], M.sketch[b]
    return (bx - ax) ** 2 + (by - ay) ** 2


def shape_of_link(M, L, ps, sk):
    P0, P1 = ps[0], ps[1]
    x0, y0 = sk[P0]
    th = mp.atan2(sk[P1][1] - y0, sk[P1][0] - x0)
    if sketch_d2(M, P0, P1) == 0:
        raise Rejected(f"/links/{L}/points: the first two points coincide in the sketch (no base)")
    M.th_sk[L], M.org_sk[L] = th, (x0, y0)
    c, s = mp.cos(th), mp.sin(th)

    def sketch_local(p):
        dx, dy = sk[p][0] - x0, sk[p][1] - y0
        return (c * dx + s * dy, -s * dx + c * dy)
    M.sk[L] = {p: sketch_local(p) for p in ps}

    loc = {}
    exact_d2 = {}                      # exact squared distances in the built shape
    untainted = set()                  # points placed where the sketch has them
    base = frozenset((P0, P1))
    if base in M.lengths:
        d01sq = M.lengths[base] ** 2
        tainted = True
    else:
        d01sq = sketch_d2(M, P0, P1)
        tainted = False
        untainted.update((P0, P1))
    if d01sq == 0:
        raise Rejected(f"/lengths/{P0}-{P1}: the base of link {L} has zero length")
    loc[P0] = (mpf(0), mpf(0))
    loc[P1] = (mp.sqrt(to_mpf(d01sq)), mpf(0))
    exact_d2[base] = d01sq

    def known_d2(a, b):
        k = frozenset((a, b))
        if k in exact_d2:
            return exact_d2[k]
        if a in untainted and b in untainted:
            return sketch_d2(M, a, b)
        return None

    for k in range(2, len(ps)):
        P = ps[k]
        earlier = ps[:k]
        refs = ([R for R in earlier if frozenset((P, R)) in M.lengths] +
                [R for R in earlier if frozenset((P, R)) not in M.lengths])
        R1, R2 = refs[0], refs[1]
        uses = frozenset((P, R1)) in M.lengths or frozenset((P, R2)) in M.lengths
        if not tainted and not uses:
            loc[P] = M.sk[L][P]              # the sketch's own position in the link's frame
            untainted.add(P)
            continue
        tainted = True
        d1sq = M.lengths.get(frozenset((P, R1)), None)
        d1sq = d1sq ** 2 if d1sq is not None else sketch_d2(M, P, R1)
        d2sq = M.lengths.get(frozenset((P, R2)), None)
        d2sq = d2sq ** 2 if d2sq is not None else sketch_d2(M, P, R2)
        (r1x, r1y), (r2x, r2y) = loc[R1], loc[R2]
        bsq = known_d2(R1, R2)
        if bsq is not None:
            # 16 * area^2 exactly (Cayley-Menger); exact zero means exactly on the line
            N = 4 * d1sq * bsq - (d1sq - d2sq + bsq) ** 2
            D = max(d1sq, d2sq, bsq)
            tol = 32 * EPS53 * D * D
            b = mp.sqrt(to_mpf(bsq))
            a_num = to_mpf(d1sq - d2sq + bsq)
            Nm = to_mpf(N)
        else:
            bsqm = (r2x - r1x) ** 2 + (r2y - r1y) ** 2
            b = mp.sqrt(bsqm)
            d1m, d2m = to_mpf(d1sq), to_mpf(d2sq)
            a_num = d1m - d2m + bsqm
            Nm = 4 * d1m * bsqm - a_num ** 2
            N = Nm
            D = max(d1m, d2m, bsqm)
            tol = 32 * to_mpf(EPS53) * D * D
        if b == 0:
            raise Rejected(f"/links/{L}: {P} is placed from {R1} and {R2}, which coincide")
        # the sketch's side of the line R1 R2, exactly
        (ax, ay), (bx, by), (px, py) = M.sketch[R1], M.sketch[R2], M.sketch[P]
        cross = (bx - ax) * (py - ay) - (by - ay) * (px - ax)
        C = max(abs(v) for v in (ax, ay, bx, by, px, py))
        on_line_sketch = cross * cross <= (8 * EPS53 * C) ** 2 * sketch_d2(M, R1, R2)
        if abs(N) <= tol and (on_line_sketch or N <= 0):
            h = mpf(0)                      # the data put P on the line of R1, R2
        elif N < 0:
            raise Rejected(f"/links/{L}: {P} cannot be placed: its distances to {R1} and {R2} "
                           f"make no triangle")
        elif on_line_sketch:
            raise Rejected(f"/points/{P}: drawn on the line of {R1} and {R2} while its distances "
                           f"make a triangle (its side cannot be read off the sketch)")
        else:
            h = mp.sqrt(Nm) / (2 * b) * (1 if cross > 0 else -1)
        a = a_num / (2 * b)
        ux, uy = (r2x - r1x) / b, (r2y - r1y) / b
        loc[P] = (r1x + a * ux - h * uy, r1y + a * uy + h * ux)
        exact_d2[frozenset((P, R1))] = d1sq
        exact_d2[frozenset((P, R2))] = d2sq
    M.dat[L] = loc
    # every length given for this link must hold in the shape built
    for pair, v in M.lengths.items():
        if pair <= set(ps):
            a, b2 = tuple(pair)
            d = mp.sqrt((loc[a][0] - loc[b2][0]) ** 2 + (loc[a][1] - loc[b2][1]) ** 2)
            if abs(d - to_mpf(v)) > mpf('1e-9') * max(to_mpf(v), mpf('1e-9') * M.S_p):
                raise Rejected(f"/lengths/{a}-{b2}: does not hold in link {L} as built "
                               f"({mp.nstr(d, 17)} m): the link is over-determined")


def read_slider(M, k, sl, length, angle):
    path = f"/sliders/{k}"
    S, G, P = str(sl.get('slider')), str(sl.get('guide')), sl.get('point')
    if S not in M.links or S == '0':
        raise Rejected(f"{path}/slider: not a moving link")
    if G not in M.links or G == S:
        raise Rejected(f"{path}/guide: unknown or the slider itself")
    if P not in M.links[S]:
        raise Rejected(f"{path}/point: not a point of the slider link")
    line = sl.get('line') or {}
    pr = {'slider': S, 'guide': G, 'point': P, 'path': path}
    thr = line.get('through')
    if isinstance(thr, str) and not isinstance(thr, Datum):
        if thr not in M.links[G]:
            raise Rejected(f"{path}/line/through: not a point of the guide link")
        pr['through'] = thr
    elif isinstance(thr, list) and len(thr) == 2:
        if G != '0':
            raise Rejected(f"{path}/line/through: coordinates only on the frame")
        pr['through'] = (to_mpf(length(f"sliders/{k}/line/through/0", thr[0])),
                         to_mpf(length(f"sliders/{k}/line/through/1", thr[1])))
    else:
        raise Rejected(f"{path}/line/through: required")
    if ('angle' in line) == ('along' in line):
        raise Rejected(f"{path}/line: exactly one of angle, along")
    if 'angle' in line:
        pr['angle'] = angle(f"sliders/{k}/line/angle", line['angle'])
    else:
        al = line['along']
        if not (isinstance(al, list) and len(al) == 2 and all(q in M.links[G] for q in al) and al[0] != al[1]):
            raise Rejected(f"{path}/line/along: two points of the guide link")
        pr['along'] = tuple(al)
    pr['offset'] = to_mpf(length(f"sliders/{k}/line/offset", line['offset'])) if 'offset' in line else mpf(0)
    return pr


def sketch_pose_of_sliders(M):
    """The sketch orientation of a one-point link is its guide line's direction."""
    state = {}

    def th(L):
        if L in M.th_sk:
            return M.th_sk[L]
        if state.get(L) == 'busy':
            raise Rejected(f"/links/{L}: one-point links guide each other in a cycle")
        state[L] = 'busy'
        pr = next((p for p in M.pairs if p['slider'] == L), None)
        if pr is None:
            raise Rejected(f"/links/{L}: a one-point link must be the slider of a prismatic pair")
        thG = th(pr['guide'])
        M.th_sk[L] = thG + line_alpha_sketch(M, pr, thG)
        P = M.links[L][0]
        M.org_sk[L] = M.sk_global[P]
        pr['defines_angle'] = True
        return M.th_sk[L]
    for L in M.moving:
        th(L)


def line_alpha_sketch(M, pr, thG):
    if 'angle' in pr:
        return pr['angle'] - thG
    Q, R = pr['along']
    (qx, qy), (rx, ry) = M.sk_global[Q], M.sk_global[R]
    if (qx, qy) == (rx, ry):
        raise Rejected(f"{pr['path']}/line/along: the two points coincide")
    return mp.atan2(ry - qy, rx - qx) - thG


def finish_line(M, pr):
    """The guide line in the guide's frame, for the sketch's and the data's shape."""
    G = pr['guide']
    thG = M.th_sk[G]
    a_sk = line_alpha_sketch(M, pr, thG)
    if 'angle' in pr:
        a_dat = a_sk
    else:
        Q, R = pr['along']
        (qx, qy), (rx, ry) = M.dat[G][Q], M.dat[G][R]
        if (qx, qy) == (rx, ry):
            raise Rejected(f"{pr['path']}/line/along: the two points coincide in the link's shape")
        a_dat = a_sk + wrap_pi(mp.atan2(ry - qy, rx - qx) - a_sk)
    pr['alpha_sk'], pr['alpha_dat'] = a_sk, a_dat
    t = pr['through']
    if isinstance(t, str):
        pr['c_sk'], pr['c_dat'] = M.sk[G][t], M.dat[G][t]
    else:
        pr['c_sk'] = pr['c_dat'] = t
    # the slider's angle relative to the line, as drawn (0 for the pair that
    # defines a one-point slider's angle)
    pr['delta'] = mpf(0) if pr.get('defines_angle') else M.th_sk[pr['slider']] - thG - a_sk


def read_input(M, scene, num, length, angle):
    inp = scene.get('input')
    if isinstance(inp, list):
        raise Rejected("/input: several inputs are not supported by this reference")
    if not isinstance(inp, dict):
        raise Rejected("/input: required")
    L = str(inp.get('link'))
    if L not in M.moving:
        raise Rejected("/input/link: not a moving link")
    M.input_link = L
    if inp.get('slider') is True:
        M.kind = 'slider'
        pr = next((p for p in M.pairs if p['slider'] == L), None)
        if pr is None:
            raise Rejected("/input/slider: the link is the slider of no prismatic pair")
        M.input_pair = pr
        M.q1 = to_mpf(length("input/v", inp['v'])) if 'v' in inp else mpf(0)
        M.q2 = to_mpf(length("input/a", inp['a'])) if 'a' in inp else mpf(0)
        M.default_input = inp.get('s', Datum('0'))
    else:
        M.kind = 'crank'
        piv = inp.get('pivot')
        ps = M.links[L]
        if piv not in ps[:2] or len(ps) < 2:
            raise Rejected("/input/pivot: must be one of the crank's first two points")
        if piv not in M.links['0']:
            raise Rejected("/input/pivot: must be a frame point")
        M.beta = mpf(0) if piv == ps[0] else mp.pi      # the ray pivot -> other in the link's frame
        if 'omega' in inp:
            M.q1 = to_mpf(Fraction(str(inp['omega'])))
        elif 'rpm' in inp:
            M.q1 = to_mpf(Fraction(str(inp['rpm']))) * 2 * mp.pi / 60
        else:
            raise Rejected("/input/omega: omega or rpm required")
        M.q2 = to_mpf(Fraction(str(inp['epsilon']))) if 'epsilon' in inp else mpf(0)
        if 'angle' not in inp:
            raise Rejected("/input/angle: required")
        M.default_input = inp['angle']


def read_positions(M, scene, override, num, length, angle):
    pos = scene.get('positions')
    if override is not None:
        texts = [Datum(t.strip()) for t in override.split(',') if t.strip()]
    elif pos is None:
        texts = [M.default_input]
    elif 'count' in pos:
        # n equal steps of a revolution from the extreme position of the
        # output that begins the working stroke: found after assembly
        # (`working_stroke`), the input values then known.
        if M.kind != 'crank':
            raise Rejected("/positions/count: equal steps over a revolution need a crank input")
        if 'output' not in pos:
            raise Rejected("/positions/count: this reference needs the output link named "
                           "(positions.output); it does not find Assur groups")
        out = str(pos['output'])
        if out not in M.moving:
            raise Rejected("/positions/output: not a moving link")
        M.count = (int(pos['count']), out)
        M.input_angle = angle("input/angle", M.default_input)
        M.targets = []
        M.input_texts = []
        return
    elif 'values' in pos:
        raise Rejected("/positions/values: several inputs are not supported by this reference")
    elif M.kind == 'crank' and 'angles' in pos:
        texts = pos['angles']
    elif M.kind == 'slider' and 's' in pos:
        texts = pos['s']
    else:
        raise Rejected("/positions: angles for a crank, s for a driving slider")
    M.input_texts = [str(t) for t in texts]
    if M.kind == 'crank':
        M.targets = [angle(f"positions/{k}", t) for k, t in enumerate(texts)]
    else:
        M.targets = [to_mpf(length(f"positions/{k}", t)) for k, t in enumerate(texts)]


# ---------------------------------------------------------------------------
# The constraint system.

def local(M, L, P, lam):
    d = M.dat[L][P]
    if lam is EXACT:
        return d
    s = M.sk[L][P]
    return (s[0] + lam * (d[0] - s[0]), s[1] + lam * (d[1] - s[1]))


def line_in_world(M, pose, pr, lam):
    """(psi, cx, cy): the guide line's global direction and a point on it."""
    G = pr['guide']
    xG, yG, cG, sG, thG = pose[G]
    if lam is EXACT:
        alpha, (tx, ty) = pr['alpha_dat'], pr['c_dat']
    else:
        alpha = pr['alpha_sk'] + lam * (pr['alpha_dat'] - pr['alpha_sk'])
        (ax, ay), (bx, by) = pr['c_sk'], pr['c_dat']
        tx, ty = ax + lam * (bx - ax), ay + lam * (by - ay)
    ca, sa = cos_sin(alpha)
    off = pr['offset']
    lx, ly = tx - off * sa, ty + off * ca
    return thG + alpha, xG + cG * lx - sG * ly, yG + sG * lx + cG * ly


def poses(M, X):
    pose = {'0': (0, 0, 1, 0, 0)}
    for L in M.moving:
        i = M.index[L]
        c, s = cos_sin(X[i + 2])
        pose[L] = (X[i], X[i + 1], c, s, X[i + 2])
    return pose


def world(pose, p, L):
    x, y, c, s, _ = pose[L]
    return (x + c * p[0] - s * p[1], y + s * p[0] + c * p[1])


def residual(M, X, lam, q):
    """Phi(X; lam, q): revolute pairs, prismatic pairs, the input.  lam is the
    homotopy parameter sketch shapes (0) -> data shapes (EXACT); q the input
    (crank: the angle of the ray pivot -> other; slider: the along-line
    coordinate of its point)."""
    pose = poses(M, X)
    F = []
    for P, L1, L2 in M.revolutes:
        a = world(pose, local(M, L1, P, lam), L1)
        b = world(pose, local(M, L2, P, lam), L2)
        F.append(a[0] - b[0])
        F.append(a[1] - b[1])
    for pr in M.pairs:
        S, G = pr['slider'], pr['guide']
        alpha = pr['alpha_dat'] if lam is EXACT else pr['alpha_sk'] + lam * (pr['alpha_dat'] - pr['alpha_sk'])
        F.append(pose[S][4] - pose[G][4] - alpha - pr['delta'])
        psi, cx, cy = line_in_world(M, pose, pr, lam)
        cp, sp = cos_sin(psi)
        gx, gy = world(pose, local(M, S, pr['point'], lam), S)
        gap = cp * (gy - cy) - sp * (gx - cx)
        if lam is not EXACT:
            gap = gap - (1 - lam) * pr['r0']
        F.append(gap)
    if M.kind == 'crank':
        F.append(pose[M.input_link][4] + M.beta - q)
    else:
        pr = M.input_pair
        psi, cx, cy = line_in_world(M, pose, pr, lam)
        cp, sp = cos_sin(psi)
        gx, gy = world(pose, local(M, pr['slider'], pr['point'], lam), pr['slider'])
        F.append(cp * (gx - cx) + sp * (gy - cy) - q)
    return F


def sketch_start(M):
    """The sketch's poses, the sketch's gaps of slider points from their
    lines (r0, faded out by the homotopy) and the input's sketch value."""
    X = []
    for L in M.moving:
        X += [M.org_sk[L][0], M.org_sk[L][1], M.th_sk[L]]
    M.x_sketch = X
    pose = poses(M, X)
    for pr in M.pairs:
        psi, cx, cy = line_in_world(M, pose, pr, mpf(0))
        px, py = M.sk_global[pr['point']]
        pr['r0'] = mp.cos(psi) * (py - cy) - mp.sin(psi) * (px - cx)
        if abs(pr['r0']) > mpf('1e-3') * M.S_p:
            raise Rejected(f"{pr['path']}/point: {pr['point']} is {mp.nstr(abs(pr['r0']), 6)} m off its "
                           f"guide line in the sketch (more than 0.1 % of the sketch)")
    if M.kind == 'crank':
        M.q_sketch = (M.th_sk[M.input_link] + M.beta, M.th_sk[M.input_link] + M.beta)
    else:
        pr = M.input_pair
        px, py = M.sk_global[pr['point']]
        vals = []
        for lam in (mpf(0), EXACT):
            psi, cx, cy = line_in_world(M, pose, pr, lam)
            vals.append(mp.cos(psi) * (px - cx) + mp.sin(psi) * (py - cy))
        M.q_sketch = tuple(vals)      # (sketch shapes, data shapes): where s = 0


def input_q(M, target):
    """The residual's q for a position's input value (a slider's s is from the sketch)."""
    return target if M.kind == 'crank' else M.q_sketch[1] + target


# ---------------------------------------------------------------------------
# Newton, continuation.

def scaled_norm(M, d):
    m = mpf(0)
    for L in M.moving:
        i = M.index[L]
        m = max(m, abs(d[i]) / M.S_p, abs(d[i + 1]) / M.S_p, abs(d[i + 2]))
    return m


def jacobian(M, x, lam, q):
    X = [AD(v, {i: mpf(1)}) for i, v in enumerate(x)]
    F = residual(M, X, lam, q)
    n = len(x)
    J = [[mpf(0)] * n for _ in range(n)]
    f = []
    for r, e in enumerate(F):
        if isinstance(e, AD):
            f.append(e.v)
            for k, c in e.g.items():
                J[r][k] = c
        else:
            f.append(mpf(e))
    return f, J


def newton(M, x, lam, q, maxit=14):
    """Newton's method until its (scaled) step is below 10^-(W-5), or stops
    shrinking at a noise floor below 10^-(W-15) (an ill-conditioned Jacobian
    amplifies the rounding of the residual: kappa * 10^-W)."""
    tol = mpf(10) ** (-(mp.dps - 5))
    floor = mpf(10) ** (-(mp.dps - 15))
    prev = None
    first = None
    for it in range(maxit):
        f, J = jacobian(M, x, lam, q)
        try:
            d = lu_solve(lu_factor(J), [-v for v in f])
        except Singular:
            return x, False, first
        nd = scaled_norm(M, d)
        if first is None:
            first = nd
        if prev is not None and nd > prev / 2 and it >= 2:
            # not contracting: converged to the noise floor, or no solution here
            return x, prev <= floor, first
        x = [a + b for a, b in zip(x, d)]
        if nd <= tol:
            return x, True, first
        prev = nd
    return x, prev is not None and prev <= floor, first


def taylor_coefficients(M, x, fac, lam, dlam, q, dq, order):
    """The Taylor coefficients c_1 ... c_order of the solution curve x(t) of
    Phi(x; lam + t dlam, q + t dq) = 0 at x (lam EXACT: the data's shapes).
    Order by order: J c_k = -[t^k] Phi(x_0 + ... + c_(k-1) t^(k-1)), every
    right-hand side exact (truncated Taylor arithmetic), J factored once."""
    coeffs = [list(x)]
    for k in range(1, order + 1):
        X = [Taylor([coeffs[j][i] for j in range(k)] + [mpf(0)]) for i in range(len(x))]
        lt = EXACT if lam is EXACT else series(lam, dlam, k)
        F = residual(M, X, lt, series(q, dq, k))
        coeffs.append(lu_solve(fac, [-e.c[k] for e in F]))
    return coeffs


class PathBroken(Exception):
    pass


ORDER = 8      # the Taylor predictor's order
RHO = mpf(1) / 2   # the step as a fraction of the estimated radius of convergence


def follow_path(M, x, lam0, lam1, q0, q1):
    """Continue the solution x from (lam0, q0) to (lam1, q1), the parameters
    affine in s in [0, 1].

    Predictor: the solution curve's Taylor polynomial of order 8 in s.
    Step: half the radius of convergence of that series, estimated by the
    root test min_k (|c_1| / |c_k|)^(1/(k-1)), k = 2..8.  The radius is the
    distance to the nearest singularity of the curve, real (a limit
    position, where the path ends) or complex (a narrow neck between two
    assemblies, at a distance of about the neck's width): so a step never
    jumps over a limit position, nor across a neck to the other assembly,
    nor over a small gap where the mechanism does not assemble.
    Corrector: Newton; the step is halved when it fails, or lands farther
    from the prediction than a tenth of the step.
    Raises PathBroken when the step falls below 10^-(dps-5): a limit
    position before the leg's end (the mechanism does not assemble beyond)."""
    exact_leg = lam0 is EXACT
    dlam = None if exact_leg else lam1 - lam0
    dq = q1 - q0

    def par(s):
        return (EXACT if exact_leg else lam0 + s * dlam), q0 + s * dq

    hmin = mpf(10) ** (-(mp.dps - GUARD - 5))
    floor = mpf(10) ** (-(mp.dps - 10))
    s = mpf(0)
    steps = 0
    try:
        fac = lu_factor(jacobian(M, x, *par(s))[1])
    except Singular:
        raise PathBroken("singular Jacobian at the start of the leg")
    orientation = fac[2]
    while s < 1:
        lam, q = par(s)
        cs = taylor_coefficients(M, x, fac, lam, dlam, q, dq, ORDER)
        norms = [scaled_norm(M, c) for c in cs]
        radius = mp.inf
        if norms[1] > 0:
            for k in range(2, ORDER + 1):
                if norms[k] > 0:
                    radius = min(radius, (norms[1] / norms[k]) ** (mpf(1) / (k - 1)))
        h = min(1 - s, RHO * radius)
        while True:
            if h < hmin:
                raise PathBroken(f"no assembly beyond s = {mp.nstr(s, 20)} of the leg "
                                 f"(q = {mp.nstr(par(s)[1], 20)})")
            xp = [sum(cs[k][i] * h ** k for k in range(ORDER + 1)) for i in range(len(x))]
            lam_n, q_n = par(s + h) if s + h < 1 else par(mpf(1))
            xn, ok, first = newton(M, xp, lam_n, q_n, maxit=10)
            if ok:
                move = scaled_norm(M, [a - b for a, b in zip(xp, x)])
                err = scaled_norm(M, [a - b for a, b in zip(xn, xp)])
                if err <= move / 10 + floor:
                    # the sign of det J is constant along a path of regular
                    # positions: a change means the step crossed a singular
                    # position (jumped a gap, or across a neck onto the other
                    # assembly)
                    try:
                        fac_n = lu_factor(jacobian(M, xn, lam_n, q_n)[1])
                        if fac_n[2] == orientation:
                            break
                    except Singular:
                        pass
            h = h / 2
        s = s + h if s + h < 1 else mpf(1)
        x, fac = xn, fac_n
        steps += 1
    return x, steps


def assemble(M):
    """From the sketch's poses (exact for the sketch's shapes) to the data's
    shapes at the sketch's input: the assembly the sketch shows."""
    x, ok, _ = newton(M, list(M.x_sketch), mpf(0), M.q_sketch[0])
    if not ok:
        raise Rejected("the sketch's own shapes do not assemble at the sketch's poses (a singular sketch)")
    try:
        x, _ = follow_path(M, x, mpf(0), mpf(1), M.q_sketch[0], M.q_sketch[1])
    except PathBroken as e:
        raise PathBroken(f"the data do not assemble at the sketch's input on the sketch's branch: "
                         f"the homotopy sketch shapes -> data shapes meets a limit ({e}; s = lambda)")
    x, ok, _ = newton(M, x, EXACT, M.q_sketch[1])
    if not ok:
        raise PathBroken("the data do not assemble at the sketch's input (Newton did not converge)")
    return x


def leg_target(M, q_prev, target, way):
    """The input value a leg ends at: a crank angle the short way round (or
    the other way), a slider straight."""
    q = input_q(M, target)
    if M.kind == 'slider':
        return q
    two_pi = 2 * mp.pi
    d = q - q_prev
    d = d - two_pi * mp.floor(d / two_pi + mpf(1) / 2)       # (-pi, pi]
    if d == -mp.pi or (abs(abs(d) - mp.pi) < mpf(10) ** (-(mp.dps - 5)) and M.q1 * d < 0):
        d = -d
    if way == 'long':
        d = d - two_pi if d > 0 else d + two_pi
    return q_prev + d


def output_series(M, x, q):
    """The output of `positions.count` at the solution x of input q: its
    coordinate (a frame slider's slide along its guide, else the link's
    angle, continuous along the path), and its first and second
    derivatives in q (from the solution curve's Taylor coefficients)."""
    _, out = M.count
    f, J = jacobian(M, x, EXACT, q)
    x0, c1, c2 = taylor_coefficients(M, x, lu_factor(J), EXACT, None, q, mpf(1), 2)
    X = [Taylor([v, d, dd]) for v, d, dd in zip(x, c1, c2)]
    pr = next((p for p in M.pairs if p['slider'] == out and p['guide'] == '0'), None)
    if pr is None:
        y = X[M.index[out] + 2]
    else:
        pose = poses(M, X)
        psi, cx, cy = line_in_world(M, pose, pr, EXACT)
        cp, sp = cos_sin(psi)
        gx, gy = world(pose, local(M, out, pr['point'], EXACT), out)
        y = (gx - cx) * cp + (gy - cy) * sp
    return y.c[0], y.c[1], 2 * y.c[2]


def step_to(M, x, q0, q1):
    """The solution at q1 followed from the solution x at q0."""
    if q1 == q0:
        return x
    x, _ = follow_path(M, x, EXACT, EXACT, q0, q1)
    x, ok, _ = newton(M, x, EXACT, q1)
    if not ok:
        raise PathBroken("the Newton polish did not converge")
    return x


def extreme_root(M, qa, xa, ta, qb, tb):
    """The root of the output's first derivative between qa and qb (ta, tb
    its values there, of opposite signs; xa the solution at qa): Newton
    safeguarded by bisection, to 10^-(W-25) of the input (the solutions'
    own noise floor, amplified near a toggle, is far below the digits
    reported and far above 10^-W)."""
    tol = mpf(10) ** (-(mp.dps - 25))
    q, x, t = qa, xa, ta
    for _ in range(200):
        y, t, dt = output_series(M, x, q)
        if t == 0:
            return q, x, y
        if (t > 0) == (ta > 0):
            qa, ta = q, t
        else:
            qb, tb = q, t
        nxt = q - t / dt if dt != 0 else None
        lo, hi = min(qa, qb), max(qa, qb)
        if nxt is None or not (lo < nxt < hi):
            nxt = (qa + qb) / 2
        if abs(nxt - q) <= tol or hi - lo <= tol:
            x = step_to(M, x, q, nxt)
            y, _, _ = output_series(M, x, nxt)
            return nxt, x, y
        x, q = step_to(M, x, q, nxt), nxt
    raise PathBroken("the extreme position did not converge")


SCAN = 360     # legs over the revolution where the output's extremes are bracketed


def working_stroke(M, x0, hint=None):
    """The crank angle that begins the working stroke of the output (the
    format's rule: of the two strokes between the output's smallest and
    largest coordinate, the one taking the larger crank angle, in the sense
    of omega; at a tie the one starting at the smallest coordinate; the
    input's angle when the output turns fully).  From the assembled
    solution x0 at the sketch's input, the revolution scanned in SCAN legs
    in the sense of omega, each sign change of the output's first
    derivative refined by Newton.  `hint`: a nearby root (a sensitivity
    draw of the data) refined directly."""
    q0 = M.q_sketch[1]
    sense = 1 if M.q1 >= 0 else -1
    two_pi = 2 * mp.pi
    if hint is not None:
        h = mpf('1e-6')
        xa = step_to(M, x0, q0, hint - h)
        _, ta, _ = output_series(M, xa, hint - h)
        xb = step_to(M, xa, hint - h, hint + h)
        _, tb, _ = output_series(M, xb, hint + h)
        if (ta > 0) != (tb > 0):
            return extreme_root(M, hint - h, xa, ta, hint + h, tb)[0]
    extremes = []
    x, q = x0, q0
    y, t, _ = output_series(M, x, q)
    for k in range(1, SCAN + 1):
        qn = q0 + sense * two_pi * k / SCAN
        xn = step_to(M, x, q, qn)
        yn, tn, _ = output_series(M, xn, qn)
        if t == 0:
            extremes.append((q, y))
        elif (t > 0) != (tn > 0) and tn != 0:
            r, _, yr = extreme_root(M, q, x, t, qn, tn)
            extremes.append((r, yr))
        x, q, y, t = xn, qn, yn, tn
    if len(extremes) < 2:
        return M.input_angle
    lo = min(extremes, key=lambda e: e[1])
    hi = max(extremes, key=lambda e: e[1])
    d = (sense * (hi[0] - lo[0])) % two_pi
    return lo[0] if d >= two_pi - d else hi[0]


def count_targets(M, start):
    n, _ = M.count
    sense = 1 if M.q1 >= 0 else -1
    two_pi = 2 * mp.pi
    M.start = start
    M.targets = [(start + sense * two_pi * k / n) % two_pi for k in range(n)]
    M.input_texts = [mp.nstr(t * 180 / mp.pi, 20) for t in M.targets]


def run_positions(M, legs=None, hint=None):
    """Assemble, then the positions in order.  legs: the ways ('short',
    'long', 'straight') to re-use (a sensitivity draw), else chosen here.
    `positions.count`: the working stroke's start found first (`hint`: the
    exact data's, for a draw).  Returns a list of (status, x, q, way, note)."""
    try:
        x = assemble(M)
        if getattr(M, 'count', None):
            count_targets(M, working_stroke(M, x, hint))
    except PathBroken as e:
        n = M.count[0] if getattr(M, 'count', None) else len(M.targets)
        return [('no assembly', None, None, None, str(e))] * n
    q_prev = M.q_sketch[1]
    out = []
    broken = None
    for k, target in enumerate(M.targets):
        if broken is not None:
            out.append(('no assembly', None, None, None, f"path broken at position {broken}"))
            continue
        ways = [legs[k]] if legs is not None else (['straight'] if M.kind == 'slider' else ['short', 'long'])
        done = False
        notes = []
        for way in ways:
            if way is None:
                break
            qt = leg_target(M, q_prev, target, way)
            try:
                xn, steps = follow_path(M, x, EXACT, EXACT, q_prev, qt)
                xn, ok, _ = newton(M, xn, EXACT, qt)
                if not ok:
                    raise PathBroken("the final Newton polish did not converge")
            except PathBroken as e:
                notes.append(f"{way}: {e}")
                continue
            x, q_prev = xn, qt
            out.append(('ok', x, qt, way, '; '.join(notes)))
            done = True
            break
        if not done:
            broken = k
            out.append(('no assembly', None, None, None, '; '.join(notes)))
    return out


# ---------------------------------------------------------------------------
# Velocities, accelerations.

def rates(M, x, q):
    """Positions and transfer functions of every point and link at x."""
    f, J = jacobian(M, x, EXACT, q)
    fac = lu_factor(J)
    x0, c1, c2 = taylor_coefficients(M, x, fac, EXACT, None, q, mpf(1), 2)
    xs = c1
    xss = [2 * c for c in c2]
    X = [Taylor([v, d, dd]) for v, d, dd in zip(x, c1, c2)]
    pose = poses(M, X)
    pts = {}
    for P in M.points:
        L = next(L for L in M.order if P in M.links[L])
        if L == '0':
            z = mpf(0)
            pts[P] = {'p': list(M.dat['0'][P]), 'v_q': [z, z], 'a_q': [z, z]}
            continue
        gx, gy = world(pose, M.dat[L][P], L)
        pts[P] = {'p': [gx.c[0], gy.c[0]], 'v_q': [gx.c[1], gy.c[1]], 'a_q': [2 * gx.c[2], 2 * gy.c[2]]}
    lks = {}
    for L in M.order:
        if L == '0':
            lks[L] = {'angle': mpf(0), 'phi_q': mpf(0), 'phi_qq': mpf(0)}
        else:
            i = M.index[L] + 2
            lks[L] = {'angle': wrap_pi(x[i]), 'phi_q': xs[i], 'phi_qq': xss[i]}
    w, e = M.q1, M.q2
    for d in pts.values():
        d['v'] = [w * a for a in d['v_q']]
        d['a'] = [w * w * b + e * a for a, b in zip(d['v_q'], d['a_q'])]
    for d in lks.values():
        d['omega'] = w * d['phi_q']
        d['epsilon'] = w * w * d['phi_qq'] + e * d['phi_q']
    return {'points': pts, 'links': lks, 'cond': condition(M, J, fac)}


def condition(M, J, fac):
    """kappa of the Jacobian scaled to dimensionless unknowns and rows
    (infinity norm), from its explicit inverse."""
    n = len(J)
    colscale = []
    for L in M.moving:
        colscale += [M.S_p, M.S_p, mpf(1)]
    rowscale = [max(abs(J[r][c]) * colscale[c] for c in range(n)) or mpf(1) for r in range(n)]
    norm = max(sum(abs(J[r][c]) * colscale[c] for c in range(n)) / rowscale[r] for r in range(n))
    inv_rows = [mpf(0)] * n
    for c in range(n):
        e = [mpf(0)] * n
        e[c] = mpf(1)
        col = lu_solve(fac, e)
        for r in range(n):
            inv_rows[r] += abs(col[r]) / colscale[r] * rowscale[c]
    return norm * max(inv_rows)


def scales(M, R):
    """The kind scales of a position: S_p, and S_v, S_a, S_vq, S_aq."""
    Sp = M.S_p
    pts, lks = R['points'], R['links']
    mov = M.moving

    def vmax(key):
        return max([mp.sqrt(d[key][0] ** 2 + d[key][1] ** 2) for d in pts.values()] + [mpf(0)])
    S_v = max(vmax('v'), max(abs(lks[L]['omega']) for L in mov) * Sp)
    S_a = max(vmax('a'), max(abs(lks[L]['epsilon']) for L in mov) * Sp,
              max(lks[L]['omega'] ** 2 for L in mov) * Sp)
    S_vq = max(vmax('v_q'), max(abs(lks[L]['phi_q']) for L in mov) * Sp)
    S_aq = max(vmax('a_q'), max(abs(lks[L]['phi_qq']) for L in mov) * Sp,
               max(lks[L]['phi_q'] ** 2 for L in mov) * Sp)
    return {'p': Sp, 'v': S_v, 'a': S_a, 'v_q': S_vq, 'a_q': S_aq}


def differences(M, R, R2, S):
    """Largest change of each kind from R to R2, relative to the kind's scale."""
    out = {}
    link_key = {'v': 'omega', 'a': 'epsilon', 'v_q': 'phi_q', 'a_q': 'phi_qq'}
    for kind in ('p', 'v', 'a', 'v_q', 'a_q'):
        m = mpf(0)
        for P, d in R['points'].items():
            d2 = R2['points'][P]
            m = max(m, mp.sqrt((d[kind][0] - d2[kind][0]) ** 2 + (d[kind][1] - d2[kind][1]) ** 2))
        for L in M.moving:
            if kind == 'p':
                da = abs(wrap_pi(R['links'][L]['angle'] - R2['links'][L]['angle']))
                m = max(m, da * S['p'])
            else:
                k = link_key[kind]
                m = max(m, abs(R['links'][L][k] - R2['links'][L][k]) * S['p'])
        if S[kind] == 0:
            out[kind] = mpf(0) if m == 0 else mp.inf
        else:
            out[kind] = m / S[kind]
    out['max'] = max(out.values())
    return out


# ---------------------------------------------------------------------------
# Driver.

def fmt(v):
    if v == mp.inf:
        return "inf"
    return mp.nstr(v, 25, min_fixed=-4, max_fixed=6)


def format_rates(R):
    return ({P: {k: [fmt(c) for c in d[k]] for k in ('p', 'v', 'a', 'v_q', 'a_q')}
             for P, d in R['points'].items()},
            {L: {k: fmt(d[k]) for k in ('angle', 'omega', 'epsilon', 'phi_q', 'phi_qq')}
             for L, d in R['links'].items()})


def exact_run(scene, inputs, digits):
    """The scene's positions and rates for the data exactly, at `digits`."""
    mp.dps = digits
    M = build_model(scene, inputs, exact_reader())
    runs = run_positions(M)
    return M, runs, [rates(M, x, q) if status == 'ok' else None for status, x, q, way, note in runs]


def exact_solution(scene, inputs, dps, log=None):
    """The exact data at W = dps + 20 digits and again at W + 20, W + 40 ...
    until two levels agree to 10^-(dps/2 + 5) (kind-relative) at every
    position.  The reported numbers are the higher level's: its error is far
    below that difference, since the error is a fixed amplification of
    10^-W and shrinks by ~20 digits per level.  Near-singular positions
    (kappa ~ 1e18) take a third level; regular ones stop at the second.
    Returns (M, runs, results, accuracy per position, digits, tol)."""
    tol = mpf(10) ** (-(dps // 2 + 5))
    level = dps + GUARD
    M, runs, results = exact_run(scene, inputs, level)
    accuracy = [None] * len(results)
    while True:
        M2, runs2, results2 = exact_run(scene, inputs, level + 20)
        worst = mpf(0)
        for k, (R, R2) in enumerate(zip(results, results2)):
            if (R is None) != (R2 is None):
                worst = accuracy[k] = mp.inf
            elif R is not None:
                accuracy[k] = differences(M2, R2, R, scales(M2, R2))['max']
                worst = max(worst, accuracy[k])
        M, runs, results = M2, runs2, results2
        level += 20
        if worst <= tol or level >= dps + 200:
            return M, runs, results, accuracy, level, tol
        if log:
            log(f"  two precision levels differ by {mp.nstr(worst, 3)}: going to {level + 20} digits")


def sensitivity(scene, inputs, M, runs, results, draws, seed, log=None):
    """How much the data's own rounding moves the answer: for each draw,
    every datum (sketch coordinates, lengths, guide through / angle /
    offset, the positions' input values) moved by +-half an ulp of its IEEE
    double (random signs), solved again along the same path (the same ways
    round), and the largest change of each kind relative to the kind's
    scale at each position; inf where a draw does not assemble."""
    legs = [r[3] for r in runs]
    kinds = [dict.fromkeys(('p', 'v', 'a', 'v_q', 'a_q', 'max'), mpf(0)) for _ in results]
    S = [scales(M, R) if R is not None else None for R in results]
    for draw in range(draws):
        try:
            Md = build_model(scene, inputs, exact_reader(seed=f"{seed}:{draw}"))
            runs_d = run_positions(Md, legs, getattr(M, 'start', None))
        except Rejected:
            runs_d = [('no assembly',) + (None,) * 4] * len(results)
        for k, R in enumerate(results):
            if R is None:
                continue
            if runs_d[k][0] != 'ok':
                for kind in kinds[k]:
                    kinds[k][kind] = mp.inf
                continue
            diff = differences(M, R, rates(Md, runs_d[k][1], runs_d[k][2]), S[k])
            for kind, v in diff.items():
                kinds[k][kind] = max(kinds[k][kind], v)
        if log:
            log(f"  sensitivity draw {draw + 1}/{draws} done")
    return kinds


def solve(text, name, dps=50, draws=4, seed=1, inputs=None, log=None):
    """The reference answer for a scene (text: the file's bytes or text)."""
    sha = hashlib.sha256(text.encode('utf-8') if isinstance(text, str) else text).hexdigest()
    if isinstance(text, bytes):
        text = text.decode('utf-8')
    t0 = time.time()
    scene = read_scene_text(text)
    try:
        M, runs, results, accuracy, level, tol = exact_solution(scene, inputs, dps, log)
    except Rejected as e:
        return {'scene': name, 'scene_sha256': sha, 'rejected': str(e)}
    if all(R is None for R in results):
        draws = 0                     # nothing assembles: nothing to compare
    mp.dps = dps + GUARD              # the draws need only a few digits of their changes
    sens = sensitivity(scene, inputs, M, runs, results, draws, seed, log)
    out_pos = []
    for k, (run, R) in enumerate(zip(runs, results)):
        status, x, q, way, note = run
        item = {'input': M.input_texts[k]}
        if R is None:
            item.update({'status': 'no assembly', 'note': note})
            out_pos.append(item)
            continue
        item.update({'q': fmt(M.targets[k]), 'status': 'ok', 'way': way})
        if note:
            item['note'] = note
        item['points'], item['links'] = format_rates(R)
        item['sensitivity'] = {kind: fmt(v) for kind, v in sens[k].items()} if draws else None
        item['cond'] = mp.nstr(R['cond'], 6)
        item['digits'] = level
        item['accuracy'] = mp.nstr(accuracy[k], 3)
        if not accuracy[k] <= tol:
            item['warning'] = "two precision levels disagree: fewer than 25 correct digits"
        out_pos.append(item)
    return {'scene': name, 'scene_sha256': sha, 'dps': dps, 'draws': draws, 'seed': seed,
            'S_p': fmt(M.S_p), 'positions': out_pos, '_full': results, '_time_s': time.time() - t0}


# ---------------------------------------------------------------------------
# Comparison with mechplan.

def compare(ours, theirs, positions=None):
    """Worst disagreement per kind between our result and mechplan's, each
    relative to our kind scale (angles: absolute radians)."""
    worst = {'p': 0.0, 'v': 0.0, 'a': 0.0, 'v_q': 0.0, 'a_q': 0.0}
    where = {}
    mp.dps = 40
    for k, (o, t) in enumerate(zip(ours['positions'], theirs)):
        if o.get('status') != 'ok':
            continue
        P = {n: {kk: [mpf(c) for c in v] for kk, v in d.items()} for n, d in o['points'].items()}
        Lk = {n: {kk: mpf(v) for kk, v in d.items()} for n, d in o['links'].items()}
        # the kind scales as in the sensitivity, from our values
        def vm(key):
            return max([mp.sqrt(d[key][0] ** 2 + d[key][1] ** 2) for d in P.values()] + [mpf(0)])
        Sp = mpf(ours['S_p'])
        mov = [n for n in Lk if n != '0']
        S = {'p': Sp,
             'v': max(vm('v'), max(abs(Lk[n]['omega']) for n in mov) * Sp),
             'a': max(vm('a'), max(abs(Lk[n]['epsilon']) for n in mov) * Sp,
                      max(Lk[n]['omega'] ** 2 for n in mov) * Sp),
             'v_q': max(vm('v_q'), max(abs(Lk[n]['phi_q']) for n in mov) * Sp),
             'a_q': max(vm('a_q'), max(abs(Lk[n]['phi_qq']) for n in mov) * Sp,
                        max(Lk[n]['phi_q'] ** 2 for n in mov) * Sp)}
        for n, d in t.get('points', {}).items():
            for kind in worst:
                if kind in d and n in P:
                    e = mp.sqrt((P[n][kind][0] - d[kind][0]) ** 2 + (P[n][kind][1] - d[kind][1]) ** 2)
                    r = float(e / S[kind]) if S[kind] else float(e)
                    if r > worst[kind]:
                        worst[kind], where[kind] = r, f"pos {k}: {kind} of {n}"
        lmap = {'angle': 'p', 'omega': 'v', 'epsilon': 'a', 'phi_q': 'v_q', 'phi_qq': 'a_q'}
        for n, d in t.get('links', {}).items():
            if n not in Lk:
                continue
            for key, kind in lmap.items():
                if key not in d:
                    continue
                if key == 'angle':
                    e = abs(wrap_pi(Lk[n]['angle'] - mpf(d['angle']) * mp.pi / 180)) * Sp
                else:
                    e = abs(Lk[n][key] - mpf(d[key])) * Sp
                r = float(e / S[kind]) if S[kind] else float(e)
                if r > worst[kind]:
                    worst[kind], where[kind] = r, f"pos {k}: {key} of link {n}"
    return worst, where


def against_mechplan(scene_path, ours, binary):
    """Runs mechplan on each position of the scene (after the positions that
    mechplan accepted before it, so the path is the same), compares."""
    scene = json.load(open(scene_path))
    pos = scene.get('positions')
    key = None
    if pos is not None:
        key = 'angles' if 'angles' in pos else 's'
        values = pos[key]
    else:
        values = [None]
    accepted = []
    report = []
    for k, v in enumerate(values):
        sc = json.loads(json.dumps(scene))
        if key is not None:
            sc['positions'] = {key: [values[i] for i in accepted] + [v]}
        with tempfile.NamedTemporaryFile('w', suffix='.json', delete=False) as f:
            json.dump(sc, f)
            tmp = f.name
        r = subprocess.run([binary, 'solve', tmp, '--format', 'json'], capture_output=True, text=True)
        os.unlink(tmp)
        o = ours['positions'][k]
        if r.returncode != 0:
            msg = (r.stderr.strip().splitlines() or ['?'])[-1]
            report.append({'position': k, 'input': o['input'], 'ours': o.get('status'),
                           'mechplan': 'refused', 'message': msg})
            continue
        accepted.append(k)
        theirs = json.loads(r.stdout)['positions'][-1]
        sub = dict(ours)
        sub['positions'] = [o]
        worst, where = compare(sub, [theirs])
        # mechplan's own error bound, relative to the kind's scale (docs/fuzzing.md):
        # 256 * 2^-52 * kappa + 4 * max_rel_diff + 4 * data_sensitivity
        cc = theirs.get('crosscheck', {})
        bound = (256 * 2.0 ** -52 / cc['conditioning'] + 4 * cc.get('max_rel_diff', 0)
                 + 4 * (cc.get('data_sensitivity') or 0)) if cc.get('conditioning') else None
        report.append({'position': k, 'input': o['input'], 'ours': o.get('status'), 'mechplan': 'ok',
                       'bound': bound,
                       'worst': max(worst.values()) if o.get('status') == 'ok' else None,
                       'where': where.get(max(worst, key=worst.get)) if o.get('status') == 'ok' else None,
                       'kinds': worst, 'sensitivity': (o.get('sensitivity') or {}).get('max')})
    return report


# ---------------------------------------------------------------------------
# Self-test: closed forms and finite differences.

def selftest():
    mp.dps = 50 + GUARD
    failures = []

    def check(what, got, want, scale, tol=mpf('1e-30')):
        err = abs(mpf(got) - want) / scale
        ok = err <= tol
        print(f"  {'ok ' if ok else 'BAD'} {what}: rel. error {mp.nstr(err, 3)}")
        if not ok:
            failures.append(what)

    # 1. offset slider-crank: crank r at phi, rod l, guide y = -e (offset -e), slider right of A
    r, l, e = mpf('0.08'), mpf('0.3'), mpf('0.03')
    w, eps = mpf(7), mpf(3)
    scene = {
        "mechplan": 1, "units": {"length": "mm", "angle": "deg"},
        "points": {"O": [0, 0], "A": [69.2820323027551, 40], "B": [361.0, -30.0], "S2": [171.4, 15.5]},
        "links": {"0": {"points": ["O"]}, "1": {"points": ["O", "A"]},
                  "2": {"points": ["A", "B", "S2"]}, "3": {"points": ["B"]}},
        "sliders": [{"slider": "3", "guide": "0", "point": "B",
                     "line": {"through": [0, 0], "angle": 0, "offset": -30}}],
        "lengths": {"O-A": 80, "A-B": 300, "A-S2": 105, "B-S2": 195},
        "input": {"link": "1", "pivot": "O", "angle": 30, "omega": 7, "epsilon": 3},
        "positions": {"angles": [30, 100, 200, 300]}}
    res = solve(json.dumps(scene), 'selftest-slider-crank', draws=0)
    mp.dps = 50 + GUARD
    print("offset slider-crank against closed forms:")
    for k, deg in enumerate((30, 100, 200, 300)):
        phi = mpf(deg) * mp.pi / 180
        wv = r * mp.sin(phi) + e             # height of A above the guide y = -e
        D = mp.sqrt(l * l - wv * wv)
        w1, w2 = r * mp.cos(phi), -r * mp.sin(phi)
        D1 = -wv * w1 / D
        D2 = -(w1 * w1 + wv * w2) / D - (wv * w1) ** 2 / D ** 3
        xB, xB1, xB2 = r * mp.cos(phi) + D, -r * mp.sin(phi) + D1, -r * mp.cos(phi) + D2
        psi = mp.asin(-wv / l)               # rod angle A -> B
        psi1 = -w1 / D
        psi2 = -w2 / D + w1 * D1 / D ** 2
        pos = res['_full'][k]
        B, L2 = pos['points']['B'], pos['links']['2']
        check(f"phi={deg} x_B", B['p'][0], xB, l)
        check(f"phi={deg} y_B", B['p'][1], -e, l)
        check(f"phi={deg} v_B", B['v'][0], w * xB1, w * l)
        check(f"phi={deg} a_B", B['a'][0], w * w * xB2 + eps * xB1, w * w * l)
        check(f"phi={deg} angle 2", L2['angle'], psi, 1)
        check(f"phi={deg} omega 2", L2['omega'], w * psi1, w)
        check(f"phi={deg} eps 2", L2['epsilon'], w * w * psi2 + eps * psi1, w * w)
        # S2 on AB at 105/300 of its length (the data put it on the line)
        Ax, Ay = r * mp.cos(phi), r * mp.sin(phi)
        check(f"phi={deg} x_S2", pos['points']['S2']['p'][0], Ax + mpf(105) / 300 * (xB - Ax), l)

    # 2. four-bar with a ternary coupler (point M by two distances)
    r1, l2, l3, d = mpf('0.1'), mpf('0.35'), mpf('0.3'), mpf('0.4')
    lAM, lBM = mpf('0.2'), mpf('0.25')
    w, eps = mpf(10), mpf(2)
    scene = {
        "mechplan": 1,
        "points": {"O1": [0, 0], "A": [0.070710678118655, 0.070710678118655],
                   "B": [0.340242120247775, 0.2939880878667], "M": [0.091431148379841, 0.269634437665259],
                   "O3": [0.4, 0]},
        "links": {"0": {"points": ["O1", "O3"]}, "1": {"points": ["O1", "A"]},
                  "2": {"points": ["A", "B", "M"]}, "3": {"points": ["O3", "B"]}},
        "lengths": {"O1-A": 0.1, "A-B": 0.35, "O3-B": 0.3, "A-M": 0.2, "B-M": 0.25},
        "input": {"link": "1", "pivot": "O1", "angle": 45, "omega": 10, "epsilon": 2},
        "positions": {"angles": [45, 135, 225, 315, 400]}}
    res = solve(json.dumps(scene), 'selftest-four-bar', draws=0)
    mp.dps = 50 + GUARD
    print("four-bar against closed forms:")
    for k, deg in enumerate((45, 135, 225, 315, 400)):
        p1 = mpf(deg) * mp.pi / 180
        A = (r1 * mp.cos(p1), r1 * mp.sin(p1))
        C = (d - A[0], -A[1])
        cc = mp.sqrt(C[0] ** 2 + C[1] ** 2)
        a = (l2 * l2 - l3 * l3 + cc * cc) / (2 * cc)
        h = mp.sqrt(l2 * l2 - a * a)        # B to the left of A -> O3 (as drawn)
        B = (A[0] + (a * C[0] - h * C[1]) / cc, A[1] + (a * C[1] + h * C[0]) / cc)
        p2 = mp.atan2(B[1] - A[1], B[0] - A[0])
        p3 = mp.atan2(B[1], B[0] - d)
        w2 = -r1 * w * mp.sin(p3 - p1) / (l2 * mp.sin(p3 - p2))
        w3 = r1 * w * mp.sin(p2 - p1) / (l3 * mp.sin(p2 - p3))
        e2 = (-r1 * eps * mp.sin(p3 - p1) + r1 * w * w * mp.cos(p1 - p3) + l2 * w2 * w2 * mp.cos(p2 - p3)
              - l3 * w3 * w3) / (l2 * mp.sin(p3 - p2))
        e3 = (r1 * eps * mp.sin(p2 - p1) - r1 * w * w * mp.cos(p1 - p2) - l2 * w2 * w2
              + l3 * w3 * w3 * mp.cos(p3 - p2)) / (l3 * mp.sin(p2 - p3))
        vB = (-l3 * w3 * mp.sin(p3), l3 * w3 * mp.cos(p3))
        aB = (-l3 * e3 * mp.sin(p3) - l3 * w3 * w3 * mp.cos(p3), l3 * e3 * mp.cos(p3) - l3 * w3 * w3 * mp.sin(p3))
        gam = mp.acos((lAM ** 2 + l2 ** 2 - lBM ** 2) / (2 * lAM * l2))   # M to the left of A -> B
        pm = p2 + gam
        Mp = (A[0] + lAM * mp.cos(pm), A[1] + lAM * mp.sin(pm))
        vA = (-r1 * w * mp.sin(p1), r1 * w * mp.cos(p1))
        vM = (vA[0] - w2 * lAM * mp.sin(pm), vA[1] + w2 * lAM * mp.cos(pm))
        aA = (-r1 * eps * mp.sin(p1) - r1 * w * w * mp.cos(p1), r1 * eps * mp.cos(p1) - r1 * w * w * mp.sin(p1))
        aM = (aA[0] - e2 * lAM * mp.sin(pm) - w2 * w2 * lAM * mp.cos(pm),
              aA[1] + e2 * lAM * mp.cos(pm) - w2 * w2 * lAM * mp.sin(pm))
        pos = res['_full'][k]
        P = pos['points']
        for i in (0, 1):
            check(f"phi={deg} B[{i}]", P['B']['p'][i], B[i], d)
            check(f"phi={deg} v_B[{i}]", P['B']['v'][i], vB[i], w * d)
            check(f"phi={deg} a_B[{i}]", P['B']['a'][i], aB[i], w * w * d)
            check(f"phi={deg} M[{i}]", P['M']['p'][i], Mp[i], d)
            check(f"phi={deg} v_M[{i}]", P['M']['v'][i], vM[i], w * d)
            check(f"phi={deg} a_M[{i}]", P['M']['a'][i], aM[i], w * w * d)
        check(f"phi={deg} omega 2", pos['links']['2']['omega'], w2, w)
        check(f"phi={deg} omega 3", pos['links']['3']['omega'], w3, w)
        check(f"phi={deg} eps 2", pos['links']['2']['epsilon'], e2, w * w)
        check(f"phi={deg} eps 3", pos['links']['3']['epsilon'], e3, w * w)

    # 3. finite differences of positions against v_q, a_q: a shaper (rocking
    # guide with Coriolis, a ram on a fixed guide), at q - h, q, q + h
    shaper = {
        "mechplan": 1,
        "points": {"A": [0.0, 0.3], "B": [0.086602540378444, 0.35], "C": [0.0, 0.0],
                   "D": [0.132105726889197, 0.533898938866783], "S3": [0.066052863444598, 0.266949469433392],
                   "E": [-0.3, 0.54], "F": [0.3, 0.54], "K": [0.132105726889197, 0.54],
                   "M": [0.132105726889197, 0.6]},
        "links": {"0": {"points": ["A", "C", "E", "F"]}, "1": {"points": ["A", "B"]}, "2": {"points": ["B"]},
                  "3": {"points": ["C", "D", "S3"]}, "4": {"points": ["D"]}, "5": {"points": ["K", "M"]}},
        "sliders": [{"slider": "2", "guide": "3", "point": "B", "line": {"through": "C", "along": ["C", "D"]}},
                    {"slider": "4", "guide": "5", "point": "D", "line": {"through": "K", "along": ["K", "M"]}},
                    {"slider": "5", "guide": "0", "point": "K", "line": {"through": "E", "along": ["E", "F"]}}],
        "lengths": {"A-B": 0.1, "C-D": 0.55, "C-S3": 0.275, "D-S3": 0.275, "K-M": 0.06},
        "input": {"link": "1", "pivot": "A", "angle": 30.0, "omega": 6.0, "epsilon": 0.0},
        "units": {"angle": "rad"}}
    hs = '1e-12'
    print("finite differences (h = 1e-12 rad) against the transfer functions:")
    for q0 in ('0.7', '2.5'):
        qs = [mpf(q0) - mpf(hs), mpf(q0), mpf(q0) + mpf(hs)]
        inputs = ','.join(mp.nstr(v, 60) for v in qs)
        res = solve(json.dumps(shaper), 'selftest-shaper', draws=0, inputs=inputs)
        mp.dps = 50 + GUARD
        h = mpf(hs)
        pm_, p0_, pp_ = res['_full']
        for P in ('B', 'D', 'K', 'S3', 'M'):
            for i in (0, 1):
                a, b, c = (mpf(x['points'][P]['p'][i]) for x in (pm_, p0_, pp_))
                check(f"q={q0} d{P}[{i}]/dq", (c - a) / (2 * h), mpf(p0_['points'][P]['v_q'][i]), 1, mpf('1e-20'))
                check(f"q={q0} d2{P}[{i}]/dq2", (c - 2 * b + a) / (h * h), mpf(p0_['points'][P]['a_q'][i]), 1,
                      mpf('1e-20'))
        for L in ('3', '5'):
            a, b, c = (mpf(x['links'][L]['angle']) for x in (pm_, p0_, pp_))
            check(f"q={q0} dphi{L}/dq", (c - a) / (2 * h), mpf(p0_['links'][L]['phi_q']), 1, mpf('1e-20'))
            check(f"q={q0} d2phi{L}/dq2", (c - 2 * b + a) / (h * h), mpf(p0_['links'][L]['phi_qq']), 1,
                  mpf('1e-20'))
    # 4. a narrow neck and a narrow gap: a parallelogram four-bar (crank 0.1,
    # coupler 0.4 = frame) whose rocker is 1e-11 m longer (a crank-rocker:
    # past crank angle 0 the rocker turns back) or shorter (the crank rocks:
    # it cannot pass 0, nor 180 deg, where 3e-5 rad of no assembly separate
    # two branches that look like one)
    print("narrow neck / narrow gap near a change point:")
    for l3, want in (('0.10000000001', 'neck'), ('0.09999999999', 'gap')):
        phi = mpf(60) * mp.pi / 180
        A = [float(mpf('0.1') * mp.cos(phi)), float(mpf('0.1') * mp.sin(phi))]
        sc = {"mechplan": 1, "points": {"O1": [0, 0], "A": A, "B": [0.4 + A[0], A[1]], "O3": [0.4, 0]},
              "links": {"0": {"points": ["O1", "O3"]}, "1": {"points": ["O1", "A"]},
                        "2": {"points": ["A", "B"]}, "3": {"points": ["O3", "B"]}},
              "lengths": {"O1-A": 0.1, "A-B": 0.4, "O3-B": float(l3)},
              "input": {"link": "1", "pivot": "O1", "angle": 60, "omega": 1},
              "positions": {"angles": [10, 0.001, -0.001]}}
        res = solve(json.dumps(sc), 'selftest-' + want, draws=0)
        mp.dps = 50 + GUARD
        st = [p['status'] for p in res['positions']]
        if want == 'neck':
            w3 = [res['_full'][k]['links']['3']['omega'] for k in (1, 2)]
            ok = st == ['ok'] * 3 and w3[0] > 0 > w3[1]
            print(f"  {'ok ' if ok else 'BAD'} l3 = {l3}: passes 0 deg, the rocker turns back "
                  f"(omega3 {mp.nstr(w3[0], 4)} -> {mp.nstr(w3[1], 4)})")
        else:
            ok = st == ['ok', 'ok', 'no assembly']
            print(f"  {'ok ' if ok else 'BAD'} l3 = {l3}: -0.001 deg not reached either way round ({st[2]})")
        if not ok:
            failures.append(f"neck/gap {l3}")
    print("selftest:", "FAILED " + ", ".join(failures) if failures else "passed")
    return 1 if failures else 0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('scene', nargs='?')
    ap.add_argument('--dps', type=int, default=50)
    ap.add_argument('--draws', type=int, default=4)
    ap.add_argument('--seed', default='1')
    ap.add_argument('--inputs')
    ap.add_argument('-o', '--output')
    ap.add_argument('--selftest', action='store_true')
    ap.add_argument('--compare', nargs=2, metavar=('OURS', 'MECHPLAN'))
    ap.add_argument('--against-mechplan', nargs=2, metavar=('SCENE', 'OURS'))
    ap.add_argument('--mechplan', default='target/release/mechplan')
    ap.add_argument('-q', '--quiet', action='store_true')
    a = ap.parse_args()
    if a.selftest:
        sys.exit(selftest())
    if a.compare:
        ours = json.load(open(a.compare[0]))
        theirs = json.load(open(a.compare[1]))['positions']
        worst, where = compare(ours, theirs)
        for kind, v in worst.items():
            print(f"{kind:4s} {v:.3e}  {where.get(kind, '')}")
        print(f"worst {max(worst.values()):.3e}")
        return
    if a.against_mechplan:
        ours = json.load(open(a.against_mechplan[1]))
        if 'rejected' in ours:
            print(json.dumps({'rejected': ours['rejected']}))
            return
        print(json.dumps(against_mechplan(a.against_mechplan[0], ours, a.mechplan), indent=1))
        return
    if not a.scene:
        ap.error("a scene file is required")
    data = open(a.scene, 'rb').read()
    log = None if a.quiet else (lambda m: print(m, file=sys.stderr))
    try:
        out = solve(data, os.path.basename(a.scene), a.dps, a.draws, a.seed, a.inputs, log)
    except Rejected as e:      # pragma: no cover
        out = {'rejected': str(e)}
    if 'rejected' in out and 'count' in str(out['rejected']) and '--inputs' in out['rejected']:
        print(f"mpref: {out['rejected']}", file=sys.stderr)
        sys.exit(2)
    out.pop('_full', None)
    elapsed = out.pop('_time_s', None)
    if log and elapsed is not None:
        log(f"mpref: {os.path.basename(a.scene)}: {elapsed:.1f} s")
    text = json.dumps(out, indent=1)
    if a.output:
        with open(a.output, 'w') as f:
            f.write(text + '\n')
    else:
        print(text)
    if 'rejected' in out:
        print(f"mpref: rejected: {out['rejected']}", file=sys.stderr)
        sys.exit(3)


if __name__ == '__main__':
    main()
