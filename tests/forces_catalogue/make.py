#!/usr/bin/env python3
"""Write the catalogue of force-plan answers (tests/forces_catalogue/):
honest answers and answers with one seeded mistake each, for several
positions of every dynamics fixture, every group's plan (a class III
group's too: its R^τ, R^n and reactions as triad.rs names them) and the
input link's, computed by tests/reference/forceref.py (60 digits, independent
of mechplan's force code), and a few bad answers; `labels.json` says what
each answer is. tests/check_forces_catalogue.rs grades `check` on them.

Run from the repository's root after `cargo build --release` (mechplan
gives only the input angles of a `count` scene and the positions'
numbers; for a scene of several inputs, the two-cylinder arm, the
kinematics too: forceref solves its forces from them; MECHPLAN=path
for another binary):
    python3 tests/forces_catalogue/make.py        (or tests/forces_catalogue/make.sh)
"""
import glob
import json
import math
import os
import random
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', 'reference'))
import forceref as fr  # noqa: E402
from forceref import mp, mpf, add, sub, mul, cross, norm, unit, perp  # noqa: E402

BINARY = os.environ.get('MECHPLAN', 'target/release/mechplan')
# Positions (indices into the scene's positions) per fixture; all of a
# scene with fewer.
POSITIONS = [0, 2, 5, 8]
DELTA = 0.5          # the δ the answers state, mm
SEG_NOISE = 0.3      # mm
ANG_NOISE = 0.5      # degrees
# A mistake is kept where some item moves by more than this many mm on
# the plan (an angle: sideways at the vector's end), or M_b by more than
# this many of its tolerances δ·μ_l·Σ|F| (otherwise it is no mistake a
# pencil shows).
SEEN_MM = 3.0
SEEN_MB = 3.0
# No direction is read off a segment shorter than this, mm.
MIN_ANGLE_MM = 2.0

SKIPPED = {}


def standard_at_least(x):
    """The smallest 1, 2, 2.5, 4, 5 × 10^k not below x."""
    k = math.floor(math.log10(x))
    for e in (k - 1, k, k + 1):
        for m in (1, 2, 2.5, 4, 5):
            if m * 10 ** e >= x * (1 - 1e-12):
                return float(f"{m * 10 ** e:.6g}")
    raise ValueError(x)


def f(x):
    return float(x)


# ---------------------------------------------------------------------------
# The plans as mechplan's check names their forces (docs/check.md).

def pair_between(M, a, b):
    for q in fr.pairs_of(M):
        if {q[2], q[3]} == {a, b}:
            return q
    return None


def force_on(M, pos, q, x, link):
    return fr.pair_action(M, pos, q, x)[link][0]


class Plan:
    """One plan: its links, its items [(name, vector, role)], and for a
    dyad the geometry of its polygon."""


def dyad_scheme(M, links, attached):
    """Side 0, side 1, their outer links and the three pairs, in the
    course's reading (a contour read from its revolute end)."""
    a, b = links
    pairs = fr.pairs_of(M)
    ext = {}
    for L in (a, b):
        ext[L] = next(q for q in pairs if L in (q[2], q[3]) and ({q[2], q[3]} - {L}) <= attached)
    mid = pair_between(M, a, b)
    letters = [ext[a][0], mid[0], ext[b][0]]
    s0, s1 = (b, a) if letters in (['P', 'R', 'R'], ['P', 'P', 'R']) else (a, b)
    k1 = next(iter({ext[s0][2], ext[s0][3]} - {s0}))
    k2 = next(iter({ext[s1][2], ext[s1][3]} - {s1}))
    return s0, s1, k1, k2, ext[s0], mid, ext[s1]


