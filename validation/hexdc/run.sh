#!/usr/bin/env bash
# All-hex dual contouring benchmark, one command, Release:
#   1. the hex paper's 65^3 field at levels 3-6: node and hex counts beside its Figures 3-5
#      (the paper's field is not published: builtin:ball sampled on the same 65^3 grid);
#   2. its Table 1 rows (uniform -> improved -> refined) on that field at level 4, same columns,
#      and its Table 2 columns beside the named surfaces below;
#   3. every libcgal-demo OFF surface at two levels: the verdict (meshed, or the one-line
#      refusal), hexes, hexes failing the ten corner tets, min and mean scaled Jacobian, max quad
#      distortion, volume error, boundary-to-surface Hausdorff distance against the voxel size,
#      time; surfaces that are not closed are listed with the mesher's reason;
#   4. snappyHexMesh (validation/octree/snappy_case.sh) against `volmesh mesh hexdc` on elephant,
#      fandisk and knot1 at comparable cell counts: cells, time, min scaled Jacobian and
#      inverted hexes (both by `volmesh check`), Hausdorff distance, speed ratio;
#   5. PNG cut-aways of each meshed model with the buffer layer coloured apart.
# Writes build/validation-hexdc/report.md with its pictures, CSV and JSON beside it, and prints
# it. VALIDATION_BUILD=DIR builds and writes there instead. Subsets:
#   HEXDC_PARTS="paper sweep snappy pictures"   the parts to run (default: all four)
#   HEXDC_LEVELS="4 5"                          the sweep's levels
#   HEXDC_SWEEP="all" | "named" | "NAME ..."    the sweep's surfaces (named: the five below)
#   HEXDC_TIMEOUT=1200                          seconds a run may take before it counts as refused
set -euo pipefail
cd "$(dirname "$0")/../.."
ROOT=$PWD
HERE=$ROOT/validation/hexdc
OCTREE=$ROOT/validation/octree
BUILD=${VALIDATION_BUILD:-$ROOT/build/validation-hexdc}
OUT=$BUILD/out
PY=/usr/bin/python3  # the Debian python, which has numpy and matplotlib
export WM_PROJECT_DIR=${WM_PROJECT_DIR:-/usr/share/openfoam}  # where checkMesh finds its etc/

PARTS=${HEXDC_PARTS:-paper sweep snappy pictures}
SWEEP_LEVELS=${HEXDC_LEVELS:-4 5}
SWEEP=${HEXDC_SWEEP:-all}
TIMEOUT=${HEXDC_TIMEOUT:-1200}
NAMED="elephant fandisk knot1 anchor femur"
PAPER_FIELD=builtin:ball  # stands in for the paper's unpublished 65^3 volume file
PAPER_DIM=6               # 2^6 + 1 = 65 samples per axis
PAPER_LEVELS="3 4 5 6"    # Figures 3-5 (levels 3, 5, 6) and Table 1 (level 4)
TABLE1_LEVEL=4
REFINE_LAYERS=1           # --refine-boundary for Table 1's refined column
SNAPPY_SURFACES="elephant fandisk knot1"
SNAPPY_LEVEL=2            # refinementSurfaces level: about 9,000 cells on elephant
SNAPPY_BACKGROUND=18      # background cells along the longest side
HEXDC_LEVEL=6             # the hexdc level nearest snappyHexMesh's cell count
HEXDC_DIM=7               # two voxels per node at level 6
PICTURE_LEVEL=5           # the sweep level drawn for each meshed model
PICTURE_OTHERS=4          # besides the named surfaces, the first few others that meshed

has_part() { [[ " $PARTS " == *" $1 "* ]]; }

# shellcheck source=../octree/setup.sh
. "$OCTREE/setup.sh"
openfoam=()
has_part snappy && ! command -v snappyHexMesh > /dev/null && openfoam=(openfoam)
install_missing "${openfoam[@]}" python3-numpy python3-matplotlib libcgal-demo
mkdir -p "$OUT"
build_volmesh

# volmesh mesh hexdc, timed: NAME.json, NAME.err and NAME.time in $OUT; a refusal leaves
# {"exit": N} in NAME.json and the message in NAME.err.
hexdc() {  # name domain level output [options]
  local status=0
  /usr/bin/time -f "%e %U %S" -o "$OUT/$1.time" \
    timeout "$TIMEOUT" "$VOLMESH" mesh hexdc "$2" --level "$3" -o "$4" --json -q "${@:5}" \
    > "$OUT/$1.json" 2> "$OUT/$1.err" || status=$?
  [ "$status" = 124 ] && echo "error: not finished within ${TIMEOUT} s" >> "$OUT/$1.err"
  [ "$status" = 0 ] || echo "{\"exit\": $status}" > "$OUT/$1.json"
  return 0
}
meshed() { ! grep -q '"exit"' "$OUT/$1.json"; }

