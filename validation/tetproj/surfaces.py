"""Closed, outward-oriented OFF surfaces for the tet-projection benchmark:

  surfaces.py sphere TRIANGLES OUT.off       octahedron subdivided to TRIANGLES (8 * 4^k),
                                             vertices pushed onto the unit sphere
  surfaces.py cone K OUT.off                 the paper's Fig. 5 worst case, K base vertices
  surfaces.py twisted K DEG OUT.off          a K-gon prism, top twisted by DEG degrees
  surfaces.py twist-limit K                  prints the twist at which that prism self-touches

The sphere is symmetric in z (a vertex (x, y, z) has its mirror (x, y, -z) with the same x, y
bits), so along z every TOP triangle has exactly one BOT triangle under it: the paper's best
case, M = N / 2. The cone's BOT triangles are a fan around the base polygon's centre, its TOP
triangles a fan around an apex whose projection is off that centre, so along z the two fans'
edges cross about K^2 / 2 times: M grows as N^2. The twisted prism splits each side quad
along its reflex diagonal (the one spanning 360/K + DEG degrees around the axis), so K = 3 and
DEG = 30 is Schönhardt's polyhedron, which no tetrahedralization without Steiner points fills.
"""
import math
import sys

RADIUS = 1.0
HEIGHT = 1.0
CONE_APEX = (0.3, 0.2, 1.0)  # off the base centre (0, 0, 0), inside the base polygon
STRAIGHT_DEG = 180.0         # a reflex diagonal spanning this passes through the axis


def write_off(path, vertices, triangles):
    with open(path, "w") as f:
        f.write(f"OFF\n{len(vertices)} {len(triangles)} 0\n")
        for v in vertices:
            f.write(" ".join(repr(float(c)) for c in v) + "\n")
        for t in triangles:
            f.write("3 " + " ".join(map(str, t)) + "\n")


def sphere(triangles):
    """The octahedron split k times into 4 (8 * 4^k triangles), projected onto the sphere.
    Each edge midpoint is keyed by its endpoints so neighbours share it."""
    levels = round(math.log(triangles / 8, 4))
    if 8 * 4 ** levels != triangles:
        sys.exit(f"surfaces.py: {triangles} triangles is not 8 * 4^k")
    vertices = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
    faces = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4),
             (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
    for _ in range(levels):
        midpoint = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in midpoint:
                midpoint[key] = len(vertices)
                vertices.append(tuple((p + q) / 2 for p, q in zip(vertices[a], vertices[b])))
            return midpoint[key]

        split = []
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            split += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
        faces = split
    # Normalize with |z| so that mirror vertices keep identical x and y.
    on_sphere = []
    for x, y, z in vertices:
        r = math.sqrt(x * x + y * y + abs(z) * abs(z))
        on_sphere.append((x / r, y / r, math.copysign(abs(z) / r, z)))
    return on_sphere, faces


def polygon(k, z, turn_deg=0.0):
    return [(RADIUS * math.cos(2 * math.pi * i / k + math.radians(turn_deg)),
             RADIUS * math.sin(2 * math.pi * i / k + math.radians(turn_deg)), z)
            for i in range(k)]


def cone(k):
    """Base polygon (vertices 0..k-1, counter-clockwise seen from above) fanned around its
    centre k, lateral triangles fanned around the apex k + 1."""
    vertices = polygon(k, 0.0) + [(0.0, 0.0, 0.0), CONE_APEX]
    centre, apex = k, k + 1
    faces = []
    for i in range(k):
        j = (i + 1) % k
        faces.append((centre, j, i))   # BOT: normal -z
        faces.append((i, j, apex))     # TOP: normal up and out
    return vertices, faces


def twisted(k, deg):
    """Bottom 0..k-1 at z = 0, top k..2k-1 at z = HEIGHT turned by deg; both caps fanned from
    vertex 0 of their polygon; each side quad split along b_i - t_{i+1}."""
    vertices = polygon(k, 0.0) + polygon(k, HEIGHT, deg)
    faces = []
    for i in range(1, k - 1):
        faces.append((0, i + 1, i))              # bottom cap, normal -z
        faces.append((k, k + i, k + i + 1))      # top cap, normal +z
    for i in range(k):
        j = (i + 1) % k
        faces.append((i, j, k + j))
        faces.append((i, k + j, k + i))
    return vertices, faces


def twist_limit(k):
    """The twist at which each reflex diagonal passes through the axis and all of them meet
    there: the prism touches itself."""
    return STRAIGHT_DEG - 360.0 / k


def main():
    kind, args = sys.argv[1], sys.argv[2:]
    if kind == "sphere":
        write_off(args[1], *sphere(int(args[0])))
    elif kind == "cone":
        write_off(args[1], *cone(int(args[0])))
    elif kind == "twisted":
        write_off(args[2], *twisted(int(args[0]), float(args[1])))
    elif kind == "twist-limit":
        print(f"{twist_limit(int(args[0])):g}")
    else:
        sys.exit("usage: surfaces.py sphere N OUT | cone K OUT | twisted K DEG OUT | twist-limit K")


if __name__ == "__main__":
    main()
