#!/usr/bin/python3
"""Reads a serial VTU with VTK's reader and a PVTU with VTK's parallel reader
(vtkXMLPUnstructuredGridReader) and prints one JSON object comparing them: cell and point
counts, whether the pieces' "global_cell" ids cover every cell once, and for every array of
the serial file the largest absolute difference and the largest absolute value, the cells
matched by global_cell (the serial file's "cell_id" gives its cells' mesh order) and the points
by global_point. Usage: pvtu_compare.py SERIAL.vtu PARALLEL.pvtu"""
import json
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def read(path, reader):
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def arrays(data):
    return {data.GetArrayName(i): vtk_to_numpy(data.GetArray(i)).astype(float)
            for i in range(data.GetNumberOfArrays())}


serial = read(sys.argv[1], vtk.vtkXMLUnstructuredGridReader())
parallel = read(sys.argv[2], vtk.vtkXMLPUnstructuredGridReader())
s_cells, p_cells = arrays(serial.GetCellData()), arrays(parallel.GetCellData())
s_points, p_points = arrays(serial.GetPointData()), arrays(parallel.GetPointData())
global_cell = p_cells["global_cell"].astype(int)
global_point = p_points["global_point"].astype(int)
# Serial cell arrays in mesh order.
order = s_cells.pop("cell_id").astype(int) if "cell_id" in s_cells else np.arange(serial.GetNumberOfCells())
out = {"serial_cells": serial.GetNumberOfCells(), "parallel_cells": parallel.GetNumberOfCells(),
       "serial_points": serial.GetNumberOfPoints(),
       "cells_once": bool(np.array_equal(np.sort(global_cell), np.arange(serial.GetNumberOfCells()))),
       "arrays": {}}
for name, values in s_cells.items():
    by_mesh = np.empty_like(values)
    by_mesh[order] = values
    other = p_cells.get(name)
    out["arrays"][name] = None if other is None else {
        "diff": float(np.nanmax(np.abs(by_mesh[global_cell] - other))),
        "max": float(np.nanmax(np.abs(values)))}
for name, values in s_points.items():
    other = p_points.get(name)
    out["arrays"][name] = None if other is None else {
        "diff": float(np.nanmax(np.abs(values[global_point] - other))),
        "max": float(np.nanmax(np.abs(values)))}
print(json.dumps(out))
