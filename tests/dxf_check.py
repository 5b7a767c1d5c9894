#!/usr/bin/env python3
"""Check mechplan's DXF sheets against the SVG sheets of the same run.

Usage: dxf_check.py SVG_DIR DXF_DIR

Both folders hold one `draw` run's sheets (as SVG and as DXF) with their
sheets.json. Read back with ezdxf, every DXF sheet must: load and audit with
no error; be in millimetres ($INSUNITS 4); give its paper as the paper
space's limits ($PLIMMIN–$PLIMMAX); lie within its paper; hold every
text of its SVG (the same string, tspans joined; the same height; its place
to 0.01 mm; on the layer of its class); hold every line of the SVG (the plan
vectors among them: the plan points) at its place to 0.01 mm, every circle
and every arrowhead; define its layers' linetypes and lineweights and the
Cyrillic-carrying text style. Prints one line per folder and exits 1 with
the failures listed.

Every symbol of the SVG (a group `g data-symbol`: a joint, a fixed pivot, a
slider block, a centre of mass) must be one INSERT of a block defined in
the file, on the layer of its kind, at the group's base point and angle,
its block's entities drawing, inserted, the group's lines, circles,
outlines and fills where the SVG draws them; the other checks read the INSERTs'
entities in their places (ezdxf's virtual entities).
"""

import json
import os
import re
import sys
import xml.etree.ElementTree as ET

import ezdxf
from ezdxf import bbox

TOL = 0.01
SVG = "{http://www.w3.org/2000/svg}"
failures = []


def fail(sheet, what):
    failures.append(f"{sheet}: {what}")


def plain_mtext(s):
    """MTEXT content as the SVG's joined tspans: stacks unstacked."""
    s = re.sub(r"(?<!\\)\\S([^;]*?)\^([^;]*);", lambda m: m.group(1) + m.group(2), s)
    return s.replace("\\{", "{").replace("\\}", "}").replace("\\\\", "\\")


def close(a, b):
    return abs(a - b) <= TOL + 1e-9


def flat(space):
    """The entities of a space in order, each INSERT as its block's
    entities where the INSERT places them (ezdxf's virtual entities)."""
    for e in space:
        if e.dxftype() == "INSERT":
            yield from flat(e.virtual_entities())
        else:
            yield e


def svg_points(el, h):
    """The points an SVG element draws (y up), in the order of its DXF
    entities: a line's ends; a circle's fill (the ends of a diameter, as
    (centre, radius, ±1)) and centre; a polygon's fill and outline (its vertices)."""
    tag = el.tag[len(SVG):]
    filled = el.get("fill", "black") != "none"
    stroked = el.get("stroke") not in (None, "none")
    if tag == "line":
        return [(float(el.get("x1")), h - float(el.get("y1"))), (float(el.get("x2")), h - float(el.get("y2")))]
    if tag == "circle":
        x, y, r = float(el.get("cx")), h - float(el.get("cy")), float(el.get("r"))
        # A fill's two half circles start anywhere on the circle (a
        # block's turns them): a point at r from the centre, the two
        # opposite.
        return ([(x, y, r, 1), (x, y, r, -1)] if filled else []) + ([(x, y)] if stroked else [])
    if tag == "polygon":
        v = [float(t) for t in el.get("points").replace(",", " ").split()]
        pts = [(v[i], h - v[i + 1]) for i in range(0, len(v) - 1, 2)]
        return (pts if filled else []) + (pts if stroked else [])
    return []


def dxf_points(e):
    """The points an entity draws, as svg_points reads its element."""
    t = e.dxftype()
    if t == "LINE":
        return [(e.dxf.start.x, e.dxf.start.y), (e.dxf.end.x, e.dxf.end.y)]
    if t == "CIRCLE":
        return [(e.dxf.center.x, e.dxf.center.y)]
    if t == "LWPOLYLINE":
        return [(p[0], p[1]) for p in e.get_points("xy")]
    if t == "HATCH":
        return [(v[0], v[1]) for path in e.paths for v in path.vertices]
    return []


def lands(p, got, i):
    """Whether the `i`th point drawn, of `got`, is `p` of svg_points: the
    same point, or for a circle's fill a point on the circle opposite its
    neighbour (the point after it for +1, before it for −1)."""
    q = got[i]
    if len(p) == 2:
        return close(p[0], q[0]) and close(p[1], q[1])
    x, y, r, k = p
    other = got[i + k]
    on = close(((q[0] - x) ** 2 + (q[1] - y) ** 2) ** 0.5, r)
    return on and close(q[0] + other[0], 2 * x) and close(q[1] + other[1], 2 * y)


