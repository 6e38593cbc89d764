#!/usr/bin/env bash
# Advancing-front tet mesher benchmark, one command, Release:
#   1. peers: elephant, fandisk, knot1, anchor, femur, armadillo through TetGen -pq1.414, Gmsh -3
#      (Delaunay and HXT, one thread), Netgen (its volume mesher inside the surface as given) and
#      `volmesh mesh tet-front` at a size matched to TetGen's tet count; every mesh through
#      `volmesh check`: tets, time, min/max dihedral, radius-edge max and mean, histogram;
#   2. sweep: tet-front on every closed, manifold, non-self-intersecting libcgal-demo surface
#      (`volmesh info` decides) at the mean edge of its triangles and at 10 times it (graded
#      from the boundary): validity, the volume against the exact enclosed volume, fallbacks,
#      refusals and time-outs;
#   3. paper: builtin:cube-inclusion at --size 2 beside the paper's 297 tets;
#   4. bad: inputs that must be refused with one line, exit 1 and no output file.
# Writes build/validation-tetfront/out/report.md (with CSV and JSON rows beside it) and prints
# it; each run's JSON, stderr, time and `volmesh check` JSON stay in that out/. Knobs:
#   VALIDATION_BUILD=DIR          the Release build to use (default build/release)
#   TETFRONT_RESULTS=DIR          where the results go (default build/validation-tetfront)
#   TETFRONT_PARTS="peers sweep paper bad"   the parts to run (default: all four)
#   TETFRONT_MODELS="elephant ..."           the peers' models (default: the six above)
#   TETFRONT_TIMEOUT=S            per run in the peers part, ours and theirs (default 300)
#   TETFRONT_SIZES="knot1=0.03 ..."          ours' --size per model (default: matched)
#   TETFRONT_MATCH_PASSES=N       reruns of ours at a corrected size while its tet count is
#                                 off TetGen's by more than 1.5x (default 1)
#   TETFRONT_SIZE_FROM=volume     ours at the edge of the regular tet of TetGen's mean tet
#                                 volume, no rerun (default: the mean edge, then matched)
#   TETFRONT_INTERIOR=delaunay|front         ours' --interior (default: tet-front's own)
#   TETFRONT_SWEEP="all" | "NAME ..."        the sweep's surfaces (default all)
#   TETFRONT_SWEEP_TIMEOUT=S      per sweep run (default 300)
#   TETFRONT_SWEEP_SCALES="1 10"  the sweep's sizes, in mean edges (default both)
#   TETFRONT_INTERIOR_RATIO=R     ours with --interior-size R times its --size (default none)
#   TETFRONT_KEEP_MESHES=1        keep the .vtu files (default: deleted once checked)
#   TETFRONT_REPORT_ONLY=1        no runs: the report from the results already in out/
set -euo pipefail
cd "$(dirname "$0")/../.."
ROOT=$PWD
HERE=$ROOT/validation/tetfront
OCTREE=$ROOT/validation/octree
# shellcheck disable=SC2034  # BUILD is read by setup.sh
BUILD=${VALIDATION_BUILD:-$ROOT/build/release}
# Absolute: the Gmsh .geo files name the STL beside them by this path.
RESULTS=$(realpath -m "${TETFRONT_RESULTS:-$ROOT/build/validation-tetfront}")
OUT=$RESULTS/out
PY=/usr/bin/python3  # the Debian python, which has meshio, numpy and netgen

PARTS=${TETFRONT_PARTS:-peers sweep paper bad}
MODELS=${TETFRONT_MODELS:-elephant fandisk knot1 anchor femur armadillo}
TIMEOUT=${TETFRONT_TIMEOUT:-300}
SIZES=${TETFRONT_SIZES:-}
MATCH_PASSES=${TETFRONT_MATCH_PASSES:-1}
SIZE_FROM=${TETFRONT_SIZE_FROM:-edge}
INTERIOR=${TETFRONT_INTERIOR:-}
SWEEP=${TETFRONT_SWEEP:-all}
SWEEP_TIMEOUT=${TETFRONT_SWEEP_TIMEOUT:-300}
SWEEP_SCALES=${TETFRONT_SWEEP_SCALES:-1 10}
INTERIOR_RATIO=${TETFRONT_INTERIOR_RATIO:-}
KEEP=${TETFRONT_KEEP_MESHES:-0}
REPORT_ONLY=${TETFRONT_REPORT_ONLY:-0}
TETGEN_SWITCHES=-pq1.414
MATCH_TOLERANCE=1.5      # ours' tets within this factor of TetGen's: no rerun
PAPER_SIZE=2             # the paper's example: builtin:cube-inclusion, h = 2
BAD_TIMEOUT=60           # a refusal takes a second: a bad input still running is a fault
INFO_TIMEOUT=300         # `volmesh info` (its self-intersection test) per sweep surface

