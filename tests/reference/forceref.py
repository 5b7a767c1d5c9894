#!/usr/bin/env python3
"""forceref: an independent Newton–Euler reference for mechplan's
kinetostatics (docs/kinetostatics.md), at 60 digits.

The kinematics (positions, accelerations of the points, angular
accelerations of the links) come from mpref.py (tests/reference/README.md),
which knows nothing of mechplan's code; the forces are this file's own.
A scene of several inputs (driving cylinders: fixtures/dynamics/
arm_two_cylinders.json) is beyond mpref (one input only): its kinematics
are read from `mechplan solve --format json` (points' positions and
accelerations, links' angular accelerations, each double read as the
exact decimal it prints; cross-checked by the kinematic references
elsewhere), its forces are still this file's own, solved at 60 digits:

- the loads of the scene's `dynamics` object (docs/scene-format.md,
  "Dynamics"): per link with mass the inertia force −m·a_S at its centre
  S, the inertia couple −J·ε, the weight m·g at S; the external forces
  (a vector, or one per position) at their points and couples;
- the pairs: a revolute pair per point shared by links (the first link in
  the scene's order that lists it with each other one; R the force of the
  first on the second, as mechplan names it), a prismatic pair per slider
  (N the guide's force on the slider along the guide's left normal and C
  the guide's couple on the slider about the pair's point);
- Assur groups found by this file from the structure alone (the smallest
  set of unattached links whose pairs to themselves and the attached links
  give 3k = 2p), solved from the last attached back: each group's 3k
  equilibrium equations in its 2p unknown reaction components as one
  linear system (a class III group's 12 from its 4 links, as a dyad's 6),
  the reactions of the groups already solved known; the input link last,
  with its balancing moment (a crank) or force (a driving slider); with
  several driving sliders (cylinders) no link is attached beforehand: a
  group holds its cylinder (barrel and rod), each driving pair inside it
  adds its force F_b to the unknowns (3k = 2p + d).

Nothing here calls mechplan for a force. `--against-mechplan` compares
with `mechplan solve --format json` (the input angles of a `count` scene
are taken from mechplan's positions, as mpref's README does).

    python3 tests/reference/forceref.py SCENE.json [--inputs a,b] [--dps 60]
    python3 tests/reference/forceref.py --against-mechplan SCENE.json [--mechplan target/release/mechplan]
"""
import argparse
import itertools
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mpref  # noqa: E402
from mpref import mp, mpf  # noqa: E402

DPS = 60


# ---------------------------------------------------------------------------
# Vectors (tuples of mpf).

def add(a, b):
    return (a[0] + b[0], a[1] + b[1])


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1])


def mul(a, k):
    return (a[0] * k, a[1] * k)


def cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def norm(a):
    return mp.sqrt(a[0] ** 2 + a[1] ** 2)


def unit(a):
    n = norm(a)
    return (a[0] / n, a[1] / n)


def perp(a):
    """a turned by +90°."""
    return (-a[1], a[0])


# ---------------------------------------------------------------------------
# Kinematics from mpref, and the mechanism's pairs.

class Position:
    """One solved position: points (p, a), links (angle, epsilon), guides."""


def kinematics(scene_text, inputs):
    """mpref's solution at the given inputs (None: the scene's own), at
    DPS + 20 digits; per position a Position or None (no assembly)."""
    scene = mpref.read_scene_text(scene_text)
    M, runs, results = mpref.exact_run(scene, ','.join(inputs) if inputs else None, DPS + 20)
    out = []
    for run, R in zip(runs, results):
        if R is None:
            out.append(None)
            continue
        pos = Position()
        pos.p = {P: tuple(d['p']) for P, d in R['points'].items()}
        pos.a = {P: tuple(d['a']) for P, d in R['points'].items()}
        pos.v = {P: tuple(d['v']) for P, d in R['points'].items()}
        pos.eps = {L: d['epsilon'] for L, d in R['links'].items()}
        pose = mpref.poses(M, run[1])
        pos.guides = []
        for pr in M.pairs:
            psi, cx, cy = mpref.line_in_world(M, pose, pr, mpref.EXACT)
            pos.guides.append((mp.cos(psi), mp.sin(psi)))
        out.append(pos)
    return M, out


def several_inputs(scene):
    return isinstance(scene.get('input'), list)


class Structure:
    """A scene's links, pairs and driving pairs, read as mpref reads them
    (for a scene of several inputs, which mpref's model refuses)."""


