"""The markdown sections of the hexdc validation report, from the files run.sh leaves in its
output directory OUT; each section also writes its rows to BUILD/SECTION.csv and .json:

  report.py paper OUT BUILD FIELD DIM L,L,...        the 65^3 field's counts (Figures 3-5)
  report.py table1 OUT BUILD RUN REFINED-RUN TITLE N Table 1: uniform, improved, refined
  report.py table2 OUT BUILD MESHES LEVEL SURFACE ... Table 2's columns on the named surfaces
  report.py sweep OUT BUILD MESHES L,L NAMED,...     every surface at every level
  report.py snappy OUT BUILD SURFACE ...             snappyHexMesh against hexdc

Per hexdc run NAME: NAME.json (`volmesh mesh hexdc --json`, or {"exit": N} when it refused),
NAME.err (the refusal), NAME.time (/usr/bin/time "%e %U %S"), NAME.check.json (`volmesh check
--surface --json`) when a mesh was written. Per snappyHexMesh case: NAME.snappy ("cells wall
cpu"). The mesher's summary is still growing: every figure is read where present and shown
as — otherwise.
"""
import csv
import json
import re
import sys
from pathlib import Path

# A. S. Karavaev, S. P. Kopysov, Computer Research and Modeling 5(1), 2013
# (seeds/hex-from-volume-data-dual-contouring.ru.md). Figures 3-5: the 65^3 field, level ->
# (nodes, hexes); the text says level 4 for Figure 3's counts, its caption level 3. Table 1's
# uniform mesh of region A (a 65^3 field at level 4) continues the same progression.
PAPER_FIGURES = {3: (195, 100, "Fig. 3"), 4: (1209, 814, "Table 1, region A"),
                 5: (8073, 6561, "Fig. 4"), 6: (57980, 52074, "Fig. 5")}
# Table 1 (region A, 65^3, level 4) and Table 2 (regions Б, В, Г from 225, 168 and 5804
# triangles on 65^3 grids, levels 5, 5?, 6; none with a degenerate hex): per column
# nodes, cells, max edge, min edge, aspect ratio, max quad distortion °, degenerate, c-valence.
PAPER_TABLE1 = {
    "uniform": (1209, 814, 7.4, 0.8, 6.8, 172.8, 55, "8(501)"),
    "improved": (1915, 1517, 5.6, 0.8, 4.6, 85.6, 0, "4(113), 6(150), 8(736), 10(208)"),
    "refined": (13672, 11980, 5.5, 0.25, 49.2, 85.6, 0, "4(98), 6(1419), 8(7524), 10(516)"),
}
PAPER_TABLE2 = {
    "Б": (4720, 3864, 2.4, 0.5, 3.7, 39.5, 0, "4(216), 6(256), 8(2208), 10(448)"),
    "В": (4042, 3128, 3.3, 0.5, 5.2, 76.8, 0, "4(2), 6(60), 8(2128), 10(112)"),
    "Г": (14774, 12224, 2.2, 0.04, 26.1, 130.2, 0, "4(538), 6(894), 8(7517), 10(1244)"),
}
COLUMNS = ("nodes", "cells", "max edge (voxels)", "min edge (voxels)", "aspect ratio",
           "max quad distortion °", "degenerate hexes", "c-valence")
STAGE_KEYS = ("nodes", "cells", "max_edge", "min_edge", "max_aspect_ratio",
              "max_quad_distortion_deg", "degenerate_hexes", "valence")

# The targets of validation/hexdc/README.md.
MIN_SJ_TARGET = 0.3
QUAD_DISTORTION_TARGET = 85.6   # the paper's best (Table 1)
VOLUME_TARGET = 0.02            # at the finer level
HAUSDORFF_VOXELS_TARGET = 1.0
SNAPPY_SPEEDUP_TARGET = 10.0
DASH = "—"


def load_json(path):
    path = Path(path)
    return json.loads(path.read_text()) if path.exists() else None


