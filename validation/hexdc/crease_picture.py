#!/usr/bin/env python3
"""Boundary quad edges of hexdc meshes beside a surface's creases, one panel per mesh.

crease_picture.py SURFACE.off ANGLE OUT.png TITLE=MESH.vtu [TITLE=MESH.vtu ...]

The creases are the surface's edges whose two triangles' normals lie more than ANGLE degrees
apart (hexdc's --feature-angle), drawn in red over the mesh's boundary edges in grey.
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def read_off(path):
    with open(path) as f:
        words = [w for line in f for w in line.split("#")[0].split()]
    assert words[0] == "OFF"
    nv, nf = int(words[1]), int(words[2])
    at = 4
    points = np.array(words[at:at + 3 * nv], dtype=float).reshape(nv, 3)
    at += 3 * nv
    tris = []
    for _ in range(nf):
        n = int(words[at])
        tris.append([int(w) for w in words[at + 1:at + 1 + n]])
        at += 1 + n
    return points, tris


def crease_segments(points, tris, angle):
    normals = []
    sides = {}
    for t, tri in enumerate(tris):
        a, b, c = (points[i] for i in tri[:3])
        n = np.cross(b - a, c - a)
        normals.append(n / np.linalg.norm(n))
        for k in range(3):
            key = tuple(sorted((tri[k], tri[(k + 1) % 3])))
            sides.setdefault(key, []).append(t)
    cos = np.cos(np.radians(angle))
    return [(points[e[0]], points[e[1]]) for e, ts in sides.items()
            if len(ts) == 2 and np.dot(normals[ts[0]], normals[ts[1]]) < cos]


def boundary_edges(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    surface = vtk.vtkDataSetSurfaceFilter()
    surface.SetInputConnection(reader.GetOutputPort())
    edges = vtk.vtkExtractEdges()
    edges.SetInputConnection(surface.GetOutputPort())
    edges.Update()
    out = edges.GetOutput()
    pts = vtk_to_numpy(out.GetPoints().GetData())
    lines = vtk_to_numpy(out.GetLines().GetData()).reshape(-1, 3)[:, 1:]
    return pts, lines, reader.GetOutput().GetNumberOfCells()


def main():
    surface, angle, out = sys.argv[1], float(sys.argv[2]), sys.argv[3]
    panels = [a.split("=", 1) for a in sys.argv[4:]]
    points, tris = read_off(surface)
    creases = crease_segments(points, tris, angle)
    fig = plt.figure(figsize=(7 * len(panels), 7))
    for i, (title, mesh) in enumerate(panels):
        ax = fig.add_subplot(1, len(panels), i + 1, projection="3d")
        pts, lines, cells = boundary_edges(mesh)
        for a, b in lines:
            ax.plot(*zip(pts[a], pts[b]), color="0.55", linewidth=0.4)
        for a, b in creases:
            ax.plot(*zip(a, b), color="red", linewidth=1.2)
        ax.set_title(f"{title} ({cells} hexes)", y=0.93)
        ax.view_init(elev=25, azim=-60)
        ax.set_box_aspect(np.ptp(points, axis=0))
        ax.set_axis_off()
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
