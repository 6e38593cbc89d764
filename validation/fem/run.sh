#!/usr/bin/env bash
# Finite-element benchmark, one command, Release: Poisson with a smooth manufactured
# solution at about 10^5 and 10^6 unknowns on P1 tets, on the polyhedral space over plain
# hexes and over an octree checkerboard (every cell next to finer ones through hanging
# faces), with Q1 for reference. Prints a table (and writes it to $BUILD/report.md):
# assembly time and rate (space set-up, pattern, local matrices, boundary data), solve time,
# CG iterations, residual, the whole call (with the error norms; wall and CPU seconds) and
# the L2 error. Wall times on a shared machine are only as good as its load average (printed).
#   BUILD=dir validation/fem/run.sh      (default build/validation-fem)
#   validation/fem/run.sh --quick        only the 10^5 rows
set -euo pipefail
cd "$(dirname "$0")/../.."
ROOT=$PWD
BUILD=${BUILD:-$ROOT/build/validation-fem}

mkdir -p "$BUILD"
cmake -S validation/fem -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release > "$BUILD/configure.log"
cmake --build "$BUILD" -j "$(nproc)" --target bench_fem
BENCH=$BUILD/bench_fem

# ~10^5 and ~10^6 unknowns: P1 (N+1)³; polyhedral (N+1)³ on hexes, (2N+1)³ − N³/2 on the
# checkerboard.
cases=("p1 46" "poly-grid 46" "poly-octree 23" "q1 46")
if [ "${1:-}" != "--quick" ]; then
  cases+=("p1 100" "poly-grid 100" "poly-octree 50" "q1 100")
fi

report=$BUILD/report.md
{
  echo "# Poisson FEM benchmark ($(date -u +%Y-%m-%d), $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p'), load average $(cut -d' ' -f1 /proc/loadavg))"
  echo
  echo "| mesh | space | cells | unknowns | assembly s | cells/s | solve s | solver | iterations | residual | total s | total CPU s | L2 error |"
  echo "|---|---|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|"
  for c in "${cases[@]}"; do
    # shellcheck disable=SC2086
    "$BENCH" $c
  done
} | tee "$report"
echo "report: $report"
