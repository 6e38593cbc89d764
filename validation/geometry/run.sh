#!/usr/bin/env bash
# Geometric convergence study (docs/verification.md), one command, Release. Real runs of the
# meshers — cutcell (MMCMS, exact interface points), midpoint (M3C as published) and
# staircase — per octree level on
#   builtin:ball, a torus and an ellipsoid (tests/data/domains): volume error and the
#     two-sided Hausdorff distance between the mesh boundary and the TRUE analytic surface;
#   builtin:primitives: region volumes against the exact ones, Hausdorff overall and near the
#     box edges and cylinder rims (samples within 2h of them);
#   builtin:layers6: region volumes against the exact volumes of the triangulated model, and
#     the total against the unit box (no gaps or overlaps).
# Prints the tables and writes build/validation-geometry/report.md, results.csv and the raw
# JSON lines (results.jsonl). GEOMETRY_MAX_LEVEL (default 7) caps the levels; level 8 needs
# about 1.4 GB and a minute per case.
set -euo pipefail
cd "$(dirname "$0")/../.."
ROOT=$PWD
BUILD=${GEOMETRY_BUILD_DIR:-$ROOT/build/validation-geometry}
MAX=${GEOMETRY_MAX_LEVEL:-7}
DOMAINS=$ROOT/tests/data/domains
PYTHON=/usr/bin/python3

mkdir -p "$BUILD"
cmake -S validation/geometry -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release > "$BUILD/configure.log"
cmake --build "$BUILD" -j "$(nproc)" --target geometry_study > "$BUILD/build.log" 2>&1 || {
  tail -20 "$BUILD/build.log" >&2
  echo "run.sh: building geometry_study failed (log: $BUILD/build.log)" >&2
  exit 1
}
STUDY=$BUILD/geometry_study
RESULTS=$BUILD/results.jsonl
TIMES=$BUILD/times.log
: > "$RESULTS"
: > "$TIMES"
LOAD_START=$(cut -d' ' -f1-3 /proc/loadavg)

run() {  # label domain method last-level
  echo "== $1 $3, levels 3..$4" >&2
  /usr/bin/time -a -o "$TIMES" -f "$1 $3: %e s wall %U s user %M KB" \
    "$STUDY" "$2" --method "$3" --levels "3..$4" | sed "s/^{/{\"case\":\"$1\",/" >> "$RESULTS"
}

MM=$((MAX < 6 ? MAX : 6))  # multi-material cases beyond cutcell stop at level 6
for method in cutcell midpoint staircase; do
  run ball builtin:ball "$method" "$MAX"
  run torus "$DOMAINS/torus.json" "$method" "$MAX"
  run ellipsoid "$DOMAINS/ellipsoid.json" "$method" "$MAX"
done
run primitives builtin:primitives cutcell "$MAX"
run primitives builtin:primitives midpoint "$MM"
run primitives builtin:primitives staircase "$MM"
for method in cutcell midpoint staircase; do run layers6 builtin:layers6 "$method" "$MM"; done

"$PYTHON" validation/geometry/report.py "$RESULTS" "$BUILD/results.csv" "$TIMES" \
  "$LOAD_START" "$(cut -d' ' -f1-3 /proc/loadavg)" | tee "$BUILD/report.md"
echo "report: $BUILD/report.md, CSV: $BUILD/results.csv"
