"""The geometric convergence report (run.sh): markdown tables on stdout and a CSV.

usage: report.py RESULTS.jsonl OUT.csv TIMES.log LOAD_START LOAD_END
RESULTS: geometry_study's JSON lines, each with a "case" added by run.sh.
"""
import csv
import datetime
import json
import math
import os
import subprocess
import sys

SECOND_ORDER = 1.8        # least-squares slope target for cut cells
FIRST_ORDER = (0.6, 1.4)  # staircase and midpoint M3C
PER_LEVEL = 3.5           # cut cells: each error falls by at least this factor per level
TOTAL_TOLERANCE = 1e-10   # layers6: total volume = box volume, relative


def slope(h, e):
    """Least-squares slope of log(e) against log(h); None when fewer than 2 usable points."""
    pts = [(math.log(a), math.log(b)) for a, b in zip(h, e) if b > 0]
    if len(pts) < 2:
        return None
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    return sum((p[0] - mx) * (p[1] - my) for p in pts) / sxx


def factors(e):
    return [a / b if b > 0 else math.inf for a, b in zip(e, e[1:])]


def rate(coarse, fine, h_coarse, h_fine):
    """The factor by which an error fell from one level to the next, and the order it means."""
    if fine <= 0 or coarse <= 0:
        return "—"
    factor = coarse / fine
    return f"{factor:.2f}× ({math.log(factor) / math.log(h_coarse / h_fine):.2f})"


def fmt(x, spec=".3e"):
    return "—" if x is None else format(x, spec)


def total_relative(r):
    return abs(r["volume"] - r["exact_volume"]) / r["exact_volume"]


def quantities(case, method, rows):
    """(name, getter) of the errors reported for a case."""
    single = case in ("ball", "torus", "ellipsoid")
    out = [("volume error" if single else "max region volume error",
            (lambda r: r["volume_error"]) if single else (lambda r: r["max_region_error"]))]
    if "hausdorff" in rows[0]:
        out.append(("Hausdorff (two-sided)", lambda r: r["hausdorff"]["hausdorff"]))
    for name in rows[0].get("features", {}):
        out.append((f"Hausdorff within 2h of the {name}'s sharp edges",
                    lambda r, n=name: r["features"][n]["hausdorff"]))
    if case == "layers6":
        out.append(("total volume vs box (relative)", total_relative))
    return out


def verdict(method, name, rows, values):
    """Target and whether it is met, over the last four levels (the coarsest are often
    pre-asymptotic: the volume error changes sign there)."""
    h = [r["h"] for r in rows][-4:]
    values = values[-4:]
    s = slope(h, values)
    if name.startswith("total volume"):
        return f"≤ {TOTAL_TOLERANCE:g}", max(values) <= TOTAL_TOLERANCE
    if method == "cutcell":
        if name in ("volume error", "Hausdorff (two-sided)"):
            return (f"slope ≥ {SECOND_ORDER}, each level ≥ {PER_LEVEL}×",
                    s is not None and s >= SECOND_ORDER and min(factors(values)) >= PER_LEVEL)
        return f"slope ≥ {SECOND_ORDER}", s is not None and s >= SECOND_ORDER
    if name.startswith("Hausdorff"):
        return (f"slope in [{FIRST_ORDER[0]}, {FIRST_ORDER[1]}]",
                s is not None and FIRST_ORDER[0] <= s <= FIRST_ORDER[1])
    return "reported", None


