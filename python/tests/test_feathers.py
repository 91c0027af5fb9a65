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


def test_colour_arguments_equal_cli_and_reach_the_file(cli, tmp_path):
    cli("feather", "--neck", "--feathers", "4", "--barbs", "4", "--height", "0.66", "--purple-height", "0.47",
        "--height-spread", "0.02", "--purple-below", "0.2", "--colour-blend", "0.1", "-o", tmp_path / "cli.ply")
    columba.generate_feathers(tmp_path / "py.ply", neck=True, feathers=4, barbs=4, height=0.66, purple_height=0.47,
                              height_spread=0.02, purple_below=0.2, colour_blend=0.1)
    assert (tmp_path / "py.ply").read_bytes() == (tmp_path / "cli.ply").read_bytes()
    heights = columba.read_feather_ply(tmp_path / "py.ply")["height"]
    assert heights.min() >= 0.47 - 0.028 - 1e-6 and heights.max() <= 0.66 + 0.028 + 1e-6
    assert heights.max() > 0.6 and heights.min() < 0.5  # both colours on the neck
    with pytest.raises(ValueError, match="purple_height applies to a neck"):
        columba.generate_feathers(tmp_path / "x.ply", purple_height=0.5)
    with pytest.raises(ValueError, match="the height must be a number of micrometres"):
        columba.generate_feathers(tmp_path / "x.ply", height=-1)


def test_write_feather_ply_writes_what_read_feather_ply_reads(tmp_path):
    barbs = columba.feather_barbs(barbs=5)
    barbs["height"] = barbs["height"] * 0.9
    for binary in (False, True):
        path = tmp_path / f"f{int(binary)}.ply"
        columba.write_feather_ply(path, barbs, binary=binary)
        back = columba.read_feather_ply(path)
        for name in ("positions", "H", "mu", "height"):
            np.testing.assert_array_equal(back[name], barbs[name], err_msg=name)
        np.testing.assert_allclose(back["normals"], barbs["normals"], rtol=0, atol=1e-6)  # normalised again
        assert back["barb_width"] == barbs["barb_width"]
    # Without per-vertex values and barb width, they stay absent.
    bare = {"positions": barbs["positions"], "normals": barbs["normals"], "H": None, "mu": None, "height": None,
            "barb_width": None}
    columba.write_feather_ply(tmp_path / "bare.ply", bare)
    back = columba.read_feather_ply(tmp_path / "bare.ply")
    assert back["height"] is None and back["barb_width"] is None
    np.testing.assert_array_equal(back["positions"], barbs["positions"])
    with pytest.raises(ValueError, match="B x 64 x 3"):
        columba.write_feather_ply(tmp_path / "bad.ply", {"positions": np.zeros((2, 10, 3)), "normals": np.zeros((2, 10, 3))})
    with pytest.raises(ValueError, match="height at least 0"):
        columba.write_feather_ply(tmp_path / "bad.ply", dict(barbs, height=-barbs["height"]))


def test_layer_stacks_are_written_and_read_per_vertex(cli, tmp_path):
    barbs = columba.feather_barbs(barbs=5)
    assert barbs["stack"] is None  # the generator chooses none
    stack = (np.arange(barbs["height"].size).reshape(barbs["height"].shape) % 4).astype(np.int64)
    for binary in (False, True):
        path = tmp_path / f"s{int(binary)}.ply"
        columba.write_feather_ply(path, dict(barbs, stack=stack), binary=binary)
        back = columba.read_feather_ply(path)
        assert back["stack"].dtype == np.uint8
        np.testing.assert_array_equal(back["stack"], stack)
        np.testing.assert_array_equal(back["height"], barbs["height"])
    for bad in (stack + 0.5, stack - 1, stack + 256):
        with pytest.raises(ValueError, match="whole numbers from 0 to 255"):
            columba.write_feather_ply(tmp_path / "bad.ply", dict(barbs, stack=bad))
    # The generator's purple stack, as `columba feather --neck --purple-stack` writes it.
    columba.generate_feathers(tmp_path / "py.ply", neck=True, feathers=3, barbs=4, purple_stack=2)
    cli("feather", "--neck", "--feathers", "3", "--barbs", "4", "--purple-stack", "2", "-o", tmp_path / "cli.ply")
    assert (tmp_path / "py.ply").read_bytes() == (tmp_path / "cli.ply").read_bytes()
    assert set(np.unique(columba.read_feather_ply(tmp_path / "py.ply")["stack"])) <= {0, 2}
    with pytest.raises(ValueError, match="purple_stack must be a whole number from 1 to 15"):
        columba.generate_feathers(tmp_path / "x.ply", neck=True, purple_stack=16)
    with pytest.raises(ValueError, match="stack must be B x 64"):
        columba.write_feather_ply(tmp_path / "bad.ply", dict(barbs, stack=stack[:, :10]))
