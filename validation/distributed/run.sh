#!/usr/bin/env bash
# The distributed solve, one command, Release, on the PETSc backend:
#   1. a cut-cell Poisson problem end to end (mesh, partition, assembly, BoomerAMG set-up,
#      CG to 1e-8 relative, errors, PVTU output) on 1 and 2 ranks: iterations, stage
#      seconds, parallel efficiency of the solver stages and of the whole run;
#   2. the iteration counts over four refinement levels, beside the anchor's at the same sizes;
#   3. the anchors: PETSc/hypre on a Poisson problem on a box grid with as many unknowns
#      (poisson_anchor.c) on 1 and 2 ranks, in the 7-point stencil and in the 27-point Q1
#      stencil (the like-for-like one: whole octree cells give our rows its 27 entries), each
#      with our BoomerAMG defaults and with the classical tuning; ours is compared with the
#      faster setting of each;
#   4. elasticity on one rank: hypre nodal with our defaults and two variants, and GAMG;
#   5. meshing and solving in pieces (--partition octree; pieces.py), for the staircase and
#      the cut-cell methods: the pieces of 1, 2 and 4 ranks against the serial mesh through
#      VTK's PVTU reader (cells, region volumes) and the solution against the serial one; each
#      rank's peak memory (/usr/bin/time) and the meshing time on 2 ranks against one process,
#      at PIECES_LEVEL (7); the cut cells' mesh alone is the solve's (uniform to the level);
#   6. a convergence study on 2 ranks against the serial one (study convergence --np 2, levels
#      STUDY_LEVELS, 3..6), cut cells and staircase: the slopes;
#   7. the cut-cell solve at LARGE_LEVEL (8) on 2 ranks: each rank's peak memory and the stages;
#   8. the messages and bytes the 2 ranks of the cut-cell pieces send at PIECES_LEVEL, meshing
#      alone and the whole solve.
# SECTIONS (all) picks some of them: "pieces" (section 5; "staircase" or "cutcell" for one
# method), "study" (6), "large" (7), "traffic" (8), e.g. SECTIONS="cutcell study".
# DOMAIN (builtin:ball), LEVEL (7, ~0.9·10⁶ unknowns; 8 gives ~7·10⁶), LEVELS ("4 5 6 7")
# and ELASTICITY_LEVEL (6, ~2.8·10⁵ unknowns) choose the cases. Prints the report and writes
# it to $OUT/report.md (OUT=dir, default build/validation-distributed).
set -euo pipefail
cd "$(dirname "$0")/../.."
ROOT=$PWD
BUILD=${BUILD:-$ROOT/build/release}
OUT=${OUT:-$ROOT/build/validation-distributed}
DOMAIN=${DOMAIN:-builtin:ball}
LEVEL=${LEVEL:-7}
LEVELS=${LEVELS:-"4 5 6 7"}
ELASTICITY_LEVEL=${ELASTICITY_LEVEL:-6}
VOLMESH=$BUILD/apps/volmesh/volmesh
# mpirun refuses root unless told; -q keeps its banners out of the output.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
MPIRUN="mpirun -q --oversubscribe"

mkdir -p "$OUT"
if [ ! -x "$VOLMESH" ]; then
  cmake -S . -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release > "$OUT/configure.log"
  cmake --build "$BUILD" -j "$(nproc)" --target volmesh > "$OUT/build.log" 2>&1
fi
"$VOLMESH" --version | grep -q PETSc || { echo "volmesh was built without PETSc" >&2; exit 1; }

