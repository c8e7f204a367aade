"""Shared by the tests of the Python module (bench/python/): the `quadmc` command of the same
build, which CTest names in QUADMC_COMMAND (tests/CMakeLists.txt), to compare the module with."""
import os
import subprocess

import pytest


@pytest.fixture(scope="session")
def command():
    path = os.environ.get("QUADMC_COMMAND")
    if not path or not os.access(path, os.X_OK):
        pytest.fail(f"QUADMC_COMMAND must name the build's quadmc command, got {path!r}")

    def run(*args):
        return subprocess.run([path, *args], capture_output=True, text=True, check=False)

    return run