def cylinder_scheme(M, links, attached):
    """A group of a link and a driving cylinder (barrel and rod: a side of
    variable length, docs/kinetostatics.md): side 0 the link, side 1 the
    cylinder, named as mechplan's check names them (R^τ_01, R_01, R_02,
    R_31 on the boom's plan): (s0, outer, k1, k2, e1, mid, e2, rod), the
    cylinder's outer link (its pair on an attached link) and its other one
    (the middle pair's on the link)."""
    pr = next(pr for pr in M.drives if pr['slider'] in links and pr['guide'] in links)
    cyl = [pr['guide'], pr['slider']]
    a = next(L for L in links if L not in cyl)
    pairs = fr.pairs_of(M)
    e1 = next(q for q in pairs if q[0] == 'R' and a in (q[2], q[3]) and ({q[2], q[3]} - {a}) <= attached)
    mid = next(q for q in pairs if q[0] == 'R' and a in (q[2], q[3]) and ({q[2], q[3]} - {a}) & set(cyl))
    rod = next(iter({mid[2], mid[3]} - {a}))
    outer = next(L for L in cyl if L != rod)
    e2 = next(q for q in pairs if q[0] == 'R' and outer in (q[2], q[3]) and ({q[2], q[3]} - {outer}) <= attached)
    k1 = next(iter({e1[2], e1[3]} - {a}))
    k2 = next(iter({e2[2], e2[3]} - {outer}))
    return a, outer, k1, k2, e1, mid, e2, rod


def link_forces(lds, L):
    return [ld for ld in lds if ld['link'] == L and norm(ld['f']) > 0]


def plan_items(M, pos, lds, solved, gi, groups, balancing):
    """The items of plan gi (None: the input link's): (name, vector, role);
    roles: 'measured', 'tau', 'load', 'neighbour'."""
    attached = {'0', M.input_link} if M.kind != 'cylinders' else {'0'}
    for g in groups[:gi] if gi is not None else groups:
        attached |= set(g)
    links = groups[gi] if gi is not None else [M.input_link]
    items = []
    later = set()
    if gi is not None:
        for g in groups[gi + 1:]:
            later |= set(g)
    else:
        for g in groups:
            later |= set(g)
    # The answer gives what the plan finds (the reactions, their τ
    # components, M_b) and the later group's reactions it takes over; the
    # given loads are not asked for.
    for L in links:
        for q, x in solved.items():
            other = next(iter({q[2], q[3]} - {L}), None)
            if L in (q[2], q[3]) and other in later:
                items.append((f"R_{other}{L}", force_on(M, pos, q, x, L), 'neighbour'))
    scheme = None
    triad = None
    side1 = None
    if gi is not None and M.kind == 'cylinders':
        s0, s1, k1, k2, e1, mid, e2, rod = cylinder_scheme(M, links, attached)
        scheme = (s0, s1, k1, k2, e1, mid, e2)
        side1 = [s1, rod]
        r1 = force_on(M, pos, e1, solved[e1], s0)
        r2 = force_on(M, pos, e2, solved[e2], s1)
        rm = force_on(M, pos, mid, solved[mid], s0)
        for k_, s_, e_, r_ in ((k1, s0, e1, r1), (k2, s1, e2, r2)):
            e = perp(unit(sub(pos.p[mid[1]], pos.p[e_[1]])))
            items.append((f"R^τ_{k_}{s_}", mul(e, r_[0] * e[0] + r_[1] * e[1]), 'tau'))
        items += [(f"R_{k1}{s0}", r1, 'measured'), (f"R_{k2}{s1}", r2, 'measured'),
                  (f"R_{rod}{s0}", rm, 'measured')]
    elif gi is not None and len(links) == 4:
        triad = triad_scheme(M, pos, links, attached)
        items += triad_items(M, pos, solved, triad)
    elif gi is not None:
        s0, s1, k1, k2, e1, mid, e2 = dyad_scheme(M, links, attached)
        scheme = (s0, s1, k1, k2, e1, mid, e2)
        r1 = force_on(M, pos, e1, solved[e1], s0)
        r2 = force_on(M, pos, e2, solved[e2], s1)
        rm = force_on(M, pos, mid, solved[mid], s0)
        if e1[0] == 'R' and mid[0] == 'R':
            A, B = pos.p[e1[1]], pos.p[mid[1]]
            e = perp(unit(sub(B, A)))
            items.append((f"R^τ_{k1}{s0}", mul(e, r1[0] * e[0] + r1[1] * e[1]), 'tau'))
        if e2[0] == 'R' and mid[0] == 'R':
            C, B = pos.p[e2[1]], pos.p[mid[1]]
            e = perp(unit(sub(B, C)))
            items.append((f"R^τ_{k2}{s1}", mul(e, r2[0] * e[0] + r2[1] * e[1]), 'tau'))
        items += [(f"R_{k1}{s0}", r1, 'measured'), (f"R_{k2}{s1}", r2, 'measured'),
                  (f"R_{s1}{s0}", rm, 'measured')]
    else:
        L = M.input_link
        q = next(q for q in solved if L in (q[2], q[3]) and '0' in (q[2], q[3]))
        items.append((f"R_0{L}", force_on(M, pos, q, solved[q], L), 'measured'))
    p = Plan()
    p.gi, p.links, p.items, p.scheme, p.balancing = gi, links, items, scheme, balancing
    p.triad = triad
    p.side1 = side1
    # Σ|F| of the forces laid off on the plan (the loads and the later
    # reactions): what M_b's arms multiply.
    n_laid = sum(1 for L in links for ld in link_forces(lds, L)) + sum(
        1 for _, _, role in items if role in ('neighbour', 'tau'))
    p.bound = drafting_bound(M, pos, scheme, n_laid) if triad is None else triad_bound(triad, n_laid)
    p.laid = sum(f(norm(ld['f'])) for L in links for ld in link_forces(lds, L)) + sum(
        f(norm(v)) for _, v, role in items if role == 'neighbour')
    return p


