#!/usr/bin/env bash
# Finite-element benchmark, one command, Release: Poisson with a smooth manufactured
# solution at about 10^5 and 10^6 unknowns on P1 tets, on cut cells (builtin:ball, uniform
# octree, the polyhedral space), on the polyhedral space over plain hexes and over an
# octree checkerboard (every cell next to finer ones through hanging faces), with Q1 for
# reference. Prints a table (and writes it to $BUILD/report.md): assembly time and rate
# (space set-up, pattern, local matrices, boundary data), solve time, CG iterations,
# residual, the whole call (with the error norms; wall and CPU seconds) and the L2 error.
# Wall times on a shared machine are only as good as its load average (printed).
#   BUILD=dir validation/fem/run.sh      (default build/validation-fem)
#   validation/fem/run.sh --quick        only the 10^5 rows
#   validation/fem/run.sh --solvers      sparse LDLT against CG + incomplete Cholesky from
#                                        125 to 36,000 unknowns: where direct_limit lies
set -euo pipefail
cd "$(dirname "$0")/../.."
ROOT=$PWD
BUILD=${BUILD:-$ROOT/build/validation-fem}

mkdir -p "$BUILD"
cmake -S validation/fem -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release > "$BUILD/configure.log"
cmake --build "$BUILD" -j "$(nproc)" --target bench_fem
BENCH=$BUILD/bench_fem

HEADER="| mesh | space | cells | DOFs | unknowns | assembly s | cells/s | solve s | solver | iterations | residual | total s | total CPU s | L2 error |
|---|---|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|"

if [ "${1:-}" = "--solvers" ]; then
  report=$BUILD/solvers.md
  {
    echo "# Direct (LDLT) against CG + incomplete Cholesky ($(date -u +%Y-%m-%d), load average $(cut -d' ' -f1 /proc/loadavg))"
    echo
    echo "$HEADER"
    for c in "p1 6" "p1 10" "p1 12" "p1 16" "p1 20" "p1 24" "p1 28" "p1 34" \
             "q1 8 --elasticity" "q1 13 --elasticity" "q1 16 --elasticity" "q1 19 --elasticity" \
             "cutcell 3" "cutcell 4" "cutcell 5" "cutcell 4 --elasticity"; do
      for solver in direct cg; do
        # shellcheck disable=SC2086
        "$BENCH" $c --solver $solver
      done
    done
  } | tee "$report"
  echo "report: $report"
  exit 0
fi

# ~10^5 and ~10^6 unknowns: P1 (N+1)³; polyhedral (N+1)³ on hexes, (2N+1)³ − N³/2 on the
# checkerboard; cut cells of the ball, uniform octree depth 6 and 7.
cases=("p1 46" "cutcell 6" "poly-grid 46" "poly-octree 23" "q1 46")
if [ "${1:-}" != "--quick" ]; then
  cases+=("p1 100" "cutcell 7" "poly-grid 100" "poly-octree 50" "q1 100")
fi

report=$BUILD/report.md
{
  echo "# Poisson FEM benchmark ($(date -u +%Y-%m-%d), $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p'), load average $(cut -d' ' -f1 /proc/loadavg))"
  echo
  echo "$HEADER"
  for c in "${cases[@]}"; do
    # shellcheck disable=SC2086
    "$BENCH" $c
  done
} | tee "$report"
echo "report: $report"
