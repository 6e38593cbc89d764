"""The markdown sections of the tet-projection validation report, from the files run.sh leaves
in its output directory OUT; each section also writes its rows to RESULTS/SECTION.csv and .json
and its plots to RESULTS/*.png:

  report.py sweep OUT RESULTS MESHES NAMED,...       every libcgal-demo surface
  report.py tetgen OUT RESULTS NAMED,...             TetGen -pQ and -pYQ beside ours
  report.py complexity OUT RESULTS N,N,... K,K,...   sphere and cone: time and M against N
  report.py twisted OUT RESULTS SCHOENHARDT-DEG      Schönhardt's polyhedron, twisted prisms

Per run NAME: NAME.json (`volmesh mesh tet-projection --json`, or {"exit": N} when it refused
or timed out: 124), NAME.err (the refusal), NAME.time (/usr/bin/time "%e %U %S"),
NAME.check.json (`volmesh check --json`) when a mesh was written. Per TetGen run:
NAME.tetgen ("exit nodes tets"), NAME.tetgen.time, NAME.tetgen.log.
"""
import json
import math
import sys
from pathlib import Path

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


# validation/hexdc/report.py: the markdown table, CSV/JSON rows and refusal reading shared.
sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from hexdc.report import table, write_rows, refusal, DASH  # noqa: E402


TIMEOUT_EXIT = 124
SCHOENHARDT_LIMIT_DEG = 180.0 - 360.0 / 3  # surfaces.py twist-limit 3
VOLUME_TOLERANCE = 1e-9  # relative: the written doubles against the exact volume
# Bounds of the paper's section "Оценка вычислительной сложности".
PAPER_BEST = "O(N), M = N/2 (each TOP triangle over one BOT triangle, no WALL)"
PAPER_WORST = "O(M³) for stage two (the Fig. 5 cone), O(N²) for stage one, N < M < N²"


def load_json(path):
    path = Path(path)
    if not path.exists():
        return None
    try:
        return json.loads(path.read_text())
    except json.JSONDecodeError:
        return None


def wall_time(out, suffix_name):
    path = out / f"{suffix_name}.time"
    fields = path.read_text().split() if path.exists() else []
    return float(fields[-3]) if len(fields) >= 3 else None


def fmt(value, spec=""):
    if value is None:
        return DASH
    if isinstance(value, str):
        return value
    if isinstance(value, bool):
        return "yes" if value else "NO"
    if spec:
        return format(value, spec)
    return f"{value:,}" if isinstance(value, int) else f"{value:.3g}"


def off_faces(path):
    """The face count in an OFF file's header (the N of a run that made no mesh)."""
    if path is None or not Path(path).exists():
        return None
    with open(path, errors="replace") as f:
        lines = (l.split("#", 1)[0].split() for l in f)
        header = [w for w in next((l for l in lines if l), []) if not w.isalpha()]
        counts = header or next((l for l in lines if l), [])
    return int(counts[1]) if len(counts) > 1 else None


def run_row(out, name, surface_file=None, surface_path=None):
    """One tet-projection run as a flat dict; status meshed, input (refused by the input
    check, which names the file), refused (by the mesher), time-out or not run."""
    run = load_json(out / f"{name}.json")
    row = {"name": name, "status": "not run", "message": "", "N": None, "top": None,
           "bot": None, "wall": None, "plane_vertices": None, "plane_triangles": None, "M": None,
           "degenerate_prisms": None, "tets": None, "vertices": None, "steiner_boundary": None,
           "steiner_interior": None, "direction": None, "directions_tried": None, "moved_points": None,
           "repaired_prisms": None, "seconds": wall_time(out, name), "valid": None,
           "check_valid": None, "volume_exact": None, "volume": None, "mesh_volume": None,
           "volume_difference": None}
    for stage in ("check", "classify", "project", "prisms", "stitch", "fill", "round"):
        row[f"stage_{stage}"] = None
    if run is None:
        return row
    if "exit" in run:
        row["N"] = off_faces(surface_path)
        if run["exit"] == TIMEOUT_EXIT:
            row["status"], row["message"] = "time-out", f"killed after {row['seconds']:.0f} s"
        else:
            row["message"] = refusal(out, name)
            named = surface_file and f"{surface_file}:" in row["message"]
            row["status"] = "input" if named else "refused"
        return row
    steiner = run.get("steiner_points", {})
    rounding = run.get("rounding", {})
    volume = run.get("enclosed_volume", {})
    plane = run.get("plane", {})
    row.update(status="meshed", N=run.get("surface_triangles"), top=run.get("top"),
               bot=run.get("bot"), wall=run.get("wall"), plane_vertices=plane.get("vertices"),
               plane_triangles=plane.get("triangles"), M=run.get("prisms"),
               degenerate_prisms=run.get("degenerate_prisms"), tets=run.get("tets"),
               vertices=run.get("vertices"), steiner_boundary=steiner.get("boundary"),
               steiner_interior=steiner.get("interior"), direction=run.get("direction"),
               directions_tried=rounding.get("directions_tried"), moved_points=rounding.get("moved_points"),
               repaired_prisms=rounding.get("repaired_prisms"),
               seconds=run.get("time_seconds", row["seconds"]),
               valid=run.get("validity", {}).get("valid"), volume_exact=volume.get("exact"),
               volume=volume.get("value"))
    for stage, seconds in run.get("stage_seconds", {}).items():
        row[f"stage_{stage}"] = seconds
    check = load_json(out / f"{name}.check.json") or {}
    validity = check.get("validity", {})
    row["check_valid"] = validity.get("valid")
    row["mesh_volume"] = validity.get("total_volume")
    if row["volume"] and row["mesh_volume"] is not None:
        row["volume_difference"] = (row["mesh_volume"] - row["volume"]) / abs(row["volume"])
    return row