class Triad:
    """A class III group at a position: its base, its leashes (each with
    its outer pair E on a known link and inner pair J on the base), the
    pair of leashes (i, j) whose axes close the polygon, the third k, and
    Assur's point S where the axes of i and j meet."""


def triad_scheme(M, pos, links, attached):
    """The group's base (the link paired with the three others), its
    leashes in the group's order, and (i, j, k), S as the course picks
    them: the two axes E→J meeting at the largest angle (the smallest
    amplification of the closing point's error), k the third."""
    pairs = fr.pairs_of(M)
    s = set(links)
    inside = [q for q in pairs if q[2] in s and q[3] in s]
    base = next(L for L in links if sum(1 for q in inside if L in (q[2], q[3])) == 3)
    t = Triad()
    t.base = base
    t.leashes = []
    for L in links:
        if L == base:
            continue
        inner = next(q for q in inside if {q[2], q[3]} == {L, base})
        outer = next(q for q in pairs if L in (q[2], q[3]) and (({q[2], q[3]} - {L}) <= attached))
        known = next(iter({outer[2], outer[3]} - {L}))
        E, J = pos.p[outer[1]], pos.p[inner[1]]
        t.leashes.append({'link': L, 'known': known, 'outer': outer, 'inner': inner,
                          'E': E, 'J': J, 'axis': sub(J, E)})

    def sine(a, b):
        return abs(cross(unit(t.leashes[a]['axis']), unit(t.leashes[b]['axis'])))
    best = None
    for c in ((0, 1, 2), (0, 2, 1), (1, 2, 0)):
        if best is None or sine(c[0], c[1]) >= sine(best[0], best[1]):
            best = c
    t.ijk = best
    t.sin = f(sine(best[0], best[1]))
    li, lj = t.leashes[best[0]], t.leashes[best[1]]
    # S = E_i + a·axis_i = E_j + b·axis_j
    a = cross(sub(lj['E'], li['E']), lj['axis']) / cross(li['axis'], lj['axis'])
    t.S = add(li['E'], mul(li['axis'], a))
    return t


