"""Pictures of a volmesh OpenFOAM case (ascii polyMesh with one cellZone per region), for the
validation report. meshio 5.0 cannot read polyhedral VTU files with cell data (it splits the
polyhedra into blocks by face count but not the data), so the polyMesh is parsed here.

  render.py CASE.foam/ OUT.png --title T [--clip x:0.5 [--cut-only]] [--view AZIMUTH,ELEVATION]
            [--boundary-layer]

Without --clip: every boundary face, coloured by the region of its cell. With --clip A:F: only
the cells whose centroid lies below the fraction F of the bounding box along axis A; the
faces bounding that set are drawn with their edges, so the cut cells along the boundaries
and interfaces show on the clip plane; --cut-only keeps only the cut cells (those with a face
not parallel to a coordinate plane), which shows the boundaries and interfaces as the shells
of cut cells the mesher made of them. --boundary-layer colours the cells with a face on the
boundary apart from the rest (hexdc's buffer layer). Orthographic view, Lambert shading, painter's order.
"""
import argparse
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import PolyCollection

HEADER_END = re.compile(r"//\s*\*[ *]*//")


def foam_body(path):
    """The text after the FoamFile header and its closing rule of stars."""
    text = open(path).read()
    match = HEADER_END.search(text)
    return text[match.end():] if match else text


def read_points(path):
    body = foam_body(path)
    triples = re.findall(r"\(\s*([-+0-9.eE]+)\s+([-+0-9.eE]+)\s+([-+0-9.eE]+)\s*\)", body)
    return np.array(triples, dtype=float)


def read_faces(path):
    return [np.array(f.split(), dtype=np.int64)
            for f in re.findall(r"\d+\s*\(([0-9\s]*)\)", foam_body(path))]


def read_labels(path):
    """owner / neighbour: a count, then the labels in parentheses."""
    body = foam_body(path)
    inner = body[body.index("(") + 1:body.rindex(")")]
    return np.array(inner.split(), dtype=np.int64)


def read_zones(path, num_cells):
    """Region per cell from cellZones named region_<n> (0 when a cell is in no zone)."""
    region = np.zeros(num_cells, dtype=np.int64)
    body = foam_body(path)
    for name, labels in re.findall(r"(\w+)\s*\{[^{}]*?List<label>\s*\d+\s*\(([0-9\s]*)\)", body):
        number = re.search(r"(\d+)$", name)
        region[np.array(labels.split(), dtype=np.int64)] = int(number.group(1)) if number else 0
    return region


def read_case(case):
    mesh = case.rstrip("/") + "/constant/polyMesh/"
    points = read_points(mesh + "points")
    faces = read_faces(mesh + "faces")
    owner = read_labels(mesh + "owner")
    neighbour = read_labels(mesh + "neighbour")
    num_cells = int(max(owner.max(), neighbour.max() if len(neighbour) else 0)) + 1
    try:
        region = read_zones(mesh + "cellZones", num_cells)
    except FileNotFoundError:
        region = np.ones(num_cells, dtype=np.int64)
    return points, faces, owner, neighbour, region


def cell_centroids(points, faces, owner, neighbour, num_cells):
    """Mean of the face centres around each cell: enough to decide the side of a clip plane."""
    centres = np.array([points[f].mean(axis=0) for f in faces])
    total = np.zeros((num_cells, 3))
    count = np.zeros(num_cells)
    np.add.at(total, owner, centres)
    np.add.at(count, owner, 1)
    internal = np.arange(len(neighbour))
    np.add.at(total, neighbour, centres[internal])
    np.add.at(count, neighbour, 1)
    return total / count[:, None]


def cut_cells(points, faces, owner, neighbour, num_cells):
    """Cells with a face whose normal is not along a coordinate axis."""
    oblique = np.zeros(len(faces), dtype=bool)
    for i, f in enumerate(faces):
        corners = points[f]
        normal = np.abs(np.cross(corners, np.roll(corners, -1, axis=0)).sum(axis=0))
        oblique[i] = np.sort(normal)[1] > 1e-9 * normal.max()
    cut = np.zeros(num_cells, dtype=bool)
    cut[owner[oblique]] = True
    cut[neighbour[oblique[:len(neighbour)]]] = True
    return cut


