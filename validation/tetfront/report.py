"""The markdown sections of the tet-front validation report, from the files run.sh leaves in
its output directory OUT; each section also writes its rows to OUT/SECTION.csv and .json:

  report.py peers OUT TETGEN-SWITCHES    TetGen, Gmsh (Delaunay, HXT), Netgen and ours
  report.py sweep OUT -                  every closed libcgal-demo surface through tet-front
  report.py paper OUT -                  builtin:cube-inclusion at h = 2 beside the paper
  report.py bad OUT -                    the inputs that must be refused

Per run NAME: NAME.exit (124: the time-out), NAME.out (stdout: ours' --json), NAME.err,
NAME.time (/usr/bin/time "%e %U %S"), NAME.check.json (`volmesh check --json`) when a mesh was
written; ours also NAME.size. Every figure of a mesh comes from NAME.check.json, whoever made it.
"""
import json
import re
import sys
from pathlib import Path


# validation/hexdc/report.py: the markdown table, CSV/JSON rows and refusal reading shared.
sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from hexdc.report import table, write_rows, fmt, load_json, DASH  # noqa: E402


TIMEOUT_EXIT = 124
SIGNAL_EXIT = 128                                # a process killed by signal S exits 128 + S
# The targets the benchmark checks.
WELL_SHAPED = ("elephant", "fandisk", "knot1")   # min dihedral >= MIN_DIHEDRAL_TARGET
CAD_LIKE = ("anchor", "femur")                   # min dihedral no worse than the best peer
MIN_DIHEDRAL_TARGET = 10.0
TIME_RATIO_TARGET = 3.0                          # ours / TetGen's wall time
VOLUME_TOLERANCE = 1e-12                         # relative, mesh against enclosed volume
PAPER_TETS = 297                                 # the paper's cube-inclusion mesh at h = 2
CUBE_INCLUSION_VOLUME = 512.0                    # builtin:cube-inclusion is the cube [0, 8]^3
HISTOGRAM_TOP_DEG = 70                           # a tet's min dihedral is at most 70.53°
PEERS = (("tetgen", "TetGen"), ("gmsh-del3d", "Gmsh Delaunay"), ("gmsh-hxt", "Gmsh HXT"),
         ("netgen", "Netgen"), ("ours", "tet-front"))
VOLMESH_ERROR = "volmesh: error: "              # the prefix of volmesh's one-line refusals
LINE_SHOWN = 160                                 # characters of a refusal shown in a table
SELF_INTERSECTION_PAIR = re.compile(r"triangles \d+ and \d+")


def text(out, name, suffix):
    path = out / f"{name}.{suffix}"
    return path.read_text(errors="replace") if path.exists() else ""


def message(out, name):
    """The one line a run ended with: volmesh's error line, else the last line it printed."""
    lines = [l.strip() for l in (text(out, name, "err") + text(out, name, "out")).splitlines()
             if l.strip() and not l.startswith("Command exited")]
    errors = [l for l in lines if "error" in l.lower()]
    return (errors or lines or ["(no message)"])[-1].removeprefix(VOLMESH_ERROR)


def wall_time(out, name):
    """The process's wall time from /usr/bin/time's "%e %U %S" line, None while it runs."""
    fields = text(out, name, "time").split()
    return float(fields[-3]) if len(fields) >= 3 else None


def mesher_seconds(out, name, tool, run):
    """The tool's own figure for its meshing, without start-up, reading and writing where it
    reports that."""
    log = text(out, name, "out") + text(out, name, "err")
    if tool == "ours":
        return (run or {}).get("time_seconds")
    patterns = {"tetgen": r"Total running seconds:\s*([\d.eE+-]+)",
                "gmsh-del3d": r"Done meshing 3D \(Wall ([\d.eE+-]+)s",
                "gmsh-hxt": r"Done meshing 3D \(Wall ([\d.eE+-]+)s",
                "netgen": r"^\d+ ([\d.eE+-]+)\s*$"}
    found = re.findall(patterns[tool], log, re.MULTILINE)
    return float(found[-1]) if found else None


