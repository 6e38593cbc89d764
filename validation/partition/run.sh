#!/usr/bin/env bash
# Partitioning benchmark, one command, Release: METIS k-way (volmesh's default) and recursive
# bisection on the face-adjacency graph of 100^3 = 10^6 hexes, K = 2 .. 64 — graph and METIS
# time, edge cut (faces between parts), imbalance, contiguity — and `gmsh -part K` on the same
# mesh as the peer. With a mesh file argument the volmesh rows are run on that mesh too (e.g.
# a cut-cell mesh: validation/partition/run.sh primitives-l3.vtu).
# Prints the table and writes it to build/validation-partition/report.md.
set -euo pipefail
cd "$(dirname "$0")/../.."
ROOT=$PWD
BUILD=$ROOT/build/validation-partition
OUT=$BUILD/out
EXTRA_MESH=${1:-}
PARTS=2,4,8,16,32,64
GMSH_PARTS="8 64"

if ! command -v gmsh > /dev/null; then
  SUDO=$([ "$(id -u)" = 0 ] || echo sudo)
  echo "installing: gmsh"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends gmsh
fi

mkdir -p "$OUT"
cmake -S validation/partition -B "$BUILD" -DCMAKE_BUILD_TYPE=Release > "$BUILD/configure.log"
cmake --build "$BUILD" -j "$(nproc)" --target bench_partition > "$BUILD/build.log" 2>&1
BENCH=$BUILD/bench_partition

# volmesh rows: the bench's JSON lines as a markdown table.
TABLE_PY=$(cat <<'EOF'
import json, sys
rows = [json.loads(line) for line in sys.stdin if line.startswith("{")]
print("| mesh | cells | K | method | graph s | METIS s (wall) | METIS s (CPU) "
      "| edge cut (faces) | imbalance | contiguous |")
print("|---|---:|---:|---|---:|---:|---:|---:|---:|---|")
for r in rows:
    print(f"| {r['mesh']} | {r['cells']:,} | {r['parts']} | {r['method']} "
          f"| {r['graph_seconds']:.2f} | {r['metis_seconds']:.2f} | {r['cpu_seconds']:.2f} "
          f"| {r['edge_cut']:,} | {r['imbalance']:.4f} | {'yes' if r['contiguous'] else 'no'} |")
EOF
)
table() { python3 -c "$TABLE_PY"; }

report=$BUILD/report.md
{
  echo "# Partitioning benchmark ($(date -u +%Y-%m-%d), $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p'))"
  echo
  echo "Load average at start: $(cut -d' ' -f1-3 /proc/loadavg). Wall times grow with the load"
  echo "of a shared machine; CPU times do not."
  echo
  echo "## volmesh: METIS on the face-adjacency graph"
  echo
  "$BENCH" --grid 100 --write "$OUT/grid100.msh" --parts "$PARTS" --method all | table
  if [ -n "$EXTRA_MESH" ]; then
    "$BENCH" "$EXTRA_MESH" --parts "$PARTS" --method all | table | tail -n +3
  fi
  echo
  echo "## gmsh -part K on the same 10^6 hexes (gmsh $(gmsh -version 2>&1 | tail -1))"
  echo
  echo "gmsh partitions the hexes and the 60,000 boundary quads together (recursive bisection"
  echo "by default); its edge-cut count is on that graph, so it is not the face count above."
  echo
  echo "| K | partitioning s (wall) | partitioning s (CPU) | edge cuts (gmsh's graph) | hex imbalance |"
  echo "|---:|---:|---:|---:|---:|"
  for k in $GMSH_PARTS; do
    log=$OUT/gmsh-$k.log
    gmsh "$OUT/grid100.msh" -part "$k" -0 -o "$OUT/gmsh-part.msh" > "$log" 2>&1
    python3 - "$log" "$k" <<'EOF'
import re, sys
text = open(sys.argv[1]).read()
wall, cpu = re.search(r"Done partitioning mesh \(Wall ([\d.e+-]+)s, CPU ([\d.e+-]+)s\)", text).groups()
cuts = re.search(r"(\d+) total edge-cuts", text).group(1)
lo, hi, avg = re.search(r"Repartition of \d+ hexahedra: (\d+)\(min\) (\d+)\(max\) ([\d.]+)\(avg\)", text).groups()
print(f"| {sys.argv[2]} | {float(wall):.2f} | {float(cpu):.2f} | {int(cuts):,} | {int(hi) / float(avg):.4f} |")
EOF
  done
} | tee "$report"
rm -f "$OUT/grid100.msh" "$OUT/gmsh-part.msh"
echo
echo "report: $report"