def volume_ok(row):
    d = row["volume_difference"]
    return d is not None and abs(d) <= VOLUME_TOLERANCE


def mesh_cells(row):
    """The columns every meshed run shows."""
    return [row["N"], f"{fmt(row['top'])}/{fmt(row['bot'])}/{fmt(row['wall'])}", row["M"],
            row["degenerate_prisms"], row["tets"],
            f"{fmt(row['steiner_boundary'])} / {fmt(row['steiner_interior'])}",
            f"{fmt(row['direction'])} ({fmt(row['directions_tried'])})", fmt(row["seconds"], ".2f"),
            fmt(row["check_valid"]), fmt(row["volume"], ".6g"),
            fmt(row["volume_difference"], ".1e")]


MESH_HEADER = ["N", "top/bot/wall", "M", "degenerate prisms", "tets", "Steiner bnd / int",
               "direction (tried)", "time s", "check valid", "exact volume", "mesh vol. rel. diff."]


def sweep(out, results, meshes, named):
    surfaces = sweep_surfaces(out)
    rows = []
    for surface in surfaces:
        row = run_row(out, f"sweep-{surface}", f"{surface}.off", meshes / f"{surface}.off")
        row["surface"] = surface
        rows.append(row)
    closed = [r for r in rows if r["status"] not in ("input", "not run")]
    meshed = [r for r in closed if r["status"] == "meshed"]
    good = [r for r in meshed if r["check_valid"] and r["valid"] and volume_ok(r)]
    print("`volmesh mesh tet-projection SURFACE.off --json` (axis auto), then `volmesh check` on "
          "the written VTU. N: surface triangles; top/bot/wall: their classes along the axis; "
          "M: prisms; Steiner points on the boundary / inside; direction (tried): the projection "
          "direction used (an axis, or an axis tilted by a shear) and how many were tried before "
          "one rounded to doubles; exact volume: the enclosed volume computed in rationals "
          "(its double); mesh vol. rel. diff.: `volmesh check`'s total volume of the written "
          "(rounded) mesh against it. Surfaces the input check refuses (a hole, inconsistent "
          "orientation, crossing or degenerate triangles) are listed apart with its one line.\n")
    print(f"**{len(good)} of {len(closed)} valid surfaces meshed, checked valid, with the "
          f"volume within {VOLUME_TOLERANCE:g} ({100 * len(good) / max(1, len(closed)):.1f}%)**; "
          f"{len([r for r in closed if r['status'] == 'time-out'])} time-outs, "
          f"{len([r for r in closed if r['status'] == 'refused'])} refusals; "
          f"{len([r for r in rows if r['status'] == 'input'])} of the {len(rows)} files "
          f"refused by the input check, {len([r for r in rows if r['status'] == 'not run'])} "
          "not run. "
          f"Meshing time in all: {sum(r['seconds'] or 0 for r in closed):.1f} s.\n")
    failed = [r for r in closed if r not in good]
    if failed:
        print("Not meshed, or meshed with a fault:\n")
        for r in failed:
            what = r["message"] or (f"check valid {fmt(r['check_valid'])}, volume difference "
                                    f"{fmt(r['volume_difference'], '.1e')}")
            print(f"- {r['surface']} (N = {fmt(r['N'])}): {r['status']}: `{what}`")
        print()
    print("### The named surfaces\n")
    table(["surface"] + MESH_HEADER,
          [[r["surface"]] + mesh_cells(r) for r in rows if r["surface"] in named.split(",")])
    print("### Every valid surface, by N\n")
    by_n = sorted(meshed, key=lambda r: r["N"])
    table(["surface"] + MESH_HEADER, [[r["surface"]] + mesh_cells(r) for r in by_n])
    if by_n:
        big = by_n[-1]
        print(f"Largest meshed: {big['surface']}, N = {big['N']:,} → M = {big['M']:,}, "
              f"{big['tets']:,} tets in {big['seconds']:.1f} s. M / N over the sweep: "
              f"median {np.median([r['M'] / r['N'] for r in by_n]):.1f}, "
              f"max {max(r['M'] / r['N'] for r in by_n):.1f}.\n")
    stage_names = ("check", "classify", "project", "prisms", "stitch", "fill", "round")
    total = {s: sum(r[f"stage_{s}"] or 0 for r in meshed) for s in stage_names}
    table(["stage"] + list(stage_names),
          [["seconds over the sweep"] + [fmt(total[s], ".1f") for s in stage_names]])
    print(f"### Refused by the input check: {len([r for r in rows if r['status'] == 'input'])}\n")
    for r in rows:
        if r["status"] == "input":
            print(f"- {r['surface']}: `{r['message'].split('.off: ', 1)[-1]}`")
    print()
    if meshed:
        n = sorted(r["N"] for r in meshed)
        scatter_against_n(results / "sweep-counts.png",
                          "libcgal-demo sweep: prisms and tets against N", "count",
                          [(meshed, "M", "o", "prisms M"), (meshed, "tets", "s", "tets")],
                          (n, [v / 2 for v in n], "N/2 (paper's best case)"))
    write_rows(results, "sweep", rows)


