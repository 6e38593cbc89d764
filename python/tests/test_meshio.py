"""Mesh.to_meshio and volmesh.from_meshio: round trips, and files meshio writes for other tools."""
import meshio
import numpy as np
import pytest
import volmesh


def volume(mesh):
    return volmesh.check(mesh)["validity"]["total_volume"]


def boundary_by_tag(mesh):
    """Each boundary face's sorted vertices, by its tag's name."""
    out = {}
    for f in np.flatnonzero(mesh.neighbour == -1):
        face = mesh.face_vertices[mesh.face_offsets[f]:mesh.face_offsets[f + 1]]
        out.setdefault(mesh.tag_names[mesh.face_tags[f]], set()).add(tuple(sorted(face)))
    return out


def test_tets_round_trip_with_regions_and_tags(tmp):
    mesh = volmesh.mesh("grid", "builtin:box", level=2, tets=True)
    m = mesh.to_meshio()
    assert [b.type for b in m.cells][0] == "tetra"
    assert {b.type for b in m.cells[1:]} == {"triangle"}
    back = volmesh.from_meshio(m)
    assert back.num_cells == mesh.num_cells and np.array_equal(back.regions, mesh.regions)
    assert sorted(back.tag_names) == sorted(mesh.tag_names)
    assert boundary_by_tag(back) == boundary_by_tag(mesh)
    # Through a file: meshio's VTU keeps the cell data, not the field data (the tag names).
    meshio.write(tmp / "tets.vtu", m)
    read = volmesh.from_meshio(meshio.read(tmp / "tets.vtu"))
    assert np.array_equal(read.regions, mesh.regions)
    assert len(read.tag_names) == len(mesh.tag_names)
    assert volume(read) == pytest.approx(volume(mesh), rel=1e-12)


def test_polyhedra_travel_as_meshio_polyhedra(tmp):
    mesh = volmesh.mesh("cutcell", "builtin:primitives", level=3)
    m = mesh.to_meshio()
    assert all(b.type.startswith("polyhedron") for b in m.cells)
    meshio.write(tmp / "cut.vtu", m)
    read = meshio.read(tmp / "cut.vtu")
    assert sum(len(b) for b in read.cells) == mesh.num_cells
    back = volmesh.from_meshio(read)
    assert back.num_cells == mesh.num_cells
    assert volmesh.check(back)["validity"]["valid"]
    assert volume(back) == pytest.approx(volume(mesh), rel=1e-12)
    assert volmesh.check(back)["validity"]["region_volume"] == pytest.approx(
        volmesh.check(mesh)["validity"]["region_volume"], rel=1e-12)


def test_decomposed_to_gmsh_through_meshio(tmp):
    mesh = volmesh.mesh("cutcell", "builtin:ball", level=3)
    m = mesh.to_meshio(decompose="tets", boundary=False)  # meshio's Gmsh writer: one cell type
    meshio.write(tmp / "ball.msh", m, file_format="gmsh", binary=False)
    back = volmesh.from_meshio(meshio.read(tmp / "ball.msh"))
    assert np.array_equal(back.regions, np.ones(back.num_cells))
    assert volume(back) == pytest.approx(volume(mesh), rel=1e-12)


def test_bad_meshio_meshes_raise_one_line():
    with pytest.raises(volmesh.InputError) as e:
        volmesh.from_meshio(meshio.Mesh(np.zeros((4, 3)), [("tetra", [[0, 1, 2, 5]])]))
    assert str(e.value) == "meshio mesh: tetra cell 0: vertex index 5 out of range (4 vertices)"
    with pytest.raises(volmesh.InputError):
        volmesh.from_meshio(meshio.Mesh(np.zeros((4, 3)), [("tetra10", [list(range(10))])]))
