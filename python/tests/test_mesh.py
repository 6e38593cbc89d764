"""volmesh.mesh against `volmesh mesh`: the same cells, figures and bytes."""
import gc
import json

import numpy as np
import pytest
import volmesh

from conftest import TEST_DATA, cli, cli_json, pair, same_files

# What --json reports beyond the mesh: its output, and times that differ run to run.
NOT_COMPARED = {"output", "total_seconds", "time_seconds"}


def figures_without_times(figures):
    return {k: v for k, v in figures.items()
            if k not in NOT_COMPARED and not k.endswith("_seconds")}


def test_cutcell_matches_the_command_line(tmp):
    a, b = pair(tmp, "primitives.vtu")
    expected = cli_json("mesh", "cutcell", "builtin:primitives", "--level", 4, "-o", a)
    mesh = volmesh.mesh("cutcell", "builtin:primitives", level=4)
    assert mesh.num_cells == expected["cells"]
    figures = mesh.figures
    assert figures.pop("h") > 0
    assert figures_without_times(figures) == figures_without_times(expected)
    mesh.write(b)
    assert same_files(a, b)


def test_options_take_the_command_line_names(tmp):
    a, b = pair(tmp, "ball.vtu")
    cli("mesh", "staircase", "builtin:ball", "--level", 4, "--cells-between-levels", 2,
        "-o", a)
    volmesh.mesh("staircase", "builtin:ball", level=4, cells_between_levels=2).write(b)
    assert same_files(a, b)
    a, b = pair(tmp, "box.msh")
    cli("mesh", "grid", "builtin:box", "--level", 2, "--tets", "-o", a)
    volmesh.mesh("grid", "builtin:box", level=2, tets=True).write(b)
    assert same_files(a, b)


def test_arrays_are_read_only_views_that_keep_the_mesh_alive():
    mesh = volmesh.mesh("grid", "builtin:box", level=2)
    points, regions, offsets = mesh.points, mesh.regions, mesh.face_offsets
    assert points.shape == (mesh.num_points, 3) and points.dtype == np.float64
    assert regions.shape == (mesh.num_cells,) and set(regions) == {1}
    assert offsets.shape == (mesh.num_faces + 1,) and offsets[-1] == len(mesh.face_vertices)
    assert not points.flags.writeable
    with pytest.raises(ValueError):
        points[0, 0] = 1.0
    boundary = mesh.neighbour == -1
    assert (mesh.face_tags[boundary] >= 0).all() and (mesh.face_tags[~boundary] == -1).all()
    assert len(mesh.tag_names) > 0
    del mesh
    gc.collect()
    assert np.allclose(points.min(axis=0), 0.0) and np.allclose(points.max(axis=0), 1.0)


def test_cell_blocks():
    hexes = volmesh.mesh("grid", "builtin:box", level=2)
    (kind, data), = hexes.cells
    assert kind == "hexahedron" and data.shape == (64, 8)
    cut = volmesh.mesh("cutcell", "builtin:ball", level=3)
    blocks = cut.cells
    assert all(kind.startswith("polyhedron") for kind, _ in blocks)
    assert sum(len(cells) for _, cells in blocks) == cut.num_cells
    # Every face of every cell once: internal faces twice, boundary faces once.
    faces = sum(len(c) for _, cells in blocks for c in cells)
    assert faces == 2 * cut.num_faces - (cut.neighbour == -1).sum()


def test_the_registry_lists_every_method_and_its_options():
    methods = {m["name"]: m for m in volmesh.methods()}
    assert {"cutcell", "staircase", "grid", "hexdc"} <= set(methods)
    names = {o["name"] for o in methods["cutcell"]["options"]}
    assert "cells_between_levels" in names


def test_domains_from_files_and_dicts(tmp):
    path = TEST_DATA / "domains" / "solids.json"
    expected = cli_json("mesh", "staircase", path, "--level", 3, "-o", tmp / "a.vtu")
    as_dict = json.loads(path.read_text())
    assert volmesh.mesh("staircase", str(path), level=3).num_cells == expected["cells"]
    assert volmesh.mesh("staircase", as_dict, level=3).num_cells == expected["cells"]
    assert volmesh.domain(as_dict).regions == [1, 2]


def test_progress_reports_stages():
    seen = []
    volmesh.mesh("cutcell", "builtin:ball", level=3, progress=lambda s, f: seen.append((s, f)))
    assert seen and all(0.0 <= f <= 1.0 for _, f in seen)
