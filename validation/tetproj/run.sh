#!/usr/bin/env bash
# Exact projection tet mesher benchmark, one command, Release:
#   1. sweep: every libcgal-demo OFF surface through `volmesh mesh tet-projection`: N, TOP/BOT/
#      WALL, prisms M, tets, Steiner points, degenerate prisms, axis and axes tried, time,
#      `volmesh check` validity, the exact enclosed volume against the mesh's; refusals and
#      time-outs listed with their one-line reason;
#   2. complexity: time and M against N for a sphere (the paper's best case) and the paper's
#      worst-case cone (its Fig. 5), five resolutions each, log-log fitted exponents, plots;
#   3. twisted: Schönhardt's polyhedron and K-gon prisms (K = 3..8) twisted up to just below
#      the twist where they touch themselves (and one just past it, which must be refused);
#   4. tetgen: Debian's TetGen `-pQ` and `-pYQ` on the sweep's surfaces and the twisted
#      prisms: success, tets, nodes, time.
# Writes build/validation-tetproj/report.md with its PNG plots, CSV and JSON beside it, and
# prints it; runs' JSON and logs stay in build/validation-tetproj/out/. Knobs:
#   VALIDATION_BUILD=DIR        the Release build to use (default build/release)
#   TETPROJ_RESULTS=DIR         where the results go (default build/validation-tetproj)
#   TETPROJ_PARTS="sweep complexity twisted tetgen"   the parts to run (default: all four)
#   TETPROJ_SWEEP="all" | "named" | "NAME ..."        the sweep's surfaces (named: the three
#                               of the issue's TetGen target)
#   TETPROJ_TIMEOUT=S           per run, ours and TetGen's (default 300)
#   TETPROJ_SPHERES="512 ..."   sphere triangle counts, each 8 * 4^k
#   TETPROJ_CONES="16 ..."      cone base vertices K (N = 2K)
#   TETPROJ_KEEP_MESHES=1       keep the .vtu files (default: deleted once checked)
#   TETPROJ_REPORT_ONLY=1       no runs: the report from the results already in out/
set -euo pipefail
cd "$(dirname "$0")/../.."
ROOT=$PWD
HERE=$ROOT/validation/tetproj
OCTREE=$ROOT/validation/octree
# shellcheck disable=SC2034  # BUILD is read by setup.sh
BUILD=${VALIDATION_BUILD:-$ROOT/build/release}
RESULTS=${TETPROJ_RESULTS:-$ROOT/build/validation-tetproj}
OUT=$RESULTS/out
PY=/usr/bin/python3  # the Debian python, which has numpy and matplotlib

PARTS=${TETPROJ_PARTS:-sweep complexity twisted tetgen}
SWEEP=${TETPROJ_SWEEP:-all}
TIMEOUT=${TETPROJ_TIMEOUT:-300}
SPHERES=${TETPROJ_SPHERES:-512 2048 8192 32768 131072}
CONES=${TETPROJ_CONES:-32 64 128 256 512}
KEEP=${TETPROJ_KEEP_MESHES:-0}
REPORT_ONLY=${TETPROJ_REPORT_ONLY:-0}
NAMED="elephant fandisk knot1"   # the issue's target: within 10x of TetGen's time
TWIST_KS="3 4 5 6 7 8"
TWIST_FRACTIONS="0.25 0.5 0.75 0.9 0.99"   # of the twist where the prism touches itself
TWIST_PAST=1                     # degrees past that twist: must be refused
SCHOENHARDT_TWIST=30

has_part() { [[ " $PARTS " == *" $1 "* ]]; }

# shellcheck source=../octree/setup.sh
. "$OCTREE/setup.sh"
tetgen=()
has_part tetgen && tetgen=(tetgen)
install_missing "${tetgen[@]}" python3-numpy python3-matplotlib libcgal-demo
mkdir -p "$OUT"
build_volmesh
runs() { [ "$REPORT_ONLY" != 1 ] && has_part "$1"; }

# volmesh mesh tet-projection, timed and time-boxed: NAME.json, NAME.err, NAME.time in $OUT;
# a refusal leaves {"exit": N} in NAME.json (124: the time-out) and the message in NAME.err.
# A written mesh is checked by `volmesh check` (NAME.check.json), then deleted unless kept.
tetproj() {  # name surface [options]
  local status=0 mesh=$OUT/$1.vtu
  /usr/bin/time -f "%e %U %S" -o "$OUT/$1.time" timeout "$TIMEOUT" \
    "$VOLMESH" mesh tet-projection "$2" -o "$mesh" --json -q "${@:3}" \
    > "$OUT/$1.json" 2> "$OUT/$1.err" || status=$?
  if [ "$status" != 0 ]; then
    echo "{\"exit\": $status}" > "$OUT/$1.json"
    rm -f "$mesh"
    return 0
  fi
  "$VOLMESH" check "$mesh" --json -q > "$OUT/$1.check.json" 2> "$OUT/$1.check.err" \
    || true  # an invalid mesh is reported in the JSON
  [ "$KEEP" = 1 ] || rm -f "$mesh"
}

