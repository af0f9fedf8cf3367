#!/usr/bin/env python3
"""Parses a grainflow SVG figure as XML (so it is well-formed) and checks
what was drawn against what the C test asked for.

usage: check_svg.py FILE CHECK...
  markers=N              number of data markers (<g class="marker">)
  shapes=circle:2,polygon:1,rect:3   marker count per drawn shape
  reflines=N             number of reference-line pieces
  curves=N               number of data polylines
  regions=N              number of shaded regions
  legend=N               number of legend rows
  xticks=v1,v2,...       major tick values of the x axis, in order (also yticks)
  xlabels=t1|t2|...      rendered tick-label text of the x axis (also ylabels)
  xscale=log|linear      axis scales used by the inverse-map checks (also yscale)
  point=X,Y              a marker with data (X, Y) sits where the axis ticks say
                         (less its data-dx, the shift that sets variants side by side)
  apart=X,Y,N            N markers with data (X, Y), each where the axes say once its
                         data-dx is removed, drawn at least 8 px apart (all visible)
  hollow=N               number of hollow (outlined) data markers
  legend_labels=t1;t2    the legend rows' texts, in order
  curve_start=K,X,Y      the first vertex of data curve K is at data (X, Y)
  refline_through=X,Y    some reference line has a vertex at data (X, Y)
  refline_law=K,L,E      every vertex of reference line K lies on y = L x^E (to 0.05 px)
  title=TEXT             the title text (after XML unescaping)
  caption~TEXT           the caption contains TEXT
The pixel position expected for a value is interpolated between the first and
last major tick marks of the axis (linearly in the value or its log10), i.e.
the check inverts the axis from what a reader of the figure sees.
"""
import math
import re
import sys
import xml.etree.ElementTree as ET

NS = "{http://www.w3.org/2000/svg}"
# checks that count the elements of a class: key -> (class, tag, what the message calls them)
COUNTED = {
    "reflines": ("refline", "polyline", "reflines"),
    "regions": ("region", "polygon", "regions"),
    "curves": ("curve", "polyline", "curves"),
    "legend": ("legend-label", "text", "legend rows"),
}
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)


def by_class(root, cls, tag=None):
    out = []
    for el in root.iter():
        if el.get("class") == cls and (tag is None or el.tag == NS + tag):
            out.append(el)
    return out


def group(root, cls):
    g = by_class(root, cls, "g")
    return g[0] if g else None


def axis_ticks(root, axis):
    """(values, pixel positions, label texts) of the major ticks of an axis."""
    lines = [el for el in group(root, f"{axis}-axis") if el.get("class") == "tick-major"]
    labels = [el for el in group(root, f"{axis}-tick-labels") if el.get("class") == "tick-label"]
    pos = [float(el.get("x1" if axis == "x" else "y1")) for el in lines]
    vals = [float(el.get("data-value")) for el in labels]
    texts = ["".join(el.itertext()) for el in labels]
    return vals, pos, texts


def expected_px(root, axis, scale, v):
    vals, pos, _ = axis_ticks(root, axis)
    t = math.log10 if scale == "log" else (lambda u: u)
    a, b = 0, len(vals) - 1
    return pos[a] + (t(v) - t(vals[a])) / (t(vals[b]) - t(vals[a])) * (pos[b] - pos[a])


def data_of_px(root, axis, scale, px):
    """Inverse of expected_px: the value at pixel px along the axis."""
    vals, pos, _ = axis_ticks(root, axis)
    a, b = 0, len(vals) - 1
    if scale == "log":
        la, lb = math.log10(vals[a]), math.log10(vals[b])
        return 10 ** (la + (px - pos[a]) / (pos[b] - pos[a]) * (lb - la))
    return vals[a] + (px - pos[a]) / (pos[b] - pos[a]) * (vals[b] - vals[a])


def translate(el):
    m = re.match(r"translate\(([-0-9.e]+),([-0-9.e]+)\)", el.get("transform"))
    return float(m.group(1)), float(m.group(2))


def close(a, b, rel=1e-9):
    return abs(a - b) <= rel * max(1.0, abs(a), abs(b))