def structure_of(scene):
    M = Structure()
    lu = mpf(1) if (scene.get('units') or {}).get('length', 'm') == 'm' else mpf(1) / 1000
    M.links = {str(k): list(v['points']) for k, v in scene['links'].items()}
    M.order = list(M.links.keys())
    M.moving = [L for L in M.order if L != '0']
    M.points = list(scene['points'].keys())
    xs = [num(xy[0]) * lu for xy in scene['points'].values()]
    ys = [num(xy[1]) * lu for xy in scene['points'].values()]
    M.S_p = mp.sqrt((max(xs) - min(xs)) ** 2 + (max(ys) - min(ys)) ** 2)
    M.pairs = []
    for k, sl in enumerate(scene.get('sliders') or []):
        line = sl.get('line') or {}
        if 'along' not in line:
            raise SystemExit(f"forceref: /sliders/{k}/line: only a line `along` two points is read "
                             "for a scene of several inputs")
        M.pairs.append({'slider': str(sl['slider']), 'guide': str(sl['guide']), 'point': sl['point'],
                        'along': tuple(line['along'])})
    M.revolutes = []
    for p in M.points:
        ls = [L for L in M.order if p in M.links[L]]
        for L2 in ls[1:]:
            M.revolutes.append((p, ls[0], L2))
    M.kind = 'cylinders'
    M.input_link = None
    M.drives = []
    for i, inp in enumerate(scene['input']):
        if inp.get('slider') is not True:
            raise SystemExit(f"forceref: /input/{i}: several inputs are read as driving sliders only")
        M.drives.append(next(pr for pr in M.pairs if pr['slider'] == str(inp['link'])))
    return M


def dec(x):
    """A double of mechplan's JSON as the exact decimal it prints."""
    return mpf(repr(float(x)))


def kinematics_from_mechplan(scene_text, mj):
    """The kinematics of a scene of several inputs, from mechplan's JSON
    (`mechplan solve --format json`): per position a Position."""
    scene = json.loads(scene_text)
    M = structure_of(scene)
    mp.dps = DPS + 20
    out = []
    for P in mj['positions']:
        pos = Position()
        pos.p = {n: (dec(d['p'][0]), dec(d['p'][1])) for n, d in P['points'].items()}
        pos.a = {n: (dec(d['a'][0]), dec(d['a'][1])) for n, d in P['points'].items()}
        pos.v = {n: (dec(d['v'][0]), dec(d['v'][1])) for n, d in P['points'].items()}
        pos.eps = {L: dec(d['epsilon']) for L, d in P['links'].items()}
        pos.guides = [unit(sub(pos.p[pr['along'][1]], pos.p[pr['along'][0]])) for pr in M.pairs]
        out.append(pos)
    return M, out


# ---------------------------------------------------------------------------
# Loads.

def at_position(x, k):
    """A per-position list's k-th value, or the value itself."""
    if isinstance(x, list) and x and isinstance(x[0], list):
        return x[k]
    if isinstance(x, list) and len(x) != 2 and all(not isinstance(v, list) for v in x):
        return x[k]
    return x


def num(x):
    return mpf(str(x))


def loads(scene, M, pos, k, variant=()):
    """The known loads at position k: dicts with name, link, f (vector),
    at (point), c (couple), origin. `variant`: the mistakes a student
    makes with them ('not_reversed', 'no_weights')."""
    dyn = scene.get('dynamics') or {}
    out = []
    g = dyn.get('g')
    sign = 1 if 'not_reversed' in variant else -1
    for L in M.order:                       # the scene's order of links
        body = (dyn.get('links') or {}).get(L)
        if body is None:
            continue
        m, J, S = num(body['m']), num(body['J']), body['centre']
        aS = pos.a[S]
        at = pos.p[S]
        out.append({'name': f"Φ_{L}", 'link': L, 'f': (sign * m * aS[0], sign * m * aS[1]),
                    'at': at, 'c': mpf(0), 'origin': 'inertia'})
        out.append({'name': f"M_Φ{L}", 'link': L, 'f': (mpf(0), mpf(0)), 'at': at,
                    'c': sign * J * pos.eps[L], 'origin': 'inertia'})
        if g is not None and 'no_weights' not in variant:
            out.append({'name': f"G_{L}", 'link': L, 'f': (m * num(g[0]), m * num(g[1])),
                        'at': at, 'c': mpf(0), 'origin': 'gravity'})
    for i, fo in enumerate(dyn.get('forces') or []):
        F = fo['F']
        if isinstance(F, dict):
            raise SystemExit(f"forceref: /dynamics/forces/{i}/F: tables are not supported here")
        F = at_position(F, k)
        out.append({'name': f"F_{fo['link']}", 'link': str(fo['link']), 'f': (num(F[0]), num(F[1])),
                    'at': pos.p[fo['point']], 'c': mpf(0), 'origin': 'external'})
    for i, mo in enumerate(dyn.get('moments') or []):
        c = mo['M']
        c = c[k] if isinstance(c, list) else c
        out.append({'name': f"M_{mo['link']}", 'link': str(mo['link']), 'f': (mpf(0), mpf(0)),
                    'at': (mpf(0), mpf(0)), 'c': num(c), 'origin': 'external'})
    return out


