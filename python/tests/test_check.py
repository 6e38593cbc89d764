"""volmesh.check, volmesh.partition and volmesh.improve against their commands."""
import numpy as np
import pytest
import volmesh

from conftest import TEST_DATA, cli, cli_json


def without_file(report):
    report = dict(report)
    report.pop("file")
    if "surface" in report:
        report["surface"] = {k: v for k, v in report["surface"].items() if k != "file"}
    return report


def test_check_is_check_json(tmp):
    cli("mesh", "cutcell", "builtin:ball", "--level", 3, "-o", tmp / "ball.vtu")
    expected = cli_json("check", tmp / "ball.vtu", "--surface", "builtin:ball")
    mesh = volmesh.read(tmp / "ball.vtu")
    report = volmesh.check(mesh, surface="builtin:ball")
    assert report["file"] == str(tmp / "ball.vtu")
    assert without_file(report) == without_file(expected)
    assert report["validity"]["valid"] and report["surface"]["hausdorff_relative"] < 0.01


def test_check_against_a_numpy_surface(tmp):
    path = TEST_DATA / "surfaces" / "cube.obj"
    cli("mesh", "cutcell", path, "--level", 3, "-o", tmp / "cube.vtu")
    expected = cli_json("check", tmp / "cube.vtu", "--surface", path)
    surface = volmesh.read_surface(path)
    own = volmesh.surface(surface.vertices, surface.triangles)
    report = volmesh.check(volmesh.read(tmp / "cube.vtu"), surface=own)
    assert without_file(report) == without_file(expected)


def test_partition_is_the_commands(tmp):
    cli("mesh", "grid", "builtin:box", "--level", 3, "-o", tmp / "box.vtu")
    expected = cli_json("partition", tmp / "box.vtu", "--parts", 4, "-o", tmp / "parts.vtu")
    parts = volmesh.partition(volmesh.read(tmp / "box.vtu"), 4)
    assert parts.shape == (512,) and not parts.flags.writeable
    assert np.bincount(parts).tolist() == expected["part_cells"]
    import meshio
    written = meshio.read(tmp / "parts.vtu")
    assert np.concatenate(written.cell_data["partition"]).tolist() == parts.tolist()


def test_improve_is_the_commands(tmp):
    cli("mesh", "grid", "builtin:box", "--level", 2, "--tets", "-o", tmp / "tets.vtu")
    expected = cli_json("improve", tmp / "tets.vtu", "-o", tmp / "better.vtu")
    better = volmesh.improve(volmesh.read(tmp / "tets.vtu"))
    for key in ("before", "after", "operations", "passes"):
        assert better.figures[key] == expected[key]
    better.write(tmp / "py.vtu")
    assert (tmp / "py.vtu").read_bytes() == (tmp / "better.vtu").read_bytes()
    with pytest.raises(volmesh.InputError) as e:
        volmesh.improve(volmesh.mesh("grid", "builtin:box", level=1))
    assert "not a tetrahedron" in str(e.value)