def run_row(out, name, tool="ours"):
    """One run as a flat dict; status meshed, refused, time-out, no mesh or not run."""
    exit_text = text(out, name, "exit").strip()
    wall = wall_time(out, name)
    row = {"name": name, "status": "not run", "message": "", "wall_seconds": wall,
           "mesher_seconds": None, "size": None, "tets": None, "nodes": None, "valid": None,
           "non_positive": None, "volume": None, "min_dihedral": None, "max_dihedral": None,
           "mean_min_dihedral": None, "radius_edge_max": None, "radius_edge_mean": None,
           "histogram": None, "stalls": None, "fallback_tets": None, "cavity_faces": None}
    size = text(out, name, "size").strip()
    row["size"] = float(size) if size else None
    if not exit_text:
        return row
    status = int(exit_text)
    run = load_json_safe(out / f"{name}.out") if tool == "ours" else None
    if status == TIMEOUT_EXIT:
        row.update(status="time-out", message=f"killed after {fmt(wall, '.0f')} s")
        return row
    if status > SIGNAL_EXIT:
        row.update(status="crashed", message=f"signal {status - SIGNAL_EXIT}: {message(out, name)}")
        return row
    if status != 0:
        row.update(status="refused", message=message(out, name))
        return row
    row["mesher_seconds"] = mesher_seconds(out, name, tool, run)
    if run:
        fallback = run.get("fallback", {})
        row.update(stalls=fallback.get("stalls"), fallback_tets=fallback.get("tets"),
                   cavity_faces=fallback.get("cavity_faces"))
    check = load_json_safe(out / f"{name}.check.json")
    if not check:
        row.update(status="no mesh", message=message(out, name))
        return row
    quality, validity = check.get("quality", {}), check.get("validity", {})
    metrics = quality.get("metrics", {})
    low, high = metrics.get("tet_min_dihedral", {}), metrics.get("tet_max_dihedral", {})
    ratio = metrics.get("tet_radius_edge_ratio", {})
    row.update(status="meshed", tets=quality.get("tets"), nodes=validity.get("points"),
               valid=validity.get("valid"), non_positive=validity.get("non_positive_cells"),
               volume=validity.get("total_volume"), min_dihedral=low.get("min"),
               mean_min_dihedral=low.get("mean"), max_dihedral=high.get("max"),
               radius_edge_max=ratio.get("max"), radius_edge_mean=ratio.get("mean"),
               histogram=low.get("histogram"))
    return row


def yes(value):
    return DASH if value is None else ("yes" if value else "NO")


def load_json_safe(path):
    try:
        return load_json(path)
    except json.JSONDecodeError:
        return None


def histogram_percent(histogram):
    """Percent of the tets per 10° bin of their min dihedral, 0 to HISTOGRAM_TOP_DEG and above."""
    if not histogram or not histogram.get("counts"):
        return None
    counts = histogram["counts"]
    width = (histogram["hi"] - histogram["lo"]) / len(counts)
    top = round(HISTOGRAM_TOP_DEG / width)
    bins = counts[:top] + [sum(counts[top:])]
    total = sum(bins) or 1
    return [100.0 * c / total for c in bins]


def ratio(a, b):
    return a / b if a is not None and b else None


def verdict(value, ok):
    if value is None:
        return DASH
    return f"{value} ✓" if ok else f"{value} ✗"


def outcome(row):
    """The status cell: the figures' row says meshed; otherwise what happened."""
    if row["status"] == "meshed":
        return "meshed" if row["valid"] else f"INVALID ({row['non_positive']} non-positive)"
    if row["status"] == "refused":
        return f"refused: {row['message']}"
    return f"{row['status']}: {row['message']}" if row["message"] else row["status"]