def scatter_against_n(path, title, ylabel, series, reference=None):
    """A log-log scatter of rows' values against their N, printed as a markdown image.
    series: (rows, key, marker, label); reference: (x, y, label), drawn dashed."""
    plt.figure(figsize=(6, 4.5))
    for rows, key, marker, label in series:
        plt.loglog([r["N"] for r in rows], [r[key] for r in rows], marker, label=label,
                   alpha=0.7)
    if reference:
        plt.loglog(reference[0], reference[1], "k--", lw=0.8, label=reference[2])
    plt.xlabel("surface triangles N")
    plt.ylabel(ylabel)
    plt.legend()
    plt.title(title)
    plt.tight_layout()
    plt.savefig(path, dpi=110)
    plt.close()
    print(f"![{title}]({path.name})\n")


def sweep_surfaces(out):
    """The surfaces of the last sweep run, none before one."""
    path = out / "sweep.surfaces"
    return path.read_text().split() if path.exists() else []


def tetgen_row(out, name):
    path = out / f"{name}.tetgen"
    if not path.exists():
        return None
    status, nodes, tets = (int(v) for v in path.read_text().split())
    log = (out / f"{name}.tetgen.log").read_text().strip().splitlines() \
        if (out / f"{name}.tetgen.log").exists() else []
    message = "time-out" if status == TIMEOUT_EXIT else (log[-1] if log and status else "")
    return {"ok": status == 0 and tets > 0, "exit": status, "nodes": nodes, "tets": tets,
            "seconds": wall_time(out, f"{name}.tetgen"), "message": message}