def check_symbols(name, root, doc, h):
    """Every symbol's group of the SVG (`g data-symbol`) is one INSERT, in
    order, on the layer of its kind, of a block defined in the file whose
    entities, inserted, draw the group's lines, circles, outlines and fills
    where the SVG draws them (to 0.01 mm). Returns the number of symbols and of
    blocks."""
    groups = [g for g in root.iter(SVG + "g") if g.get("data-symbol")]
    inserts = list(doc.modelspace().query("INSERT"))
    if len(groups) != len(inserts):
        fail(name, f"{len(groups)} symbols in the SVG, {len(inserts)} INSERTs in the DXF")
    names = set()
    for g, ins in zip(groups, inserts):
        kind = g.get("data-symbol")
        block = doc.blocks.get(ins.dxf.name)
        if block is None:
            fail(name, f"{kind}: INSERT of the undefined block {ins.dxf.name}")
            continue
        names.add(ins.dxf.name)
        if not ins.dxf.name.startswith(kind.upper()):
            fail(name, f"{kind} inserted as the block {ins.dxf.name}")
        if ins.dxf.layer != kind:
            fail(name, f"{kind} inserted on layer {ins.dxf.layer}")
        at = (float(g.get("data-x")), h - float(g.get("data-y")))
        if not (close(ins.dxf.insert.x, at[0]) and close(ins.dxf.insert.y, at[1])):
            fail(name, f"{kind} inserted at {ins.dxf.insert}, not {at}")
        if not close(ins.dxf.rotation, float(g.get("data-angle") or 0)):
            fail(name, f"{kind} turned by {ins.dxf.rotation}°, not {g.get('data-angle') or 0}°")
        want = [p for el in g.iter() for p in svg_points(el, h)]
        drawn = [e for e in ins.virtual_entities() if e.dxftype() in ("LINE", "CIRCLE", "LWPOLYLINE", "HATCH")]
        got = [p for e in drawn for p in dxf_points(e)]
        if len(want) != len(got) or not all(lands(p, got, i) for i, p in enumerate(want)):
            fail(name, f"{kind} at {at}: inserted {got}, drawn in the SVG at {want}")
    return len(groups), len(names)


