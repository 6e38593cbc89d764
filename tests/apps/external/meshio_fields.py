#!/usr/bin/python3
"""Reads one mesh with meshio and prints one JSON object: the point and cell counts and, for
every point and cell data array, its number of components and the largest absolute value
(NaN left out). Usage: meshio_fields.py FILE"""
import json
import sys

import meshio
import numpy as np


def summary(arrays):
    out = {}
    for name, data in arrays.items():
        values = np.concatenate([np.asarray(a, dtype=float).reshape(len(a), -1) for a in data]) \
            if isinstance(data, list) else np.asarray(data, dtype=float).reshape(len(data), -1)
        finite = values[np.isfinite(values)]
        out[name] = {"components": int(values.shape[1]), "count": int(values.shape[0]),
                     "max_abs": float(np.abs(finite).max()) if finite.size else None}
    return out


mesh = meshio.read(sys.argv[1])
print(json.dumps({
    "points": len(mesh.points),
    "cells": int(sum(len(block.data) for block in mesh.cells)),
    "point_data": summary(mesh.point_data),
    "cell_data": summary(mesh.cell_data),
}))
