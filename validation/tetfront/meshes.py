"""The Python steps of the tet-front validation: surface figures, the peers' inputs and outputs
in formats `volmesh check` reads, and Netgen through its Python API.

  meshes.py edge SURFACE.off                  prints the mean edge length of the triangles
  meshes.py volume SURFACE.off                prints the enclosed volume, summed exactly
  meshes.py stl SURFACE.off OUT.stl           the surface as binary STL (Gmsh's input)
  meshes.py vtu IN OUT.vtu                    a peer's tets alone as VTU: IN is TetGen's
                                              BASE.1.node (with BASE.1.ele) or a .msh
  meshes.py netgen SURFACE.off MAXH OUT.vtu   Netgen's volume mesher inside the surface
                                              triangles as given; prints "tets seconds"
  meshes.py sweepable INFO.json               exit 0 when `volmesh info --json` found the
                                              surface closed, manifold, not self-intersecting

Every peer's tets go through `volmesh check`, so all figures come from one tool. A peer whose
convention orders a tet's vertices the other way (Netgen's) writes every tet negative: `vtu`
reverses the order of all tets of a mesh whose signed volumes are mostly negative, and leaves a
mesh whose tets disagree as it is, so that `volmesh check` reports the inverted ones.
"""
import json
import math
import sys
import time
from fractions import Fraction
from pathlib import Path

import meshio
import numpy as np

SIX = 6  # a tet's volume is the triple product over six


def read_surface(path):
    """An OFF file's vertices and triangles, read line by line as volmesh reads it: '#' starts
    a comment, a header word (OFF, COFF, ...) may precede the counts on its line, a vertex line
    may carry a colour after its three coordinates, and a polygon is split into the fan of its
    first corner."""
    lines = (line.split("#", 1)[0].split() for line in open(path, errors="replace"))
    lines = [words for words in lines if words]
    if lines[0][0].isalpha() or lines[0][0].endswith("OFF"):
        lines[0] = lines[0][1:] or lines.pop(1)
    vertex_count, face_count = int(lines[0][0]), int(lines[0][1])
    points = np.array([[float(c) for c in words[:3]] for words in lines[1:1 + vertex_count]])
    triangles = []
    for words in lines[1 + vertex_count:1 + vertex_count + face_count]:
        corners = [int(v) for v in words[1:1 + int(words[0])]]
        triangles += [(corners[0], corners[i - 1], corners[i]) for i in range(2, len(corners))]
    return points, np.array(triangles, dtype=np.int64)


def mean_edge(path):
    points, triangles = read_surface(path)
    edges = [np.linalg.norm(points[triangles[:, a]] - points[triangles[:, b]], axis=1)
             for a, b in ((0, 1), (1, 2), (2, 0))]
    return float(np.concatenate(edges).mean())


def enclosed_volume(path):
    """The divergence theorem over the triangles, in rationals: the exact volume enclosed by
    the doubles of the file (oriented outward; the absolute value if it is inward)."""
    points, triangles = read_surface(path)
    exact = [[Fraction(float(c)) for c in p] for p in points]
    total = Fraction(0)
    for a, b, c in triangles:
        p, q, r = exact[a], exact[b], exact[c]
        total += (p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0])
                  + p[2] * (q[0] * r[1] - q[1] * r[0]))
    return abs(total) / SIX


def signed_volumes(points, tets):
    a, b, c, d = (points[tets[:, i]] for i in range(4))
    return np.einsum("ij,ij->i", np.cross(b - a, c - a), d - a) / SIX


def tets_to_vtu(source, target):
    source = Path(source)
    mesh = meshio.read(source, file_format="tetgen" if source.suffix == ".node" else None)
    tets = mesh.cells_dict["tetra"].copy()
    volumes = signed_volumes(mesh.points, tets)
    if np.count_nonzero(volumes < 0) > len(tets) / 2:
        tets[:, [0, 1]] = tets[:, [1, 0]]
    meshio.write(target, meshio.Mesh(mesh.points, [("tetra", tets)]), binary=True)


def netgen(surface, maxh, target):
    """Netgen's volume mesher (Delaunay filling, then its optimization) inside the surface
    triangles, which it keeps; prints the tets and the seconds of GenerateVolumeMesh."""
    from netgen.meshing import (Element2D, FaceDescriptor, Mesh, MeshingParameters,
                                MeshPoint, Pnt)
    points, triangles = read_surface(surface)
    mesh = Mesh(dim=3)
    ids = [mesh.Add(MeshPoint(Pnt(*map(float, p)))) for p in points]
    mesh.Add(FaceDescriptor(surfnr=1, domin=1, domout=0, bc=1))
    for t in triangles:
        mesh.Add(Element2D(1, [ids[i] for i in t]))
    start = time.perf_counter()
    mesh.GenerateVolumeMesh(MeshingParameters(maxh=maxh))
    seconds = time.perf_counter() - start
    msh = Path(target).with_suffix(".msh")
    mesh.Export(str(msh), "Gmsh2 Format")
    tets_to_vtu(msh, target)
    msh.unlink()
    print(len(mesh.Elements3D()), seconds)


def regular_edge(surface, tets):
    """The edge of the regular tet whose volume is the mean over `tets` tets filling the
    surface: V = h^3 / (6 sqrt 2)."""
    mean = float(enclosed_volume(surface)) / tets
    return (6.0 * math.sqrt(2.0) * mean) ** (1.0 / 3.0)


def sweepable(info):
    surface = json.loads(Path(info).read_text()).get("surface", {})
    return surface.get("closed") and surface.get("manifold") \
        and not surface.get("self_intersections")


def main():
    kind, args = sys.argv[1], sys.argv[2:]
    if kind == "edge":
        print(repr(mean_edge(args[0])))
    elif kind == "regular-edge":
        print(repr(regular_edge(args[0], int(args[1]))))
    elif kind == "volume":
        print(repr(float(enclosed_volume(args[0]))))
    elif kind == "stl":
        points, triangles = read_surface(args[0])
        meshio.write(args[1], meshio.Mesh(points, [("triangle", triangles)]), binary=True)
    elif kind == "vtu":
        tets_to_vtu(args[0], args[1])
    elif kind == "netgen":
        netgen(args[0], float(args[1]), args[2])
    elif kind == "sweepable":
        sys.exit(0 if sweepable(args[0]) else 1)
    else:
        sys.exit("usage: meshes.py edge|regular-edge|volume|stl|vtu|netgen|sweepable ...")


if __name__ == "__main__":
    main()