def tetgen(out, results, named):
    surfaces = sweep_surfaces(out)
    rows, json_rows = [], []
    for surface in surfaces:
        p = tetgen_row(out, f"sweep-{surface}")
        if p is None:
            continue
        y = tetgen_row(out, f"sweep-{surface}-Y")
        ours = run_row(out, f"sweep-{surface}", f"{surface}.off")
        ours_ok = ours["status"] == "meshed" and bool(ours["check_valid"])
        ratio = ours["seconds"] / p["seconds"] if ours_ok and p["ok"] and p["seconds"] else None
        rows.append([surface, ours["N"], "yes" if ours_ok else ours["status"], ours["tets"],
                     fmt(ours["seconds"], ".2f"),
                     "yes" if p["ok"] else f"NO ({p['message'][:60]})", p["tets"] or None,
                     fmt(p["seconds"], ".2f"),
                     "yes" if y["ok"] else f"NO ({y['message'][:60]})", y["tets"] or None,
                     y["nodes"] or None, fmt(y["seconds"], ".2f"), fmt(ratio, ".1f")])
        json_rows.append({"surface": surface, "N": ours["N"], "ours_ok": ours_ok,
                          "ours_status": ours["status"], "ours_tets": ours["tets"],
                          "ours_vertices": ours["vertices"], "ours_seconds": ours["seconds"],
                          "tetgen_p_ok": p["ok"], "tetgen_p_exit": p["exit"],
                          "tetgen_p_tets": p["tets"], "tetgen_p_nodes": p["nodes"],
                          "tetgen_p_seconds": p["seconds"], "tetgen_p_message": p["message"],
                          "tetgen_pY_ok": y["ok"], "tetgen_pY_exit": y["exit"],
                          "tetgen_pY_tets": y["tets"], "tetgen_pY_nodes": y["nodes"],
                          "tetgen_pY_seconds": y["seconds"], "tetgen_pY_message": y["message"],
                          "time_ratio_vs_pQ": ratio})
    print("Debian's TetGen 1.5 on a copy of each surface the input check accepts: `tetgen -pQ` "
          "(may split boundary faces) and `tetgen -pYQ` (keeps the boundary as given; its "
          "nodes are the input vertices plus its Steiner points). Time: the process's wall "
          "time (reading and writing included); ours: the mesher's time_seconds. ratio: ours / "
          "TetGen -pQ (the issue's target: ≤ 10 on elephant, fandisk, knot1).\n")
    j = json_rows
    tg_fail = [r for r in j if not r["tetgen_p_ok"]]
    tgy_fail = [r for r in j if not r["tetgen_pY_ok"]]
    ours_fail = [r for r in j if not r["ours_ok"]]
    print(f"Of {len(j)} surfaces: ours meshed {len(j) - len(ours_fail)}; TetGen -pQ "
          f"{len(j) - len(tg_fail)}, -pYQ {len(j) - len(tgy_fail)}.\n")
    print("- TetGen -pQ fails, ours does not: "
          + (", ".join(r["surface"] for r in tg_fail if r["ours_ok"]) or "none"))
    print("- TetGen -pYQ fails, ours does not: "
          + (", ".join(r["surface"] for r in tgy_fail if r["ours_ok"]) or "none"))
    print("- ours fails, TetGen -pQ does not: "
          + (", ".join(r["surface"] for r in ours_fail if r["tetgen_p_ok"]) or "none"))
    print()
    print("### The named surfaces\n")
    header = ["surface", "N", "ours", "tets", "time s", "TetGen -pQ", "tets", "time s",
              "TetGen -pYQ", "tets", "nodes", "time s", "ours / -pQ time"]
    table(header, [r for r in rows if r[0] in named.split(",")])
    per_tet(j, named.split(","))
    print("### Every surface\n")
    table(header, rows)
    timed = [r for r in j if r["N"] and r["ours_ok"] and r["tetgen_p_ok"]]
    if timed:
        scatter_against_n(results / "tetgen-times.png", "libcgal-demo sweep: time against N",
                          "seconds", [(timed, "ours_seconds", "o", "tet-projection"),
                                      (timed, "tetgen_p_seconds", "s", "TetGen -pQ")])
    write_rows(results, "tetgen", json_rows)


def per_tet(json_rows, named):
    """What the time ratio is made of: tets per surface triangle and time per tet, both tools."""
    rows = []
    for r in json_rows:
        if r["surface"] not in named or not (r["ours_ok"] and r["tetgen_p_ok"] and r["N"]):
            continue
        if not (r["ours_tets"] and r["tetgen_p_tets"] and r["tetgen_p_seconds"]):
            continue
        rows.append([r["surface"], r["N"],
                     fmt(r["ours_tets"] / r["N"], ".1f"), fmt(r["tetgen_p_tets"] / r["N"], ".1f"),
                     fmt(r["ours_tets"] / r["tetgen_p_tets"], ".0f"),
                     fmt(1e6 * r["ours_seconds"] / r["ours_tets"], ".1f"),
                     fmt(1e6 * r["tetgen_p_seconds"] / r["tetgen_p_tets"], ".1f")])
    if not rows:
        return
    print("The time ratio splits into how many tets each tool makes and how long each tet "
          "takes. The projection method's prisms overlay the projections of the TOP and BOT "
          "triangulations (N < M < N², the paper's complexity section), and each prism is "
          "coned from its centre, so its tets per surface triangle are fixed by the method, "
          "not by the implementation:\n")
    table(["surface", "N", "ours tets / N", "TetGen -pQ tets / N", "tets ours / TetGen",
           "ours µs per tet", "TetGen µs per tet"], rows)


