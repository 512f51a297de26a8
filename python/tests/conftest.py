"""Shared fixtures: the yamsc executable of the same build and the source tree
(ctest sets YAMSC_EXE, YAMSC_SOURCE_DIR and PYTHONPATH, python/CMakeLists.txt)."""
import json
import os
import subprocess
from pathlib import Path

import pytest


def _required(name):
    value = os.environ.get(name)
    if not value:
        pytest.exit(f"{name} is not set (run the tests through ctest -R python)", returncode=2)
    return value


@pytest.fixture(scope="session")
def source_dir():
    return Path(_required("YAMSC_SOURCE_DIR"))


@pytest.fixture(scope="session")
def models(source_dir):
    return source_dir / "models"


@pytest.fixture(scope="session")
def cli():
    """Runs `yamsc ARGS...` and returns its stdout; fails the test on a non-zero exit."""
    exe = _required("YAMSC_EXE")

    def run(*args, parse_json=False):
        done = subprocess.run([exe, *map(str, args)], capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
        return json.loads(done.stdout) if parse_json else done.stdout

    return run
