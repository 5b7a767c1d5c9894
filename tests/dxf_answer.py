"""A plan drawn as a CAD would save it, written with ezdxf (tests/check_dxf.rs).

Reads a JSON spec on stdin and writes the DXF file it names:
  path      the file to write
  version   "R12", "R2000", "R2018" …
  points    {name: [x, y]} in mm from the pole, y up
  pole      the pole's label ("p_v")
  scale     the scale's text ("μv = 0.005 (m/s)/mm"), or null
  origin    [x, y]: where the pole is drawn
  lines     "line", "lwpolyline" or "polyline" (each vector from the pole)
  texts     "text" or "mtext"
  block     true: everything inside a block, inserted scaled and rotated
            back to the true plan (scale 2, the block drawn at half size)
  codepage  e.g. "ANSI_1251" (R12: texts in that code page)
  frame     true: a frame and a title block with texts on their layers
  font      MTEXT's font code before each text (default "\\fArial|b0|i0;")
  index     how a point's index is written: "plain" (s2, the default;
            MTEXT stacked s\\S^2;), "space" (s 2), "underscore" (s_2),
            "unicode" (s₂), "braces" (s_{2}), "stacked" (MTEXT s\\S2^;)
  sheet     "A4" … "A0": the sheet's border, the frame inside it (20 mm
            margin at the left, 5 mm elsewhere) and a title block of
            185 x 55 mm in its lower right corner, lines touching the
            frame, its cells filled with a title block's texts (a group, a
            sheet number, the format "A3" beside a cell's corner, a
            litera "У", the scale of the drawing "1:1")
  captions  texts put beside the plan: [text, dx, dy] from the pole (mm)
  hatch     true: a HATCH (a ground's hatching) beside the plan
  dimension true: a DIMENSION measuring the first vector, rendered
  second    {"pole": …, "points": {…}, "offset": [dx, dy]}: a second plan
            (the other plan of the same position) drawn beside the first,
            its pole offset from the first's, as TEXT and LINE
  arcs      true: construction arcs and circles as a student draws them
            (a similar figure by two arcs: ARCs about the pole and the
            first point through the last point; a CIRCLE at the pole; an
            LWPOLYLINE arc — a bulge — through the last point whose end
            stands where that point's label is)
"""

import json
import sys

import ezdxf

spec = json.load(sys.stdin)
doc = ezdxf.new(spec["version"])
if spec.get("codepage"):
    doc.header["$DWGCODEPAGE"] = spec["codepage"]
if spec.get("encoding"):
    # The header's code page as saved follows the document's encoding
    # (setting the header alone, ezdxf writes ANSI_1252 back).
    doc.encoding = spec["encoding"]
if spec["version"] != "R12":
    doc.header["$INSUNITS"] = 4
msp = doc.modelspace()
ox, oy = spec["origin"]
block = spec.get("block", False)
if block:
    # Drawn at half size around (0, 0), inserted at the origin scaled 2.
    target = doc.blocks.new(name="PLAN", base_point=(0, 0))
    k = 0.5
    bx, by = 0.0, 0.0
else:
    target = msp
    k = 1.0
    bx, by = ox, oy
h = 3.5 * k


font = spec.get("font", "\\fArial|b0|i0;")
SUBSCRIPT = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def put(text, x, y):
    # Text beside its point, 1.5 mm up and right (as a person places it).
    if spec["texts"] == "mtext":
        target.add_mtext(
            "{" + font + text + "}",
            dxfattribs={"char_height": h, "insert": (x + 1.5 * k, y + 1.5 * k + h), "attachment_point": 1},
        )
    else:
        target.add_text(text, dxfattribs={"height": h, "insert": (x + 1.5 * k, y + 1.5 * k)})


put(spec["pole"], bx, by)
for name, (x, y) in spec["points"].items():
    px, py = bx + k * x, by + k * y
    kind = spec["lines"]
    if kind == "line":
        target.add_line((bx, by), (px, py))
    elif kind == "lwpolyline":
        target.add_lwpolyline([(bx, by), (px, py)])
    else:
        target.add_polyline2d([(bx, by), (px, py)])
    label = name
    index = spec.get("index", "plain")
    if len(name) >= 2 and name[1:].isdigit():
        letter, digits = name[0], name[1:]
        if index == "space":
            label = letter + " " + digits
        elif index == "underscore":
            label = letter + "_" + digits
        elif index == "unicode":
            label = letter + digits.translate(SUBSCRIPT)
        elif index == "braces":
            label = letter + "_{" + digits + "}"
        elif index == "stacked" and spec["texts"] == "mtext":
            label = letter + "\\S" + digits + "^;"
        elif spec["texts"] == "mtext":
            # A subscript as a CAD writes it: n\S^2;
            label = letter + "\\S^" + digits + ";"
    put(label, px, py)
if spec.get("scale"):
    put(spec["scale"], bx, by - 40 * k)
if block:
    msp.add_blockref("PLAN", (ox, oy), dxfattribs={"xscale": 2, "yscale": 2})
