"""A mesh to meshio, and from there to a Gmsh file and a ParaView file: the primitives' cut
cells as conforming tetrahedra for Gmsh, as polyhedra for ParaView, regions as cell data.

    PYTHONPATH=build/release/python python3 examples/mesh_to_meshio.py
"""
import meshio
import numpy as np
import volmesh

mesh = volmesh.mesh("cutcell", "builtin:primitives", level=4)
print(mesh, "regions", np.unique(mesh.regions))

# meshio's Gmsh writer takes one cell type: the tetrahedra without their boundary triangles.
tets = mesh.to_meshio(decompose="tets", boundary=False)
meshio.write("primitives.msh", tets, file_format="gmsh")
print("primitives.msh:", len(tets.cells[0]), "tetrahedra")

polyhedra = mesh.to_meshio()  # every cell a polyhedron, as ParaView shows them
meshio.write("primitives.vtu", polyhedra)
print("primitives.vtu:", sum(len(b) for b in polyhedra.cells), "polyhedra")
