#!/usr/bin/env bash
# Tet improvement against its targets, one command, Release: each model through TetGen
# -pq1.414, then `volmesh improve` on TetGen's .node/.ele with the boundary kept; one case at
# a time. Reports per model TetGen's and the improved mesh's tets, min and max dihedral
# angle, tets under 10°, largest radius-edge ratio, the tet count ratio, both wall times and
# their ratio, and the improved mesh's `volmesh check` verdict, beside the targets:
# min dihedral >= 15°, max <= 165°, at most 1.2x the tets, at most 10x TetGen's time. In the
# same run, `volmesh mesh tet-projection --improve` on the surface, against its targets: at most
# 3x TetGen's tets and min dihedral >= 10°.
# Writes build/validation-tetimprove/report.md and prints it. Knobs:
#   VALIDATION_BUILD=DIR          the Release build to use (default build/release)
#   TETIMPROVE_RESULTS=DIR        where the results go (default build/validation-tetimprove)
#   TETIMPROVE_MODELS="elephant ..."   libcgal-demo models (default: elephant fandisk knot1)
#   TETIMPROVE_THREADS=T          volmesh's --threads (default: all cores)
set -euo pipefail
cd "$(dirname "$0")/../.."
ROOT=$PWD
# shellcheck disable=SC2034  # BUILD is read by setup.sh
BUILD=${VALIDATION_BUILD:-$ROOT/build/release}
RESULTS=${TETIMPROVE_RESULTS:-$ROOT/build/validation-tetimprove}
MODELS=${TETIMPROVE_MODELS:-elephant fandisk knot1}
THREADS=${TETIMPROVE_THREADS:-}
TETGEN_SWITCHES=-pq1.414

# shellcheck source=../octree/setup.sh
. "$ROOT/validation/octree/setup.sh"
install_missing tetgen libcgal-demo python3
build_volmesh
mkdir -p "$RESULTS"

for model in $MODELS; do
  cp "$MESHES/$model.off" "$RESULTS/$model.off"
  /usr/bin/time -f "%e" -o "$RESULTS/$model.tetgen.time" \
    tetgen "$TETGEN_SWITCHES" -Q "$RESULTS/$model.off" > "$RESULTS/$model.tetgen.log" 2>&1
  threads=()
  [ -n "$THREADS" ] && threads=(--threads "$THREADS")
  status=0
  /usr/bin/time -f "%e" -o "$RESULTS/$model.improve.time" \
    "$VOLMESH" improve "$RESULTS/$model.1.ele" -o "$RESULTS/$model.improved.vtu" --json -q \
    "${threads[@]}" > "$RESULTS/$model.improve.json" 2> "$RESULTS/$model.improve.err" || status=$?
  echo "$status" > "$RESULTS/$model.improve.exit"
  "$VOLMESH" check "$RESULTS/$model.improved.vtu" --json -q > "$RESULTS/$model.check.json" \
    2> "$RESULTS/$model.check.err" || true
  status=0
  /usr/bin/time -f "%e" -o "$RESULTS/$model.projection.time" \
    "$VOLMESH" mesh tet-projection "$RESULTS/$model.off" --improve \
    -o "$RESULTS/$model.projection.vtu" --json -q "${threads[@]}" \
    > "$RESULTS/$model.projection.json" 2> "$RESULTS/$model.projection.err" || status=$?
  echo "$status" > "$RESULTS/$model.projection.exit"
  "$VOLMESH" check "$RESULTS/$model.projection.vtu" --json -q \
    > "$RESULTS/$model.projection.check.json" 2> "$RESULTS/$model.projection.check.err" || true
done

/usr/bin/python3 - "$RESULTS" $MODELS > "$RESULTS/report.md" <<'EOF'
import json, sys
results, models = sys.argv[1], sys.argv[2:]
MIN_DIHEDRAL, MAX_DIHEDRAL, TET_RATIO, TIME_RATIO = 15.0, 165.0, 1.2, 10.0
PROJECTION_RATIO, PROJECTION_MIN = 3.0, 10.0
def seconds(name):
    return float(open(f"{results}/{name}").read().split()[0])
print("# Tet improvement of TetGen -pq1.414 meshes, boundary kept\n")
print(f"Targets: min dihedral >= {MIN_DIHEDRAL}°, max <= {MAX_DIHEDRAL}°, "
      f"tets <= {TET_RATIO}x TetGen's, time <= {TIME_RATIO}x TetGen's.\n")
print("| model | mesh | tets | min dihedral | max dihedral | tets < 10° | max radius-edge | seconds |")
print("|---|---|---|---|---|---|---|---|")
verdicts = []
for m in models:
    if int(open(f"{results}/{m}.improve.exit").read()) != 0:
        print(f"| {m} | improve failed: {open(f'{results}/{m}.improve.err').read().strip()} |||||||")
        verdicts.append(f"{m}: improve failed")
        continue
    j = json.load(open(f"{results}/{m}.improve.json"))
    check = json.load(open(f"{results}/{m}.check.json"))
    t_tetgen, t_improve = seconds(f"{m}.tetgen.time"), seconds(f"{m}.improve.time")
    for label, q, t in (("TetGen", j["before"], t_tetgen), ("improved", j["after"], t_improve)):
        print(f"| {m} | {label} | {q['tets']} | {q['min_dihedral_deg']:.2f}° | "
              f"{q['max_dihedral_deg']:.2f}° | {q['tets_below_10_deg']} | "
              f"{q['max_radius_edge']:.2f} | {t:.2f} |")
    ratio = j["after"]["tets"] / j["before"]["tets"]
    time_ratio = t_improve / t_tetgen
    met = (j["after"]["min_dihedral_deg"] >= MIN_DIHEDRAL and
           j["after"]["max_dihedral_deg"] <= MAX_DIHEDRAL and ratio <= TET_RATIO and
           time_ratio <= TIME_RATIO and check["validity"]["valid"])
    verdicts.append(f"{m}: tets x{ratio:.3f}, time x{time_ratio:.2f}, "
                    f"valid {check['validity']['valid']}, operations {j['operations']}, "
                    f"passes {j['passes']}: {'targets met' if met else 'TARGETS MISSED'}")
print()
for v in verdicts:
    print(f"- {v}")
print("\n## tet-projection --improve\n")
print(f"Targets: tets <= {PROJECTION_RATIO}x TetGen's, min dihedral >= {PROJECTION_MIN}°.\n")
print("| model | tets | x TetGen | min dihedral | max dihedral | seconds | valid | verdict |")
print("|---|---|---|---|---|---|---|---|")
for m in models:
    if int(open(f"{results}/{m}.projection.exit").read()) != 0:
        print(f"| {m} | failed: {open(f'{results}/{m}.projection.err').read().strip()} |||||||")
        continue
    j = json.load(open(f"{results}/{m}.projection.json"))
    check = json.load(open(f"{results}/{m}.projection.check.json"))
    tetgen = json.load(open(f"{results}/{m}.improve.json"))["before"]["tets"]
    i = j["improvement"]["improve"]
    ratio = i["tets"] / tetgen
    met = ratio <= PROJECTION_RATIO and i["min_dihedral_deg"][1] >= PROJECTION_MIN
    print(f"| {m} | {i['tets']} | {ratio:.2f} | {i['min_dihedral_deg'][1]:.2f}° | "
          f"{i['max_dihedral_deg'][1]:.2f}° | {seconds(f'{m}.projection.time'):.2f} | "
          f"{check['validity']['valid']} | {'targets met' if met else 'TARGETS MISSED'} |")
EOF
cat "$RESULTS/report.md"
