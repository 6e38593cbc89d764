"""volmesh.solve and volmesh.study.convergence against `volmesh solve` and `study convergence`."""
import pytest
import volmesh

from conftest import cli, cli_json, pair, same_files

# What solve --json reports beyond the solution: its output and times.
NOT_COMPARED = {"output", "seconds"}


def test_solve_by_method_is_solve_json(tmp):
    a, b = pair(tmp, "u.vtu")
    expected = cli_json("solve", "poisson", "--problem", "sine", "--method", "cutcell", "--level", 3, "-o", a)
    s = volmesh.solve("poisson", problem="sine", method="cutcell", level=3)
    assert s.figures == {k: v for k, v in expected.items() if k not in NOT_COMPARED}
    assert s.errors == expected["errors"] and s.errors["l2"] < 0.1
    assert s.u.shape == (s.mesh.num_points,) and s.error.shape == s.u.shape
    s.write(b)
    assert same_files(a, b)


def test_solve_on_a_mesh_is_solve_mesh(tmp):
    cli("mesh", "grid", "builtin:box", "--level", 3, "--tets", "-o", tmp / "box.vtu")
    expected = cli_json("solve", "poisson", "--problem", "sine", "--mesh", tmp / "box.vtu", "--space", "p2",
                        "-o", tmp / "u.vtu")
    s = volmesh.solve(problem="sine", mesh=volmesh.read(tmp / "box.vtu"), space="p2")
    assert s.errors == expected["errors"] and s.figures["dofs"] == expected["dofs"]


def test_elasticity_gives_displacements():
    s = volmesh.solve("elasticity", problem="elastic-patch", method="grid", level=2)
    assert s.u.shape == (s.mesh.num_points, 3)
    assert s.errors["l2"] < 1e-8


def test_user_expressions():
    s = volmesh.solve(exact="x*x + y", method="grid", level=2, tets=True, space="p2")
    assert s.errors["l2"] < 1e-10


def test_study_is_study_json(tmp):
    expected = cli_json("study", "convergence", "--problem", "sine", "--methods", "staircase,cutcell",
                        "--levels", "2..3", "-o", tmp / "cli")
    study = volmesh.study.convergence(problem="sine", methods=["staircase", "cutcell"], levels=(2, 3),
                                      output=tmp / "py")
    assert len(study["rows"]) == 4
    for row, level in zip(study["rows"], [l for s in expected["series"] for l in s["levels"]]):
        assert {k: row[k] for k in ("level", "h", "cells", "dofs", "l2", "linf", "h1")} == \
               {k: level[k] for k in ("level", "h", "cells", "dofs", "l2", "linf", "h1")}
    assert study["slopes"] == {s["label"]: s["slope"] for s in expected["series"]}
    assert study["png"].endswith("convergence.png")
    assert (tmp / "py" / "convergence.csv").read_bytes() == (tmp / "cli" / "convergence.csv").read_bytes()


@pytest.mark.parametrize("call, says", [
    (lambda: volmesh.solve(problem="sine"), "give a mesh"),
    (lambda: volmesh.solve("elasticity", problem="sine", method="grid", level=1), "is a Poisson problem"),
    (lambda: volmesh.solve(problem="nope", method="grid", level=1), "nope"),
    (lambda: volmesh.mesh("nope", "builtin:ball", level=2), "unknown method nope"),
    (lambda: volmesh.mesh("cutcell", "builtin:ball", level=2, tets=True), "--tets applies to"),
    (lambda: volmesh.mesh("cutcell", "builtin:ball", level=2, no_such_option=1), "--no-such-option: no method takes it"),
    (lambda: volmesh.mesh("cutcell", "builtin:nope", level=2), "nope"),
    (lambda: volmesh.mesh("cutcell", "builtin:ball"), "--level"),
    (lambda: volmesh.study.convergence(problem="sine", methods="grid", levels="3..2"), "first level exceeds"),
])
def test_bad_calls_raise_input_error(call, says):
    with pytest.raises(volmesh.InputError) as e:
        call()
    assert says in str(e.value) and "\n" not in str(e.value)