def peers(out, switches):
    models = text(out, "peers", "models").split()
    print("## Beside TetGen, Gmsh and Netgen\n")
    print(f"Each tool meshes the libcgal-demo surface: TetGen `tetgen {switches}` on the OFF "
          "file; Gmsh 4.8 `gmsh -3 -nt 1 -algo del3d|hxt` on the surface as STL (a `.geo` "
          "that merges it and makes the volume inside: its triangles are kept); Netgen's "
          "`GenerateVolumeMesh` through its Python API inside the triangles as given, `maxh` "
          "the mean edge of the triangles; ours `volmesh mesh tet-front` at the size in the "
          "h column, chosen so that its tet count is near TetGen's. Every mesh, converted to "
          "VTU tets by meshio (Netgen's tets reordered: its convention writes them all "
          "negative), goes through `volmesh check --json`: all the figures below come from "
          "that one tool. wall: the process's wall time (start-up, reading and writing "
          "included); mesher: the tool's own figure (TetGen's total running seconds, Gmsh's "
          "3D meshing wall time, Netgen's GenerateVolumeMesh, ours time_seconds). Ratios are "
          "to TetGen in the same run. r/e: radius-edge ratio (circumradius over shortest "
          "edge; 0.612 for the regular tet).\n")
    rows, json_rows, histograms, targets = [], [], [], []
    for model in models:
        by_tool = {tool: run_row(out, f"{tool}-{model}", tool) for tool, _ in PEERS}
        tetgen = by_tool["tetgen"]
        for tool, label in PEERS:
            r = by_tool[tool]
            meshed = r["status"] == "meshed"
            rows.append([model, label, outcome(r), fmt(r["size"], ".4g") if tool == "ours" else None,
                         r["tets"], fmt(ratio(r["tets"], tetgen["tets"]), ".2f") if meshed else None,
                         fmt(r["wall_seconds"], ".2f"), fmt(r["mesher_seconds"], ".2f"),
                         fmt(ratio(r["wall_seconds"], tetgen["wall_seconds"]), ".2f") if meshed else None,
                         fmt(r["min_dihedral"], ".2f"), fmt(r["max_dihedral"], ".2f"),
                         fmt(r["radius_edge_max"], ".3g"), fmt(r["radius_edge_mean"], ".3f"),
                         fmt(r["mean_min_dihedral"], ".1f"),
                         f"{r['stalls']} / {r['fallback_tets']}" if tool == "ours" and meshed else None])
            percent = histogram_percent(r["histogram"])
            if percent:
                histograms.append([model, label] + [fmt(p, ".1f") for p in percent])
            json_rows.append({"model": model, "tool": tool,
                              **{k: v for k, v in r.items() if k != "histogram"},
                              "min_dihedral_percent_per_10deg": percent})
        targets.append(target_row(model, by_tool))
    table(["model", "tool", "status", "h", "tets", "tets / TetGen", "wall s", "mesher s",
           "wall / TetGen", "min dihedral °", "max dihedral °", "r/e max", "r/e mean",
           "mean min dihedral °", "ours: stalls / fallback tets"], rows)
    print("### Histogram of the tets' min dihedral angle\n")
    print("Percent of each mesh's tets per 10° bin of their smallest dihedral angle "
          "(`volmesh check`'s tet_min_dihedral histogram).\n")
    bins = [f"{a}–{a + 10}°" for a in range(0, HISTOGRAM_TOP_DEG, 10)] + [f"≥ {HISTOGRAM_TOP_DEG}°"]
    table(["model", "tool"] + bins, histograms)
    print("### Targets (issue 28)\n")
    print(f"min dihedral ≥ {MIN_DIHEDRAL_TARGET:g}° on {', '.join(WELL_SHAPED)}; on "
          f"{', '.join(CAD_LIKE)} no worse than the best peer's; worst and mean radius-edge "
          f"no worse than TetGen's; wall time within {TIME_RATIO_TARGET:g}× TetGen's. ✓ met, ✗ "
          "not met, — no mesh of ours (or no target for that model).\n")
    table(["model", "ours", "min dihedral target", "r/e max ≤ TetGen's", "r/e mean ≤ TetGen's",
           f"time ≤ {TIME_RATIO_TARGET:g}× TetGen's"], targets)
    write_rows(out, "peers", json_rows)


def target_row(model, by_tool):
    ours, tetgen = by_tool["ours"], by_tool["tetgen"]
    if ours["status"] != "meshed" or not ours["valid"]:
        return [model, outcome(ours), DASH, DASH, DASH, DASH]
    peer_best = max((r["min_dihedral"] for t, r in by_tool.items()
                     if t != "ours" and r["status"] == "meshed" and r["min_dihedral"] is not None),
                    default=None)
    low = ours["min_dihedral"]
    if model in WELL_SHAPED:
        dihedral = verdict(f"{low:.2f}° ≥ {MIN_DIHEDRAL_TARGET:g}°", low >= MIN_DIHEDRAL_TARGET)
    elif model in CAD_LIKE and peer_best is not None:
        dihedral = verdict(f"{low:.2f}° ≥ best peer {peer_best:.2f}°", low >= peer_best)
    else:
        dihedral = DASH
    if tetgen["status"] != "meshed":
        return [model, "meshed", dihedral, DASH, DASH, DASH]
    time_ratio = ratio(ours["wall_seconds"], tetgen["wall_seconds"])
    return [model, "meshed", dihedral,
            verdict(f"{ours['radius_edge_max']:.3g} vs {tetgen['radius_edge_max']:.3g}",
                    ours["radius_edge_max"] <= tetgen["radius_edge_max"]),
            verdict(f"{ours['radius_edge_mean']:.3f} vs {tetgen['radius_edge_mean']:.3f}",
                    ours["radius_edge_mean"] <= tetgen["radius_edge_mean"]),
            verdict(f"{time_ratio:.2f}×", time_ratio <= TIME_RATIO_TARGET)]


