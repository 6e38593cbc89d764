"""A surface from numpy arrays to a solved problem: a torus-like ring made with numpy, meshed
by cut cells, and a Poisson problem with a known solution solved on it.

    PYTHONPATH=build/release/python python3 examples/surface_to_solution.py
"""
import numpy as np
import volmesh

# A closed ring: a square tube swept around the z axis, as vertices and triangles.
SEGMENTS = 24
square = np.array([[0.6, -0.2], [1.0, -0.2], [1.0, 0.2], [0.6, 0.2]])  # (r, z), counter-clockwise
angles = np.linspace(0.0, 2.0 * np.pi, SEGMENTS, endpoint=False)
vertices = np.array([[r * np.cos(a), r * np.sin(a), z] for a in angles for r, z in square])
triangles = []
for s in range(SEGMENTS):
    here, there = 4 * s, 4 * ((s + 1) % SEGMENTS)
    for k in range(4):
        a, b = here + k, here + (k + 1) % 4
        c, d = there + k, there + (k + 1) % 4
        triangles += [[a, c, b], [b, c, d]]
ring = volmesh.surface(vertices, np.array(triangles))
print(volmesh.info(ring)["surface"]["volume"], "enclosed")

mesh = volmesh.mesh("cutcell", ring, level=5, progress=lambda stage, f: None)
print(mesh, volmesh.check(mesh)["validity"]["valid"])

solution = volmesh.solve("poisson", mesh=mesh, domain=ring, exact="sin(2*x) * cos(y) + z")
print("u at", solution.u.shape, "points; errors", solution.errors)
solution.write("ring-solution.vtu")
