"""Shared set-up: the columba package from the build (PYTHONPATH) and the CLI it is compared with."""
import os
import pathlib
import shutil
import subprocess

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def repo():
    return REPO


@pytest.fixture(scope="session")
def cli():
    """Runs the `columba` executable of the same build: cli("render", ...) -> CompletedProcess."""
    binary = os.environ.get("COLUMBA_BINARY") or shutil.which("columba")
    if not binary:
        pytest.fail("set COLUMBA_BINARY to the columba executable (CTest does)")

    def run(*args, check=True, cwd=None):
        result = subprocess.run([binary, *map(str, args)], capture_output=True, text=True, cwd=cwd)
        if check and result.returncode != 0:
            raise AssertionError(f"columba {' '.join(map(str, args))} failed:\n{result.stderr}")
        return result

    return run


@pytest.fixture(scope="session")
def single_feather(tmp_path_factory, cli):
    """A generated single feather (feather_linear_light.xml's geometry)."""
    path = tmp_path_factory.mktemp("feather") / "feather.ply"
    cli("feather", "--single", "-o", path, "--binary")
    return path
