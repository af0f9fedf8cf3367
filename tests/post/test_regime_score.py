#!/usr/bin/env python3
"""workflows/regime_score.py on summaries with known answers.

1. Its T_v against the hand value of tests/post/test_post_regime.c: rho_p/rho
   2.5 (rho_f 1000), D 5 mm, 25 deg: T_ff = 6.34039e-2 s, so T_v = T_ff/(2 St)
   = 3.170195e-2 s at St = 1 (1e-5 relative).
2. A summary built from Table 4.2 itself (each run at the thesis' T, with the
   thesis' label): 24/24 labels and 24/24 times. Then four labels made wrong
   and five times moved by factors 2.5, 0.3 (outside a factor 2) and 1.9, 0.6
   (inside): 20/24 labels, 21/24 times. One row removed: found 23.
3. Its 24 points are those of tests/post/table42.h, which the C tests use
   (the two copies must not drift apart).
"""
import csv
import importlib.util
import io
import math
import os
import re
import sys
import tempfile
from contextlib import redirect_stdout

here = os.path.dirname(os.path.abspath(__file__))
spec = importlib.util.spec_from_file_location(
    "regime_score", os.path.join(here, "..", "..", "workflows", "regime_score.py"))
rs = importlib.util.module_from_spec(spec)
spec.loader.exec_module(rs)

failures = 0


def check(cond, what):
    global failures
    if not cond:
        failures += 1
        print("FAIL:", what)


def write(rows):
    f = tempfile.NamedTemporaryFile("w", suffix=".csv", delete=False, newline="")
    w = csv.DictWriter(f, fieldnames=["St", "r", "regime", "T_over_Tv"])
    w.writeheader()
    w.writerows(rows)
    f.close()
    return f.name


def score(rows):
    path = write(rows)
    out = io.StringIO()
    with redirect_stdout(out):
        rs.main([path])
    os.unlink(path)
    return out.getvalue().strip().splitlines()[-1]


with open(os.path.join(here, "table42.h")) as f:
    header = f.read()
body = header[header.index("table42[] = {"):header.index("};", header.index("table42[] = {"))]
points = [tuple(float(v) for v in m.groups())
          for m in re.finditer(r"\{\s*([-\d.eE]+),\s*([-\d.eE]+),\s*([-\d.eE]+),\s*\d+\s*\}", body)]
check(points == [tuple(float(v) for v in p) for p in rs.TABLE42],
      "regime_score.py's TABLE42 differs from tests/post/table42.h (%d points there)" % len(points))

check(abs(rs.t_viscous(2.5, 1.0) / 3.170195e-2 - 1) < 1e-5, "T_v %g" % rs.t_viscous(2.5, 1.0))

rows = []
for ratio, St, T_ms in rs.TABLE42:
    r = math.sqrt(5.0 * ratio / 3.0)
    rows.append({"St": St, "r": 11.2 if ratio == 75 else round(r, 2),
                 "regime": rs.expected(St, r), "T_over_Tv": T_ms * 1e-3 / rs.t_viscous(ratio, St)})
line = score(rows)
print(line)
check(line.startswith("thesis label at 24/24, T within a factor 2 at 24/24 (24 points"), line)

for k in (0, 5, 10, 15):
    rows[k]["regime"] = "transitional"
for k, f in ((1, 2.5), (2, 0.3), (3, 2.5), (4, 1.9), (6, 0.6)):
    rows[k]["T_over_Tv"] *= f
line = score(rows)
print(line)
check(line.startswith("thesis label at 20/24, T within a factor 2 at 21/24 (24 points"), line)
line = score(rows[1:])
print(line)
check("(23 points found)" in line, line)

print("%d failed" % failures)
sys.exit(1 if failures else 0)