# NAME.check.json: validity, scaled Jacobian, volume error, Hausdorff distance to the surface.
check() {  # name mesh surface
  "$VOLMESH" check "$2" --surface "$3" --json -q > "$OUT/$1.check.json" 2> "$OUT/$1.check.err" \
    || true  # an invalid mesh is reported in the JSON
}

load() { uptime | sed 's/.*load average: //'; }
LOAD_BEFORE=$(load)
START=$(date +%s)

if has_part paper; then
  for l in $PAPER_LEVELS; do
    echo "hexdc $PAPER_FIELD --dim $PAPER_DIM --level $l"
    hexdc "paper-l$l" "$PAPER_FIELD" "$l" "$OUT/paper-l$l.foam/" --dim "$PAPER_DIM"
  done
  echo "hexdc $PAPER_FIELD --dim $PAPER_DIM --level $TABLE1_LEVEL --refine-boundary $REFINE_LAYERS"
  hexdc paper-refined "$PAPER_FIELD" "$TABLE1_LEVEL" "$OUT/paper-refined.vtu" \
    --dim "$PAPER_DIM" --refine-boundary "$REFINE_LAYERS"
fi

if has_part sweep; then
  case $SWEEP in
    all) surfaces=$(cd "$MESHES" && ls -- *.off | sed 's/\.off$//') ;;
    named) surfaces=$NAMED ;;
    *) surfaces=$SWEEP ;;
  esac
  echo "$surfaces" | tr ' ' '\n' | grep . > "$OUT/sweep.surfaces"
  for name in $surfaces; do
    for l in $SWEEP_LEVELS; do
      echo "hexdc $name --level $l"
      hexdc "$name-l$l" "$MESHES/$name.off" "$l" "$OUT/$name-l$l.vtu"
      if meshed "$name-l$l"; then
        check "$name-l$l" "$OUT/$name-l$l.vtu" "$MESHES/$name.off"
      elif grep -q "$name.off:" "$OUT/$name-l$l.err"; then
        break  # the surface itself is refused (a hole, ...): the same at every level
      fi
    done
  done
fi

if has_part snappy; then
  for name in $SNAPPY_SURFACES; do
    echo "snappyHexMesh $name (level $SNAPPY_LEVEL, $SNAPPY_BACKGROUND background cells)"
    bash "$OCTREE/snappy_case.sh" "$VOLMESH" "$MESHES/$name.off" "$SNAPPY_LEVEL" \
      "$SNAPPY_BACKGROUND" "$OUT/$name-snappy" > "$OUT/$name-snappy.snappy"
    check "$name-snappy" "$OUT/$name-snappy" "$MESHES/$name.off"
    echo "hexdc $name --level $HEXDC_LEVEL --dim $HEXDC_DIM"
    hexdc "$name-vs-snappy" "$MESHES/$name.off" "$HEXDC_LEVEL" "$OUT/$name-vs-snappy.vtu" \
      --dim "$HEXDC_DIM"
    if meshed "$name-vs-snappy"; then
      check "$name-vs-snappy" "$OUT/$name-vs-snappy.vtu" "$MESHES/$name.off"
    fi
  done
fi
LOAD_AFTER=$(load)
MESHING_SECONDS=$(( $(date +%s) - START ))

