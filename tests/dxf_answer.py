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
"""

import json
import sys

import ezdxf

spec = json.load(sys.stdin)
doc = ezdxf.new(spec["version"])
if spec.get("codepage"):
    doc.header["$DWGCODEPAGE"] = spec["codepage"]
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


def put(text, x, y):
    # Text beside its point, 1.5 mm up and right (as a person places it).
    if spec["texts"] == "mtext":
        target.add_mtext(
            "{\\fArial|b0|i0;" + text + "}",
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
    if spec["texts"] == "mtext" and len(name) == 2 and name[1].isdigit():
        # A subscript as a CAD writes it: n\S^2;
        label = name[0] + "\\S^" + name[1] + ";"
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
doc.saveas(spec["path"], encoding=spec.get("encoding"))
