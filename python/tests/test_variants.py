"""dtlab.variants: the registries the command line lists, in the same order, the optimization
operators of a round included (`dtlab optimize --list-operators`)."""

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