# Cut-aways: the cells on one side of a plane through the middle, the boundary layer (the cells
# with a face on the boundary, after pillowing the buffer layer) coloured apart.
pictures=()
picture() {  # case.foam png title
  "$PY" "$OCTREE/render.py" "$1" "$BUILD/$2.png" --title "$3" --clip x:0.5 --boundary-layer
  pictures+=("$2")
}
if has_part pictures; then
  echo "pictures"
  if has_part paper && [ -f "$OUT/paper-l$TABLE1_LEVEL.foam/constant/polyMesh/owner" ]; then
    picture "$OUT/paper-l$TABLE1_LEVEL.foam" paper-l$TABLE1_LEVEL \
      "$PAPER_FIELD, --dim $PAPER_DIM --level $TABLE1_LEVEL"
  fi
  others=0
  for name in $NAMED $(grep -vxF -f <(echo "$NAMED" | tr ' ' '\n') "$OUT/sweep.surfaces" || true); do
    run=$name-l$PICTURE_LEVEL
    [ -f "$OUT/$run.json" ] && meshed "$run" || continue
    if [[ " $NAMED " != *" $name "* ]]; then
      [ "$others" -lt "$PICTURE_OTHERS" ] || continue
      others=$((others + 1))
    fi
    "$VOLMESH" convert "$OUT/$run.vtu" "$OUT/$run.foam/" > "$OUT/$run.convert.log" 2>&1
    picture "$OUT/$run.foam" "$run" "$name.off, hexdc --level $PICTURE_LEVEL"
  done
fi

report=$BUILD/report.md
{
  echo "# All-hex dual contouring (hexdc): the paper's cases, libcgal-demo, snappyHexMesh"
  echo
  echo "$(date -u +%Y-%m-%d), $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p'),"\
       "Release build, commit $(git -C "$ROOT" rev-parse --short HEAD)."
  echo "Load average (1, 5, 15 min) before the runs: $LOAD_BEFORE; after: $LOAD_AFTER;"\
       "meshing and checking took $MESHING_SECONDS s. Parts run: $PARTS."
  echo "Times are \`volmesh mesh --json\`'s time_seconds (wall, both cores) where the mesher"
  echo "wrote a mesh; for a refusal, the process's wall time. CPU is the process's user + system"
  echo "time. ✗ marks a figure that misses its target; — a figure this mesher does not report"
  echo "(yet) or a run that did not make a mesh."
  echo
  if has_part paper; then
    echo "## The paper's 65³ field at levels 3–6 (Figures 3–5)"
    echo
    "$PY" "$HERE/report.py" paper "$OUT" "$BUILD" "$PAPER_FIELD" "$PAPER_DIM" "${PAPER_LEVELS// /,}"
    echo "## Table 1: uniform → improved → refined"
    echo
    "$PY" "$HERE/report.py" table1 "$OUT" "$BUILD" "paper-l$TABLE1_LEVEL" paper-refined \
      "$PAPER_FIELD --dim $PAPER_DIM --level $TABLE1_LEVEL" "$REFINE_LAYERS"
  fi
  if has_part sweep; then
    echo "## Table 2's columns on the named libcgal-demo surfaces"
    echo
    "$PY" "$HERE/report.py" table2 "$OUT" "$BUILD" "$MESHES" "${SWEEP_LEVELS##* }" $NAMED
    echo "## libcgal-demo surfaces at \`--level ${SWEEP_LEVELS// /\` and \`}\`"
    echo
    "$PY" "$HERE/report.py" sweep "$OUT" "$BUILD" "$MESHES" "${SWEEP_LEVELS// /,}" \
      "${NAMED// /,}"
  fi
  if has_part snappy; then
    echo "## snappyHexMesh against hexdc"
    echo
    echo "snappyHexMesh: validation/octree/snappy_case.sh, refinementSurfaces level"\
         "$SNAPPY_LEVEL on a background of $SNAPPY_BACKGROUND cells along the longest side,"
    echo "implicit feature snapping, no layers; its time is snappyHexMesh's alone (blockMesh"
    echo "not counted). hexdc: \`--level $HEXDC_LEVEL --dim $HEXDC_DIM\`. Both meshes checked"
    echo "by \`volmesh check --surface\`: the scaled Jacobian of each hexahedral cell (snappy's"
    echo "other cells are polyhedra), inverted = scaled Jacobian < 0, the two-sided Hausdorff"
    echo "distance of the boundary to the surface. Target: hexdc ≥ 10× faster, no inverted hex."
    echo
    "$PY" "$HERE/report.py" snappy "$OUT" "$BUILD" $SNAPPY_SURFACES
  fi
  if [ ${#pictures[@]} -gt 0 ]; then
    echo "## Pictures"
    echo
    echo "Cells with their centroid below the middle of the bounding box in x, drawn with their"
    echo "edges (validation/octree/render.py --clip x:0.5 --boundary-layer): the cells with a"
    echo "face on the boundary — the buffer layer — in orange, the interior hexes in blue."
    echo "Models refused by the mesher have no picture."
    echo
    for png in "${pictures[@]}"; do echo "![$png]($png.png)"; done
  fi
} > "$report"
cat "$report"
