"""The markdown sections of the octree validation report, from the files run.sh leaves in its
output directory:

  report.py tables OUT STEM:LEVEL,LEVEL,LEVEL ...   the paper's Tables 1 and 2 side by side
                                                    (runs STEM-lLEVEL; STEM: the case, or
                                                    CASE-VARIANT for other settings)
  report.py snappy OUT LEVEL SURFACE ...            snappyHexMesh against volmesh cutcell
  report.py levels OUT LEVEL LEVEL,LEVEL,... SURFACE ...
                                                    the same surfaces per level (LEVEL: the
                                                    one compared with snappyHexMesh)

Per volmesh run NAME: NAME.json (`volmesh mesh --json`) and NAME.time (/usr/bin/time
"%e %U %S"). Per snappyHexMesh case: NAME.snappy ("cells wall cpu"). Per mesh checked:
NAME.check.json (`volmesh check --surface --json`) and NAME.checkMesh (checkMesh's log).
"""
import json
import re
import sys
from pathlib import Path

# A. Yu. Chernyshenko, octree cut-cell meshes (seeds/octree-cut-cells-multimaterial.ru.txt),
# Tables 1 and 2: level, time s, cells, cut cells, faces, vertices (2013, one core).
PAPER = {
    "primitives": ("Table 1: builtin:primitives (ball, box, cylinder; 7 regions)", [
        (1, 0.75, 22073, 7792, 88645, 29786),
        (2, 3.25, 99206, 31422, 391859, 134526),
        (3, 14.62, 421894, 119306, 1724179, 604021),
    ]),
    "layers6": ("Table 2: builtin:layers6 (six layers, a fault, a pinch-out)", [
        (1, 1.14, 8293, 3370, 34354, 11159),
        (2, 6.38, 54846, 13422, 202180, 66394),
        (3, 38.96, 199991, 96978, 768287, 439839),
    ]),
}
SPEEDUP_TARGET = 15.0
COUNT_TOLERANCE = 1.5
SNAPPY_SPEEDUP_TARGET = 50.0
HAUSDORFF_TARGET = 0.2


def load_json(path):
    return json.loads(Path(path).read_text())


def cpu_seconds(path):
    """User + system seconds from a /usr/bin/time -f "%e %U %S" file."""
    _, user, system = Path(path).read_text().split()[-3:]
    return float(user) + float(system)


def count_ratio(ours, paper):
    ratio = ours / paper
    mark = "" if 1 / COUNT_TOLERANCE <= ratio <= COUNT_TOLERANCE else " ✗"
    return f"{ratio:.2f}{mark}"


def speedup(paper_seconds, ours):
    ratio = paper_seconds / ours
    return f"{ratio:.1f}×" + ("" if ratio >= SPEEDUP_TARGET else " ✗")


def tables(out, specs):
    for spec in specs:
        stem, levels = spec.split(":")
        title, paper_rows = PAPER[stem.split("-")[0]]
        print(f"### {title}\n")
        print("| paper level | `--level` / `--base-level` / `--cells-between-levels` / `--crossing-levels` | time s (paper) | time s | speed-up | CPU s "
              "| speed-up (CPU) | cells (paper) | cells | ratio | cut cells (paper) | cut cells "
              "| faces (paper) | faces | vertices (paper) | vertices | octree s | cut s | total s "
              "| max leaf level |")
        print("|" + "---:|" * 20)
        uncut = []
        for paper, level in zip(paper_rows, levels.split(",")):
            name = out / f"{stem}-l{level}"
            run = load_json(f"{name}.json")
            uncut.append((run["cells"] - run["cut_cells"], paper[2] - paper[3]))
            cpu = cpu_seconds(f"{name}.time")
            p_level, p_time, p_cells, p_cut, p_faces, p_vertices = paper
            print(f"| {p_level} | {run['level']} / {run['base_level']} / {run['cells_between_levels']} "
                  f"/ {run['crossing_levels']} | {p_time:.2f} | {run['time_seconds']:.2f} "
                  f"| {speedup(p_time, run['time_seconds'])} | {cpu:.2f} | {speedup(p_time, cpu)} "
                  f"| {p_cells:,} | {run['cells']:,} | {count_ratio(run['cells'], p_cells)} "
                  f"| {p_cut:,} | {run['cut_cells']:,} | {p_faces:,} | {run['faces']:,} "
                  f"| {p_vertices:,} | {run['vertices']:,} | {run['octree_seconds']:.2f} "
                  f"| {run['cut_seconds']:.2f} | {run['total_seconds']:.2f} "
                  f"| {run['max_leaf_level']} |")
        print()
        print("Uncut cells (cells − cut cells), ours / the paper's: "
              + ", ".join(f"{ours:,} / {theirs:,}" for ours, theirs in uncut) + ".")
        print()


