#!/usr/bin/env python3
"""Score a regime-map campaign against Izard (2014) Table 4.2.

usage: regime_score.py RUNS/avalanche_regime_map/summary.csv [more summary.csv ...]

For each of the table's 24 (rho_p/rho, St, T) points (the ends of its printed
ranges, paired as tests/post/test_post_regime.c pairs them; r = 12.91 for
rho_p/rho = 100) the run with the same St and r is looked up, and two things
are counted:
  - label: the classifier's label (summary column `regime`) is the one the
    thesis' boundaries give (r >= 4: viscous below St = 1, free fall above;
    r < 4: viscous below St = r/4, inertial above; Izard 2014 §4.1.4.2);
  - time: the run's T is within a factor 2 of the table's T.
T of the run is T_over_Tv x T_v, with T_v = T_ff/(2 St) and
T_ff = sqrt(2 rho_p D/(drho g sin(theta))) at D = 5 mm, rho_p = 2500 kg/m3,
theta = 25 degrees (the campaign's set-up; gf_groups.h). With several files,
the first that holds a point is used. The same 24 points are in
tests/post/table42.h; tests/post/test_regime_score.py checks this script.
"""
import csv
import math
import sys

TABLE42 = [(2.7, 0.03, 130), (2.7, 95, 25), (3, 28, 24), (4, 0.05, 605), (4, 155, 24),
           (5, 0.05, 589), (5, 51, 21), (6, 62, 21), (7, 0.15, 182), (7, 23, 23),
           (7.5, 79, 21), (10, 0.4, 71), (10, 107, 18), (15, 10, 28), (16, 0.7, 43),
           (16, 0.75, 28), (20, 220, 32), (30, 20, 32), (30, 330, 28), (40, 0.2, 243),
           (40, 177, 33), (75, 843, 31), (100, 0.04, 1200), (100, 111, 38)]
D, RHO_P, G, THETA = 5e-3, 2500.0, 9.81, math.radians(25.0)


def expected(St, r):
    if r >= 4.0:
        return "viscous" if St < 1.0 else "free-fall"
    return "viscous" if St < r / 4.0 else "inertial"


def t_viscous(ratio, St):
    drho = RHO_P - RHO_P / ratio
    t_ff = math.sqrt(2.0 * RHO_P * D / (drho * G * math.sin(THETA)))
    return t_ff / (2.0 * St)


def load(paths):
    rows = []
    for p in paths:
        with open(p, newline="") as f:
            rows += list(csv.DictReader(f))
    return rows


def find(rows, St, r):
    for row in rows:
        try:
            if abs(float(row["St"]) / St - 1) < 1e-3 and abs(float(row["r"]) - r) < 0.02:
                return row
        except (KeyError, ValueError):
            continue
    return None


def main(paths):
    rows = load(paths)
    n_label = n_time = n_found = 0
    print(f"{'rho_p/rho':>9} {'r':>6} {'St':>6} {'thesis':>10} {'label':>13} {'T/T_thesis':>10}")
    for ratio, St, T_ms in TABLE42:
        r = math.sqrt(5.0 * ratio / 3.0)
        r_grid = 11.2 if ratio == 75 else r
        row = find(rows, St, r_grid)
        want = expected(St, r)
        if row is None:
            print(f"{ratio:9g} {r:6.2f} {St:6g} {want:>10} {'(no run)':>13}")
            continue
        n_found += 1
        T = float(row["T_over_Tv"]) * t_viscous(ratio, St)
        ratio_T = T / (T_ms * 1e-3)
        label = row.get("regime", "")
        n_label += label == want
        n_time += abs(math.log10(ratio_T)) <= math.log10(2.0)
        print(f"{ratio:9g} {r:6.2f} {St:6g} {want:>10} {label:>13} {ratio_T:10.3g}")
    print(f"thesis label at {n_label}/24, T within a factor 2 at {n_time}/24 ({n_found} points found)")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
