"""A teacher's overlay (check --dxf) read back with ezdxf (tests/check_dxf.rs).

Reads a JSON spec on stdin:
  original  the student's DXF file
  copy      the copy with the overlay
  points    {name: [x, y]}: where the right plan's points are in the file
            (drawing units, y up)
Prints a JSON report: the copy's audit errors, the entities by type
outside the overlay's layer in the original and in the copy (model
space, with blocks exploded), the overlay layer's colour and entities by
type, and the points with no vertex of the overlay within 0.01 units.
"""

import json
import sys
from collections import Counter

import ezdxf

LAYER = "MECHPLAN-CHECK"
spec = json.load(sys.stdin)


def flat(msp):
    for e in msp:
        if e.dxftype() == "INSERT":
            yield from flat(e.virtual_entities())
        else:
            yield e


def counts(doc, overlay):
    return Counter(
        e.dxftype() for e in flat(doc.modelspace()) if (e.dxf.layer.upper() == LAYER) == overlay
    )


def vertices(e):
    t = e.dxftype()
    if t == "LINE":
        return [e.dxf.start, e.dxf.end]
    if t == "LWPOLYLINE":
        return [(p[0], p[1]) for p in e.get_points()]
    if t == "POLYLINE":
        return [v.dxf.location for v in e.vertices]
    if t == "CIRCLE":
        return [e.dxf.center]
    return []


original = ezdxf.readfile(spec["original"])
copy = ezdxf.readfile(spec["copy"])
audit = copy.audit()
ends = [v for e in copy.modelspace() if e.dxf.layer.upper() == LAYER for v in vertices(e)]
missing = [
    n
    for n, (x, y) in spec["points"].items()
    if not any(abs(v[0] - x) <= 0.01 and abs(v[1] - y) <= 0.01 for v in ends)
]
print(
    json.dumps(
        {
            "audit_errors": [str(e.message) for e in audit.errors],
            "original": counts(original, False),
            "copy": counts(copy, False),
            "overlay": counts(copy, True),
            "layer_color": copy.layers.get(LAYER).color if LAYER in copy.layers else None,
            "missing": missing,
        }
    )
)
