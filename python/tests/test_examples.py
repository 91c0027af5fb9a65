"""The example scripts of examples/ run with their default settings and write what they say, from\nanother directory."""
import os
import subprocess
import sys

import numpy as np
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


def test_mirror_spectra_reports_maxima_of_the_visible_range(repo, tmp_path):
    # The highest value of R over 380-780 nm was reported as its peak: at 30 degrees 384 nm, the
    # violet end of the range, where the green barbule's film has one of its interference orders.
    env = dict(os.environ, MPLBACKEND="Agg", MPLCONFIGDIR=str(tmp_path / "mpl"), PYTHONPATH=PACKAGE_DIR)
    result = subprocess.run([sys.executable, str(repo / "examples" / "mirror_spectra.py"), "-o", str(tmp_path)],
                            cwd=tmp_path, env=env, capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    peaks = {}
    for line in result.stdout.splitlines():
        if "R peaks at" in line:
            preset, _, angle = line.split()[:3]
            peaks[(preset, int(angle))] = float(line.split("R peaks at ")[1].split(" nm")[0])
    assert len(peaks) == 10, result.stdout
    wavelengths = np.arange(380, 781, 2, dtype=np.float32)
    for (preset, angle), peak in peaks.items():
        assert 400 <= peak <= 700, (preset, angle, peak)
        r = columba.BarbuleBSDF(preset=preset).specular_spectra(angle, wavelengths=wavelengths)["R"]
        inside = (wavelengths >= 400) & (wavelengths <= 700)
        k = int(np.flatnonzero(wavelengths == peak)[0])
        assert r[k - 1] <= r[k] > r[k + 1], (preset, angle, peak)  # a maximum, not the end of a range
        interior = [j for j in np.flatnonzero(inside) if r[j - 1] <= r[j] > r[j + 1]]
        assert r[k] == max(r[j] for j in interior), (preset, angle, peak)
    assert peaks[("dove-green", 30)] == 488
