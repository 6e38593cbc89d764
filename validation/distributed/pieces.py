#!/usr/bin/python3
"""Section 5 of run.sh: meshing and solving in pieces. Reads the files run.sh's pieces() wrote
in DIR and prints the report: the pieces of 1, 2 and 4 ranks through VTK's PVTU reader
(vtkXMLPUnstructuredGridReader, cell volumes by vtkCellSizeFilter) against the serial mesh
through VTK's VTU reader, the solutions against the serial one, each process's peak memory and
the meshing time. Usage: pieces.py DIR LEVEL METHOD MESHING (the meshing command measured)"""
import json
import sys

import vtk

out, level, method, meshing = sys.argv[1:5]
RANKS = (1, 2, 4)


def load(name):
    with open(f"{out}/{name}") as f:
        return json.load(f)


def volumes(path, reader):
    """Cells and the volume of each region, through VTK."""
    reader.SetFileName(path)
    reader.Update()
    sizes = vtk.vtkCellSizeFilter()
    sizes.SetInputData(reader.GetOutput())
    sizes.Update()
    data = sizes.GetOutput().GetCellData()
    volume, region = data.GetArray("Volume"), data.GetArray("region")
    by_region = {}
    for c in range(volume.GetNumberOfTuples()):
        r = int(region.GetValue(c))
        by_region[r] = by_region.get(r, 0.0) + volume.GetValue(c)
    ids = data.GetArray("GlobalCellIds")
    once = None if ids is None else sorted(int(ids.GetValue(c)) for c in range(ids.GetNumberOfTuples())) == list(
        range(ids.GetNumberOfTuples()))
    return volume.GetNumberOfTuples(), by_region, once


def peak_mb(path):
    with open(path) as f:
        for line in f:
            if "Maximum resident set size" in line:
                return int(line.split(":")[1]) / 1024.0
    raise ValueError(f"{path}: no maximum resident set size")


cells, serial, _ = volumes(f"{out}/mesh.vtu", vtk.vtkXMLUnstructuredGridReader())
print(f"## The same mesh: {method}, level 5 (graded), serial {cells} cells\n")
print("| ranks | cells (PVTU reader) | every global cell id once | largest relative region-volume difference |")
print("|---|---|---|---|")
for np in RANKS:
    n, regions, once = volumes(f"{out}/mesh{np}.pvtu", vtk.vtkXMLPUnstructuredGridPReader()
                               if hasattr(vtk, "vtkXMLUnstructuredGridPReader") else vtk.vtkXMLPUnstructuredGridReader())
    worst = max(abs(regions.get(r, 0.0) - v) / v for r, v in serial.items())
    print(f"| {np} | {n} | {once} | {worst:.1e} |")

u = load("u.json")
print(f"\n## The same solution: sine on the {method} mesh, level 5, {u['unknowns']} unknowns\n")
print("| ranks | partition | unknowns | iterations | L2 error | relative difference of L2, H1, Linf | "
      "grid level 5, largest difference of u |")
print("|---|---|---|---|---|---|---|")
print(f"| serial | | {u['unknowns']} | {u['iterations']} | {u['errors']['l2']:.6e} | | |")
for np in RANKS:
    r, g = load(f"u{np}.json"), load(f"g{np}.cmp.json")
    diff = max(abs(r["errors"][k] - u["errors"][k]) / u["errors"][k] for k in ("l2", "h1", "linf"))
    print(f"| {np} | {r['partition']} | {r['unknowns']} | {r['iterations']} | {r['errors']['l2']:.6e} | "
          f"{diff:.1e} | {g['arrays']['u']['diff']:.1e} |")

big1, big2 = load("big-serial.json"), load("big-2.json")
print(f"\n## Peak memory per process: level {level}, {big1['cells']} cells, {big1['unknowns']} unknowns\n")
print("| command | one process MB | rank 0 MB | rank 1 MB | largest rank / one process |")
print("|---|---|---|---|---|")
for name, what in (("solve", f"solve poisson --problem sine --method {method} --level {level}"),
                   ("mesh", meshing)):
    one = peak_mb(f"{out}/rss-{name}-serial")
    ranks = [peak_mb(f"{out}/rss-{name}-2.{r}") for r in (0, 1)]
    print(f"| {what} | {one:.0f} | {ranks[0]:.0f} | {ranks[1]:.0f} | {max(ranks) / one:.2f} |")

mesh1, mesh2 = load("bigmesh-serial.json"), load("bigmesh-2.json")
print(f"\n## Time: level {level}\n")
print("| | one process s | 2 ranks s (slowest rank) | 2 ranks / one |")
print("|---|---|---|---|")
print(f"| {meshing}: meshing | {mesh1['time_seconds']:.2f} | {mesh2['time_seconds']:.2f} | "
      f"{mesh2['time_seconds'] / mesh1['time_seconds']:.2f} |")
print(f"| {meshing}: whole command | {mesh1['total_seconds']:.2f} | {mesh2['total_seconds']:.2f} | "
      f"{mesh2['total_seconds'] / mesh1['total_seconds']:.2f} |")
stages = ["mesh", "setup", "assembly", "preconditioner", "solve", "errors", "write", "total"]
for k in stages:
    a, b = big1["seconds"][k], big2["seconds_max"][k]
    print(f"| solve: {k} | {a:.2f} | {b:.2f} | {b / a if a > 0 else float('nan'):.2f} |")