def refusal(out, name):
    """The mesher's one-line refusal, without the program's prefix."""
    path = out / f"{name}.err"
    lines = [l for l in path.read_text().splitlines() if "error:" in l] if path.exists() else []
    return lines[-1].split("error:", 1)[1].strip() if lines else "(no message)"


def times(out, name):
    """(wall, cpu) of the process, or (None, None)."""
    path = out / f"{name}.time"
    if not path.exists():
        return None, None
    wall, user, system = path.read_text().split()[-3:]
    return float(wall), float(user) + float(system)


def fmt(value, spec=""):
    if value is None:
        return DASH
    if isinstance(value, str):
        return value
    if spec:
        return format(value, spec)
    return f"{value:,}" if isinstance(value, int) else f"{value:.3g}"


def first(*values):
    """The first of the values that is not None."""
    return next((v for v in values if v is not None), None)


def valence_text(valence):
    if not isinstance(valence, dict):
        return None
    return ", ".join(f"{k}({v})" for k, v in sorted(valence.items(), key=lambda kv: int(kv[0])))


def stage(run, name):
    """One of the mesher's stages (uniform, refined, improved) as a dict of the paper's
    figures; empty for a run that made no mesh or has no such stage."""
    return (run.get("stages") or {}).get(name, {})


def final_stage(run):
    """The figures of the mesh the mesher wrote."""
    return stage(run, "improved")


def voxel_size(run):
    """The field's sample spacing, None for a run that made no mesh."""
    return run.get("voxel_size")


def edge_in_voxels(value, voxel):
    return None if value is None or not voxel else value / voxel


def mark(text, ok):
    return text if ok or text == DASH else text + " ✗"


