#!/usr/bin/env bash
# Domain benchmarks, one command, Release: `volmesh sdf` on armadillo.off at 65^3, 129^3 and
# 257^3 side by side with OpenVDB's mesh-to-level-set on the same grids, and region and
# crossing queries per second for each kind of domain. Writes the report to
# build/validation-domains/report.md (and prints it); the figures in README.md come from it.
set -euo pipefail
cd "$(dirname "$0")/../.."
ROOT=$PWD
BUILD=$ROOT/build/validation-domains
SUDO=$([ "$(id -u)" = 0 ] || echo sudo)

need=()
for p in libopenvdb-dev libcgal-demo; do
  dpkg-query -W -f='${Status}\n' "$p" 2>/dev/null | grep -q '^install ok installed' || need+=("$p")
done
if [ ${#need[@]} -gt 0 ]; then
  echo "installing: ${need[*]}"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${need[@]}"
fi

mkdir -p "$BUILD"
cmake -S validation/domains -B "$BUILD" -DCMAKE_BUILD_TYPE=Release > "$BUILD/configure.log"
cmake --build "$BUILD" -j "$(nproc)" --target volmesh bench_domain_queries vdb_mesh_to_sdf
VOLMESH=$BUILD/volmesh/apps/volmesh/volmesh
DATA=$BUILD/cgal-data/data
MESH=$DATA/meshes/armadillo.off
OUT=$BUILD/out
mkdir -p "$OUT"

# The best of three runs: the machine may be shared.
best() { sort -g | head -1; }
json() { python3 -c "import json,sys; print(json.load(sys.stdin)$1)"; }

report=$BUILD/report.md
{
  echo "# Domain benchmarks ($(date -u +%Y-%m-%d), $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p'))"
  echo
  echo "## Signed distances of armadillo.off (52,000 triangles), dense grid, margin 5%"
  echo
  echo "| grid | volmesh sdf: distances s | total s (read, check, write) | OpenVDB dense s | OpenVDB max error (voxels) | OpenVDB sign errors | OpenVDB narrow band (3 voxels) s |"
  echo "|---|---:|---:|---:|---:|---:|---:|"
  for n in 65 129 257; do
    grid=$OUT/armadillo-$n.rawiv
    dist=() total=()
    for run in 1 2 3; do
      j=$("$VOLMESH" sdf "$MESH" --dim "$n" -o "$grid" --json)
      dist+=("$(echo "$j" | json "['seconds']['distance']")")
      total+=("$(echo "$j" | json "['seconds']['total']")")
    done
    vdb=() narrow=()
    for run in 1 2 3; do
      dense_json=$("$BUILD/vdb_mesh_to_sdf" "$MESH" "$grid")
      vdb+=("$(echo "$dense_json" | json "['seconds']")")
      narrow+=("$("$BUILD/vdb_mesh_to_sdf" "$MESH" "$grid" 3 | json "['seconds']")")
    done
    printf '| %s^3 | %.2f | %.2f | %.2f | %s | %s | %.2f |\n' "$n" \
      "$(printf '%s\n' "${dist[@]}" | best)" "$(printf '%s\n' "${total[@]}" | best)" \
      "$(printf '%s\n' "${vdb[@]}" | best)" "$(echo "$dense_json" | json "['max_error_voxels']")" \
      "$(echo "$dense_json" | json "['sign_mismatches']")" "$(printf '%s\n' "${narrow[@]}" | best)"
  done
  echo
  echo "## Queries per second (uniform points in the bounds + 5%; segments of 1/64 of the diagonal)"
  echo
  "$BUILD/bench_domain_queries" "$DATA" "$OUT/armadillo-129.rawiv"
} | tee "$report"
echo "report: $report"