# Section 5: meshing and solving in pieces, for one method ($1: staircase or cutcell).
PIECES_LEVEL=${PIECES_LEVEL:-7}
pieces() {
  local method=$1
  local dir=$OUT/pieces-$method
  mkdir -p "$dir"
  "$VOLMESH" --version | grep -q "p4est 2" || { echo "volmesh was built without p4est" >&2; exit 1; }
  # The same mesh and solution on 1, 2 and 4 ranks (4 oversubscribed here).
  local mesh="$method $DOMAIN --level 5" solve="poisson --problem sine --domain $DOMAIN --level 5"
  [ "$method" = staircase ] && mesh="$mesh --base-level 3"
  "$VOLMESH" mesh $mesh -o "$dir/mesh.vtu" --quiet > /dev/null
  "$VOLMESH" solve $solve --method $method --solver petsc -o "$dir/u.vtu" --json --quiet > "$dir/u.json"
  "$VOLMESH" solve poisson --problem sine --method grid --level 5 --solver petsc -o "$dir/g.vtu" \
    --quiet > /dev/null
  for np in 1 2 4; do
    $MPIRUN -np $np "$VOLMESH" mesh $mesh -o "$dir/mesh$np.pvtu" --quiet > /dev/null
    $MPIRUN -np $np "$VOLMESH" solve $solve --method $method -o "$dir/u$np.pvtu" --json --quiet \
      > "$dir/u$np.json"
    $MPIRUN -np $np "$VOLMESH" solve poisson --problem sine --method grid --level 5 \
      -o "$dir/g$np.pvtu" --quiet > /dev/null
    /usr/bin/python3 tests/apps/external/pvtu_compare.py "$dir/g.vtu" "$dir/g$np.pvtu" > "$dir/g$np.cmp.json"
  done
  # Peak memory per process and time: one process, then each of 2 ranks (its own time file).
  local big="solve poisson --problem sine --method $method --domain $DOMAIN --level $PIECES_LEVEL"
  local meshing="mesh $method $DOMAIN --level $PIECES_LEVEL"
  [ "$method" = cutcell ] && meshing="$meshing --base-level $PIECES_LEVEL"
  /usr/bin/time -v -o "$dir/rss-solve-serial" "$VOLMESH" $big -o "$dir/big.vtu" --json --quiet \
    > "$dir/big-serial.json"
  $MPIRUN -np 2 sh -c 'exec /usr/bin/time -v -o "$0.$OMPI_COMM_WORLD_RANK" "$@"' "$dir/rss-solve-2" \
    "$VOLMESH" $big -o "$dir/big.pvtu" --json --quiet > "$dir/big-2.json"
  /usr/bin/time -v -o "$dir/rss-mesh-serial" "$VOLMESH" $meshing -o "$dir/bigmesh.vtu" --json --quiet \
    > "$dir/bigmesh-serial.json"
  $MPIRUN -np 2 sh -c 'exec /usr/bin/time -v -o "$0.$OMPI_COMM_WORLD_RANK" "$@"' "$dir/rss-mesh-2" \
    "$VOLMESH" $meshing -o "$dir/bigmesh.pvtu" --json --quiet > "$dir/bigmesh-2.json"
  echo "load average before and after: $(cut -d' ' -f1-3 /proc/loadavg)" >> "$dir/load"
  /usr/bin/python3 validation/distributed/pieces.py "$dir" "$PIECES_LEVEL" "$method" "$meshing" \
    | tee "$OUT/pieces-$method.md"
}

# Section 6: convergence studies on 2 ranks against serial ones.
STUDY_LEVELS=${STUDY_LEVELS:-3..6}
study() {
  local dir=$OUT/study
  mkdir -p "$dir"
  for method in cutcell staircase; do
    for np in 1 2; do
      local ranks="--np $np"
      [ $np = 1 ] && ranks="--solver petsc"
      "$VOLMESH" study convergence --problem sine --method $method --levels "$STUDY_LEVELS" $ranks \
        -o "$dir/$method-$np" --json --quiet > "$dir/$method-$np.json"
    done
  done
  /usr/bin/python3 - "$dir" <<'PY' | tee "$OUT/study.md"
import json, sys
d = sys.argv[1]
print("| method | norm | serial slope | 2 ranks slope | difference |")
print("|---|---|---|---|---|")
for m in ("cutcell", "staircase"):
    a, b = (json.load(open(f"{d}/{m}-{np}.json")) for np in (1, 2))
    sa, sb = a["series"][0]["slope"], b["series"][0]["slope"]
    for k in sa:
        print(f"| {m} | {k} | {sa[k]:.3f} | {sb[k]:.3f} | {sb[k] - sa[k]:+.3f} |")
PY
}