def checkmesh_verdict(path):
    """"Mesh OK." or "Failed N mesh checks: <each *** line, shortened>"."""
    log = Path(path).read_text()
    if "Mesh OK." in log:
        return "Mesh OK."
    failed = re.search(r"Failed (\d+) mesh checks", log)
    problems = []
    for line in log.splitlines():
        if "***" in line:
            text = line.split("***", 1)[1].split(" which ")[0].strip().rstrip(".")
            problems.append(re.sub(r"(\d+\.\d{2})\d+", r"\1", text))
    verdict = f"Failed {failed.group(1)} mesh checks" if failed else "no verdict (see the log)"
    return verdict + (": " + "; ".join(problems) if problems else "")


def snappy(out, level, surfaces):
    print(f"| surface | mesher | cells | time s | CPU s | Hausdorff / diagonal "
          f"| mesh→surface | surface→mesh | volume error | checkMesh |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---|")
    summary = []
    for surface in surfaces:
        cells, wall, cpu = Path(out / f"{surface}-snappy.snappy").read_text().split()
        rows = {"snappy": (f"snappyHexMesh (level {level})", int(cells), float(wall), float(cpu))}
        run = load_json(out / f"{surface}-volmesh.json")
        rows["volmesh"] = (f"volmesh cutcell (`--level {run['level']}`)", run["cells"],
                           run["time_seconds"], cpu_seconds(out / f"{surface}-volmesh.time"))
        hausdorff = {}
        for key, (label, n, seconds, cpu_s) in rows.items():
            check = load_json(out / f"{surface}-{key}.check.json")["surface"]
            d = check["diagonal"]
            hausdorff[key] = check["hausdorff_relative"]
            print(f"| {surface} | {label} | {n:,} | {seconds:.2f} | {cpu_s:.2f} "
                  f"| {check['hausdorff_relative']:.2e} "
                  f"| {check['hausdorff_mesh_to_surface'] / d:.2e} "
                  f"| {check['hausdorff_surface_to_mesh'] / d:.2e} | {check['volume_error']:.1e} "
                  f"| {checkmesh_verdict(out / f'{surface}-{key}.checkMesh')} |")
        speed = rows["snappy"][2] / rows["volmesh"][2]
        speed_cpu = rows["snappy"][3] / rows["volmesh"][3]
        distance = hausdorff["volmesh"] / hausdorff["snappy"]
        summary.append(
            f"- {surface}: volmesh is {speed:.1f}× faster (wall; {speed_cpu:.1f}× in CPU time)"
            f"{'' if speed >= SNAPPY_SPEEDUP_TARGET else ' ✗'} with "
            f"{rows['volmesh'][1] / rows['snappy'][1]:.2f}× the cells, at {distance:.2f}× "
            f"snappyHexMesh's Hausdorff distance{'' if distance <= HAUSDORFF_TARGET else ' ✗'}; "
            f"volmesh's octree {run['octree_seconds']:.2f} s, cut cells {run['cut_seconds']:.2f} s, "
            f"{run['total_seconds']:.2f} s with reading, checking and writing.")
    print()
    print("\n".join(summary))
    print()


def levels(out, compared_level, level_list, surfaces):
    """The cut-cell mesh of each surface per level: cells, time, Hausdorff distance, and how
    much it falls from the level before (4x at second order, 2x at first)."""
    print("| surface | `--level` | cells | time s | Hausdorff / diagonal | mesh→surface "
          "| surface→mesh | fall from the level before | snappyHexMesh's Hausdorff / diagonal |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for surface in surfaces:
        snappy_distance = load_json(out / f"{surface}-snappy.check.json")["surface"]["hausdorff_relative"]
        before = None
        for level in level_list.split(","):
            name = f"{surface}-volmesh" if level == compared_level else f"{surface}-l{level}"
            run = load_json(out / f"{name}.json")
            check = load_json(out / f"{name}.check.json")["surface"]
            d, distance = check["diagonal"], check["hausdorff_relative"]
            fall = f"{before / distance:.2f}×" if before else ""
            print(f"| {surface} | {level} | {run['cells']:,} | {run['time_seconds']:.2f} "
                  f"| {distance:.2e} | {check['hausdorff_mesh_to_surface'] / d:.2e} "
                  f"| {check['hausdorff_surface_to_mesh'] / d:.2e} | {fall} | {snappy_distance:.2e} |")
            before = distance
    print()


def main():
    out = Path(sys.argv[2])
    if sys.argv[1] == "tables":
        tables(out, sys.argv[3:])
    elif sys.argv[1] == "snappy":
        snappy(out, sys.argv[3], sys.argv[4:])
    elif sys.argv[1] == "levels":
        levels(out, sys.argv[3], sys.argv[4], sys.argv[5:])
    else:
        sys.exit("usage: report.py tables OUT STEM:L,L,L ... | snappy OUT LEVEL SURFACE ... "
                 "| levels OUT LEVEL L,L,L SURFACE ...")


if __name__ == "__main__":
    main()
