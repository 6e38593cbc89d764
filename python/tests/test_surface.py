"""Surfaces from numpy: conversions, nested regions, and bad input as InputError."""
import numpy as np
import pytest
import volmesh

from conftest import TEST_DATA, cli, cli_error, cli_json, cube, pair, read_off, write_off


def test_any_numeric_dtype_is_converted():
    v, t = cube()
    reference = volmesh.info(volmesh.surface(v, t))
    for vertices, triangles in [(v.astype(np.float32), t.astype(np.int32)),
                                (v.astype(np.int64), t.astype(np.uint16)),
                                (v.tolist(), t.astype(np.float64).tolist())]:
        assert volmesh.info(volmesh.surface(vertices, triangles)) == reference
    assert reference["surface"]["volume"] == pytest.approx(1.0)


def test_info_matches_the_command_line(tmp):
    v, t = cube()
    write_off(tmp / "cube.off", v, t)
    expected = cli_json("info", tmp / "cube.off")
    assert volmesh.info(volmesh.surface(v, t)) == {k: expected[k] for k in ("kind", "surface", "bounding_box")}
    assert volmesh.info(str(tmp / "cube.off"))["surface"] == expected["surface"]


def test_a_numpy_surface_meshes_as_its_file(tmp):
    v, t = cube(-1.0, 1.0)
    write_off(tmp / "cube.off", v, t)
    expected = cli_json("mesh", "cutcell", tmp / "cube.off", "--level", 3, "-o", tmp / "a.vtu")
    mesh = volmesh.mesh("cutcell", volmesh.surface(v, t), level=3)
    assert mesh.num_cells == expected["cells"]
    assert volmesh.check(mesh)["validity"]["total_volume"] == pytest.approx(8.0, rel=1e-12)


def test_nested_surfaces_make_regions():
    outer, inner = volmesh.surface(*cube(-1.0, 1.0)), volmesh.surface(*cube(-0.5, 0.5))
    domain = volmesh.domain([outer, inner])
    assert domain.regions == [1, 2]
    mesh = volmesh.mesh("cutcell", domain, level=3)
    volumes = volmesh.check(mesh)["validity"]["region_volume"]
    assert volumes["1"] + volumes["2"] == pytest.approx(8.0, rel=1e-12)
    assert volumes["2"] == pytest.approx(1.0, rel=0.05)


def one_line(error):
    text = str(error.value)
    assert "\n" not in text and text
    return text


def test_an_open_surface_is_refused_as_the_command_line_does():
    path = TEST_DATA / "bad" / "open_surface.off"
    v, t = read_off(path)
    with pytest.raises(volmesh.InputError) as e:
        volmesh.surface(v, t, name=str(path))
    assert one_line(e) == cli_error("info", path)
    assert isinstance(e.value, ValueError)


@pytest.mark.parametrize("vertices, triangles, says", [
    (np.zeros((8, 2)), cube()[1], "vertex: expected an (n, 3) array, got shape (8, 2)"),
    (cube()[0], cube()[1][:, :2], "triangles: expected an (n, 3) array, got shape (12, 2)"),
    (np.where(np.arange(24).reshape(8, 3) == 4, np.nan, cube()[0]), cube()[1], "vertex 1: coordinates not finite"),
    (cube()[0], np.where(cube()[1] == 7, 8, cube()[1]), "vertex index 8 out of range (8 vertices)"),
    (cube()[0], np.where(cube()[1] == 7, -1, cube()[1]), "vertex index -1 out of range (8 vertices)"),
    (cube()[0], cube()[1] + 0.5, "is not an integer"),
    (np.array([["a", "b", "c"]] * 8), cube()[1], "expected numbers"),
])
def test_bad_arrays_raise_one_line(vertices, triangles, says):
    with pytest.raises(volmesh.InputError) as e:
        volmesh.surface(vertices, triangles)
    assert says in one_line(e)
    assert one_line(e).startswith("surface: ")


def test_sdf_matches_the_command_line(tmp):
    a, b = pair(tmp, "cube.rawiv")
    v, t = cube()
    write_off(tmp / "cube.off", v, t)
    cli("sdf", tmp / "cube.off", "--dim", 9, "-o", a)
    d = volmesh.sdf(volmesh.surface(v, t), 9, output=b)
    assert a.read_bytes() == b.read_bytes()
    assert d.shape == (9, 9, 9) and d.dtype == np.float32
    assert d[4, 4, 4] == pytest.approx(0.5) and d[0, 0, 0] < 0
    with pytest.raises(volmesh.InputError):
        volmesh.sdf(volmesh.surface(v, t), 10)