def sweep(out):
    surfaces = text(out, "sweep", "surfaces").split()
    scales = text(out, "sweep", "scales").split() or ["1"]
    rows = []
    for surface, scale in [(s, k) for s in surfaces for k in scales]:
        r = run_row(out, f"sweep-{surface}" if scale == "1" else f"sweep{scale}x-{surface}")
        info = (load_json_safe(out / f"sweep-{surface}.info.json") or {}).get("surface", {})
        enclosed = text(out, f"sweep-{surface}", "volume").strip()
        r["surface"], r["triangles"], r["scale"] = surface, info.get("triangles"), int(scale)
        r["enclosed_volume"] = float(enclosed) if enclosed else None
        r["volume_difference"] = (r["volume"] - r["enclosed_volume"]) / r["enclosed_volume"] \
            if r["volume"] is not None and r["enclosed_volume"] else None
        r["volume_ok"] = r["volume_difference"] is not None \
            and abs(r["volume_difference"]) <= VOLUME_TOLERANCE
        rows.append(r)
    meshed = [r for r in rows if r["status"] == "meshed"]
    good = [r for r in meshed if r["valid"] and r["volume_ok"]]
    fell_back = [r for r in meshed if r["stalls"]]
    print("## libcgal-demo sweep\n")
    print("Every libcgal-demo `.off` that `volmesh info` finds closed, manifold and free of "
          "self-intersections, through `volmesh mesh tet-front` at h = the mean edge of its "
          f"triangles times {' and '.join(scales)} (×: the scale; above the boundary's edges "
          "the size is graded from them), then `volmesh check`: valid, and its total volume "
          "against the volume "
          "the surface encloses (summed exactly in rationals from the file's doubles) to "
          f"{VOLUME_TOLERANCE:g} relative. stalls / fallback tets: the front's stalls closed "
          "by the projection fallback (`--json` fallback).\n")
    print(f"**{len(good)} of {len(rows)} runs meshed, valid, volume within "
          f"{VOLUME_TOLERANCE:g}**; {len(meshed) - len(good)} meshed with a fault, "
          f"{sum(r['status'] == 'refused' for r in rows)} refused, "
          f"{sum(r['status'] == 'time-out' for r in rows)} time-outs, "
          f"{sum(r['status'] in ('no mesh', 'not run') for r in rows)} without a mesh. "
          f"Fallback used on {len(fell_back)} of {len(meshed)} meshed surfaces "
          f"({sum(r['stalls'] for r in fell_back)} stalls, "
          f"{sum(r['fallback_tets'] or 0 for r in fell_back)} tets). Meshing wall time in "
          f"all: {sum(r['wall_seconds'] or 0 for r in rows):.0f} s.\n")
    failed = [r for r in rows if r not in good]
    if failed:
        print("Not meshed, or meshed with a fault:\n")
        for r in failed:
            what = r["message"] if r["status"] != "meshed" else (
                f"valid {yes(r['valid'])}, volume difference {fmt(r['volume_difference'], '.1e')}")
            print(f"- {r['surface']} ×{r['scale']} ({fmt(r['triangles'])} triangles): "
                  f"{r['status']}: `{what}`")
        print()
    excluded(out, set(surfaces))
    table(["surface", "triangles", "×", "h", "status", "tets", "valid", "enclosed volume",
           "mesh vol. rel. diff.", "min dihedral °", "stalls / fallback tets", "wall s"],
          [[r["surface"], r["triangles"], r["scale"], fmt(r["size"], ".4g"),
            r["status"] if r["status"] == "meshed" else outcome(r), r["tets"], yes(r["valid"]),
            fmt(r["enclosed_volume"], ".8g"), fmt(r["volume_difference"], ".1e"),
            fmt(r["min_dihedral"], ".2f"),
            f"{r['stalls']} / {r['fallback_tets']}" if r["status"] == "meshed" else None,
            fmt(r["wall_seconds"], ".1f")]
           for r in sorted(rows, key=lambda r: (r["triangles"] or 0, r["surface"], r["scale"]))])
    write_rows(out, "sweep", [{k: v for k, v in r.items() if k != "histogram"} for r in rows])