if spec.get("frame"):
    doc.layers.add("FRAME")
    doc.layers.add("TITLE")
    msp.add_lwpolyline([(0, 0), (420, 0), (420, 297), (0, 297)], close=True, dxfattribs={"layer": "FRAME"})
    msp.add_text("Plan of velocities", dxfattribs={"layer": "TITLE", "height": 5, "insert": (300, 20)})
    msp.add_text("TMM 2026", dxfattribs={"layer": "TITLE", "height": 3.5, "insert": (300, 10)})
for text, dx, dy in spec.get("captions", []):
    msp.add_text(text, dxfattribs={"height": 3.5, "insert": (ox + dx, oy + dy)})
if spec.get("second"):
    sec = spec["second"]
    sx0, sy0 = ox + sec["offset"][0], oy + sec["offset"][1]
    msp.add_text(sec["pole"], dxfattribs={"height": 3.5, "insert": (sx0 + 1.5, sy0 + 1.5)})
    for name, (x, y) in sec["points"].items():
        msp.add_line((sx0, sy0), (sx0 + x, sy0 + y))
        msp.add_text(name, dxfattribs={"height": 3.5, "insert": (sx0 + x + 1.5, sy0 + y + 1.5)})
SHEETS = {"A4": (210, 297), "A3": (420, 297), "A2": (594, 420), "A1": (841, 594), "A0": (1189, 841)}
if spec.get("sheet"):
    w, hh = SHEETS[spec["sheet"]]
    # The sheet placed so that the plan is inside its frame, above the
    # title block.
    xs = [0] + [p[0] for p in spec["points"].values()]
    ys = [0] + [p[1] for p in spec["points"].values()]
    sx, sy = ox + min(xs) - 40, oy + min(ys) - 80

    def rect(x0, y0, x1, y1):
        corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
        if spec["version"] == "R12":
            msp.add_polyline2d(corners, close=True)
        else:
            msp.add_lwpolyline(corners, close=True)

    rect(sx, sy, sx + w, sy + hh)
    fx0, fy0, fx1, fy1 = sx + 20, sy + 5, sx + w - 5, sy + hh - 5
    rect(fx0, fy0, fx1, fy1)
    # The title block: 185 x 55 in the frame's lower right corner, its
    # cells' lines each touching the frame or another of its lines.
    tx, ty = fx1 - 185, fy0
    msp.add_line((tx, ty), (tx, ty + 55))
    msp.add_line((tx, ty + 55), (fx1, ty + 55))
    for k in (1, 2, 3, 4):
        msp.add_line((tx, ty + 11 * k), (fx1, ty + 11 * k))
    for x in (17, 40, 55, 120, 135, 150):
        msp.add_line((tx + x, ty), (tx + x, ty + 55))
    for text, x, y in [
        ("Machine Design, gr. 41", 57, 30),
        ("Лист 3", 137, 14),
        ("Листов 4", 152, 14),
        ("1:1", 152, 3),
        ("Разраб.", 1, 36),
        ("Иванов И.И.", 18, 36),
        ("TMM 2026", 57, 3),
        ("Кинематический анализ", 57, 19),
    ]:
        msp.add_text(text, dxfattribs={"height": 3.5, "insert": (tx + x, ty + y)})
    # The litera and the format beside their cells' corners.
    msp.add_text("У", dxfattribs={"height": 3.5, "insert": (tx + 121.5, ty + 1.5)})
    msp.add_text("A3", dxfattribs={"height": 3.5, "insert": (fx1 - 8, fy0 - 4.5)})
if spec.get("hatch"):
    hatch = msp.add_hatch(color=3)
    hatch.set_pattern_fill("ANSI31", scale=0.5)
    hatch.paths.add_polyline_path([(ox - 40, oy - 30), (ox - 20, oy - 30), (ox - 20, oy - 25), (ox - 40, oy - 25)], is_closed=True)
pts = list(spec["points"].values())
if spec.get("dimension") and pts:
    x, y = pts[0]
    dim = msp.add_aligned_dim(p1=(ox, oy), p2=(ox + x, oy + y), distance=10)
    dim.render()
if spec.get("arcs") and len(pts) >= 2:
    import math

    (x0, y0), (x1, y1) = pts[0], pts[-1]
    for cx, cy in [(ox, oy), (ox + x0, oy + y0)]:
        r = math.hypot(ox + x1 - cx, oy + y1 - cy)
        at = math.degrees(math.atan2(oy + y1 - cy, ox + x1 - cx))
        msp.add_arc((cx, cy), r, at - 8, at + 8)
    msp.add_circle((ox, oy), 1.0)
    # An arc drawn as a polyline's bulge from where the last point's
    # label stands to past the point: read as a straight line, its end
    # would take the label.
    lx, ly = ox + x1 + 2.55, oy + y1 + 2.7
    msp.add_lwpolyline([(lx, ly, 0, 0, 0.4), (ox + x1 - 3, oy + y1 - 4, 0, 0, 0)], format="xyseb")
doc.saveas(spec["path"], encoding=spec.get("encoding"))
