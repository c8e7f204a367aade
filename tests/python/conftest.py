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

    # Without LD_PRELOAD: under the sanitizers CTest preloads the shared ASan runtime into the
    # interpreter (tests/CMakeLists.txt), and the command carries a runtime of its own.
    environment = {k: v for k, v in os.environ.items() if k != "LD_PRELOAD"}

    def run(*args):
        return subprocess.run([path, *args], capture_output=True, text=True, check=False,
                              env=environment)

    return run
