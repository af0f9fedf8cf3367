"""Reads a campaign's summary.nc with xarray and checks it against summary.csv
and the CF attributes post-processing promises (used by test_post_campaign).
Usage: check_summary.py CAMPAIGN_DIR N_RUNS. Prints one line per failure;
exit status 1 on any failure."""
import csv
import math
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import xarray as xr

d = Path(sys.argv[1])
n_runs = int(sys.argv[2])
bad = []
ds = xr.open_dataset(d / "summary.nc")
if ds.attrs.get("Conventions") != "CF-1.10":
    bad.append(f"Conventions = {ds.attrs.get('Conventions')!r}")
for a in ("title", "history", "source", "institution", "references", "comment"):
    if not ds.attrs.get(a):
        bad.append(f"global attribute {a} missing")
if ds.sizes.get("run") != n_runs:
    bad.append(f"run dimension {ds.sizes.get('run')} != {n_runs}")
for name, v in ds.data_vars.items():
    if "long_name" not in v.attrs:
        bad.append(f"{name}: no long_name")
    if v.dtype.kind == "f" and "units" not in v.attrs:
        bad.append(f"{name}: numeric without units")
rows = list(csv.DictReader(open(d / "summary.csv")))
if len(rows) != n_runs:
    bad.append(f"csv has {len(rows)} rows")
for i, row in enumerate(rows):
    if str(ds["run_id"].values[i]) != row["run_id"] or str(ds["status"].values[i]) != row["status"]:
        bad.append(f"row {i}: run_id/status differ between csv and nc")
    for col in ("R_inf_m", "Ecx_max_over_mgD", "T_over_Ti", "Qg_mean", "Pb_min_Pa"):
        x = float(ds[col].values[i])
        c = row[col]
        if (c == "") != math.isnan(x) or (c != "" and abs(float(c) - x) > 1e-9 * max(1.0, abs(x))):
            bad.append(f"row {i} {col}: csv {c!r} vs nc {x}")
svgs = sorted((d / "figures").glob("*.svg"))
for s in svgs:
    root = ET.parse(s).getroot()
    if not root.tag.endswith("svg"):
        bad.append(f"{s.name}: root element {root.tag}")
print("summary.nc: %d runs, %d variables; figures: %s" % (ds.sizes.get("run", 0), len(ds.data_vars),
      ", ".join(s.name for s in svgs)))
for b in bad:
    print("FAIL", b)
sys.exit(1 if bad else 0)