def excluded(out, swept):
    """The candidates `volmesh info` kept out of the sweep, with its reason."""
    candidates = [s for s in text(out, "sweep", "candidates").split() if s not in swept]
    rest = [s for s in candidates if (out / f"sweep-{s}.info.json").exists()]
    unreached = [s for s in candidates if s not in rest]
    if unreached:
        print(f"Not reached (the sweep was stopped before them): {', '.join(unreached)}.\n")
    print(f"Not swept: {len(rest)} files that are not closed, manifold surfaces free of "
          "self-intersections (`volmesh info`'s reason):\n")
    for name in rest:
        surface = (load_json_safe(out / f"sweep-{name}.info.json") or {}).get("surface")
        if surface:
            why = ", ".join(w for w, bad in (("open", not surface.get("closed")),
                                             ("non-manifold", not surface.get("manifold")),
                                             (f"{len(surface.get('self_intersections', []))}"
                                              f"{'+' if surface.get('self_intersections_truncated') else ''}"
                                              " self-intersecting triangle pairs",
                                              surface.get("self_intersections"))) if bad)
        else:
            why = message(out, f"sweep-{name}.info").split(".off: ", 1)[-1]
        print(f"- {name}: {why}")
    print()


def paper(out):
    r = run_row(out, "paper")
    print("## The paper's example\n")
    print("`volmesh mesh tet-front builtin:cube-inclusion --size 2`: the cube [0, 8]³ with "
          "its inclusion, boundary triangles of size 2 outside and 1.5 inside, beside the "
          f"paper's {PAPER_TETS} tets.\n")
    difference = ratio(r["volume"] - CUBE_INCLUSION_VOLUME, CUBE_INCLUSION_VOLUME) \
        if r["volume"] is not None else None
    table(["status", "tets", "paper's tets", "valid", "mesh volume", "rel. diff. to 512",
           "min dihedral °", "max dihedral °", "r/e max", "r/e mean", "stalls / fallback tets",
           "wall s"],
          [[outcome(r), r["tets"], PAPER_TETS, yes(r["valid"]), fmt(r["volume"], ".10g"),
            fmt(difference, ".1e"), fmt(r["min_dihedral"], ".2f"), fmt(r["max_dihedral"], ".2f"),
            fmt(r["radius_edge_max"], ".3g"), fmt(r["radius_edge_mean"], ".3f"),
            f"{r['stalls']} / {r['fallback_tets']}" if r["status"] == "meshed" else None,
            fmt(r["wall_seconds"], ".2f")]])
    write_rows(out, "paper", [{k: v for k, v in r.items() if k != "histogram"}])


def bad(out):
    names = sorted(p.name[len("bad-"):-len(".args")] for p in out.glob("bad-*.args"))
    print("## Bad inputs\n")
    print("Each must end with exit status 1, one line on stderr naming what is wrong (a "
          "self-intersecting surface: a pair of triangles), and no output file. ✗ marks a "
          "run that did not.\n")
    rows, json_rows = [], []
    for name in names:
        run = f"bad-{name}"
        status = text(out, run, "exit").strip()
        lines = [l for l in text(out, run, "err").splitlines() if l.strip()]
        written = text(out, run, "written").strip() == "yes"
        first = lines[0] if lines else ("(killed by the time-out)"
                                        if status == str(TIMEOUT_EXIT) else "")
        first = " ".join(Path(w).name if w.startswith("/") else w for w in first.split())
        ok = status == "1" and len(lines) == 1 and not written
        if name == "self-intersecting":
            ok = ok and bool(SELF_INTERSECTION_PAIR.search(first))
        shown = first if len(first) <= LINE_SHOWN else first[:LINE_SHOWN] + "…"
        args = " ".join(Path(a).name if "/" in a else a for a in text(out, run, "args").split())
        rows.append([name, f"`{args}`", status or DASH, len(lines),
                     "yes" if written else "no", f"`{shown}`", "✓" if ok else "✗"])
        json_rows.append({"name": name, "args": args, "exit": status,
                          "stderr_lines": len(lines), "written": written, "first_line": first,
                          "ok": ok})
    table(["input", "arguments", "exit", "stderr lines", "output written", "first line", ""],
          rows)
    write_rows(out, "bad", json_rows)


def main():
    section, out = sys.argv[1], Path(sys.argv[2])
    if section == "peers":
        peers(out, sys.argv[3])
    elif section == "sweep":
        sweep(out)
    elif section == "paper":
        paper(out)
    elif section == "bad":
        bad(out)
    else:
        sys.exit("usage: report.py peers|sweep|paper|bad OUT [TETGEN-SWITCHES]")


if __name__ == "__main__":
    main()
