#!/usr/bin/env bash
# Partitioning benchmark, one command, Release. METIS on the face-adjacency graph:
#   1. 100^3 = 10^6 hexes, K = 2 .. 64 (powers of two), k-way (volmesh's default) and
#      recursive bisection: graph and METIS time, edge cut (faces between parts), imbalance,
#      contiguity; `gmsh -part K` on the same mesh as the peer;
#   2. the target case, a cut-cell mesh of about 10^5 cells (builtin:ball, level 7), every
#      K = 2 .. 64 with k-way: the largest imbalance (target <= 1.03), and the powers of two
#      with and without --contiguous.
# With a mesh file argument, case 2 also runs on that mesh (e.g. primitives-l7.vtu).
# Prints the report and writes it to $BUILD/report.md (BUILD=dir, default
# build/validation-partition).
set -euo pipefail
cd "$(dirname "$0")/../.."
ROOT=$PWD
BUILD=${BUILD:-$ROOT/build/validation-partition}
OUT=$BUILD/out
EXTRA_MESH=${1:-}
POWERS=2,4,8,16,32,64
ALL=$(seq -s, 2 64)
GMSH_PARTS="8 64"

if ! command -v gmsh > /dev/null; then
  SUDO=$([ "$(id -u)" = 0 ] || echo sudo)
  echo "installing: gmsh"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends gmsh
fi

mkdir -p "$OUT"
cmake -S validation/partition -B "$BUILD" -DCMAKE_BUILD_TYPE=Release > "$BUILD/configure.log"
cmake --build "$BUILD" -j "$(nproc)" --target bench_partition volmesh > "$BUILD/build.log" 2>&1
BENCH=$BUILD/bench_partition
VOLMESH=$BUILD/volmesh/apps/volmesh/volmesh

# The bench's JSON lines as a markdown table.
TABLE_PY=$(cat <<'EOF'
import json, os, sys
rows = [json.loads(line) for line in sys.stdin if line.startswith("{")]
print("| mesh | cells | K | method | graph s | METIS s (wall) | METIS s (CPU) "
      "| edge cut (faces) | imbalance | contiguous |")
print("|---|---:|---:|---|---:|---:|---:|---:|---:|---|")
for r in rows:
    contiguous = ("yes" if r["contiguous"] else "no") + (" (forced)" if r["contiguity_enforced"] else "")
    print(f"| {os.path.basename(r['mesh'])} | {r['cells']:,} | {r['parts']} | {r['method']} "
          f"| {r['graph_seconds']:.2f} | {r['metis_seconds']:.2f} | {r['cpu_seconds']:.2f} "
          f"| {r['edge_cut']:,} | {r['imbalance']:.4f} | {contiguous} |")
EOF
)
table() { /usr/bin/python3 -c "$TABLE_PY"; }

# One line over many K: the largest imbalance and where, non-contiguous runs, filled parts.
SUMMARY_PY=$(cat <<'EOF'
import json, os, sys
rows = [json.loads(line) for line in sys.stdin if line.startswith("{")]
worst = max(rows, key=lambda r: r["imbalance"])
split = [r["parts"] for r in rows if not r["contiguous"]]
print(f"{os.path.basename(rows[0]['mesh'])}, {rows[0]['cells']:,} cells, K = {rows[0]['parts']} .. {rows[-1]['parts']} "
      f"(k-way): largest imbalance {worst['imbalance']:.4f} (K = {worst['parts']}); "
      f"METIS at most {max(r['cpu_seconds'] for r in rows):.2f} s CPU; "
      f"{len(split)} of {len(rows)} runs with a part in several pieces; "
      f"{sum(r['filled_empty_parts'] for r in rows)} parts left empty by METIS; "
      f"target imbalance <= 1.03: {'met' if worst['imbalance'] <= 1.03 else 'NOT MET'}.")
EOF
)
summary() { /usr/bin/python3 -c "$SUMMARY_PY"; }

cut_cell_case() {  # mesh file
  "$BENCH" "$1" --parts "$ALL" --method kway | summary
  echo
  {
    "$BENCH" "$1" --parts "$POWERS" --method kway
    "$BENCH" "$1" --parts "$POWERS" --method kway --contiguous
  } | table
  echo
}

"$VOLMESH" mesh cutcell builtin:ball --level 7 -o "$OUT/ball-l7.vtu" > "$OUT/ball-l7.log"

report=$BUILD/report.md
{
  echo "# Partitioning benchmark ($(date -u +%Y-%m-%d), $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p'))"
  echo
  echo "Load average at start: $(cut -d' ' -f1-3 /proc/loadavg). Wall times grow with the load"
  echo "of a shared machine; CPU times do not. METIS CPU time includes the statistics."
  echo
  echo "## 10^6 hexes"
  echo
  "$BENCH" --grid 100 --write "$OUT/grid100.msh" --parts "$POWERS" --method all | table
  echo
  echo "gmsh $(gmsh -version 2>&1 | tail -1) \`-part K\` on the same mesh partitions the hexes and"
  echo "the 60,000 boundary quads together (recursive bisection by default); its edge-cut count"
  echo "is on that graph, so it is not the face count above."
  echo
  echo "| K | gmsh partitioning s (wall) | (CPU) | edge cuts (gmsh's graph) | hex imbalance |"
  echo "|---:|---:|---:|---:|---:|"
  for k in $GMSH_PARTS; do
    log=$OUT/gmsh-$k.log
    gmsh "$OUT/grid100.msh" -part "$k" -0 -o "$OUT/gmsh-part.msh" > "$log" 2>&1
    /usr/bin/python3 - "$log" "$k" <<'EOF'
import re, sys
text = open(sys.argv[1]).read()
wall, cpu = re.search(r"Done partitioning mesh \(Wall ([\d.e+-]+)s, CPU ([\d.e+-]+)s\)", text).groups()
cuts = re.search(r"(\d+) total edge-cuts", text).group(1)
lo, hi, avg = re.search(r"Repartition of \d+ hexahedra: (\d+)\(min\) (\d+)\(max\) ([\d.]+)\(avg\)", text).groups()
print(f"| {sys.argv[2]} | {float(wall):.2f} | {float(cpu):.2f} | {int(cuts):,} | {int(hi) / float(avg):.4f} |")
EOF
  done
  echo
  echo "## Cut cells: $(head -1 "$OUT/ball-l7.log" | sed 's/^[^:]*: //')"
  echo
  cut_cell_case "$OUT/ball-l7.vtu"
  if [ -n "$EXTRA_MESH" ]; then
    echo "## $EXTRA_MESH"
    echo
    cut_cell_case "$EXTRA_MESH"
  fi
} | tee "$report"
rm -f "$OUT/grid100.msh" "$OUT/gmsh-part.msh"
echo "report: $report"