# Section 7: the cut-cell solve at LARGE_LEVEL on 2 ranks.
LARGE_LEVEL=${LARGE_LEVEL:-8}
large() {
  local dir=$OUT/large
  mkdir -p "$dir"
  $MPIRUN -np 2 sh -c 'exec /usr/bin/time -v -o "$0.$OMPI_COMM_WORLD_RANK" "$@"' "$dir/rss" \
    "$VOLMESH" solve poisson --problem sine --method cutcell --domain "$DOMAIN" --level "$LARGE_LEVEL" \
    -o "$dir/u.pvtu" --json --quiet -ksp_rtol 1e-8 > "$dir/u.json"
  /usr/bin/python3 - "$dir" <<'PY' | tee "$OUT/large.md"
import json, sys
d = sys.argv[1]
j = json.load(open(f"{d}/u.json"))
def peak(r):
    for line in open(f"{d}/rss.{r}"):
        if "Maximum resident set size" in line:
            return int(line.split(":")[1]) / 1024.0
print(f"cells {j['cells']}, unknowns {j['unknowns']}, iterations {j['iterations']}, "
      f"L2 error {j['errors']['l2']:.4e}; peak MB per rank {peak(0):.0f}, {peak(1):.0f}")
print("| stage | " + " | ".join(j["seconds_max"]) + " |")
print("|---|" + "---|" * len(j["seconds_max"]))
print("| seconds (slowest rank) | " + " | ".join(f"{v:.2f}" for v in j["seconds_max"].values()) + " |")
PY
}

# Section 8: what the ranks send, for the cut-cell pieces at PIECES_LEVEL on 2 ranks: meshing
# alone, then the whole solve (Open MPI's monitoring components: messages and bytes per peer,
# point to point and inside the collectives).
traffic() {
  local dir=$OUT/traffic
  mkdir -p "$dir"
  local monitor="--mca pml_monitoring_enable 2 --mca pml_monitoring_enable_output 3"
  $MPIRUN -np 2 $monitor --mca pml_monitoring_filename "$dir/mesh" "$VOLMESH" mesh cutcell "$DOMAIN" \
    --level "$PIECES_LEVEL" --base-level "$PIECES_LEVEL" -o "$dir/mesh.pvtu" --quiet > /dev/null
  $MPIRUN -np 2 $monitor --mca pml_monitoring_filename "$dir/solve" "$VOLMESH" solve poisson \
    --problem sine --method cutcell --domain "$DOMAIN" --level "$PIECES_LEVEL" -o "$dir/u.pvtu" \
    --quiet > /dev/null
  /usr/bin/python3 - "$dir" <<'PY' | tee "$OUT/traffic.md"
import sys
d = sys.argv[1]
print("| command | rank | point-to-point messages | point-to-point MB | collectives' messages | collectives' MB |")
print("|---|---|---|---|---|---|")
for what in ("mesh", "solve"):
    for r in (0, 1):
        p2p = [0, 0]
        coll = [0, 0]
        for line in open(f"{d}/{what}.{r}.prof"):
            f = line.split("\t")
            if f[0] in ("E", "C") and f[1] != f[2]:
                into = p2p if f[0] == "E" else coll
                into[0] += int(f[4].split()[0])
                into[1] += int(f[3].split()[0])
        print(f"| {what} | {r} | {p2p[0]} | {p2p[1] / 1e6:.2f} | {coll[0]} | {coll[1] / 1e6:.2f} |")
PY
}

case " ${SECTIONS:-all} " in
  *" all "*) ;;
  *)
    for section in ${SECTIONS}; do
      case $section in
        pieces) pieces staircase; pieces cutcell ;;
        staircase | cutcell) pieces $section ;;
        study) study ;;
        large) large ;;
        traffic) traffic ;;
        *) echo "SECTIONS: unknown section $section (pieces, staircase, cutcell, study, large, traffic)" >&2
           exit 2 ;;
      esac
    done
    exit 0 ;;
esac
mpicc -O2 validation/distributed/poisson_anchor.c $(pkg-config --cflags --libs PETSc) -o "$OUT/anchor"

CASE="solve poisson --problem sine --method cutcell --domain $DOMAIN"
for np in 1 2; do
  $MPIRUN -np $np "$VOLMESH" $CASE --level "$LEVEL" -o "$OUT/u$np.pvtu" --json --quiet \
    -ksp_rtol 1e-8 > "$OUT/solve$np.json"
done
for level in $LEVELS; do
  $MPIRUN -np 1 "$VOLMESH" $CASE --level "$level" -o "$OUT/level$level.vtu" --json --quiet \
    -ksp_rtol 1e-8 > "$OUT/level$level.json"
