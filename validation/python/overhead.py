"""The module's overhead over the command line: volmesh.mesh("cutcell", "builtin:primitives",
level=6) timed around the call, against the mesher's own time_seconds of `volmesh mesh ...
--json`, the median of RUNS runs each, one at a time.

    PYTHONPATH=build/release/python python3 validation/python/overhead.py [build/release]
"""
import json
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import volmesh

RUNS = 3
METHOD, DOMAIN, LEVEL = "cutcell", "builtin:primitives", 6

build = Path(sys.argv[1] if len(sys.argv) > 1 else "build/release")
binary = build / "apps" / "volmesh" / "volmesh"
cli, python, inside = [], [], []
with tempfile.TemporaryDirectory() as tmp:
    command = [str(binary), "mesh", METHOD, DOMAIN, "--level", str(LEVEL), "-o",
               str(Path(tmp) / "out.vtu"), "--json", "--quiet"]
    # Alternately, so that the load of a shared machine weighs on both alike.
    for _ in range(RUNS):
        run = subprocess.run(command, check=True, capture_output=True, text=True)
        cli.append(json.loads(run.stdout)["time_seconds"])
        start = time.perf_counter()
        mesh = volmesh.mesh(METHOD, DOMAIN, level=LEVEL)
        python.append(time.perf_counter() - start)
        inside.append(mesh.figures["time_seconds"])  # the mesher's own time in this call
        del mesh
c, p, i = (statistics.median(x) for x in (cli, python, inside))
print(f"{METHOD} {DOMAIN} level {LEVEL}, median of {RUNS}: command line time_seconds {c:.3f} s "
      f"{sorted(cli)}; volmesh.mesh {p:.3f} s {sorted(python)}: {100 * (p / c - 1):+.1f}%; "
      f"the call against its own mesher's time_seconds ({i:.3f} s): {100 * (p / i - 1):+.1f}%")
