#!/usr/bin/env bash
# The distributed octree against build_octree, one command, Release: the octree of the
# built-in DOMAIN (ball) at LEVEL (7) built by build_octree on one process (its threads) and on 1,
# 2 and 4 ranks (RANKS) with p4est: leaves, cut leaves and ghosts per rank, wall seconds and
# each process's peak resident memory (/usr/bin/time's maximum RSS). Prints the table and
# writes it to $OUT/report.md (OUT=dir, default build/validation-octree-dist).
set -euo pipefail
cd "$(dirname "$0")/../.."
ROOT=$PWD
OUT=${OUT:-$ROOT/build/validation-octree-dist}
DOMAIN=${DOMAIN:-ball}
LEVEL=${LEVEL:-7}
RANKS=${RANKS:-"1 2 4"}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$OUT"
if [ -z "${BENCH:-}" ]; then  # BENCH=path: a bench_octree_dist already built
  cmake -S validation/octree_dist -B "$OUT/build" -G Ninja -DCMAKE_BUILD_TYPE=Release > "$OUT/configure.log"
  cmake --build "$OUT/build" -j "$(nproc)" --target bench_octree_dist > "$OUT/build.log" 2>&1
  BENCH=$OUT/build/bench_octree_dist
fi

# rss FILE: the maximum resident set size /usr/bin/time -v wrote, in MB.
rss() { awk -F': ' '/Maximum resident set size/ { printf "%.0f", $2 / 1024 }' "$1"; }

{
  echo "| run | rank | leaves | cut leaves | ghosts | seconds | peak RSS (MB) |"
  echo "|---|---|---|---|---|---|---|"
  /usr/bin/time -v -o "$OUT/serial.time" "$BENCH" "$DOMAIN" "$LEVEL" --serial > "$OUT/serial.json"
  python3 -c "import json,sys; d=json.load(open('$OUT/serial.json')); print(f\"| build_octree | - | {d['leaves']} | | | {d['seconds']:.2f} | $(rss "$OUT/serial.time") |\")"
  for np in $RANKS; do
    mpirun -q --oversubscribe -np "$np" sh -c \
      "exec /usr/bin/time -v -o $OUT/np$np.\$OMPI_COMM_WORLD_RANK.time $BENCH $DOMAIN $LEVEL" > "$OUT/np$np.json"
    rank=0
    while read -r line; do
      python3 -c "import json,sys; d=json.loads(sys.argv[1]); print(f\"| p4est, {d['ranks']} ranks | {d['rank']} | {d['leaves']} | {d['cut_leaves']} | {d['ghosts']} | {d['seconds']:.2f} | $(rss "$OUT/np$np.$rank.time") |\")" "$line"
      rank=$((rank + 1))
    done < "$OUT/np$np.json"
  done
} | tee "$OUT/report.md"
