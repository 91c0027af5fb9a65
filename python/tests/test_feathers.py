"""The feather generator through Python against `columba feather`."""
import numpy as np
import pytest

import columba


def test_single_feather_equals_cli(cli, tmp_path):
    cli("feather", "--single", "--seed", "5", "-o", tmp_path / "cli.ply")
    summary = columba.generate_feathers(tmp_path / "py.ply", seed=5)
    assert (tmp_path / "py.ply").read_bytes() == (tmp_path / "cli.ply").read_bytes()
    assert summary["feathers"] == 1 and summary["barbs"] > 0 and summary["tiling_barb_width"] > 0


def test_neck_equals_cli_and_reads_back(cli, tmp_path):
    cli("feather", "--neck", "--feathers", "3", "--barbs", "6", "--binary", "--seed", "2", "-o", tmp_path / "cli.ply")
    summary = columba.generate_feathers(tmp_path / "py.ply", neck=True, feathers=3, barbs=6, binary=True, seed=2)
    assert (tmp_path / "py.ply").read_bytes() == (tmp_path / "cli.ply").read_bytes()
    data = columba.read_feather_ply(tmp_path / "py.ply")
    assert data["positions"].shape == (summary["faces"], columba.BARB_VERTICES, 3)
    assert data["positions"].dtype == np.float32
    assert data["normals"].shape == data["positions"].shape
    np.testing.assert_allclose(np.linalg.norm(data["normals"], axis=2), 1, rtol=1e-5)
    assert data["height"].shape == (summary["faces"], columba.BARB_VERTICES)
    assert data["barb_width"] == pytest.approx(summary["tiling_barb_width"], rel=1e-4)
    heights = np.unique(np.round(data["height"], 2))
    assert heights.min() >= 0.49 and heights.max() <= 0.62


def test_feather_barbs_returns_arrays():
    data = columba.feather_barbs(barbs=10, seed=3)
    # The rachis and 10 barbs on each side.
    assert data["positions"].shape == (21, columba.BARB_VERTICES, 3)
    assert np.isfinite(data["positions"]).all()


def test_feather_errors(tmp_path):
    with pytest.raises(ValueError, match="feathers applies to a neck"):
        columba.generate_feathers(tmp_path / "x.ply", feathers=3)
    with pytest.raises(ValueError, match="barbs must be positive"):
        columba.generate_feathers(tmp_path / "x.ply", barbs=0)
    with pytest.raises(RuntimeError, match="nodir"):
        columba.generate_feathers(tmp_path / "nodir" / "x.ply")
    bad = tmp_path / "bad.ply"
    bad.write_text("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\nzz\n")
    with pytest.raises(columba.InputError, match=str(bad)):
        columba.read_feather_ply(bad)
