#!/usr/bin/python3
"""Writes with meshio a VTU file holding a unit cube hexahedron, a pyramid on its top
(apex z = 1.5) and a wedge on its x = 1 side (ridge x = 1.5): volumes 1, 1/6 and 1/4,
cell data "region" = 5, and with CELL_IDS (e.g. 2,0,1) cell data "cell_id" of those values.
The normal of the wedge's (0,1,2) triangle points towards (3,4,5): Gmsh's convention, not the
one VTK documents. Usage: meshio_write.py OUT.vtu [CELL_IDS]"""
import sys

import meshio
import numpy as np

points = np.array([
    [0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],   # 0-3 hex bottom
    [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1],   # 4-7 hex top
    [0.5, 0.5, 1.5],                              # 8 pyramid apex
    [1.5, 0, 0.5], [1.5, 1, 0.5],                 # 9-10 wedge ridge
], dtype=float)
cells = [
    ("hexahedron", np.array([[0, 1, 2, 3, 4, 5, 6, 7]])),
    ("pyramid", np.array([[4, 5, 6, 7, 8]])),
    ("wedge", np.array([[1, 5, 9, 2, 6, 10]])),
]
cell_data = {"region": [np.array([5])] * 3}
if len(sys.argv) > 2:
    cell_data["cell_id"] = [np.array([int(i)]) for i in sys.argv[2].split(",")]
meshio.write(sys.argv[1], meshio.Mesh(points, cells, cell_data=cell_data))