def main():
    results, csv_path, times_path, load_start, load_end = sys.argv[1:6]
    rows = [json.loads(line) for line in open(results) if line.startswith("{")]
    groups = {}
    for r in rows:
        groups.setdefault((r["case"], r["method"]), []).append(r)

    cpu = subprocess.run(["lscpu"], capture_output=True, text=True).stdout
    model = next((l.split(":", 1)[1].strip() for l in cpu.splitlines() if l.startswith("Model name")), "")
    print(f"# Geometric convergence ({datetime.date.today()}, {os.cpu_count()} cores, {model})\n")
    print(f"Load average at start {load_start}, at the end {load_end} (a shared machine: wall times")
    print("grow with the load, CPU times do not). h is the octree cell edge at the level; errors are")
    print("absolute (volumes in the domain's units³). Hausdorff: max over mesh-boundary samples of the")
    print("exact distance to the analytic surface (mesh→surface) and over dense samples of the")
    print("analytic surface of the distance to the nearest boundary triangle (surface→mesh), samples")
    print("h/6 apart; the two-sided distance is the larger. Factor: error at the previous level")
    print("divided by this one (second order: 4×, first order: 2×), with the pairwise order in")
    print("brackets. Slopes: least squares of log(error) against log(h), over all levels and over")
    print("the last four.\n")

    print("## Summary\n")
    print("| case | method | error | levels | slope (all) | slope (last 4) | smallest factor (last 4) | target (last 4 levels) | met |")
    print("|---|---|---|---|---:|---:|---:|---|---|")
    for (case, method), g in groups.items():
        h = [r["h"] for r in g]
        for name, get in quantities(case, method, g):
            e = [get(r) for r in g]
            target, ok = verdict(method, name, g, e)
            met = "—" if ok is None else ("yes" if ok else "**no**")
            print(f"| {case} | {method} | {name} | {g[0]['level']}–{g[-1]['level']} "
                  f"| {fmt(slope(h, e), '.2f')} | {fmt(slope(h[-4:], e[-4:]), '.2f')} "
                  f"| {min(factors(e[-4:])):.2f}× | {target} | {met} |")
    print()

    for (case, method), g in groups.items():
        print(f"## {case}, {method}\n")
        names = quantities(case, method, g)
        head = "| level | h | cells | cut cells |"
        rule = "|---:|---:|---:|---:|"
        for name, _ in names:
            head += f" {name} | factor |"
            rule += "---:|---:|"
        if "hausdorff" in g[0]:
            head += " mesh→surface | surface→mesh |"
            rule += "---:|---:|"
        print(head)
        print(rule)
        series = [[get(r) for r in g] for _, get in names]
        for i, r in enumerate(g):
            line = f"| {r['level']} | {r['h']:.4g} | {r['cells']:,} | {r['cut_cells']:,} |"
            for e in series:
                line += f" {e[i]:.3e} | {'' if i == 0 else rate(e[i - 1], e[i], g[i - 1]['h'], r['h'])} |"
            if "hausdorff" in r:
                line += f" {r['hausdorff']['mesh_to_surface']:.3e} | {r['hausdorff']['surface_to_mesh']:.3e} |"
            print(line)
        if g[-1].get("features"):
            print("\nWhere the largest distances are at the finest level (x, y, z):\n")
            for name, f in [("all", g[-1]["hausdorff"])] + list(g[-1]["features"].items()):
                at = lambda v: "(" + ", ".join(f"{x:.3f}" for x in v) + ")"
                print(f"- {name}: mesh→surface {f['mesh_to_surface']:.2e} at {at(f['mesh_worst'])}, "
                      f"surface→mesh {f['surface_to_mesh']:.2e} at {at(f['surface_worst'])}")
        if case not in ("ball", "torus", "ellipsoid"):
            print("\nRegion volume errors (mesh − exact) at the finest level: " + ", ".join(
                f"{k}: {v['error']:+.2e}" for k, v in g[-1]["regions"].items()))
        print()

    print("## Run times\n")
    print("| run | time |")
    print("|---|---|")
    wall = user = 0.0
    for line in open(times_path):
        if ":" in line and " s wall " in line:
            run, t = line.strip().split(": ", 1)
            print(f"| {run} | {t} |")
            words = t.split()
            wall += float(words[0])
            user += float(words[3])
    print(f"| all | {wall:.0f} s wall {user:.0f} s user |")

    fields = ["case", "method", "level", "h", "cells", "cut_cells", "mesh_seconds",
              "measure_seconds", "volume", "exact_volume", "volume_error", "max_region_error",
              "total_relative_error", "mesh_to_surface", "surface_to_mesh", "hausdorff"]
    feature_names = sorted({n for r in rows for n in r.get("features", {})})
    for n in feature_names:
        fields += [f"{n}_edges_mesh_to_surface", f"{n}_edges_surface_to_mesh"]
    with open(csv_path, "w", newline="") as out:
        w = csv.DictWriter(out, fieldnames=fields)
        w.writeheader()
        for r in rows:
            row = {k: r.get(k, "") for k in fields}
            row["total_relative_error"] = total_relative(r)
            if "hausdorff" in r:
                for k in ("mesh_to_surface", "surface_to_mesh", "hausdorff"):
                    row[k] = r["hausdorff"][k]
            for n, f in r.get("features", {}).items():
                row[f"{n}_edges_mesh_to_surface"] = f["mesh_to_surface"]
                row[f"{n}_edges_surface_to_mesh"] = f["surface_to_mesh"]
            w.writerow(row)


main()
