#!/usr/bin/env python3
"""Reads a grainflow output file with a real client (xarray on netCDF4) and
checks what post-processing relies on: Conventions, featureType and cf_role
for the file kind, the time coordinate decoded to datetime64 from
"s since 2000-01-01 00:00:00", and values written by the C test.

usage: check_cf.py KIND PATH [time=t0,t1,...] [VAR[i,j]=value] ... [NAME[i]=text]
KIND: diagnostics | particles | probes | fields. Exit status 0 when all pass.
"""
import re
import sys

import numpy as np
import xarray as xr

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)


def main():
    kind, path = sys.argv[1], sys.argv[2]
    ds = xr.open_dataset(path)
    check(ds.attrs.get("Conventions") == "CF-1.10", "Conventions")
    check(str(ds.attrs.get("source", "")).startswith("grainflow "), "source")
    want_ft = {"particles": "trajectory", "probes": "timeSeries"}.get(kind)
    check(ds.attrs.get("featureType") == want_ft, f"featureType {ds.attrs.get('featureType')!r} != {want_ft!r}")
    check(np.issubdtype(ds["time"].dtype, np.datetime64), f"time decoded as {ds['time'].dtype}")
    check(ds["time"].attrs.get("axis") == "T" or ds["time"].encoding.get("units", "").startswith("s since"),
          "time axis")
    check(ds["time"].encoding.get("units") == "s since 2000-01-01 00:00:00", "time units")
    if kind == "particles":
        roles = [v for v in ds.variables if ds[v].attrs.get("cf_role") == "trajectory_id"]
        check(roles == ["trajectory_id"], f"cf_role trajectory_id on {roles}")
        for v in ("x", "y", "z", "u", "v", "w"):
            check(ds[v].dims == ("trajectory", "time"), f"{v} dims {ds[v].dims}")
        for v, a in (("x", "X"), ("y", "Y"), ("z", "Z")):
            check(ds[v].attrs.get("axis") == a, f"{v} axis")
    if kind == "probes":
        roles = [v for v in ds.variables if ds[v].attrs.get("cf_role") == "timeseries_id"]
        check(roles == ["station_name"], f"cf_role timeseries_id on {roles}")
    if kind == "fields":
        for v, a in (("x", "X"), ("y", "Y"), ("z", "Z")):
            check(v in ds.coords and ds[v].attrs.get("axis") == a, f"coordinate {v} with axis {a}")
        for v in ds.data_vars:
            check(ds[v].dims == ("time", "z", "y", "x"), f"{v} dims {ds[v].dims}")
    for arg in sys.argv[3:]:
        key, value = arg.split("=", 1)
        if key == "time":
            want = [float(s) for s in value.split(",")]
            origin = np.datetime64("2000-01-01T00:00:00", "ns")
            got = (ds["time"].values - origin) / np.timedelta64(1, "ns") * 1e-9
            check(len(got) == len(want) and np.allclose(got, want, rtol=0, atol=1e-6),
                  f"decoded time {got} != {want}")
            continue
        m = re.fullmatch(r"(\w+)\[([0-9,]+)\]", key)
        if not m:
            check(False, f"bad check {arg}")
            continue
        name, idx = m.group(1), tuple(int(i) for i in m.group(2).split(","))
        if name == "station_name":
            names = [s.decode() if isinstance(s, bytes) else str(s) for s in ds["station_name"].values]
            check(names[idx[0]] == value, f"station_name[{idx[0]}] = {names[idx[0]]!r} != {value!r}")
            continue
        got = float(ds[name].values[idx])
        if value == "nan":
            check(np.isnan(got), f"{name}{list(idx)} = {got} != nan")
        else:
            want = float(value)
            check(abs(got - want) <= 1e-12 * max(1.0, abs(want)), f"{name}{list(idx)} = {got!r} != {want!r}")
    ds.close()
    for f in failures:
        print(f"FAIL check_cf.py {kind} {path}: {f}", file=sys.stderr)
    print(f"check_cf.py {kind}: {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
