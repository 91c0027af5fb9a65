"""The example scripts of examples/ run and write what they say, from another directory."""
import os
import subprocess
import sys

import pytest

import columba

PACKAGE_DIR = os.path.dirname(os.path.dirname(os.path.abspath(columba.__file__)))


@pytest.mark.parametrize("script, args, outputs", [
    ("strip_light_sequence.py", ["--res", "64", "--spp", "4", "--angles", "-30", "0", "30"],
     ["strip_light_sequence.png", "strip_light_0.exr"]),
    ("mirror_spectra.py", [], ["mirror_spectra.png", "mirror_spectra.csv"]),
    ("thickness_sweep.py", ["--res", "64"], ["thickness_sweep.png"]),
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