def triad_items(M, pos, solved, t):
    """The class III plan's items as mechplan's check names them: each
    leash's R^τ (from its moments about J), the third leash's R^n (from
    the group's moments about S), then the measured reactions: the outer
    ones of i, j, k and the base's on i, k, j."""
    i, j, k = t.ijk
    out, meas = [], []
    for n in (i, j, k):
        ls = t.leashes[n]
        r = force_on(M, pos, ls['outer'], solved[ls['outer']], ls['link'])
        e = perp(unit(ls['axis']))
        out.append((f"R^τ_{ls['known']}{ls['link']}", mul(e, r[0] * e[0] + r[1] * e[1]), 'tau'))
        if n == k:
            u = unit(ls['axis'])
            out.append((f"R^n_{ls['known']}{ls['link']}", mul(u, r[0] * u[0] + r[1] * u[1]), 'tau'))
        meas.append((f"R_{ls['known']}{ls['link']}", r, 'measured'))
    for n in (i, k, j):
        ls = t.leashes[n]
        r = force_on(M, pos, ls['inner'], solved[ls['inner']], ls['link'])
        meas.append((f"R_{t.base}{ls['link']}", r, 'measured'))
    return out + meas


def triad_check(M, pos, lds, solved, t, right):
    """The honest items as the course's construction gives them: each R^τ
    from its leash's moments about J, R^n_k from the group's about S (the
    loads and the τ known); they must be the reference's components."""
    i, j, k = t.ijk
    links = [ls['link'] for ls in t.leashes] + [t.base]

    def moment(Ls, about):
        m = mpf(0)
        for ld in lds:
            if ld['link'] in Ls:
                m += cross(sub(ld['at'], about), ld['f']) + ld['c']
        return m
    tau = {}
    for n, ls in enumerate(t.leashes):
        e = perp(unit(ls['axis']))
        v = -moment([ls['link']], ls['J']) / cross(sub(ls['E'], ls['J']), e)
        tau[n] = mul(e, v)
        name = f"R^τ_{ls['known']}{ls['link']}"
        assert f(norm(sub(tau[n], right[name]))) < 1e-30 * max(f(norm(right[name])), 1.0), name
    lk = t.leashes[k]
    u = unit(lk['axis'])
    taus = sum(cross(sub(t.leashes[n]['E'], t.S), tau[n]) for n in range(3))
    nk = -(moment(links, t.S) + taus) / cross(sub(lk['E'], t.S), u)
    name = f"R^n_{lk['known']}{lk['link']}"
    assert f(norm(sub(mul(u, nk), right[name]))) < 1e-30 * max(f(norm(right[name])), 1.0), name


def triad_bound(t, n):
    """drafting_bound's model for the class III polygon: closed by the
    axes of leashes i and j."""
    return DELTA * (n + 2) / max(t.sin, 1e-12) + DELTA


def drafting_bound(M, pos, scheme, n):
    """How far a careful pencil may put a plan's closing point, mm: δ per
    vector laid off (n of them) and per line, over the sine at which the
    closing lines meet, and δ more to measure (this file's own model of
    drafting, docs/check.md's in spirit)."""
    if scheme is None:
        return DELTA * (n + 1) + DELTA
    s0, s1, k1, k2, e1, mid, e2 = scheme

    def line(e, o):
        if e[0] == 'P':
            return perp(pos.guides[e[1]])
        if mid[0] == 'R':
            return sub(pos.p[mid[1]], pos.p[e[1]])
        return perp(pos.guides[mid[1]])
    if e1[0] == 'R' and mid[0] == 'P' and e2[0] == 'R':
        sin = 1.0
    else:
        d1, d2 = line(e1, 0), line(e2, 1)
        sin = abs(f(cross(unit(d1), unit(d2))))
    return DELTA * (n + 2) / max(sin, 1e-12) + DELTA


