#!/usr/bin/python3
"""Reads mesh files with meshio and prints, for each file, one line holding a JSON object
of what meshio saw: the point count, the cell count per meshio cell type, and the names of
the data arrays. Usage: meshio_read.py FILE..."""
import json
import sys
from collections import Counter

import meshio

for path in sys.argv[1:]:
    mesh = meshio.read(path)
    cells = Counter()
    for block in mesh.cells:
        cells[block.type] += len(block.data)
    print(json.dumps({
        "points": len(mesh.points),
        "cells": dict(cells),
        "cell_data": sorted(mesh.cell_data),
        "point_data": sorted(mesh.point_data),
        "field_data": sorted(mesh.field_data),
    }))