has_part() { [[ " $PARTS " == *" $1 "* ]]; }
runs() { [ "$REPORT_ONLY" != 1 ] && has_part "$1"; }

# shellcheck source=../octree/setup.sh
. "$OCTREE/setup.sh"
if [ "$REPORT_ONLY" != 1 ]; then
  install_missing tetgen gmsh netgen python3-netgen python3-meshio python3-numpy libcgal-demo
  build_volmesh
else
  MESHES=$BUILD/cgal-data/data/meshes
fi
mkdir -p "$OUT"

# A command timed and time-boxed: NAME.out (stdout), NAME.err, NAME.time ("%e %U %S"),
# NAME.exit (124: the time-out).
timed() {  # name seconds command...
  local status=0
  /usr/bin/time -f "%e %U %S" -o "$OUT/$1.time" timeout "$2" "${@:3}" \
    > "$OUT/$1.out" 2> "$OUT/$1.err" || status=$?
  echo "$status" > "$OUT/$1.exit"
  return 0
}

# `volmesh check` of a written mesh into NAME.check.json, the mesh deleted unless kept.
check() {  # name mesh
  rm -f "$OUT/$1.check.json"
  if [ -f "$2" ]; then
    "$VOLMESH" check "$2" --json -q > "$OUT/$1.check.json" 2> "$OUT/$1.check.err" \
      || true  # an invalid mesh is reported in the JSON
    [ "$KEEP" = 1 ] || rm -f "$2"
  fi
}

# Ours: NAME.out is `volmesh mesh tet-front --json`, NAME.size the size used.
ours() {  # name domain size seconds
  local mesh=$OUT/$1.vtu
  local graded=()
  [ -z "$INTERIOR_RATIO" ] \
    || graded=(--interior-size "$("$PY" -c "import sys; print(float(sys.argv[1]) * float(sys.argv[2]))" "$3" "$INTERIOR_RATIO")")
  rm -f "$mesh"
  echo "$3" > "$OUT/$1.size"
  timed "$1" "$4" "$VOLMESH" mesh tet-front "$2" --size "$3" ${INTERIOR:+--interior "$INTERIOR"} \
    "${graded[@]}" -o "$mesh" --json -q
  check "$1" "$mesh"
}

# A finished peer's tets as VTU; a file the converter cannot read leaves no mesh (the row
# then says "no mesh" with the tool's last line).
convert() {  # peer-output vtu
  "$PY" "$HERE/meshes.py" vtu "$1" "$2" 2>> "${2%.vtu}.err" || rm -f "$2"
}

