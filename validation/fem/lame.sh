#!/usr/bin/env bash
# The Lamé thick-walled sphere under internal pressure on cut cells: builtin:thick-sphere
# (radii 0.5 and 1), E = 1, ν = 0.3, pressure 1 on the inner surface (traction −p n with
# the true normal, at points mapped onto the true sphere), the exact displacement on the
# outer one. The target: displacement L2 slope ≥ 1.8 over four levels.
#
# Why levels 4..7 and not 3..6: the inner sphere spans 1.8 cells of its radius at level 3
# and 3.6 at level 4, where the solution's relative curvature |∇²u|/|∇u| ≈ 4/r = 8 makes
# h|∇²u|/|∇u| ≈ 1. The coarse levels are pre-asymptotic there: the pairwise L2 rates climb
# from 1.5 (3→4) through 1.6-1.7 (4→5) to 2.0 (5→6 and 6→7): the slope over 3..6 is 1.7,
# over 4..7 1.93 (measured 2026-11-21). Neither the boundary data nor the traction normal
# is the cause: with the exact traction of the cut surface, σ(u)·n_h, the 4→5 rate is still
# 1.77, with −p n_h (the face normal) it is lower; with the exact displacement on both
# spheres it is 2.0 — the natural condition on a coarsely resolved, curved surface is.
# Level 7 has about 760,000 cells and 2.4 million unknowns: 9 GB and 4 minutes of CPU.
#   BUILD=dir LEVELS=4..7 validation/fem/lame.sh    (defaults: build/validation-fem, 4..7)
set -euo pipefail
cd "$(dirname "$0")/../.."
ROOT=$PWD
BUILD=${BUILD:-$ROOT/build/validation-fem}
LEVELS=${LEVELS:-4..7}

mkdir -p "$BUILD"
cmake -S validation/fem -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release > "$BUILD/configure.log"
cmake --build "$BUILD" -j "$(nproc)" --target volmesh > "$BUILD/build-volmesh.log" 2>&1
VOLMESH=$BUILD/volmesh/apps/volmesh/volmesh
OUT=$BUILD/lame

report=$BUILD/lame.md
{
  echo "# Lamé thick-walled sphere on cut cells, levels $LEVELS ($(date -u +%Y-%m-%d), load average $(cut -d' ' -f1 /proc/loadavg))"
  echo
  echo '```'
  /usr/bin/time -f "%e s wall, %U s CPU, %M KB peak" "$VOLMESH" study convergence \
    --problem lame --method cutcell --domain builtin:thick-sphere --levels "$LEVELS" \
    -o "$OUT" 2>&1 | grep -v 'level [0-9]*: '
  echo '```'
} | tee "$report"
/usr/bin/python3 - "$OUT/summary.json" <<'EOF' | tee -a "$report"
import json, sys
series = json.load(open(sys.argv[1]))["series"][0]
slope = series["slope"]["L2"]
levels = [r["level"] for r in series["levels"]]
verdict = "met" if len(levels) >= 4 and slope >= 1.8 else "NOT MET"
print(f"\ndisplacement L2 slope over levels {levels[0]}..{levels[-1]}: {slope:.2f} "
      f"(target >= 1.8 over >= 4 levels: {verdict})")
sys.exit(0 if verdict == "met" else 1)
EOF
echo "report: $report"
