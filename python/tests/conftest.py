"""Shared set-up of the Python tests: the dtlab command (DTLAB_CLI, set by ctest; else the
build trees' binary) and a deterministic Hypothesis profile (fixed derandomized examples, no
example database in the source tree), so that a run is reproducible and stays short."""

import os
import pathlib
import shutil

import pytest
from hypothesis import HealthCheck, settings

settings.register_profile(
    "dtlab", derandomize=True, database=None, deadline=None, max_examples=60,
    suppress_health_check=[HealthCheck.too_slow])
# DTLAB_HYPOTHESIS_PROFILE=long: many more examples, for a search rather than a check.
settings.register_profile("long", settings.get_profile("dtlab"), max_examples=2000)
settings.load_profile(os.environ.get("DTLAB_HYPOTHESIS_PROFILE", "dtlab"))

SOURCE_DIR = pathlib.Path(os.environ.get("DTLAB_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))


@pytest.fixture(scope="session")
def cli():
    """The path of the built `dtlab` command."""
    given = os.environ.get("DTLAB_CLI")
    if given:  # ctest names the built binary: missing means the build failed, not a skip
        if not os.access(given, os.X_OK):
            pytest.fail(f"DTLAB_CLI={given} is not an executable")
        return given
    candidates = []
    import dtlab
    build = pathlib.Path(dtlab.__file__).resolve().parents[2]  # <build>/python/dtlab/__init__.py
    candidates += [str(build / "dtlab"), shutil.which("dtlab")]
    for c in candidates:
        if c and os.access(c, os.X_OK):
            return c
    pytest.skip("the dtlab command is not built")


@pytest.fixture(scope="session")
def source_dir():
    return SOURCE_DIR