# TetGen on a copy of the surface (its name without a dot before .off: TetGen reads a.0.off
# as iteration 0 of a).
tetgen_run() {  # model
  local dir=$OUT/tetgen base=${1//./_}
  mkdir -p "$dir"
  cp "$MESHES/$1.off" "$dir/$base.off"
  timed "tetgen-$1" "$TIMEOUT" tetgen "$TETGEN_SWITCHES" "$dir/$base.off"
  rm -f "$OUT/tetgen-$1.vtu"
  if [ "$(cat "$OUT/tetgen-$1.exit")" = 0 ]; then
    convert "$dir/$base.1.node" "$OUT/tetgen-$1.vtu"
  fi
  check "tetgen-$1" "$OUT/tetgen-$1.vtu"
  rm -f "$dir/$base".*
}

# Gmsh on the surface as STL, the volume inside its triangles, one thread.
gmsh_run() {  # model algorithm (del3d | hxt)
  local name=gmsh-$2-$1 geo=$OUT/gmsh-$1.geo
  [ -f "$OUT/$1.stl" ] || "$PY" "$HERE/meshes.py" stl "$MESHES/$1.off" "$OUT/$1.stl"
  printf 'Merge "%s";\nSurface Loop(1) = {1};\nVolume(1) = {1};\n' "$OUT/$1.stl" > "$geo"
  rm -f "$OUT/$name.msh" "$OUT/$name.vtu"
  timed "$name" "$TIMEOUT" gmsh "$geo" -3 -nt 1 -algo "$2" -format msh22 -o "$OUT/$name.msh"
  if [ "$(cat "$OUT/$name.exit")" = 0 ]; then
    convert "$OUT/$name.msh" "$OUT/$name.vtu"
  fi
  rm -f "$OUT/$name.msh"
  check "$name" "$OUT/$name.vtu"
}

netgen_run() {  # model maxh
  rm -f "$OUT/netgen-$1.vtu"
  echo "$2" > "$OUT/netgen-$1.size"
  timed "netgen-$1" "$TIMEOUT" "$PY" "$HERE/meshes.py" netgen "$MESHES/$1.off" "$2" \
    "$OUT/netgen-$1.vtu"
  check "netgen-$1" "$OUT/netgen-$1.vtu"
}

size_of() {  # model: TETFRONT_SIZES' entry, else empty
  local entry
  for entry in $SIZES; do
    [ "${entry%%=*}" = "$1" ] && echo "${entry#*=}"
  done
  return 0
}

tets_of() {  # name: the tets `volmesh check` counted, else 0
  "$PY" -c "import json,sys
try: print(json.load(open(sys.argv[1]))['quality']['tets'])
except Exception: print(0)" "$OUT/$1.check.json"
}

# Ours at the given size, else at the regular tet's edge for TetGen's mean tet volume
# (TETFRONT_SIZE_FROM=volume), else at the mean edge of the surface's triangles, then rerun at
# h (ours / TetGen's tets)^(1/3) while the counts differ by more than MATCH_TOLERANCE.
ours_matched() {  # model
  local h pass=0 target tets
  h=$(size_of "$1")
  target=$(tets_of "tetgen-$1")
  if [ -z "$h" ] && [ "$SIZE_FROM" = volume ] && [ "$target" -gt 0 ]; then
    h=$("$PY" "$HERE/meshes.py" regular-edge "$MESHES/$1.off" "$target")
    echo "tet-front $1 --size $h"
    ours "ours-$1" "$MESHES/$1.off" "$h" "$TIMEOUT"
    echo "$h $(tets_of "ours-$1")" > "$OUT/ours-$1.sizes"
    return 0
  fi
  [ -n "$h" ] || h=$("$PY" "$HERE/meshes.py" edge "$MESHES/$1.off")
  : > "$OUT/ours-$1.sizes"
  while :; do
    echo "tet-front $1 --size $h"
    ours "ours-$1" "$MESHES/$1.off" "$h" "$TIMEOUT"
    tets=$(tets_of "ours-$1")
    echo "$h $tets" >> "$OUT/ours-$1.sizes"
    if [ -n "$(size_of "$1")" ] || [ "$pass" -ge "$MATCH_PASSES" ] || [ "$tets" -eq 0 ] \
       || [ "$target" -eq 0 ]; then
      break
    fi
    h=$("$PY" -c "import sys; h, n, t, tol = map(float, sys.argv[1:])
r = n / t
print(repr(h * r ** (1 / 3)) if r > tol or r < 1 / tol else '')" "$h" "$tets" "$target" \
      "$MATCH_TOLERANCE")
    [ -n "$h" ] || break
    pass=$((pass + 1))
  done
}

load() { uptime | sed 's/.*load average: //'; }
LOAD_BEFORE=$(load)
START=$(date +%s)

if runs peers; then
  echo "$MODELS" | tr ' ' '\n' | grep . > "$OUT/peers.models"
  for model in $MODELS; do
    echo "tetgen $TETGEN_SWITCHES $model"
    tetgen_run "$model"
    for algorithm in del3d hxt; do
      echo "gmsh -3 -algo $algorithm $model"
      gmsh_run "$model" "$algorithm"
    done
    echo "netgen $model"
    netgen_run "$model" "$("$PY" "$HERE/meshes.py" edge "$MESHES/$model.off")"
    ours_matched "$model"
  done
fi

if runs sweep; then
  case $SWEEP in
    all) surfaces=$(cd "$MESHES" && ls -- *.off | sed 's/\.off$//') ;;
    *) surfaces=$SWEEP ;;
  esac
  echo "$surfaces" | tr ' ' '\n' | grep . > "$OUT/sweep.candidates"
  : > "$OUT/sweep.surfaces"
  for name in $surfaces; do
    info=$OUT/sweep-$name.info.json
    timeout "$INFO_TIMEOUT" "$VOLMESH" info "$MESHES/$name.off" --json > "$info" \
      2> "$OUT/sweep-$name.info.err" || true  # a surface info refuses is not swept
    "$PY" "$HERE/meshes.py" sweepable "$info" 2> /dev/null || continue
    echo "$name" >> "$OUT/sweep.surfaces"
    edge=$("$PY" "$HERE/meshes.py" edge "$MESHES/$name.off")
    rm -f "$OUT/sweep-$name.volume"
    for scale in $SWEEP_SCALES; do
      run=sweep-$name
      [ "$scale" = 1 ] || run=sweep${scale}x-$name
      h=$("$PY" -c "import sys; print(float(sys.argv[1]) * float(sys.argv[2]))" "$edge" "$scale")
      echo "tet-front $name --size $h"
      ours "$run" "$MESHES/$name.off" "$h" "$SWEEP_TIMEOUT"
      [ -f "$OUT/sweep-$name.volume" ] || [ ! -f "$OUT/$run.check.json" ] \
        || "$PY" "$HERE/meshes.py" volume "$MESHES/$name.off" > "$OUT/sweep-$name.volume"
    done
  done
  echo "$SWEEP_SCALES" > "$OUT/sweep.scales"