done
# Elasticity, one rank: the default (hypre nodal, Chebyshev), hybrid Gauss-Seidel, the
# interpolation fitted to the rigid-body modes, and GAMG with the rigid-body near-null space.
ELASTICITY="solve elasticity --problem lame --method cutcell --domain builtin:thick-sphere"
ELASTICITY_SETTINGS=("" "-pc_hypre_boomeramg_relax_type_all symmetric-SOR/Jacobi"
  "-pc_hypre_boomeramg_vec_interp_variant 3" "-pc_type gamg")
for i in "${!ELASTICITY_SETTINGS[@]}"; do
  # shellcheck disable=SC2086  # each setting is a list of options
  $MPIRUN -np 1 "$VOLMESH" $ELASTICITY --level "$ELASTICITY_LEVEL" -o "$OUT/elasticity.vtu" \
    --json --quiet -ksp_rtol 1e-8 ${ELASTICITY_SETTINGS[$i]} > "$OUT/elasticity$i.json"
done
cube_side() { python3 -c "import json; print(round(json.load(open('$1'))['unknowns'] ** (1/3)))"; }
N=$(cube_side "$OUT/solve1.json")
for level in $LEVELS; do  # the anchor's own iterations at the levels' sizes
  $MPIRUN -np 1 "$OUT/anchor" -n "$(cube_side "$OUT/level$level.json")" > "$OUT/anchor-level$level.json"
done
# Each anchor twice: with our defaults, and tuned the classical way for the 7-point stencil
# (HMIS, threshold 0.5, V-cycles, hybrid symmetric Gauss-Seidel, Gaussian elimination on the
# coarsest level); ours is compared with the faster.
TUNED="-pc_hypre_boomeramg_coarsen_type HMIS -pc_hypre_boomeramg_strong_threshold 0.5
  -pc_hypre_boomeramg_cycle_type V -pc_hypre_boomeramg_relax_type_all symmetric-SOR/Jacobi
  -pc_hypre_boomeramg_relax_type_coarse Gaussian-elimination"
for np in 1 2; do
  for stencil in 7 27; do
    case $stencil in 7) suffix="" ;; 27) suffix="-q1" ;; esac
    $MPIRUN -np $np "$OUT/anchor" -n "$N" -stencil $stencil > "$OUT/anchor$suffix$np.json"
    # shellcheck disable=SC2086  # TUNED is a list of options
    $MPIRUN -np $np "$OUT/anchor" -n "$N" -stencil $stencil $TUNED > "$OUT/anchor-tuned$suffix$np.json"
  done
done

python3 - "$OUT" "$LEVEL" "$LEVELS" "$ELASTICITY_LEVEL" <<'PY' | tee "$OUT/report.md"
import json, sys
out, level, levels, elasticity_level = sys.argv[1], sys.argv[2], sys.argv[3].split(), sys.argv[4]
load = lambda name: json.load(open(f"{out}/{name}.json"))
runs = {np: load(f"solve{np}") for np in (1, 2)}
anchor = {np: load(f"anchor{np}") for np in (1, 2)}
tuned = {np: load(f"anchor-tuned{np}") for np in (1, 2)}
stages = ["mesh", "partition", "setup", "assembly", "preconditioner", "solve", "errors", "write"]
r1 = runs[1]
print(f"## Cut-cell Poisson, {r1['domain']} level {level}: {r1['cells']} cells, "
      f"{r1['unknowns']} unknowns, CG + BoomerAMG to 1e-8\n")
print("| ranks | iterations | " + " | ".join(stages) + " | total |")
print("|---" * (len(stages) + 3) + "|")
for np, r in runs.items():
    s = r["seconds"]
    print(f"| {np} | {r['iterations']} | " + " | ".join(f"{s[k]:.2f}" for k in stages) +
          f" | {s['total']:.2f} |")
solver = lambda r: r["seconds"]["preconditioner"] + r["seconds"]["solve"]
parallel = lambda r: sum(r["seconds"][k] for k in ("setup", "assembly", "preconditioner", "solve", "errors"))
print(f"\n2-rank efficiency (T1 / 2 T2): solver stages {solver(runs[1]) / (2 * solver(runs[2])):.2f}, "
      f"distributed stages (set-up to errors) {parallel(runs[1]) / (2 * parallel(runs[2])):.2f}, "
      f"whole run {runs[1]['seconds']['total'] / (2 * runs[2]['seconds']['total']):.2f}\n")
