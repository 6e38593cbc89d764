"""A convergence study to a plot: staircase against cut cells on the unit ball, the sine
problem, levels 2 to 5; prints the slopes and the PNG the study drew.

    PYTHONPATH=build/release/python python3 examples/convergence_plot.py
"""
import volmesh

study = volmesh.study.convergence(problem="sine", methods=["staircase", "cutcell"],
                                  levels="2..5", output="ball-study")
for row in study["rows"]:
    print(f'{row["label"]:28} level {row["level"]}  h {row["h"]:.4f}  L2 {row["l2"]:.3e}')
for label, slope in study["slopes"].items():
    print(label, "slopes:", {norm: round(s, 2) for norm, s in slope.items() if s is not None})
print("plot:", study["png"])