# ---------------------------------------------------------------------------
# Structure: pairs, Assur groups.

def pairs_of(M):
    """Every pair: ('R', point, first, second) and ('P', index, slider, guide)."""
    ps = [('R', P, L1, L2) for P, L1, L2 in M.revolutes]
    ps += [('P', i, pr['slider'], pr['guide']) for i, pr in enumerate(M.pairs)]
    return ps


def groups_of(M):
    """Assur groups in the order they attach: lists of link ids."""
    pairs = pairs_of(M)
    multi = M.kind == 'cylinders'
    attached = {'0'} if multi else {'0', M.input_link}
    rest = [L for L in M.moving if L not in attached]
    groups = []
    while rest:
        found = None
        for size in (range(1, len(rest) + 1) if multi else range(2, len(rest) + 1, 2)):
            for sub_ in itertools.combinations(rest, size):
                s = set(sub_)
                p = [q for q in pairs if (q[2] in s or q[3] in s) and q[2] in s | attached
                     and q[3] in s | attached]
                d = sum(1 for pr in M.drives if pr['slider'] in s and pr['guide'] in s) if multi else 0
                if 3 * size == 2 * len(p) + d:
                    found = list(sub_)
                    break
            if found:
                break
        if not found:
            raise SystemExit("forceref: no Assur group attaches to the links found so far")
        groups.append(found)
        attached |= set(found)
        rest = [L for L in rest if L not in found]
    return groups


# ---------------------------------------------------------------------------
# Equilibrium.

def pair_point(M, pos, q):
    if q[0] == 'R':
        return pos.p[q[1]]
    return pos.p[M.pairs[q[1]]['point']]


def pair_action(M, pos, q, x):
    """The pair's action on each of its links: {link: (force, at, couple)}.
    x: the unknowns (R: (Rx, Ry); P: (N, C))."""
    at = pair_point(M, pos, q)
    if q[0] == 'R':
        R = (x[0], x[1])
        return {q[3]: (R, at, mpf(0)), q[2]: (mul(R, -1), at, mpf(0))}
    n = perp(pos.guides[q[1]])
    N = mul(n, x[0])
    return {q[2]: (N, at, x[1]), q[3]: (mul(N, -1), at, -x[1])}


def wrench(items, about):
    """(Σ F, Σ M about `about`) of (force, at, couple) items."""
    F, Mo = (mpf(0), mpf(0)), mpf(0)
    for f, at, c in items:
        F = add(F, f)
        Mo += cross(sub(at, about), f) + c
    return F, Mo


def solve_group(M, pos, links, unknown_pairs, known, extra=None):
    """The equilibrium of `links` (3 equations each) in the components of
    `unknown_pairs` (2 each) and `extra` (a list of (name, fn(value) ->
    {link: (f, at, c)}) for a balancing moment / force); `known`:
    {link: [(f, at, c)]}. Returns ({pair: (x0, x1)}, {name: value})."""
    extra = extra or []
    cols = []
    for q in unknown_pairs:
        cols += [(q, 0), (q, 1)]
    cols += [(e[0], None) for e in extra]
    n = len(cols)
    if 3 * len(links) != n:
        raise SystemExit(f"forceref: links {links}: {3 * len(links)} equations, {n} unknowns")
    about = {L: pos.p[M.links[L][0]] for L in links}
    A = mp.matrix(n, n)
    b = mp.matrix(n, 1)
    for r, L in enumerate(links):
        F, Mo = wrench(known.get(L, []), about[L])
        b[3 * r], b[3 * r + 1], b[3 * r + 2] = -F[0], -F[1], -Mo
    for c, (q, comp) in enumerate(cols):
        if comp is None:
            acts = dict(extra)[q](mpf(1))
        else:
            x = [mpf(0), mpf(0)]
            x[comp] = mpf(1)
            acts = pair_action(M, pos, q, x)
        for r, L in enumerate(links):
            if L in acts:
                f, at, cc = acts[L]
                A[3 * r, c] += f[0]
                A[3 * r + 1, c] += f[1]
                A[3 * r + 2, c] += cross(sub(at, about[L]), f) + cc
    sol = mp.lu_solve(A, b)
    out, ex = {}, {}
    for c, (q, comp) in enumerate(cols):
        if comp is None:
            ex[q] = sol[c]
        else:
            out.setdefault(q, [mpf(0), mpf(0)])[comp] = sol[c]
    return out, ex