def tetgen_cell(run, nodes=False):
    if run is None:
        return None
    if not run["ok"]:
        return f"fails ({run['message'][:50]})" if run["message"] else "fails"
    return f"{run['tets']:,} ({run['nodes']:,})" if nodes else f"{run['tets']:,}"


def fit(x, y):
    """The exponent and factor of y = c x^p by least squares in log-log, None if < 2 points."""
    pts = [(a, b) for a, b in zip(x, y) if a and b and a > 0 and b > 0]
    if len(pts) < 2:
        return None, None
    lx, ly = np.log([p[0] for p in pts]), np.log([p[1] for p in pts])
    p, c = np.polyfit(lx, ly, 1)
    return float(p), float(math.exp(c))


def complexity(out, results, spheres, cones):
    series = {kind: [run_row(out, f"{kind}-{n}", None, out / f"{kind}-{n}.off")
                     for n in sizes.split(",")]
              for kind, sizes in (("sphere", spheres), ("cone", cones))}
    print("Both along `--axis z`. **Sphere**: the octahedron split k times into four, its "
          "vertices pushed onto the unit sphere, symmetric in z bit for bit, so every TOP "
          "triangle lies exactly over one BOT triangle: the paper's best case. **Cone** (the "
          "paper's Fig. 5): K base vertices on the unit circle at z = 0, the base fanned around "
          "its centre (0, 0, 0) (the K BOT triangles), the lateral surface fanned around the apex "
          "(0.3, 0.2, 1), whose projection lies inside the base but off its centre, so the "
          "two fans' projected edges cross about K²/2 times (the K TOP triangles); N = 2K. "
          f"Paper: best case {PAPER_BEST}; worst case {PAPER_WORST}.\n")
    header = ["surface", "N", "M", "M / N", "tets", "Steiner bnd / int", "time s",
              "project s", "stitch s", "fill s", "check valid", "mesh vol. rel. diff."]
    rows, json_rows, fits = [], [], []
    for kind, runs in series.items():
        for r in runs:
            rows.append([r["name"], r["N"], r["M"] if r["status"] == "meshed" else r["status"],
                         fmt(r["M"] / r["N"], ".2f") if r["M"] else None, r["tets"],
                         f"{fmt(r['steiner_boundary'])} / {fmt(r['steiner_interior'])}",
                         fmt(r["seconds"], ".2f"), fmt(r["stage_project"], ".2f"),
                         fmt(r["stage_stitch"], ".2f"), fmt(r["stage_fill"], ".2f"),
                         fmt(r["check_valid"]), fmt(r["volume_difference"], ".1e")])
            json_rows.append({"series": kind, **r})
        ok = [r for r in runs if r["status"] == "meshed"]
        n = [r["N"] for r in ok]
        m = [r["M"] for r in ok]
        t = [r["seconds"] for r in ok]
        st = [r["stage_stitch"] for r in ok]
        fits.append([kind, len(ok), fmt(fit(n, m)[0], ".2f"), fmt(fit(n, t)[0], ".2f"),
                     fmt(fit(m, t)[0], ".2f"), fmt(fit(m, st)[0], ".2f"),
                     "M ~ N¹ (M = N/2), time ~ N¹" if kind == "sphere" else
                     "M ~ N² at most, time ~ M³ at most (stage two)"])
    table(header, rows)
    print("Fitted exponents p of y = c·x^p (log-log least squares over the meshed "
          "resolutions):\n")
    table(["series", "points", "M vs N", "time vs N", "time vs M", "stitch time vs M",
           "paper's bound"], fits)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    all_n = []
    for (kind, runs), colour in zip(series.items(), ("tab:blue", "tab:orange")):
        ok = [r for r in runs if r["status"] == "meshed"]
        if not ok:
            continue
        n = np.array([r["N"] for r in ok], float)
        all_n += list(n)
        axes[0].loglog(n, [r["M"] for r in ok], "o-", color=colour, label=f"{kind}: M")
        axes[1].loglog(n, [r["seconds"] for r in ok], "o-", color=colour, label=f"{kind}: time")
        axes[1].loglog(n, [r["stage_stitch"] for r in ok], "x:", color=colour,
                       label=f"{kind}: stitch stage")
    if all_n:
        n_ref = np.geomspace(min(all_n), max(all_n), 20)
        axes[0].loglog(n_ref, n_ref / 2, "k--", lw=0.8, label="N/2 (best case)")
        axes[0].loglog(n_ref, n_ref ** 2 / 8, "k:", lw=0.8, label="N²/8")
    for ax, ylabel in zip(axes, ("prisms M", "seconds")):
        ax.set_xlabel("surface triangles N")
        ax.set_ylabel(ylabel)
        ax.grid(True, which="both", lw=0.3)
        ax.legend()
    fig.suptitle("tet-projection: prisms and time against N (sphere: best case, cone: worst)")
    fig.tight_layout()
    fig.savefig(results / "complexity.png", dpi=110)
    plt.close(fig)
    print("![complexity](complexity.png)\n")
    write_rows(results, "complexity", json_rows)