def visible_faces(faces, owner, neighbour, keep):
    """(face, cell) for every face with a kept cell on exactly one side."""
    result = []
    for i in range(len(faces)):
        a = keep[owner[i]]
        b = keep[neighbour[i]] if i < len(neighbour) else False
        if a != b:
            result.append((i, owner[i] if a else neighbour[i]))
    return result


def view_basis(azimuth, elevation):
    """Rows: screen x, screen y, towards the viewer."""
    az, el = np.radians(azimuth), np.radians(elevation)
    towards = np.array([np.cos(el) * np.cos(az), np.cos(el) * np.sin(az), np.sin(el)])
    right = np.array([-np.sin(az), np.cos(az), 0.0])
    up = np.cross(towards, right)
    return np.array([right, up, towards])


def mark_boundary_layer(owner, neighbour, region):
    """A region number past the others for every cell owning a boundary face, and the legend's
    names."""
    marked = region.copy()
    layer = region.max() + 1
    marked[owner[len(neighbour):]] = layer
    names = {r: f"region {r}" for r in np.unique(region)}
    names[layer] = "boundary layer"
    return marked, names


def render(points, faces, drawn, region, out, title, azimuth, elevation, edges, names=None):
    basis = view_basis(azimuth, elevation)
    light = basis[2] * 0.8 + basis[1] * 0.45 + basis[0] * 0.25
    light /= np.linalg.norm(light)
    colours = plt.get_cmap("tab10")
    projected, depth, shade = [], [], []
    for face, cell in drawn:
        corners = points[faces[face]]
        p = corners @ basis.T
        normal = np.cross(corners, np.roll(corners, -1, axis=0)).sum(axis=0)  # Newell
        length = np.linalg.norm(normal)
        lambert = abs(normal @ light) / length if length > 0 else 0.0
        base = np.array(colours((region[cell] - 1) % 10)[:3])
        projected.append(p[:, :2])
        depth.append(p[:, 2].mean())
        shade.append(base * (0.35 + 0.65 * lambert))
    order = np.argsort(depth)  # far to near
    fig, ax = plt.subplots(figsize=(8, 8), dpi=150)
    ax.add_collection(PolyCollection(
        [projected[i] for i in order], facecolors=[shade[i] for i in order],
        edgecolors=(0.1, 0.1, 0.1) if edges else "face",
        linewidths=0.15 if edges else 0.05, antialiased=True))
    everything = np.concatenate(projected)
    ax.set_xlim(everything[:, 0].min(), everything[:, 0].max())
    ax.set_ylim(everything[:, 1].min(), everything[:, 1].max())
    ax.set_aspect("equal")
    ax.axis("off")
    shown = np.unique(region)
    names = names or {r: f"region {r}" for r in shown}
    handles = [plt.Rectangle((0, 0), 1, 1, color=colours((r - 1) % 10)) for r in shown]
    ax.legend(handles, [names[r] for r in shown], loc="upper left",
              fontsize=8, frameon=False)
    ax.set_title(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("case")
    parser.add_argument("out")
    parser.add_argument("--title", default="")
    parser.add_argument("--clip", help="AXIS:FRACTION, e.g. x:0.5")
    parser.add_argument("--cut-only", action="store_true", help="with --clip: only the cut cells")
    parser.add_argument("--view", default="-60,25", help="AZIMUTH,ELEVATION in degrees")
    parser.add_argument("--boundary-layer", action="store_true",
                        help="colour the cells with a boundary face apart")
    args = parser.parse_args()
    points, faces, owner, neighbour, region = read_case(args.case)
    keep = np.ones(len(region), dtype=bool)
    if args.clip:
        axis_name, fraction = args.clip.split(":")
        axis = "xyz".index(axis_name)
        lo, hi = points[:, axis].min(), points[:, axis].max()
        centroids = cell_centroids(points, faces, owner, neighbour, len(region))
        cut = lo + float(fraction) * (hi - lo)
        keep = centroids[:, axis] < cut
        kept = "cut cells" if args.cut_only else "cells"
        args.title += f": {kept} with centroid {axis_name} < {cut:.2f}"
        if args.cut_only:
            keep &= cut_cells(points, faces, owner, neighbour, len(region))
    names = None
    if args.boundary_layer:
        region, names = mark_boundary_layer(owner, neighbour, region)
    azimuth, elevation = (float(v) for v in args.view.split(","))
    render(points, faces, visible_faces(faces, owner, neighbour, keep), region, args.out,
           args.title, azimuth, elevation, edges=bool(args.clip), names=names)


if __name__ == "__main__":
    main()