def polygon(M, pos, lds, solved, plan, t1, t2):
    """A dyad's polygon (RRR, RRP) as drawn with the first side's τ vector
    t1 and (RRR) the second's t2: the three measured reactions."""
    s0, s1, k1, k2, e1, mid, e2 = plan.scheme
    A, B = pos.p[e1[1]], pos.p[mid[1]]

    def known_sum(L):
        F = (mpf(0), mpf(0))
        for ld in lds:
            if ld['link'] == L:
                F = add(F, ld['f'])
        for q, x in solved.items():
            if q in (e1, mid, e2):
                continue
            acts = fr.pair_action(M, pos, q, x)
            if L in acts:
                F = add(F, acts[L][0])
        return F
    P1 = t1
    end0 = add(P1, known_sum(s0))
    if plan.side1 is None:
        end1 = add(end0, known_sum(s1))
    else:
        # a cylinder: barrel and rod one side (their pair's N and the
        # drive's F_b inside it cancel)
        end1 = end0
        for L in plan.side1:
            end1 = add(end1, known_sum(L))
    end = add(end1, t2) if t2 is not None else end1
    l1 = sub(B, A)
    if e2[0] == 'R':
        d2 = sub(B, pos.p[e2[1]])
    else:
        d2 = perp(pos.guides[e2[1]])
    # X = t·l1 = end + s·d2
    det = cross(l1, mul(d2, -1))
    t = cross(end, mul(d2, -1)) / det
    X = mul(l1, t)
    m_ = plan.side1[-1] if plan.side1 is not None else s1
    return {f"R_{k1}{s0}": sub(P1, X), f"R_{k2}{s1}": sub(X, end1), f"R_{m_}{s0}": sub(X, end0)}


# ---------------------------------------------------------------------------
# Answers.

def choose_mu(items):
    longest = max(f(norm(v)) for _, v, _ in items)
    return standard_at_least(longest / 100.0)


def angle_of(v):
    return math.degrees(math.atan2(f(v[1]), f(v[0]))) % 360.0


def input_moment_tolerance(plan, mu_l):
    """check's tolerance of M_b: δ·μ_l·Σ|F| over the forces laid off."""
    return DELTA * mu_l * plan.laid


def answer(position, plan, mu, mu_l, vecs, style, rng, mb=None, seg_factor=1.0, noise=True):
    """The JSON answer of `vecs` [(name, vector)] in `style`: 'vectors'
    (segments, angles and values), 'segments', 'values'; M_b as a value
    (the input link's plan)."""
    a = {'plan': 'force', 'position': position, 'links': plan.links, 'mu': mu, 'delta': DELTA,
         'mu_l': mu_l}
    segs, angs, vals = {}, {}, {}
    for name, v in vecs:
        n = f(norm(v))
        ds = rng.uniform(-SEG_NOISE, SEG_NOISE) if noise else 0.0
        da = rng.uniform(-ANG_NOISE, ANG_NOISE) if noise else 0.0
        if style in ('vectors', 'segments'):
            segs[name] = round(max(n / mu * seg_factor + ds, 0.0), 1)
        if style == 'vectors' and n / mu * seg_factor >= MIN_ANGLE_MM:
            angs[name] = round((angle_of(v) + da) % 360.0, 1)
        if style in ('vectors', 'values'):
            dv = rng.uniform(-SEG_NOISE, SEG_NOISE) if noise else 0.0
            vals[name] = float(f"{max(n + dv * mu, 0.0):.4g}")
    if mb is not None and style in ('vectors', 'values'):
        tol = input_moment_tolerance(plan, mu_l)
        d = rng.uniform(-0.3, 0.3) * tol if noise else 0.0
        vals['M_b'] = float(f"{f(mb) + d:.5g}")
    if segs:
        a['segments'] = segs
    if angs:
        a['angles'] = angs
    if vals:
        a['values'] = vals
    return a


def seen(plan, mu, mu_l, right, wrong, mb_right=None, mb_wrong=None):
    """Whether a mistaken set of vectors (and M_b) differs from the right
    one by more than a pencil's error somewhere."""
    limit = max(SEEN_MM, 1.5 * plan.bound)
    for name, v in wrong.items():
        r = right[name]
        a, b = f(norm(v)) / mu, f(norm(r)) / mu
        if abs(a - b) > limit:
            return True
        if min(a, b) >= MIN_ANGLE_MM and f(norm(sub(mul(unit(v), norm(r)), r))) / mu > limit:
            return True
    if mb_right is not None and mb_wrong is not None:
        tol = input_moment_tolerance(plan, mu_l)
        if abs(f(mb_wrong - mb_right)) > SEEN_MB * tol:
            return True
    return False