def main():
    path = sys.argv[1]
    tree = ET.parse(path)   # raises on malformed XML: the test fails
    root = tree.getroot()
    check(root.tag == NS + "svg" and root.get("version") == "1.1", "root is <svg version=1.1>")
    scales = {"x": "linear", "y": "linear"}
    for arg in sys.argv[2:]:
        m = re.match(r"(\w+)(=|~)(.*)", arg, re.S)
        key, op, val = m.group(1), m.group(2), m.group(3)
        markers = by_class(root, "marker", "g")
        if key == "markers":
            check(len(markers) == int(val), f"markers: {len(markers)} != {val}")
        elif key == "shapes":
            want = dict((k, int(n)) for k, n in (s.split(":") for s in val.split(",")))
            got = {}
            for mk in markers:
                tag = list(mk)[-1].tag.replace(NS, "")
                got[tag] = got.get(tag, 0) + 1
            check(got == want, f"shapes: {got} != {want}")
        elif key in COUNTED:
            cls, tag, what = COUNTED[key]
            n = len(by_class(root, cls, tag))
            check(n == int(val), f"{what}: {n} != {val}")
        elif key in ("xticks", "yticks"):
            vals, pos, _ = axis_ticks(root, key[0])
            want = [float(s) for s in val.split(",")]
            check(len(vals) == len(want) and all(close(a, b) for a, b in zip(vals, want)),
                  f"{key}: {vals} != {want}")
            check(len(pos) == len(vals), f"{key}: {len(pos)} tick marks for {len(vals)} labels")
        elif key in ("xlabels", "ylabels"):
            _, _, texts = axis_ticks(root, key[0])
            check(texts == val.split("|"), f"{key}: {texts} != {val.split('|')}")
        elif key in ("xscale", "yscale"):
            scales[key[0]] = val
        elif key == "point":
            x, y = (float(s) for s in val.split(","))
            hit = [mk for mk in markers if close(float(mk.get("data-x")), x) and close(float(mk.get("data-y")), y)]
            check(len(hit) == 1, f"point {x},{y}: {len(hit)} markers")
            if hit:
                px, py = translate(hit[0])
                px -= float(hit[0].get("data-dx", "0"))
                ex, ey = expected_px(root, "x", scales["x"], x), expected_px(root, "y", scales["y"], y)
                # coordinates are printed with 2 decimals: 0.02 px covers the rounding of three numbers
                check(abs(px - ex) < 0.02 and abs(py - ey) < 0.02,
                      f"point {x},{y} at ({px},{py}), axes say ({ex:.3f},{ey:.3f})")
        elif key == "apart":
            x, y, n = (float(s) for s in val.split(","))
            hit = [mk for mk in markers if close(float(mk.get("data-x")), x) and close(float(mk.get("data-y")), y)]
            check(len(hit) == int(n), f"apart {x},{y}: {len(hit)} markers, expected {int(n)}")
            ex, ey = expected_px(root, "x", scales["x"], x), expected_px(root, "y", scales["y"], y)
            drawn = [translate(mk) for mk in hit]
            for mk, (px, py) in zip(hit, drawn):
                px -= float(mk.get("data-dx", "0"))
                check(abs(px - ex) < 0.02 and abs(py - ey) < 0.02, f"apart {x},{y}: a marker at data ({px},{py})")
            gaps = [math.hypot(a[0] - b[0], a[1] - b[1]) for i, a in enumerate(drawn) for b in drawn[i + 1:]]
            check(all(g >= 8.0 for g in gaps), f"apart {x},{y}: centres {gaps} px apart, < 8 px hides one")
        elif key == "hollow":
            n = sum(1 for mk in markers if mk.get("fill") == "white")
            check(n == int(val), f"hollow markers: {n} != {val}")
        elif key == "legend_labels":
            t = ["".join(el.itertext()) for el in by_class(root, "legend-label", "text")]
            check(t == val.split(";"), f"legend labels {t} != {val.split(';')}")
        elif key == "curve_start":
            k, x, y = val.split(",")
            curves = by_class(root, "curve", "polyline")
            first = curves[int(k)].get("points").split()[0].split(",")
            px, py = float(first[0]), float(first[1])
            ex = expected_px(root, "x", scales["x"], float(x))
            ey = expected_px(root, "y", scales["y"], float(y))
            check(abs(px - ex) < 0.02 and abs(py - ey) < 0.02,
                  f"curve {k} starts at ({px},{py}), axes say ({ex:.3f},{ey:.3f})")
        elif key == "refline_through":
            x, y = (float(v) for v in val.split(","))
            ex, ey = expected_px(root, "x", scales["x"], x), expected_px(root, "y", scales["y"], y)
            found = False
            for line in by_class(root, "refline", "polyline"):
                for pt in line.get("points").split():
                    px, py = (float(v) for v in pt.split(","))
                    found = found or (abs(px - ex) < 0.02 and abs(py - ey) < 0.02)
            check(found, f"no reference line through ({x},{y}) at ({ex:.2f},{ey:.2f})")
        elif key == "refline_law":
            k, lam, ex_ = val.split(",")
            line = by_class(root, "refline", "polyline")[int(k)]
            worst = 0.0
            for pt in line.get("points").split():
                px, py = (float(v) for v in pt.split(","))
                x = data_of_px(root, "x", scales["x"], px)
                want_py = expected_px(root, "y", scales["y"], float(lam) * x ** float(ex_))
                worst = max(worst, abs(py - want_py))
            check(worst < 0.05, f"reference line {k} is off y = {lam} x^{ex_} by {worst:.3f} px")
        elif key == "title":
            t = by_class(root, "title", "text")
            check(len(t) == 1 and "".join(t[0].itertext()) == val, f"title {[''.join(x.itertext()) for x in t]}")
        elif key == "caption":
            t = by_class(root, "caption", "text")
            check(len(t) == 1 and val in "".join(t[0].itertext()), f"caption lacks {val!r}")
        else:
            check(False, f"unknown check {arg}")
    for f in failures:
        print(f"FAIL check_svg.py {path}: {f}", file=sys.stderr)
    print(f"check_svg.py {path}: {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
