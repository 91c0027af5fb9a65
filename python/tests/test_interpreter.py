"""The package names the Python it was built for when another one cannot load it, and the build's
columba-python launcher runs that Python with the package found, whatever python3 is on PATH."""
import os
import pathlib
import subprocess
import sys

import columba

BUILD = pathlib.Path(columba.__file__).resolve().parents[2]


def test_a_python_without_numpy_is_told_which_python_to_run():
    # -S leaves out site-packages and dist-packages, so this Python has no numpy, as a pyenv or
    # virtualenv python3 without Debian's python3-numpy does.
    package_dir = pathlib.Path(columba.__file__).resolve().parents[1]
    result = subprocess.run(
        [sys.executable, "-S", "-c", f"import sys; sys.path.insert(0, {str(package_dir)!r}); import columba"],
        capture_output=True, text=True)
    assert result.returncode != 0
    assert "columba was built for /usr/bin/python3" in result.stderr
    assert "columba-python" in result.stderr
    assert "No module named 'numpy'" in result.stderr


def test_the_launcher_runs_the_built_for_python_with_the_package(tmp_path):
    # A python3 first on PATH that is not Debian's: a script that fails if it is ever run.
    (tmp_path / "python3").write_text("#!/bin/sh\necho 'the wrong python3 ran' >&2\nexit 3\n")
    (tmp_path / "python3").chmod(0o755)
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "COLUMBA_BINARY")}
    env["PATH"] = f"{tmp_path}:{env.get('PATH', '')}"
    result = subprocess.run(
        [str(BUILD / "columba-python"), "-c",
         "import sys, os, columba; print(sys.executable, columba.__version__, os.environ['COLUMBA_BINARY'])"],
        capture_output=True, text=True, env=env, cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    executable, version, binary = result.stdout.split()
    assert executable == "/usr/bin/python3"
    assert version == columba.__version__
    assert pathlib.Path(binary) == BUILD / "columba"