def scene_answers(name, path, out_dir, labels):
    mj = fr.mechplan_json(path, BINARY)
    text = open(path).read()
    inputs = fr.input_texts(mj)
    numbers = [p['position'] for p in mj['positions']]
    scene, M, groups, ref = fr.reference(text, inputs, mj=mj)
    _, _, _, ref_nr = fr.reference(text, inputs, ('not_reversed',), mj=mj)
    _, _, _, ref_nw = fr.reference(text, inputs, ('no_weights',), mj=mj)
    S_p = f(M.S_p)
    mu_l = standard_at_least(S_p / 200.0)
    ks = [k for k in POSITIONS if k < len(ref)] or [0]
    crank = M.kind == 'crank'
    count = 0
    for k in ks:
        if ref[k] is None:
            continue
        pos, lds, solved, b = ref[k]
        plans = [plan_items(M, pos, lds, solved, gi, groups, b) for gi in range(len(groups))]
        if M.kind != 'cylinders':
            # (several inputs: no input link's plan; each cylinder's F_b is
            # found in its group's)
            plans.append(plan_items(M, pos, lds, solved, None, groups, b))
        for plan in plans:
            tag = f"{numbers[k]}_{''.join(plan.links)}"
            rng = random.Random(f"{name}|{tag}")
            right = {n: v for n, v, _ in plan.items}
            vecs = [(n, v) for n, v, _ in plan.items]
            mu = choose_mu(plan.items)
            is_input = plan.gi is None
            mb = b if is_input and crank else None

            def put(kind, a, style):
                nonlocal count
                fn = f"{tag}_{kind}_{style}.json"
                with open(os.path.join(out_dir, fn), 'w') as fh:
                    json.dump(a, fh, ensure_ascii=False, indent=1)
                    fh.write('\n')
                labels.append({'file': f"{name}/{fn}", 'scene': f"fixtures/dynamics/{name}.json",
                               'position': numbers[k], 'links': plan.links, 'style': style,
                               'expected': kind})
                count += 1

            # (a) honest, three styles
            if plan.scheme and plan.scheme[4][0] == 'R' and plan.scheme[5][0] == 'R':
                # the polygon closed from the reference's τ must give its reactions
                t1 = right[f"R^τ_{plan.scheme[2]}{plan.scheme[0]}"]
                t2 = right.get(f"R^τ_{plan.scheme[3]}{plan.scheme[1]}")
                got = polygon(M, pos, lds, solved, plan, t1, t2)
                for n_, v in got.items():
                    assert f(norm(sub(v, right[n_]))) < 1e-30 * max(f(norm(right[n_])), 1.0), (name, tag, n_)
            if plan.triad is not None:
                triad_check(M, pos, lds, solved, plan.triad, right)
            for style in ('vectors', 'segments', 'values'):
                put('honest', answer(numbers[k], plan, mu, mu_l, vecs, style, rng, mb), style)

            # (b) one seeded mistake each
            def mistaken_whole(ref_v, kind):
                pv, lv, sv, bv = ref_v[k]
                pl = plan_items(M, pv, lv, sv, plan.gi, groups, bv)
                w = {n: v for n, v, _ in pl.items}
                if set(w) != set(right):
                    return    # a load vanishes: its name is absent, not wrong
                mbw = bv if is_input and crank else None
                if seen(plan, mu, mu_l, right, w, mb, mbw):
                    put(kind, answer(numbers[k], plan, mu, mu_l, list(w.items()), 'vectors', rng, mbw),
                        'vectors')
            mistaken_whole(ref_nr, 'not_reversed')
            # weights left out: the G vectors are not drawn at all
            pv, lv, sv, bv = ref_nw[k]
            pl = plan_items(M, pv, lv, sv, plan.gi, groups, bv)
            w = {n: v for n, v, _ in pl.items}
            mbw = bv if is_input and crank else None
            if seen(plan, mu, mu_l, right, w, mb, mbw):
                put('weights_left_out', answer(numbers[k], plan, mu, mu_l, list(w.items()), 'vectors',
                                               rng, mbw), 'vectors')
            # (τ's mistakes on a dyad's scheme only: mechplan draws no τ slip
            # of a class III group, grading/forces/mistakes.rs)
            if plan.scheme and plan.scheme[4][0] == 'R' and plan.scheme[5][0] == 'R':
                s0, s1, k1, k2 = plan.scheme[:4]
                n1, n2 = f"R^τ_{k1}{s0}", f"R^τ_{k2}{s1}"
                t1, t2 = right[n1], right.get(n2)
                # τ with the wrong sign, the polygon closed with it
                got = polygon(M, pos, lds, solved, plan, mul(t1, -1), t2)
                w = dict(right)
                w.update(got)
                w[n1] = mul(t1, -1)
                if seen(plan, mu, mu_l, right, w):
                    put('tau_wrong_sign', answer(numbers[k], plan, mu, mu_l, list(w.items()), 'vectors', rng),
                        'vectors')
                # τ laid along the link instead of across it
                A, B = pos.p[plan.scheme[4][1]], pos.p[plan.scheme[5][1]]
                e = perp(unit(sub(B, A)))
                tau1 = t1[0] * e[0] + t1[1] * e[1]
                a1 = mul(unit(sub(B, A)), tau1)
                a2 = None
                if t2 is not None:
                    C = pos.p[plan.scheme[6][1]]
                    e_ = perp(unit(sub(B, C)))
                    a2 = mul(unit(sub(B, C)), t2[0] * e_[0] + t2[1] * e_[1])
                got = polygon(M, pos, lds, solved, plan, a1, a2)
                w = dict(right)
                w.update(got)
                w[n1] = a1
                if a2 is not None:
                    w[n2] = a2
                if seen(plan, mu, mu_l, right, w):
                    put('tau_along_link', answer(numbers[k], plan, mu, mu_l, list(w.items()), 'vectors', rng),
                        'vectors')
            # a reaction drawn as the action: the measured ones turned by 180°
            w = dict(right)
            for n_, v, role in plan.items:
                if role == 'measured' and f(norm(v)) / mu > max(SEEN_MM, plan.bound, MIN_ANGLE_MM):
                    w[n_] = mul(v, -1)
                    break
            if seen(plan, mu, mu_l, right, w):
                put('reaction_as_action', answer(numbers[k], plan, mu, mu_l, list(w.items()), 'vectors', rng, mb),
                    'vectors')
            # the later group's force taken with the wrong sign
            neighbours = [n_ for n_, _, role in plan.items if role == 'neighbour']
            if neighbours:
                w = neighbour_sign(M, scene, lds, pos, groups, plan)
                mbw = w.pop('M_b', None)
                if seen(plan, mu, mu_l, right, w, mb, mbw):
                    put('neighbour_wrong_sign', answer(numbers[k], plan, mu, mu_l, list(w.items()), 'vectors',
                                                       rng, mbw), 'vectors')
            # the polygon drawn at twice or half the stated μ_F
            for kind, factor in (('scale_twice', 2.0), ('scale_half', 0.5)):
                put(kind, answer(numbers[k], plan, mu, mu_l, vecs, 'segments', rng, None, seg_factor=factor),
                    'segments')
            if mb is not None:
                # (a sign flip of an M_b within a pencil's error of zero is
                # no mistake a drawing can show)
                if seen(plan, mu, mu_l, right, {}, mb, -mb):
                    put('mb_wrong_sign', answer(numbers[k], plan, mu, mu_l, vecs, 'values', rng, -mb),
                        'values')
                # M_b from the moments about the crank's other joint
                L = M.input_link
                other = [P for P in M.links[L][:2] if P != scene['input']['pivot']][0]
                Aq = pos.p[other]
                mw = mpf(0)
                for ld in lds:
                    if ld['link'] == L:
                        mw -= cross(sub(ld['at'], Aq), ld['f']) + ld['c']
                for q, x in solved.items():
                    acts = fr.pair_action(M, pos, q, x)
                    if L in acts and '0' not in (q[2], q[3]):
                        mw -= cross(sub(acts[L][1], Aq), acts[L][0]) + acts[L][2]
                if seen(plan, mu, mu_l, right, {}, mb, mw):
                    put('mb_arms_wrong_point', answer(numbers[k], plan, mu, mu_l, vecs, 'values', rng, mw),
                        'values')
    # (c) bad answers, at the first position's first plan
    pos, lds, solved, b = ref[ks[0]]
    plan = plan_items(M, pos, lds, solved, 0, groups, b)
    mu = choose_mu(plan.items)
    first = plan.items[-1][0]
    base = {'plan': 'force', 'position': numbers[ks[0]], 'links': plan.links, 'mu': mu, 'delta': DELTA,
            'segments': {first: round(f(norm(plan.items[-1][1])) / mu, 1)}}
    bad = [
        ('unknown_force', dict(base, segments={'R_99': 10.0}), '/segments/R_99'),
        ('negative_mu', dict(base, mu=-mu), '/mu'),
    ]
    for kind, a, pointer in bad:
        fn = f"bad_{kind}.json"
        with open(os.path.join(out_dir, fn), 'w') as fh:
            json.dump(a, fh, ensure_ascii=False, indent=1)
            fh.write('\n')
        labels.append({'file': f"{name}/{fn}", 'scene': f"fixtures/dynamics/{name}.json",
                       'expected': 'bad', 'pointer': pointer})
    # NaN is no JSON number: written as text
    fn = "bad_nan.json"
    text_ = json.dumps(base, ensure_ascii=False, indent=1).replace(
        f'"{first}": {base["segments"][first]}', f'"{first}": NaN')
    with open(os.path.join(out_dir, fn), 'w') as fh:
        fh.write(text_ + '\n')
    labels.append({'file': f"{name}/{fn}", 'scene': f"fixtures/dynamics/{name}.json",
                   'expected': 'bad', 'pointer': f"/segments/{first}"})
    return count


