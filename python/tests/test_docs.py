"""docs/python.md's examples run as written: every ```python block, in order, each in a fresh
namespace, from an empty directory."""

import os
import re

import pytest

from conftest import SOURCE_DIR

DOC = SOURCE_DIR / "docs" / "python.md"
BLOCKS = re.findall(r"```python\n(.*?)```", DOC.read_text(), re.S) if DOC.exists() else []


def test_there_are_examples():
    assert len(BLOCKS) >= 5


@pytest.mark.parametrize("index", range(len(BLOCKS)))
def test_example_runs(index, tmp_path, capsys):
    os.chdir(tmp_path)
    exec(compile(BLOCKS[index], f"{DOC}:example {index + 1}", "exec"), {"__name__": f"example_{index + 1}"})
    assert capsys.readouterr().out or True
