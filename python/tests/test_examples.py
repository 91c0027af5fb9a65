"""The example scripts of examples/ run with their default settings and write what they say, from\nanother directory."""
import os
import subprocess
import sys

import pytest

import columba

PACKAGE_DIR = os.path.dirname(os.path.dirname(os.path.abspath(columba.__file__)))


@pytest.mark.parametrize("script, args, outputs", [
    ("strip_light_sequence.py", [], ["strip_light_sequence.png", "strip_light_0.exr", "strip_light_45.exr"]),
    ("mirror_spectra.py", [], ["mirror_spectra.png", "mirror_spectra.csv"]),
    ("thickness_sweep.py", [], ["thickness_sweep.png"]),
])
def test_example_runs(repo, tmp_path, script, args, outputs):
    out = tmp_path / "out"
    env = dict(os.environ, MPLBACKEND="Agg", MPLCONFIGDIR=str(tmp_path / "mpl"), PYTHONPATH=PACKAGE_DIR)
    result = subprocess.run([sys.executable, str(repo / "examples" / script), "-o", str(out), *args],
                            cwd=tmp_path, env=env, capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    for name in outputs:
        assert (out / name).stat().st_size > 1000, name
    assert "wrote" in result.stdout
