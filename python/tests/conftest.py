"""Fixtures of the Python module's tests: the command-line tool they compare against, run from
the source tree (CTest sets GEARTRIB_BINARY and PYTHONPATH=<build>/python)."""

import os
import subprocess
from pathlib import Path

import pytest

SOURCE = Path(__file__).resolve().parents[2]
# Relative case paths as in the command's examples (gears/m6z30.toml), also for the Dask workers a
# module-scoped cluster starts before any test runs.
os.chdir(SOURCE)


@pytest.fixture(scope="session")
def tool():
    """Runs `geartrib ARGS...` in the source tree; returns its completed process (text)."""
    binary = os.environ.get("GEARTRIB_BINARY")
    if not binary:
        pytest.skip("GEARTRIB_BINARY (the command-line tool) not given")

    def run(*args, check=True):
        done = subprocess.run([binary, *map(str, args)], cwd=SOURCE, capture_output=True, text=True)
        if check and done.returncode != 0:
            raise AssertionError(f"geartrib {' '.join(map(str, args))}: exit {done.returncode}\n{done.stderr}")
        return done

    return run


@pytest.fixture(autouse=True)
def in_source_tree(monkeypatch):
    """Relative case paths as in the command's examples (gears/m6z30.toml)."""
    monkeypatch.chdir(SOURCE)