def check_sheet(name, svg_path, dxf_path):
    root = ET.parse(svg_path).getroot()
    w, h = (float(v) for v in root.get("viewBox").split()[2:4])
    doc = ezdxf.readfile(dxf_path)
    auditor = doc.audit()
    if auditor.has_errors:
        fail(name, f"audit errors: {[e.message for e in auditor.errors][:5]}")
    if doc.header.get("$INSUNITS") != 4:
        fail(name, f"$INSUNITS is {doc.header.get('$INSUNITS')}, not 4 (mm)")
    plim = (doc.header.get("$PLIMMIN"), doc.header.get("$PLIMMAX"))
    if None in plim or not (close(plim[0][0], 0) and close(plim[0][1], 0) and close(plim[1][0], w) and close(plim[1][1], h)):
        fail(name, f"$PLIMMIN–$PLIMMAX {plim} is not the paper 0, 0 – {w}×{h}")
    if doc.dxfversion < "AC1015":
        fail(name, f"version {doc.dxfversion} is before R2000")
    msp = doc.modelspace()
    n_symbols, n_blocks = check_symbols(name, root, doc, h)
    ents = list(flat(msp))
    ext = bbox.extents(msp, fast=True)
    if ext.has_data:
        lo, hi = ext.extmin, ext.extmax
        if lo.x < -TOL or lo.y < -TOL or hi.x > w + TOL or hi.y > h + TOL:
            fail(name, f"extents {lo} – {hi} outside the paper {w}×{h}")
    # The style and the layers' definitions.
    style = doc.styles.get("lc_opengost-ar")
    if style is None or not style.dxf.font.lower().endswith(".ttf"):
        fail(name, "no text style lc_opengost-ar with a TrueType font")
    for layer in doc.layers:
        lt = layer.dxf.linetype
        if lt not in doc.linetypes:
            fail(name, f"layer {layer.dxf.name}: linetype {lt} not defined")
        if layer.dxf.name not in ("0", "Defpoints") and layer.dxf.lineweight <= 0:
            fail(name, f"layer {layer.dxf.name}: no lineweight")
    for cls, lt in (("dashed", "DASHED"), ("dash-dot", "DASHDOT"), ("dash-dot-dot", "DIVIDE")):
        if cls in doc.layers and doc.layers.get(cls).dxf.linetype != lt:
            fail(name, f"layer {cls} is not of linetype {lt}")

    # Texts, in order.
    texts = [e for e in ents if e.dxftype() in ("TEXT", "MTEXT")]
    want = []
    for t in root.iter(SVG + "text"):
        s = "".join(t.itertext())
        if s.strip():
            want.append((t, s))
    if len(texts) != len(want):
        fail(name, f"{len(want)} texts in the SVG, {len(texts)} in the DXF")
    for (t, s), e in zip(want, texts):
        x, y = float(t.get("x")), h - float(t.get("y"))
        size = float(t.get("font-size"))
        cls = t.get("class") or ""
        layer = f"text-{cls}" if cls else "text"
        if e.dxftype() == "TEXT":
            got = e.dxf.text
            at = e.dxf.insert if e.dxf.halign == 0 else e.dxf.align_point
        else:
            got = plain_mtext(e.text)
            at = e.dxf.insert
        # The DXF's turning arrows are the closed ones of the same sense,
        # which LibreCAD's ГОСТ font has, and "->" for → (style.rs, escape).
        if got != s.replace("↺", "⥀").replace("↻", "⥁").replace("→", "->"):
            fail(name, f"text {s!r} written as {got!r}")
        if not close(e.dxf.height if e.dxftype() == "TEXT" else e.dxf.char_height, size):
            fail(name, f"text {s!r}: height not {size}")
        if e.dxf.layer != layer:
            fail(name, f"text {s!r} on layer {e.dxf.layer}, not {layer}")
        # A text narrowed to its cell (textLength) is narrowed in the DXF
        # too (TEXT's width factor), any other one is not.
        factor = e.dxf.width if e.dxftype() == "TEXT" else 1.0
        if t.get("textLength") is not None:
            if not 0.1 <= factor < 1.0:
                fail(name, f"text {s!r} narrowed to {t.get('textLength')} mm: width factor {factor}")
        elif factor != 1.0:
            fail(name, f"text {s!r}: width factor {factor}, not narrowed on the SVG")
        if not (close(at.x, x) and close(at.y, y)):
            fail(name, f"text {s!r} at ({at.x}, {at.y}), not ({x}, {y})")

    # Lines (the plans' vectors: their ends are the plan points), in order.
    lines = [e for e in ents if e.dxftype() == "LINE"]
    svg_lines = list(root.iter(SVG + "line"))
    if len(lines) != len(svg_lines):
        fail(name, f"{len(svg_lines)} lines in the SVG, {len(lines)} in the DXF")
    for l, e in zip(svg_lines, lines):
        a = (float(l.get("x1")), h - float(l.get("y1")))
        b = (float(l.get("x2")), h - float(l.get("y2")))
        s, t = e.dxf.start, e.dxf.end
        if not all(close(p, q) for p, q in zip((s.x, s.y, t.x, t.y), a + b)):
            fail(name, f"line {l.get('id') or l.get('class')} at {s}–{t}, not {a}–{b}")
        if e.dxf.layer != (l.get("class") or "symbol"):
            fail(name, f"line on layer {e.dxf.layer}, not {l.get('class')}")
    # Circles drawn with an outline, and the arrowheads.
    circles = [e for e in ents if e.dxftype() == "CIRCLE"]
    svg_circles = [c for c in root.iter(SVG + "circle") if c.get("stroke") not in (None, "none")]
    if len(circles) != len(svg_circles):
        fail(name, f"{len(svg_circles)} circles in the SVG, {len(circles)} in the DXF")
    for c, e in zip(svg_circles, circles):
        o = (float(c.get("cx")), h - float(c.get("cy")))
        if not (close(e.dxf.center.x, o[0]) and close(e.dxf.center.y, o[1]) and close(e.dxf.radius, float(c.get("r")))):
            fail(name, f"circle at {e.dxf.center}, not {o}")
    arrows = [p for p in root.iter(SVG + "polygon") if p.get("class") == "arrow"]
    solids = [e for e in ents if e.dxftype() == "SOLID"]
    if len(arrows) != len(solids):
        fail(name, f"{len(arrows)} arrowheads in the SVG, {len(solids)} SOLIDs in the DXF")
    return len(texts), len(lines), n_symbols, n_blocks


def main():
    svg_dir, dxf_dir = sys.argv[1], sys.argv[2]
    ms = json.load(open(os.path.join(svg_dir, "sheets.json")))
    md = json.load(open(os.path.join(dxf_dir, "sheets.json")))
    if len(ms["sheets"]) != len(md["sheets"]):
        fail(dxf_dir, "sheets.json lists another number of sheets")
    n_texts = n_lines = n_symbols = n_blocks = 0
    for s, d in zip(ms["sheets"], md["sheets"]):
        stem = os.path.splitext(s["file"])[0]
        if d["file"] != stem + ".dxf":
            fail(dxf_dir, f"sheets.json lists {d['file']}, not {stem}.dxf")
            continue
        if d["scales"] != s["scales"] or d["size"] != s["size"]:
            fail(stem, "the scales or size in sheets.json differ from the SVG run's")
        t, l, k, b = check_sheet(stem, os.path.join(svg_dir, s["file"]), os.path.join(dxf_dir, d["file"]))
        n_texts += t
        n_lines += l
        n_symbols += k
        n_blocks += b
    print(
        f"{dxf_dir}: {len(md['sheets'])} sheets, {n_texts} texts, {n_lines} lines, "
        f"{n_symbols} symbols (INSERTs of {n_blocks} blocks) checked"
    )
    if failures:
        print(f"{len(failures)} failures:", file=sys.stderr)
        for f in failures[:50]:
            print("  " + f, file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
