#!/usr/bin/env bash
# snappyHexMesh (Debian openfoam) on a closed surface, for the side-by-side comparison with
# `volmesh mesh cutcell`:
#   snappy_case.sh <volmesh> <surface.off|stl> <level> <background cells along the longest side> <case dir>
# Background: blockMesh box around the surface's SDF grid (5% margin), cubic cells; castellation with
# refinementSurfaces level (L L), implicit feature snapping, no layers. The point kept inside
# (locationInMesh) is the deepest voxel of the surface's own signed distance field.
# Prints one line: cells, snappyHexMesh wall seconds, its CPU seconds (user + system); leaves the
# case for checkMesh.
set -euo pipefail
volmesh=$1 surface=$2 level=$3 cells=$4 case=$5
name=$(basename "${surface%.*}")
export WM_PROJECT_DIR=${WM_PROJECT_DIR:-/usr/share/openfoam}

rm -rf "$case" && mkdir -p "$case/constant/triSurface" "$case/system"
"$volmesh" convert "$surface" "$case/constant/triSurface/$name.stl" >/dev/null
"$volmesh" sdf "$surface" --dim 65 -o "$case/sdf.rawiv" >/dev/null 2>&1

read -r lo_x lo_y lo_z hi_x hi_y hi_z nx ny nz in_x in_y in_z < <(/usr/bin/python3 - "$case/sdf.rawiv" "$cells" <<'EOF'
import struct, sys, math
data = open(sys.argv[1], 'rb').read()
# rawiv: minXYZ, maxXYZ (float), nverts, ncells, dimXYZ (uint), originXYZ, spanXYZ (float)
lo = struct.unpack('>3f', data[0:12]); hi = struct.unpack('>3f', data[12:24])
dims = struct.unpack('>3I', data[32:44]); origin = struct.unpack('>3f', data[44:56])
span = struct.unpack('>3f', data[56:68])
n = dims[0] * dims[1] * dims[2]
values = struct.unpack('>%df' % n, data[68:68 + 4 * n])
best = max(range(n), key=lambda i: values[i])   # positive inside: the deepest point
i, j, k = best % dims[0], (best // dims[0]) % dims[1], best // (dims[0] * dims[1])
inside = [origin[0] + i * span[0], origin[1] + j * span[1], origin[2] + k * span[2]]
# Background box: the SDF grid's box (the surface's box plus the grid's margin) grown 5%.
size = [h - l for l, h in zip(lo, hi)]
longest = max(size)
h = 1.05 * longest / int(sys.argv[2])
centre = [(l + u) / 2 for l, u in zip(lo, hi)]
n = [max(1, math.ceil(1.05 * s / h)) for s in size]
lo2 = [c - k * h / 2 for c, k in zip(centre, n)]
hi2 = [c + k * h / 2 for c, k in zip(centre, n)]
print(*lo2, *hi2, *n, *inside)
EOF
)

cat > "$case/system/controlDict" <<EOF
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application snappyHexMesh; startFrom startTime; startTime 0; stopAt endTime; endTime 1;
deltaT 1; writeControl timeStep; writeInterval 1; writeFormat ascii; writePrecision 12;
writeCompression off; timeFormat general; timePrecision 6; runTimeModifiable false;
EOF
cat > "$case/system/fvSchemes" <<EOF
FoamFile { version 2.0; format ascii; class dictionary; object fvSchemes; }
ddtSchemes { default steadyState; } gradSchemes { default Gauss linear; }
divSchemes { default none; } laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; } snGradSchemes { default corrected; }
EOF
cat > "$case/system/fvSolution" <<EOF
FoamFile { version 2.0; format ascii; class dictionary; object fvSolution; }
EOF
cat > "$case/system/blockMeshDict" <<EOF
FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
vertices (($lo_x $lo_y $lo_z) ($hi_x $lo_y $lo_z) ($hi_x $hi_y $lo_z) ($lo_x $hi_y $lo_z)
          ($lo_x $lo_y $hi_z) ($hi_x $lo_y $hi_z) ($hi_x $hi_y $hi_z) ($lo_x $hi_y $hi_z));
blocks (hex (0 1 2 3 4 5 6 7) ($nx $ny $nz) simpleGrading (1 1 1));
boundary ( box { type patch; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7)); } );
EOF
cat > "$case/system/meshQualityDict" <<EOF
FoamFile { version 2.0; format ascii; class dictionary; object meshQualityDict; }
#includeEtc "caseDicts/mesh/generation/meshQualityDict.cfg"
EOF
cat > "$case/system/snappyHexMeshDict" <<EOF
FoamFile { version 2.0; format ascii; class dictionary; object snappyHexMeshDict; }
#includeEtc "caseDicts/mesh/generation/snappyHexMeshDict.cfg"
castellatedMesh on; snap on; addLayers off;
geometry { $name.stl { type triSurfaceMesh; name $name; } };
castellatedMeshControls
{
    features ();
    refinementSurfaces { $name { level ($level $level); patchInfo { type wall; } } }
    refinementRegions {}
    locationInMesh ($in_x $in_y $in_z);
    maxLocalCells 10000000; maxGlobalCells 100000000;
}
snapControls { implicitFeatureSnap true; }
addLayersControls { layers {} }
meshQualityControls { #include "meshQualityDict" }
EOF

(cd "$case" && blockMesh -case . > log.blockMesh 2>&1)
(cd "$case" && /usr/bin/time -f "%e %U %S" -o time.snappyHexMesh \
  snappyHexMesh -case . -overwrite > log.snappyHexMesh 2>&1)
touch "$case/$(basename "$case").foam"
cells=$(grep -m1 -oP "nCells:\s*\K[0-9]+" "$case/constant/polyMesh/owner")
read -r wall user system < "$case/time.snappyHexMesh"
echo "$cells $wall $(/usr/bin/python3 -c "print(round($user + $system, 2))")"