print("## Iterations over the levels (1 rank)\n")
print("| level | unknowns | iterations | preconditioner s | solve s | anchor unknowns | anchor iterations |")
print("|---|---|---|---|---|---|---|")
for l in levels:
    r, a = load(f"level{l}"), load(f"anchor-level{l}")
    print(f"| {l} | {r['unknowns']} | {r['iterations']} | {r['seconds']['preconditioner']:.2f} | "
          f"{r['seconds']['solve']:.2f} | {a['unknowns']} | {a['iterations']} |")
its = [load(f"level{l}")["iterations"] for l in levels]
mean = sum(its) / len(its)
spread = max(abs(i - mean) for i in its) / mean
print(f"\nIterations {min(its)} to {max(its)}: every level within {100 * spread:.0f}% of their mean "
      f"{mean:.2f} (target 20%)")
print("\n## Anchor: PETSc/hypre 7-point Poisson of the same size (poisson_anchor.c -stencil 7)\n")
print("Our defaults (PMIS, threshold 0.25, W-cycles, Chebyshev), and the 7-point stencil's classical "
      "tuning (HMIS, 0.5, V-cycles, hybrid Gauss-Seidel).\n")
cost = lambda a: a["preconditioner"] + a["solve"]


def anchor_tables(ours_setting, tuned_setting, ratio_header):
    """The anchor's two settings on 1 and 2 ranks, and ours against the faster; returns it."""
    print("| ranks | BoomerAMG | unknowns | iterations | assembly s | preconditioner s | solve s |")
    print("|---|---|---|---|---|---|---|")
    for np in (1, 2):
        for name, a in (("ours: PMIS 0.25, W, Chebyshev", ours_setting[np]),
                        ("HMIS 0.5, V, Gauss-Seidel", tuned_setting[np])):
            print(f"| {np} | {name} | {a['unknowns']} | {a['iterations']} | {a['assembly']:.2f} | "
                  f"{a['preconditioner']:.2f} | {a['solve']:.2f} |")
    print(f"\n| ranks | {ratio_header}, preconditioner + solve | solve only |")
    print("|---|---|---|")
    best = {np: min(ours_setting[np], tuned_setting[np], key=cost) for np in (1, 2)}
    for np in (1, 2):
        print(f"| {np} | {solver(runs[np]) / cost(best[np]):.2f} | "
              f"{runs[np]['seconds']['solve'] / best[np]['solve']:.2f} |")
    return best


best = anchor_tables(anchor, tuned, "ours / faster anchor")
print(f"\n2-rank efficiency of preconditioner + solve: ours {solver(runs[1]) / (2 * solver(runs[2])):.2f}, "
      f"the faster anchor's {cost(best[1]) / (2 * cost(best[2])):.2f}")
q1 = {np: load(f"anchor-q1{np}") for np in (1, 2)}
q1_tuned = {np: load(f"anchor-tuned-q1{np}") for np in (1, 2)}
print("\n## Anchor like for like: Q1 on the box grid, the 27-point stencil (poisson_anchor.c -stencil 27)\n")
anchor_tables(q1, q1_tuned, "ours / faster 27-point anchor (target 1.2)")
e0 = load("elasticity0")
print(f"\n## Elasticity: lame on builtin:thick-sphere, level {elasticity_level}, {e0['unknowns']} unknowns, "
      "1 rank, to 1e-8\n")
print("| preconditioner | method | iterations | preconditioner s | solve s |")
print("|---|---|---|---|---|")
names = ["hypre nodal, Chebyshev (default)", "hypre nodal, hybrid Gauss-Seidel",
         "hypre nodal, rigid-body interpolation (vec_interp_variant 3)", "GAMG, rigid-body near-null space"]
for i, name in enumerate(names):
    e = load(f"elasticity{i}")
    print(f"| {name} | {e['linear_solver']} | {e['iterations']} | {e['seconds']['preconditioner']:.2f} | "
          f"{e['seconds']['solve']:.2f} |")
PY
pieces staircase
pieces cutcell
study
large
traffic
