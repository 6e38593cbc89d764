#!/usr/bin/env bash
# Robustness sweep, one command, Release: `volmesh mesh cutcell` on every OFF surface
# of libcgal-demo at levels 4-6 (SURFACES_LEVELS="L ..." for others). Per surface and level:
# the verdict (a mesh, or the one-line refusal of a bad input: open, non-manifold,
# inconsistently oriented, degenerate), cells, cells split at reflex edges, faces still beyond
# checkMesh's limits, the mesh's volume against the surface's own (planar-faced parts should
# come out exact), and the time; then the meshes with no such face and the faces in all. A
# closed surface that does not mesh is a bug: the script exits 1 if there is one.
# Writes build/validation-octree/surfaces.md and prints it. VALIDATION_BUILD=DIR builds there.
set -euo pipefail
cd "$(dirname "$0")/../.."
ROOT=$PWD
BUILD=${VALIDATION_BUILD:-$ROOT/build/validation-octree}
OUT=$BUILD/surfaces
LEVELS=${SURFACES_LEVELS:-4 5 6}  # SURFACES_LEVELS="7" validation/octree/surfaces.sh: level 7 alone

# shellcheck source=setup.sh
. "$ROOT/validation/octree/setup.sh"
install_missing libcgal-demo
mkdir -p "$OUT"
build_volmesh

for surface in "$MESHES"/*.off; do
  name=$(basename "$surface" .off)
  for level in $LEVELS; do
    if "$VOLMESH" mesh cutcell "$surface" --level "$level" -o "$OUT/mesh.vtu" --json \
        > "$OUT/$name-$level.json" 2> "$OUT/$name-$level.err"; then
      :
    else
      echo "{\"exit\": $?}" > "$OUT/$name-$level.json"
    fi
    # A refused input is refused at every level.
    grep -q '"exit"' "$OUT/$name-$level.json" && grep -q "$name.off:" "$OUT/$name-$level.err" && break
  done
done

status=0
python3 - "$MESHES" "$OUT" "$LEVELS" > "$BUILD/surfaces.md" <<'PY' || status=$?
import json, sys
from pathlib import Path

meshes, out, levels = Path(sys.argv[1]), Path(sys.argv[2]), sys.argv[3].split()


def off_volume(path):
    """Volume enclosed by an OFF surface (divergence theorem over its polygons' fans). The
    header may be COFF, NOFF, ...; vertex lines may carry colours after x y z."""
    lines = [l.split("#")[0].split() for l in path.read_text().splitlines()]
    lines = [l for l in lines if l]
    first = 1 if lines[0][0].endswith("OFF") else 0
    head = lines[first] if len(lines[0]) == 1 or first == 0 else lines[0][1:]
    if first == 1 and len(lines[0]) > 1:
        first = 0
    nv, nf = int(head[0]), int(head[1])
    v = [tuple(map(float, l[:3])) for l in lines[first + 1:first + 1 + nv]]
    total = 0.0
    for l in lines[first + 1 + nv:first + 1 + nv + nf]:
        ids = [int(x) for x in l[1:1 + int(l[0])]]
        a = v[ids[0]]
        for k in range(1, len(ids) - 1):
            b, c = v[ids[k]], v[ids[k + 1]]
            total += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                      + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6.0
    return abs(total)


print(f"# Every libcgal-demo surface, `volmesh mesh cutcell --level {' '.join(levels)}`\n")
print("| surface | level | cells | split | bad faces | volume error | s |")
print("|---|---:|---:|---:|---:|---:|---:|")
refused, failed, meshed, clean, bad = [], [], 0, 0, 0
for surface in sorted(meshes.glob("*.off")):
    name = surface.stem
    for level in levels:
        js = out / f"{name}-{level}.json"
        if not js.exists():
            continue
        d = json.loads(js.read_text())
        if "exit" in d:
            err = (out / f"{name}-{level}.err").read_text().strip().splitlines()
            line = err[-1] if err else "(no message)"
            (refused if f"{name}.off:" in line else failed).append((name, level, line))
            break
        meshed += 1
        clean += d["bad_faces"] == 0
        bad += d["bad_faces"]
        error = d["validity"]["total_volume"] / off_volume(surface) - 1.0
        print(f"| {name} | {level} | {d['cells']} | {d['split_cells']} | {d['bad_faces']} "
              f"| {error:.1e} | {d['time_seconds']:.2f} |")
print(f"\n{meshed} meshes, {clean} with no face beyond checkMesh's limits by our measure "
      f"({bad} such faces in all). Refused inputs (one clear line each, exit 1):\n")
for name, level, line in refused:
    print(f"- {name}: `{line}`")
print(f"\nClosed surfaces that did not mesh: {len(failed)}")
for name, level, line in failed:
    print(f"- {name} level {level}: `{line}`")
sys.exit(1 if failed else 0)
PY
cat "$BUILD/surfaces.md"
exit $status