def neighbour_sign(M, scene, lds, pos, groups, plan):
    """The plan's vectors (and M_b) when the later group's reactions on
    its links are laid off with the wrong sign."""
    later = set()
    for g in (groups[plan.gi + 1:] if plan.gi is not None else groups):
        later |= set(g)

    def override(gi, links, solved, seen_):
        if gi != plan.gi:
            return
        for L in links:
            seen_[L] = [(ld['f'], ld['at'], ld['c']) for ld in lds if ld['link'] == L]
            for q, x in solved.items():
                acts = fr.pair_action(M, pos, q, x)
                if L in acts:
                    f_, at, c = acts[L]
                    other = next(iter({q[2], q[3]} - {L}))
                    if other in later:
                        f_, c = mul(f_, -1), -c
                    seen_[L].append((f_, at, c))
    solved, b = fr.solve_position(scene, M, pos, lds, groups, override)
    # the plan's own reactions from the mistaken solve; the neighbour's
    # vectors as laid off (reversed)
    pl = plan_items(M, pos, lds, solved, plan.gi, groups, b)
    w = {}
    for n_, v, role in pl.items:
        w[n_] = mul(v, -1) if role == 'neighbour' else v
    if plan.gi is None and M.kind == 'crank':
        w['M_b'] = b
    return w


def main():
    if not os.path.exists(BINARY):
        raise SystemExit("build first: cargo build --release")
    labels = []
    for d in glob.glob(os.path.join(HERE, '*', '')):
        shutil.rmtree(d)
    total = 0
    for path in sorted(glob.glob('fixtures/dynamics/*.json')):
        name = os.path.basename(path)[:-5]
        if name in SKIPPED:
            print(f"{name}: skipped ({SKIPPED[name]})", file=sys.stderr)
            continue
        out_dir = os.path.join(HERE, name)
        os.makedirs(out_dir)
        n = scene_answers(name, path, out_dir, labels)
        if n == 0:
            os.rmdir(out_dir)
            continue
        print(f"{name}: {n} answers", file=sys.stderr)
        total += n
    with open(os.path.join(HERE, 'labels.json'), 'w') as fh:
        json.dump({'skipped': SKIPPED, 'answers': labels}, fh, ensure_ascii=False, indent=1)
        fh.write('\n')
    print(f"{total} answers, {len(labels) - total} bad", file=sys.stderr)


if __name__ == '__main__':
    main()
