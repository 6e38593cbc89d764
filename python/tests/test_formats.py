"""volmesh.read and Mesh.write for every format of the README's table, against the command line."""
import pytest
import volmesh

from conftest import TEST_DATA, cli, pair, same_files

WRITTEN = [".vtu", ".msh", ".mesh", ".inp", ".foam"]


@pytest.fixture(scope="module")
def tets(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("tets")
    cli("mesh", "grid", "builtin:box", "--level", 2, "--tets", "-o", tmp / "tets.vtu")
    return tmp / "tets.vtu"


@pytest.mark.parametrize("extension", WRITTEN)
def test_writes_the_bytes_convert_writes(tmp, tets, extension):
    a, b = pair(tmp, "m" + extension)
    cli("convert", tets, a)
    volmesh.read(tets).write(b)
    assert same_files(a, b)


@pytest.mark.parametrize("extension", [".vtu", ".msh", ".mesh", ".foam", ".pvtu"])
def test_reads_what_it_writes(tmp, tets, extension):
    mesh = volmesh.read(tets)
    mesh.write(tmp / ("out" + extension))
    back = volmesh.read(tmp / ("out" + extension))
    assert back.num_cells == mesh.num_cells and back.num_points == mesh.num_points
    volume = volmesh.check(mesh)["validity"]["total_volume"]
    assert volmesh.check(back)["validity"]["total_volume"] == pytest.approx(volume, rel=1e-12)


def test_reads_tetgen(tmp, tets):
    mesh = volmesh.read(tets)
    ((kind, cells),) = mesh.cells
    assert kind == "tetra"
    lines = [f"{mesh.num_points} 3 0 0"] + [f"{i} {p[0]!r} {p[1]!r} {p[2]!r}" for i, p in enumerate(mesh.points)]
    (tmp / "t.node").write_text("\n".join(lines) + "\n")
    lines = [f"{len(cells)} 4 0"] + [f"{i} " + " ".join(map(str, c)) for i, c in enumerate(cells)]
    (tmp / "t.ele").write_text("\n".join(lines) + "\n")
    assert volmesh.read(tmp / "t.ele").num_cells == mesh.num_cells


def test_decompose_writes_polyhedra_as_tets(tmp):
    a, b = pair(tmp, "ball.msh")
    cli("mesh", "cutcell", "builtin:ball", "--level", 3, "-o", a, "--decompose", "tets")
    mesh = volmesh.mesh("cutcell", "builtin:ball", level=3)
    with pytest.raises(volmesh.InputError):
        mesh.write(tmp / "no.msh")
    assert not (tmp / "no.msh").exists()
    mesh.write(b, decompose="tets")
    assert same_files(a, b)


@pytest.mark.parametrize("name", ["cube.obj", "cube_ascii.stl", "cube_le.ply", "cube_quads.off"])
def test_surfaces_round_trip(tmp, name):
    surface = volmesh.read_surface(TEST_DATA / "surfaces" / name)
    for extension in [".stl", ".off", ".obj", ".ply"]:
        surface.write(tmp / ("s" + extension))
        back = volmesh.read_surface(tmp / ("s" + extension))
        assert volmesh.info(back)["surface"]["volume"] == pytest.approx(
            volmesh.info(surface)["surface"]["volume"], rel=1e-6)


def test_grids_and_images_are_domains(tmp):
    cli("sdf", TEST_DATA / "surfaces" / "cube.obj", "--dim", 17, "-o", tmp / "cube.rawiv")
    expected = cli("mesh", "staircase", tmp / "cube.rawiv", "--level", 3, "-o", tmp / "a.vtu", "--json")
    import json
    assert volmesh.mesh("staircase", tmp / "cube.rawiv", level=3).num_cells == json.loads(expected.stdout)["cells"]


def test_bad_files_raise_the_command_lines_line(tmp):
    from conftest import cli_error
    path = TEST_DATA / "bad" / "truncated.stl"
    with pytest.raises(volmesh.InputError) as e:
        volmesh.read_surface(path)
    assert str(e.value) == cli_error("info", path)
    with pytest.raises(volmesh.InputError) as e:
        volmesh.read(tmp / "missing.vtu")
    assert str(e.value) == cli_error("check", tmp / "missing.vtu")