fi

if runs paper; then
  echo "tet-front builtin:cube-inclusion --size $PAPER_SIZE"
  ours paper builtin:cube-inclusion "$PAPER_SIZE" "$TIMEOUT"
fi

# Each bad input: NAME.args holds the domain and size; the report reads exit, stderr and
# whether the output file was left behind (NAME.written).
bad() {  # name domain size
  local mesh=$OUT/bad-$1.vtu
  rm -f "$mesh"
  echo "$2 --size $3" > "$OUT/bad-$1.args"
  echo "tet-front (must refuse) $1"
  timed "bad-$1" "$BAD_TIMEOUT" "$VOLMESH" mesh tet-front "$2" --size "$3" -o "$mesh" -q
  if [ -e "$mesh" ]; then echo yes; else echo no; fi > "$OUT/bad-$1.written"
  rm -f "$mesh"
}

if runs bad; then
  bad self-intersecting "$MESHES/camel.off" 0.02
  bad open "$MESHES/open_cube.off" 0.1
  bad size-zero "$MESHES/elephant.off" 0
  bad size-negative "$MESHES/elephant.off" -0.02
  bad size-nan "$MESHES/elephant.off" nan
  bad size-tiny "$MESHES/elephant.off" 1e-9
  bad size-huge "$MESHES/elephant.off" 1e9
fi

if [ "$REPORT_ONLY" != 1 ]; then
  echo "- $(date -u '+%Y-%m-%d %H:%M') UTC, commit $(git -C "$ROOT" rev-parse --short HEAD),"\
       "parts $PARTS, time-outs $TIMEOUT s (sweep $SWEEP_TIMEOUT s):"\
       "$(( $(date +%s) - START )) s; load average (1, 5, 15 min) before $LOAD_BEFORE,"\
       "after $(load)" >> "$OUT/runs.log"
fi

report=$OUT/report.md
{
  echo "# Advancing-front tet mesher (tet-front): peers, libcgal-demo sweep, paper, bad inputs"
  echo
  echo "$(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p'), Release build. The runs"\
       "behind this report (a later run of a part replaces an earlier one's results):"
  echo
  cat "$OUT/runs.log" 2> /dev/null || true
  echo
  echo "— marks a figure a run did not produce."
  echo
  for part in peers sweep paper bad; do
    if has_part "$part"; then
      "$PY" "$HERE/report.py" "$part" "$OUT" "$TETGEN_SWITCHES"
    fi
  done
} > "$report"
cat "$report"