def write_rows(build, section, rows):
    """rows: a list of dicts, all with the same keys."""
    (build / f"{section}.json").write_text(json.dumps(rows, indent=1, ensure_ascii=False) + "\n")
    if rows:
        with open(build / f"{section}.csv", "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=list(rows[0]))
            writer.writeheader()
            writer.writerows(rows)


def table(header, rows):
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    for r in rows:
        print("| " + " | ".join(fmt(v) for v in r) + " |")
    print()


def paper(out, build, field, dim, levels):
    print(f"The paper does not name or publish the 65³ field of its Figures 3–5; `{field}` "
          f"sampled on the same grid (`--dim {dim}`, 65 samples per axis) stands in for it. "
          "Nodes: octree nodes with a sample ≥ 0, the uniform mesh's vertices; hexes: the "
          "uniform mesh's (before the buffer layer). The paper's level-4 counts are Table 1's "
          "region A, also a 65³ field at level 4, whose counts continue the figures' "
          "progression (×6.2, ×6.7, ×7.2 per level).\n")
    header = ["level", "source", "nodes (paper)", "nodes", "ratio", "hexes (paper)", "hexes",
              "ratio", "cells written", "min SJ", "time s"]
    rows, json_rows = [], []
    for level in map(int, levels.split(",")):
        name = f"paper-l{level}"
        run = load_json(out / f"{name}.json") or {"exit": "not run"}
        p_nodes, p_hexes, source = PAPER_FIGURES[level]
        if "exit" in run:
            rows.append([level, source, p_nodes, "refused: " + refusal(out, name)] + [None] * 7)
            json_rows.append({"level": level, "paper_nodes": p_nodes, "paper_hexes": p_hexes,
                              "status": refusal(out, name)})
            continue
        u, f = stage(run, "uniform"), final_stage(run)
        nodes, hexes = u.get("nodes"), u.get("cells")
        rows.append([level, source, p_nodes, nodes, fmt(nodes / p_nodes, ".2f") if nodes else None,
                     p_hexes, hexes, fmt(hexes / p_hexes, ".2f") if hexes else None,
                     run.get("cells"), fmt(f.get("min_scaled_jacobian"), ".3f"),
                     fmt(run.get("time_seconds"), ".2f")])
        json_rows.append({"level": level, "paper_nodes": p_nodes, "paper_hexes": p_hexes,
                          "nodes": nodes, "hexes": hexes, "cells": run.get("cells"),
                          "min_scaled_jacobian": f.get("min_scaled_jacobian"),
                          "time_seconds": run.get("time_seconds"), "status": "meshed"})
    table(header, rows)
    write_rows(build, "paper", json_rows)


def stage_cells(s, voxel):
    """The paper's columns for one stage, edges in voxels."""
    return [s.get("nodes"), s.get("cells"), fmt(edge_in_voxels(s.get("max_edge"), voxel), ".2f"),
            fmt(edge_in_voxels(s.get("min_edge"), voxel), ".2f"),
            fmt(s.get("max_aspect_ratio"), ".1f"), fmt(s.get("max_quad_distortion_deg"), ".1f"),
            s.get("degenerate_hexes"), valence_text(s.get("valence"))]


def paired_table(columns, ours):
    """columns: [(label, paper tuple)], ours: [list of our cells]: one row per figure."""
    header = ["figure"]
    for label, _ in columns:
        header += [f"{label} (paper)", label]
    rows = []
    for i, figure in enumerate(COLUMNS):
        row = [figure]
        for (label, paper_values), our in zip(columns, ours):
            row += [paper_values[i], our[i]]
        rows.append(row)
    table(header, rows)


def table1(out, build, run_name, refined_name, title, layers):
    run = load_json(out / f"{run_name}.json") or {"exit": "not run"}
    refined = load_json(out / f"{refined_name}.json") or {"exit": "not run"}
    print(f"Ours: `{title}`; the refined column adds `--refine-boundary {layers}` "
          "(Schneiders' 27-cell templates on the hexes next to the boundary, before the buffer "
          "layer and smoothing; the column is the final mesh). Edges in voxels "
          "of the 65³ field, as the paper's. The paper's uniform mesh had 55 degenerate hexes; "
          "hexdc refuses to write a mesh with any, so its uniform column is the mesh before the "
          "buffer layer and smoothing.\n")
    stages = []
    for label, source, key in (("uniform", run, "uniform"), ("improved", run, "improved"),
                               ("refined", refined, "improved")):
        if "exit" in source:
            name = refined_name if label == "refined" else run_name
            reason = source["exit"] if isinstance(source["exit"], str) else refusal(out, name)
            stages.append((label, {}, reason))
            continue
        s = stage(source, key)
        stages.append((label, s, None))
    voxel = voxel_size(run)
    ours = [stage_cells(s, voxel) for _, s, _ in stages]
    paired_table([(label, PAPER_TABLE1[label]) for label, _, _ in stages], ours)
    extra = [["min scaled Jacobian"] + [fmt(s.get("min_scaled_jacobian"), ".3f") for _, s, _ in stages],
             ["mean scaled Jacobian"] + [fmt(s.get("mean_scaled_jacobian"), ".3f") for _, s, _ in stages],
             ["stage time s"] + [fmt(s.get("seconds"), ".3f") for _, s, _ in stages]]
    table(["ours, not in the paper"] + [label for label, _, _ in stages], extra)
    for label, _, reason in stages:
        if reason:
            print(f"- {label}: {DASH} ({reason})")
    print()
    write_rows(build, "table1", [{"stage": label, **{k: s.get(k) for k in STAGE_KEYS},
                                  "min_scaled_jacobian": s.get("min_scaled_jacobian"),
                                  "mean_scaled_jacobian": s.get("mean_scaled_jacobian"),
                                  "seconds": s.get("seconds"), "status": reason or "meshed"}
                                 for label, s, reason in stages])


def table2(out, build, meshes, level, surfaces):
    print(f"The paper's regions Б, В and Г (its own parts from 225, 168 and 5804 triangles, not "
          f"published) beside the final meshes of the named libcgal-demo surfaces at "
          f"`--level {level}`; edges in voxels of each surface's field.\n")
    ours, notes, rows = [], [], []
    for surface in surfaces:
        name = f"{surface}-l{level}"
        run = load_json(out / f"{name}.json")
        if run is None or "exit" in run:
            notes.append(f"- {surface}: {DASH} ({refusal(out, name) if run else 'not run'})")
            s, voxel = {}, None
        else:
            s = final_stage(run)
            voxel = voxel_size(run)
        ours.append(stage_cells(s, voxel))
        rows.append({"surface": surface, **{k: s.get(k) for k in STAGE_KEYS}})
    header = ["figure"] + [f"{r} (paper)" for r in PAPER_TABLE2] + list(surfaces)
    table(header, [[figure] + [v[i] for v in PAPER_TABLE2.values()] + [o[i] for o in ours]
                   for i, figure in enumerate(COLUMNS)])
    print("\n".join(notes) + "\n")
    write_rows(build, "table2", rows)


def sweep_row(out, surface, level):
    name = f"{surface}-l{level}"
    run = load_json(out / f"{name}.json")
    if run is None:
        return None
    wall, cpu = times(out, name)
    row = {"surface": surface, "level": level, "status": "meshed", "message": "",
           "hexes": None, "invalid_10tet": None, "inverted": None, "min_sj": None,
           "mean_sj": None, "max_quad_distortion_deg": None, "volume_error": None,
           "hausdorff": None, "voxel": None, "hausdorff_voxels": None, "seconds": wall,
           "cpu_seconds": cpu}
    if "exit" in run:
        message = refusal(out, name)
        row["message"] = message
        corner = re.search(r"(\d+) of (\d+) hexes .* fail the ten corner tets", message)
        if corner:
            row["status"] = "refused"
            row["invalid_10tet"], row["hexes"] = int(corner.group(1)), int(corner.group(2))
        else:
            row["status"] = "not closed" if f"{surface}.off:" in message else "failed"
        return row
    f = final_stage(run)
    check = load_json(out / f"{name}.check.json") or {}
    quality = check.get("quality", {})
    sj = quality.get("metrics", {}).get("hex_scaled_jacobian", {})
    distance = check.get("surface", {})
    row["hexes"] = f.get("cells")
    row["invalid_10tet"] = f.get("degenerate_hexes")
    row["inverted"] = quality.get("inverted_hexes")
    row["min_sj"] = first(f.get("min_scaled_jacobian"), sj.get("min"))
    row["mean_sj"] = first(f.get("mean_scaled_jacobian"), sj.get("mean"))
    row["max_quad_distortion_deg"] = f.get("max_quad_distortion_deg")
    row["volume_error"] = distance.get("volume_error")
    row["hausdorff"] = distance.get("hausdorff")
    row["voxel"] = voxel_size(run)
    if row["hausdorff"] is not None and row["voxel"]:
        row["hausdorff_voxels"] = row["hausdorff"] / row["voxel"]
    row["seconds"] = run.get("time_seconds", wall)
    return row


def sweep_cells(row, finer):
    meshed = row["status"] == "meshed"
    status = "meshed" if meshed else row["status"]
    invalid = fmt(row["invalid_10tet"])
    sj = row["min_sj"]
    volume = row["volume_error"]
    distance = row["hausdorff_voxels"]
    return [row["surface"], row["level"], status, row["hexes"],
            mark(invalid, row["invalid_10tet"] in (0, None)),
            mark(fmt(row["inverted"]), row["inverted"] in (0, None)),
            mark(fmt(sj, ".3f"), sj is None or sj >= MIN_SJ_TARGET),
            fmt(row["mean_sj"], ".3f"),
            mark(fmt(row["max_quad_distortion_deg"], ".1f"),
                 row["max_quad_distortion_deg"] is None
                 or row["max_quad_distortion_deg"] < QUAD_DISTORTION_TARGET),
            mark(fmt(None if volume is None else 100 * volume, "+.2f"),
                 volume is None or not finer or abs(volume) <= VOLUME_TARGET),
            fmt(row["hausdorff"], ".2e"), fmt(row["voxel"], ".2e"),
            mark(fmt(distance, ".2f"), distance is None or distance <= HAUSDORFF_VOXELS_TARGET),
            fmt(row["seconds"], ".2f")]


SWEEP_HEADER = ["surface", "level", "status", "hexes", "fail 10 tets", "SJ < 0", "min SJ",
                "mean SJ", "max quad distortion °", "volume error %", "Hausdorff",
                "voxel", "Hausdorff / voxel", "time s"]


def sweep(out, build, meshes, levels, named):
    levels = [int(l) for l in levels.split(",")]
    surfaces = (out / "sweep.surfaces").read_text().split()
    rows = []
    for surface in surfaces:
        for level in levels:
            row = sweep_row(out, surface, level)
            if row:
                rows.append(row)
    finer = max(levels)
    closed = [s for s in surfaces
              if not any(r["surface"] == s and r["status"] == "not closed" for r in rows)]
    print("`volmesh mesh hexdc SURFACE.off --level L` with the default field (`--dim` = level + "
          "2: four voxels per node). min and mean SJ: the scaled Jacobian at the 8 corners and "
          "the centre as the mesher reports it (else `volmesh check`'s, at the corners); SJ < 0: "
          "hexes `volmesh check` finds inverted; fail 10 tets: the paper's validity test (a "
          "refused mesh: how many of how many hexes, from the refusal). Volume error against "
          "the surface's own volume, two-sided Hausdorff distance of the boundary against the "
          "field's voxel size. Targets: no hex failing the ten tets or inverted, min SJ ≥ "
          f"{MIN_SJ_TARGET}, quad distortion < {QUAD_DISTORTION_TARGET}°, volume within "
          f"{100 * VOLUME_TARGET:.0f}% at level {finer}, Hausdorff within one voxel.\n")
    print("### The named surfaces\n")
    named_rows = [r for r in rows if r["surface"] in named.split(",")]
    table(SWEEP_HEADER, [sweep_cells(r, r["level"] == finer) for r in named_rows])
    for r in named_rows:
        if r["message"]:
            print(f"- {r['surface']} level {r['level']}: `{r['message']}`")
    missing = [s for s in named.split(",") if s not in surfaces]
    if missing:
        print(f"- not in this sweep: {', '.join(missing)}")
    print()
    print(f"### Summary over the {len(closed)} closed surfaces of {len(surfaces)}\n")
    summary = []
    for level in levels:
        at = [r for r in rows if r["level"] == level and r["surface"] in closed]
        ok = [r for r in at if r["status"] == "meshed"]
        sjs = [r["min_sj"] for r in ok if r["min_sj"] is not None]
        summary.append([level, len(at), len(ok),
                        len([r for r in at if r["status"] == "refused"]),
                        len([r for r in at if r["status"] == "failed"]),
                        sum(r["inverted"] or 0 for r in ok),
                        len([s for s in sjs if s >= MIN_SJ_TARGET]),
                        fmt(min(sjs), ".3f") if sjs else None,
                        len([r for r in ok if r["volume_error"] is not None
                             and abs(r["volume_error"]) <= VOLUME_TARGET]),
                        len([r for r in ok if r["hausdorff_voxels"] is not None
                             and r["hausdorff_voxels"] <= HAUSDORFF_VOXELS_TARGET]),
                        fmt(sum(r["seconds"] or 0 for r in at), ".1f")])
    table(["level", "closed surfaces run", "meshed", "refused (ten corner tets)",
           "failed otherwise", "inverted hexes in all", f"min SJ ≥ {MIN_SJ_TARGET}",
           "lowest min SJ", f"volume within {100 * VOLUME_TARGET:.0f}%",
           "Hausdorff ≤ 1 voxel", "time s in all"], summary)
    print("### Every closed surface\n")
    table(SWEEP_HEADER, [sweep_cells(r, r["level"] == finer) for r in rows
                         if r["surface"] in closed])
    skipped = [r for r in rows if r["status"] == "not closed"]
    print(f"### Skipped: {len(skipped)} surfaces that are not closed\n")
    print("Refused by the mesher's input check with one line naming the file and the fault:\n")
    for r in skipped:
        print(f"- {r['surface']}: `{r['message'].split(': ', 1)[-1]}`")
    print()
    write_rows(build, "sweep", rows)


def snappy(out, build, surfaces):
    header = ["surface", "mesher", "status", "cells", "hexes", "time s", "CPU s", "min SJ",
              "mean SJ", "SJ < 0", "Hausdorff", "Hausdorff / diagonal", "volume error %"]
    rows, json_rows, summary = [], [], []
    for surface in surfaces:
        cells, wall, cpu = Path(out / f"{surface}-snappy.snappy").read_text().split()
        times_of = {"snappy": (float(wall), float(cpu))}
        runs = {"snappy": ("snappyHexMesh", int(cells))}
        name = f"{surface}-vs-snappy"
        run = load_json(out / f"{name}.json") or {"exit": "not run"}
        wall_h, cpu_h = times(out, name)
        refused = "exit" in run
        runs["hexdc"] = (f"hexdc (level {run.get('level', DASH)})", run.get("cells"))
        times_of["hexdc"] = (wall_h if refused else run.get("time_seconds", wall_h), cpu_h)
        for key, (label, n) in runs.items():
            check_name = f"{surface}-{'snappy' if key == 'snappy' else 'vs-snappy'}"
            check = load_json(out / f"{check_name}.check.json") or {}
            quality = check.get("quality", {})
            sj = quality.get("metrics", {}).get("hex_scaled_jacobian", {})
            distance = check.get("surface", {})
            status = "meshed" if key == "snappy" or not refused else \
                "refused: " + refusal(out, name)
            volume = distance.get("volume_error")
            inverted = quality.get("inverted_hexes")
            rows.append([surface, label, status, n, quality.get("hexes"),
                         fmt(times_of[key][0], ".2f"), fmt(times_of[key][1], ".2f"),
                         fmt(sj.get("min"), ".3f"), fmt(sj.get("mean"), ".3f"),
                         mark(fmt(inverted), key == "snappy" or inverted in (0, None)),
                         fmt(distance.get("hausdorff"), ".2e"),
                         fmt(distance.get("hausdorff_relative"), ".2e"),
                         fmt(None if volume is None else 100 * volume, "+.2f")])
            json_rows.append({"surface": surface, "mesher": key, "status": status, "cells": n,
                              "hexes": quality.get("hexes"), "seconds": times_of[key][0],
                              "cpu_seconds": times_of[key][1], "min_sj": sj.get("min"),
                              "mean_sj": sj.get("mean"), "inverted_hexes": inverted,
                              "hausdorff": distance.get("hausdorff"),
                              "hausdorff_relative": distance.get("hausdorff_relative"),
                              "volume_error": volume})
        speed = times_of["snappy"][0] / times_of["hexdc"][0] if times_of["hexdc"][0] else None
        speed_cpu = times_of["snappy"][1] / times_of["hexdc"][1] if times_of["hexdc"][1] else None
        what = "until its refusal" if refused else "meshing"
        text = mark(f"{speed:.1f}×", speed >= SNAPPY_SPEEDUP_TARGET) if speed else DASH
        summary.append(f"- {surface}: hexdc {what} {text} faster than snappyHexMesh (wall; "
                       f"{fmt(speed_cpu, '.1f')}× in CPU time)"
                       + ("" if refused or not runs["hexdc"][1] else
                          f", with {runs['hexdc'][1] / runs['snappy'][1]:.2f}× its cells") + ".")
    table(header, rows)
    print("\n".join(summary) + "\n")
    write_rows(build, "snappy", json_rows)


def main():
    section, out, build = sys.argv[1], Path(sys.argv[2]), Path(sys.argv[3])
    args = sys.argv[4:]
    if section == "paper":
        paper(out, build, args[0], args[1], args[2])
    elif section == "table1":
        table1(out, build, args[0], args[1], args[2], args[3])
    elif section == "table2":
        table2(out, build, Path(args[0]), args[1], args[2:])
    elif section == "sweep":
        sweep(out, build, Path(args[0]), args[1], args[2])
    elif section == "snappy":
        snappy(out, build, args)
    else:
        sys.exit("usage: report.py paper|table1|table2|sweep|snappy OUT BUILD ...")


if __name__ == "__main__":
    main()