def drive_action(M, pos, scene):
    """The balancing moment's (force's) action per unit."""
    L = M.input_link
    if M.kind == 'crank':
        return lambda v: {L: ((mpf(0), mpf(0)), (mpf(0), mpf(0)), v)}
    k = M.pairs.index(M.input_pair)
    u = pos.guides[k]
    pr = M.input_pair
    at = pos.p[pr['point']]
    return lambda v: {pr['slider']: (mul(u, v), at, mpf(0)), pr['guide']: (mul(u, -v), at, mpf(0))}


def cylinder_action(M, pos, pr):
    """A driving pair's force F_b per unit: +u on the rod (the slider),
    -u on the barrel (the guide), u the guide's direction (s growing)."""
    u = pos.guides[M.pairs.index(pr)]
    at = pos.p[pr['point']]
    return lambda v: {pr['slider']: (mul(u, v), at, mpf(0)), pr['guide']: (mul(u, -v), at, mpf(0))}


def solve_position(scene, M, pos, lds, groups, override=None):
    """Every pair's unknowns and the balancing value, group by group from
    the last attached. `override(group_index, links, solved, known)` may
    change what a group sees (a student's mistake) before it is solved."""
    pairs = pairs_of(M)
    known = {}
    for ld in lds:
        known.setdefault(ld['link'], []).append((ld['f'], ld['at'], ld['c']))
    solved = {}
    multi = M.kind == 'cylinders'
    stages = [(i, g) for i, g in enumerate(groups)][::-1] + ([] if multi else [(None, [M.input_link])])
    attached_before = []
    acc = {'0'} if multi else {'0', M.input_link}
    for g in groups:
        attached_before.append(set(acc))
        acc |= set(g)
    balancing = None
    for gi, links in stages:
        s = set(links)
        before = attached_before[gi] if gi is not None else {'0'}
        unk = [q for q in pairs if q not in solved and (q[2] in s or q[3] in s)
               and q[2] in s | before and q[3] in s | before]
        seen = {L: list(known.get(L, [])) for L in links}
        for q, x in solved.items():
            for L, act in pair_action(M, pos, q, x).items():
                if L in s:
                    seen[L].append(act)
        if override:
            override(gi, links, solved, seen)
        extra = [('b', drive_action(M, pos, scene))] if gi is None else []
        if multi:
            extra = [(i, cylinder_action(M, pos, pr)) for i, pr in enumerate(M.drives)
                     if pr['slider'] in s and pr['guide'] in s]
        out, ex = solve_group(M, pos, links, unk, seen, extra)
        solved.update(out)
        if gi is None:
            balancing = ex['b']
        elif multi:
            balancing = balancing or {}
            balancing.update(ex)
    if multi:
        balancing = [balancing[i] for i in range(len(M.drives))]
    return solved, balancing


def as_mechplan(M, solved, balancing):
    """The result in mechplan's shape (docs/kinetostatics.md, Conventions)."""
    pairs = []
    for q, x in solved.items():
        if q[0] == 'R':
            pairs.append({'point': q[1], 'links': [q[2], q[3]], 'R': [x[0], x[1]]})
        else:
            pr = M.pairs[q[1]]
            pairs.append({'slider': pr['slider'], 'guide': pr['guide'], 'point': pr['point'],
                          'N': x[0], 'M': x[1]})
    if M.kind == 'cylinders':
        return {'pairs': pairs, 'balancing': [{'F': b} for b in balancing]}
    return {'pairs': pairs, 'balancing': {'M' if M.kind == 'crank' else 'F': balancing}}


def reference(scene_text, inputs=None, variant=(), mj=None):
    """Per position (None where it does not assemble): (pos, loads, solved, balancing).
    A scene of several inputs takes its kinematics from mechplan's JSON `mj`."""
    scene = json.loads(scene_text)
    if several_inputs(scene):
        if mj is None:
            raise SystemExit("forceref: several inputs: the kinematics are read from mechplan "
                             "(--against-mechplan, or make.py)")
        M, positions = kinematics_from_mechplan(scene_text, mj)
    else:
        M, positions = kinematics(scene_text, inputs)
    mp.dps = DPS + 20
    groups = groups_of(M)
    out = []
    for k, pos in enumerate(positions):
        if pos is None:
            out.append(None)
            continue
        lds = loads(scene, M, pos, k, variant)
        solved, b = solve_position(scene, M, pos, lds, groups)
        out.append((pos, lds, solved, b))
    return scene, M, groups, out


