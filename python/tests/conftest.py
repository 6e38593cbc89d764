"""What the tests of the Python module share: the command line to compare with, fixtures."""
import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

VOLMESH = os.environ.get("VOLMESH_BINARY", "volmesh")
TEST_DATA = Path(os.environ.get("VOLMESH_TEST_DATA", Path(__file__).parents[2] / "tests" / "data"))


def cli(*args, check=True):
    """Runs `volmesh ARGS...` quietly; returns the completed process."""
    run = subprocess.run([VOLMESH, *map(str, args)], capture_output=True, text=True)
    if check and run.returncode != 0:
        raise AssertionError(f"volmesh {' '.join(map(str, args))}: {run.stderr}")
    return run


def cli_json(*args):
    return json.loads(cli(*args, "--json").stdout)


def cli_error(*args):
    """The one line `volmesh ARGS...` prints on stderr when it fails, without its prefix."""
    run = cli(*args, check=False)
    assert run.returncode == 1, run.stderr
    lines = run.stderr.strip().splitlines()
    assert len(lines) == 1, run.stderr
    return lines[0].removeprefix("volmesh: error: ")


def read_off(path):
    """An OFF file's vertices and triangles as numpy arrays, read without volmesh."""
    lines = [line.split("#")[0] for line in Path(path).read_text().splitlines()]
    words = " ".join(lines).split()
    assert words[0] == "OFF"
    nv, nf = int(words[1]), int(words[2])
    values = words[4:]
    vertices = np.array(values[: 3 * nv], dtype=float).reshape(nv, 3)
    faces = np.array(values[3 * nv : 3 * nv + 4 * nf], dtype=np.int64).reshape(nf, 4)
    return vertices, faces[:, 1:]


def cube(lo=0.0, hi=1.0):
    """The surface of a box as 8 vertices and 12 outward triangles."""
    v = np.array([[x, y, z] for z in (lo, hi) for y in (lo, hi) for x in (lo, hi)], dtype=float)
    t = np.array([[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
                  [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]])
    return v, t


def write_off(path, vertices, triangles):
    lines = ["OFF", f"{len(vertices)} {len(triangles)} 0"]
    lines += [" ".join(repr(float(x)) for x in v) for v in vertices]
    lines += ["3 " + " ".join(str(int(i)) for i in t) for t in triangles]
    Path(path).write_text("\n".join(lines) + "\n")


def same_files(a, b):
    """The same bytes: two files, or two directories file by file."""
    a, b = Path(a), Path(b)
    if a.is_dir():
        names = sorted(p.relative_to(a) for p in a.rglob("*") if p.is_file())
        assert names == sorted(p.relative_to(b) for p in b.rglob("*") if p.is_file())
        return all((a / n).read_bytes() == (b / n).read_bytes() for n in names)
    return a.read_bytes() == b.read_bytes()


def pair(tmp, name):
    """Where the command line and the module write the same output: NAME in two folders, so
    that names written into the files agree."""
    (tmp / "cli").mkdir(exist_ok=True)
    (tmp / "py").mkdir(exist_ok=True)
    return tmp / "cli" / name, tmp / "py" / name


@pytest.fixture
def tmp(tmp_path):
    return tmp_path
