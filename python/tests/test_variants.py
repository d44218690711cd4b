"""dtlab.variants: the registries the command line lists, in the same order, the optimization
operators of a round included (`dtlab optimize --list-operators`), and the meshers' field point
methods (`dtlab mesh --method`)."""

import subprocess

import dtlab


def listed(cli, *args):
    out = subprocess.run([cli, *args], check=True, capture_output=True, text=True).stdout
    return [tuple(line.split("\t", 1)) for line in out.splitlines() if "\t" in line]


def test_optimization_operators_as_the_cli_lists_them(cli):
    v = dtlab.variants()
    assert [name for name, _ in v["optimize2d"]][:2] == ["bad", "collapse"]
    assert "relocate" in [name for name, _ in v["optimize3d"]]
    assert listed(cli, "optimize", "--list-operators") == v["optimize2d"] + v["optimize3d"]


def test_mesher_methods_reach_dtlab_mesh():
    v = dtlab.variants()
    assert [name for name, _ in v["mesh2d"]] == ["edge", "front"]
    assert [name for name, _ in v["mesh3d"]] == ["edge"]
    square = [[0, 0], [1, 0], [1, 1], [0, 1]]
    segments = [[0, 1], [1, 2], [2, 3], [3, 0]]
    for name, _ in v["mesh2d"]:
        assert dtlab.mesh(square, segments, size=0.25, method=name).stats["method"] == name