# ---------------------------------------------------------------------------
# Against mechplan.

def mechplan_json(scene_path, binary):
    r = subprocess.run([binary, 'solve', scene_path, '--format', 'json'],
                       capture_output=True, text=True, check=True)
    return json.loads(r.stdout)


def input_texts(mj):
    """The input values mechplan solved, as decimal text (degrees or the scene's s)."""
    out = []
    for p in mj['positions']:
        i = p['input']
        if isinstance(i, list):          # several inputs: not mpref's to solve
            out.append(','.join(repr(x['s'] if 's' in x else x['angle']) for x in i))
            continue
        out.append(repr(i['angle'] if 'angle' in i else i['s']))
    return out


def against(scene_path, binary):
    """The worst disagreement of every reaction and balancing value,
    relative to the largest force at the position (a couple over the
    mechanism's size S_p)."""
    mj = mechplan_json(scene_path, binary)
    text = open(scene_path).read()
    inputs = input_texts(mj)
    scene, M, groups, ref = reference(text, inputs, mj=mj)
    worst = mpf(0)
    rows = []
    for k, (r, theirs) in enumerate(zip(ref, mj['positions'])):
        if r is None or 'dynamics' not in theirs:
            rows.append((k, None))
            continue
        pos, lds, solved, b = r
        ours = as_mechplan(M, solved, b)
        scale = max(max(norm(x) if q[0] == 'R' else abs(x[0]) for q, x in solved.items()), mpf(1))
        if M.kind == 'cylinders':       # the largest force: the drives' F_b too
            scale = max([scale] + [abs(bi) for bi in b])
        d = mpf(0)
        tp = theirs['dynamics']['pairs']
        for o in ours['pairs']:
            if 'point' in o and 'links' in o:
                t = next(x for x in tp if x.get('links') == o['links'] and x.get('point') == o['point'])
                d = max(d, norm(sub((o['R'][0], o['R'][1]), (num(t['R'][0]), num(t['R'][1])))) / scale)
            else:
                t = next(x for x in tp if x.get('slider') == o['slider'] and x.get('guide') == o['guide'])
                k_ = next(i for i, pr in enumerate(M.pairs) if pr['slider'] == o['slider']
                          and pr['guide'] == o['guide'])
                N = mul(perp(pos.guides[k_]), o['N'])
                d = max(d, norm(sub(N, (num(t['N'][0]), num(t['N'][1])))) / scale)
                d = max(d, abs(o['M'] - num(t['M'])) / (scale * M.S_p))
        if M.kind == 'cylinders':
            for bi, tbi in zip(b, theirs['dynamics']['balancing']):
                d = max(d, abs(bi - num(tbi['F'])) / scale)
        else:
            key = 'M' if M.kind == 'crank' else 'F'
            tb = num(theirs['dynamics']['balancing'][key])
            d = max(d, abs(b - tb) / (scale * (M.S_p if key == 'M' else 1)))
        worst = max(worst, d)
        rows.append((k, d))
    return worst, rows, groups


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('scene')
    ap.add_argument('--inputs')
    ap.add_argument('--against-mechplan', action='store_true')
    ap.add_argument('--mechplan', default='target/release/mechplan')
    a = ap.parse_args()
    if a.against_mechplan:
        worst, rows, groups = against(a.scene, a.mechplan)
        print(f"{os.path.basename(a.scene)}: groups {groups}")
        for k, d in rows:
            print(f"  position {k}: " + ("not compared" if d is None else mp.nstr(d, 3)))
        print(f"  worst {mp.nstr(worst, 3)}")
        sys.exit(0 if worst < mpf('1e-9') else 1)
    text = open(a.scene).read()
    scene, M, groups, ref = reference(text, a.inputs.split(',') if a.inputs else None)
    res = []
    for r in ref:
        if r is None:
            res.append({'status': 'no assembly'})
            continue
        pos, lds, solved, b = r
        o = as_mechplan(M, solved, b)
        for p in o['pairs']:
            for k in ('R', 'N', 'M'):
                if k in p:
                    p[k] = [mp.nstr(v, DPS) for v in p[k]] if isinstance(p[k], list) else mp.nstr(p[k], DPS)
        o['balancing'] = {k: mp.nstr(v, DPS) for k, v in o['balancing'].items()}
        res.append(o)
    print(json.dumps({'scene': os.path.basename(a.scene), 'groups': groups, 'positions': res}, indent=1,
                     ensure_ascii=False))


if __name__ == '__main__':
    main()