# TetGen on a copy of the surface: NAME.tetgen ("exit nodes tets") and NAME.tetgen.time. The
# copy's name has no dot before .off: TetGen reads "a.0.off" as iteration 0 of "a" and writes
# a.1.* instead of a.0.1.*.
tetgen_run() {  # name surface switches
  local dir=$OUT/tetgen status=0 nodes=0 tets=0 base=${1//./_}
  mkdir -p "$dir"
  cp "$2" "$dir/$base.off"
  /usr/bin/time -f "%e %U %S" -o "$OUT/$1.tetgen.time" timeout "$TIMEOUT" \
    tetgen "$3" "$dir/$base.off" > "$OUT/$1.tetgen.log" 2>&1 || status=$?
  if [ "$status" = 0 ] && [ -f "$dir/$base.1.ele" ]; then
    nodes=$(awk '!/^#/ && NF { print $1; exit }' "$dir/$base.1.node")
    tets=$(awk '!/^#/ && NF { print $1; exit }' "$dir/$base.1.ele")
  fi
  echo "$status $nodes $tets" > "$OUT/$1.tetgen"
  rm -f "$dir/$base".*
}

load() { uptime | sed 's/.*load average: //'; }
LOAD_BEFORE=$(load)
START=$(date +%s)

case $SWEEP in
  all) surfaces=$(cd "$MESHES" && ls -- *.off | sed 's/\.off$//') ;;
  named) surfaces=$NAMED ;;
  *) surfaces=$SWEEP ;;
esac
if runs sweep; then
  echo "$surfaces" | tr ' ' '\n' | grep . > "$OUT/sweep.surfaces"
  for name in $surfaces; do
    echo "tet-projection $name"
    tetproj "sweep-$name" "$MESHES/$name.off"
  done
fi

# TetGen on the surfaces of the last sweep (this run's or an earlier one's), but those the
# input check refused.
if runs tetgen && [ -f "$OUT/sweep.surfaces" ]; then
  for name in $(cat "$OUT/sweep.surfaces"); do
    if [ -f "$OUT/sweep-$name.err" ] && grep -q "$name.off:" "$OUT/sweep-$name.err"; then
      continue
    fi
    echo "tetgen $name"
    tetgen_run "sweep-$name" "$MESHES/$name.off" -pQ
    tetgen_run "sweep-$name-Y" "$MESHES/$name.off" -pYQ
  done
fi

if runs complexity; then
  for n in $SPHERES; do
    echo "tet-projection sphere $n --axis z"
    "$PY" "$HERE/surfaces.py" sphere "$n" "$OUT/sphere-$n.off"
    tetproj "sphere-$n" "$OUT/sphere-$n.off" --axis z
  done
  for k in $CONES; do
    echo "tet-projection cone $k --axis z"
    "$PY" "$HERE/surfaces.py" cone "$k" "$OUT/cone-$k.off"
    tetproj "cone-$k" "$OUT/cone-$k.off" --axis z
  done
fi

# Ours and, with the tetgen part, TetGen's -pQ and -pYQ on one generated surface NAME.off.
twisted_run() {  # name
  echo "tet-projection $1"
  tetproj "$1" "$OUT/$1.off"
  if has_part tetgen; then
    tetgen_run "$1" "$OUT/$1.off" -pQ
    tetgen_run "$1-Y" "$OUT/$1.off" -pYQ
  fi
}

if runs twisted; then
  "$PY" "$HERE/surfaces.py" twisted 3 "$SCHOENHARDT_TWIST" "$OUT/schoenhardt.off"
  twisted_run schoenhardt
  : > "$OUT/twisted.runs"
  for k in $TWIST_KS; do
    limit=$("$PY" "$HERE/surfaces.py" twist-limit "$k")
    twists=$(for f in $TWIST_FRACTIONS; do "$PY" -c "print(round($f * $limit, 2))"; done)
    for deg in $twists $("$PY" -c "print($limit + $TWIST_PAST)"); do
      "$PY" "$HERE/surfaces.py" twisted "$k" "$deg" "$OUT/twisted-$k-$deg.off"
      twisted_run "twisted-$k-$deg"
      echo "$k $deg $limit" >> "$OUT/twisted.runs"
    done
  done
fi
if [ "$REPORT_ONLY" != 1 ]; then
  echo "- $(date -u '+%Y-%m-%d %H:%M') UTC, commit $(git -C "$ROOT" rev-parse --short HEAD),"\
       "parts $PARTS, time-out $TIMEOUT s: $(( $(date +%s) - START )) s; load average"\
       "(1, 5, 15 min) before $LOAD_BEFORE, after $(load)" >> "$OUT/runs.log"
fi

report=$RESULTS/report.md
{
  echo "# Exact projection tet mesher (tet-projection): libcgal-demo, complexity, twisted prisms, TetGen"
  echo
  echo "$(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p'), Release build. The runs"\
       "behind this report (meshing, checking and TetGen; a later run of a part replaces an"\
       "earlier one's results):"
  echo
  cat "$OUT/runs.log" 2> /dev/null || true
  echo
  echo "Times are \`volmesh mesh --json\`'s time_seconds (the mesher, without reading and"
  echo "writing); for a refusal or time-out, the process's wall time."
  echo "— marks a figure a run did not produce."
  echo
  if has_part sweep; then
    echo "## libcgal-demo surfaces"
    echo
    "$PY" "$HERE/report.py" sweep "$OUT" "$RESULTS" "$MESHES" "${NAMED// /,}"
  fi
  if has_part tetgen; then
    echo "## TetGen side by side"
    echo
    "$PY" "$HERE/report.py" tetgen "$OUT" "$RESULTS" "${NAMED// /,}"
  fi
  if has_part complexity; then
    echo "## Complexity: sphere (best case) and cone (worst case)"
    echo
    "$PY" "$HERE/report.py" complexity "$OUT" "$RESULTS" "${SPHERES// /,}" "${CONES// /,}"
  fi
  if has_part twisted; then
    echo "## Schönhardt's polyhedron and twisted prisms"
    echo
    "$PY" "$HERE/report.py" twisted "$OUT" "$RESULTS" "$SCHOENHARDT_TWIST"
  fi
} > "$report"
cat "$report"