def twisted(out, results, schoenhardt_deg):
    runs = [line.split() for line in (out / "twisted.runs").read_text().splitlines() if line]
    header = ["surface", "K", "twist °", "of limit", "status", "N", "M", "tets",
              "Steiner bnd / int", "time s", "check valid", "exact volume",
              "mesh vol. rel. diff.", "TetGen -pQ tets", "TetGen -pYQ tets (nodes)"]
    rows, json_rows = [], []
    entries = [("schoenhardt", 3, float(schoenhardt_deg), SCHOENHARDT_LIMIT_DEG)] + \
        [(f"twisted-{k}-{deg}", int(k), float(deg), float(limit)) for k, deg, limit in runs]
    for name, k, deg, limit in entries:
        r = run_row(out, name, f"{name}.off", out / f"{name}.off")
        past = deg > limit
        status = r["status"] if r["status"] != "input" else "refused (input check)"
        expected = (r["status"] == "input") if past else (r["status"] == "meshed"
                                                          and r["check_valid"] and volume_ok(r))
        p, y = tetgen_row(out, name), tetgen_row(out, f"{name}-Y")
        rows.append([name, k, fmt(deg, "g"), fmt(deg / limit, ".2f"),
                     status + ("" if expected else " ✗"), r["N"], r["M"], r["tets"],
                     f"{fmt(r['steiner_boundary'])} / {fmt(r['steiner_interior'])}",
                     fmt(r["seconds"], ".2f"), fmt(r["check_valid"]),
                     fmt(r["volume"], ".10g"), fmt(r["volume_difference"], ".1e"),
                     tetgen_cell(p), tetgen_cell(y, nodes=True)])
        json_rows.append({"K": k, "twist_deg": deg, "limit_deg": limit, "expected": expected,
                          **r, "tetgen_p": p, "tetgen_pY": y})
    print("Each K-gon prism: the regular K-gon of radius 1 at z = 0, the same at z = 1 turned "
          "by the twist, caps fanned from one vertex, each side quad split along its reflex "
          "diagonal (from bottom vertex i to top vertex i + 1, spanning 360/K + twist degrees "
          "around the axis). At twist 180 − 360/K every such diagonal passes through the axis "
          "and they all meet there: the limit; each K is run at fractions of it and once "
          "just past it, where the input check must refuse. Schönhardt's polyhedron: K = 3, "
          f"twist {schoenhardt_deg}°. Axis auto. ✗ marks a run that did not do what it must "
          "(mesh below the limit with a valid mesh of the exact volume; refuse past it). "
          "The exact volumes as rationals are in twisted.json. TetGen (with the tetgen part): "
          "`-pQ` and `-pYQ` on the same OFF file; -pYQ's nodes beyond the surface's 2K vertices "
          "are its Steiner points.\n")
    table(header, rows)
    for name, r in zip([e[0] for e in entries], json_rows):
        if r["message"]:
            print(f"- {name}: `{r['message'].split('.off: ', 1)[-1]}`")
    print()
    write_rows(results, "twisted", json_rows)


def main():
    section, out, results = sys.argv[1], Path(sys.argv[2]), Path(sys.argv[3])
    args = sys.argv[4:]
    if section == "sweep":
        sweep(out, results, Path(args[0]), args[1])
    elif section == "tetgen":
        tetgen(out, results, args[0])
    elif section == "complexity":
        complexity(out, results, args[0], args[1])
    elif section == "twisted":
        twisted(out, results, args[0])
    else:
        sys.exit("usage: report.py sweep|tetgen|complexity|twisted OUT RESULTS ...")


if __name__ == "__main__":
    main()
