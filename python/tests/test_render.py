"""Scenes, renders and images through Python against the command line."""
import os
import signal
import threading
import time
import warnings

import numpy as np
import pytest

import columba

SMALL = {"res": 48, "spp": 4}

BAD_BSDF = """<scene version="3.0.0">
  <shape type="sphere">
    <bsdf type="barbulebsdf">
      <float name="b" value="-1"/>
    </bsdf>
  </shape>
</scene>
"""


def cli_error(cli, *args):
    result = cli(*args, check=False)
    assert result.returncode != 0
    line = [l for l in result.stderr.splitlines() if l.startswith("error: ")][0]
    return line[len("error: "):]


def test_render_equals_cli_bit_for_bit(cli, repo, tmp_path):
    scene_path = repo / "examples" / "tiny_feather.xml"
    out = tmp_path / "tiny.exr"
    cli("render", scene_path, "-o", out, "-D", "res=48", "-D", "spp=16", "--spp", "4", "--seed", "3")
    expected = columba.read_image(out)
    scene = columba.load_file(scene_path, res=48, spp=16)
    image = columba.render(scene, spp=4, seed=3)
    assert image.dtype == np.float32 and image.shape == (48, 48, 3)
    assert image.flags.c_contiguous
    assert image.max() > 0
    np.testing.assert_array_equal(image, expected)
    # Any thread count gives the same image; another seed does not.
    np.testing.assert_array_equal(columba.render(scene, spp=4, seed=3, threads=1), expected)
    assert not np.array_equal(columba.render(scene, spp=4, seed=4), expected)


def test_render_is_a_view_of_the_image(repo):
    scene = columba.load_file(repo / "examples" / "tiny_feather.xml", res=8, spp=1)
    image, stats = columba.render(scene, stats=True)
    assert image.base is not None and image.flags.writeable  # owns the C++ image, no copy
    assert stats["spp"] == 1 and stats["samples"] == 64 and stats["rays"] > 0
    assert (scene.width, scene.height, scene.spp) == (8, 8, 1)


def test_load_string_resolves_against_base_dir(repo):
    xml = (repo / "examples" / "tiny_feather.xml").read_text()
    scene = columba.load_string(xml, base_dir=repo / "examples", defines={"res": 16}, spp=2)
    from_file = columba.load_file(repo / "examples" / "tiny_feather.xml", res=16, spp=2)
    np.testing.assert_array_equal(columba.render(scene, seed=1), columba.render(from_file, seed=1))
    assert scene.source == "<string>"


def test_scene_errors_carry_the_cli_message(cli, tmp_path):
    bad = tmp_path / "bad.xml"
    bad.write_text(BAD_BSDF)
    message = cli_error(cli, "render", bad, "-o", tmp_path / "x.exr")
    assert message.startswith(f"{bad}:4: ")
    with pytest.raises(columba.InputError) as error:
        columba.load_file(bad)
    assert str(error.value) == message
    assert isinstance(error.value, ValueError)
    with pytest.raises(columba.InputError, match=r"^<string>:4: <bsdf> 'barbulebsdf', parameter 'b'"):
        columba.load_string(BAD_BSDF)


def test_missing_scene_file(cli, tmp_path):
    missing = tmp_path / "missing.xml"
    message = cli_error(cli, "render", missing, "-o", tmp_path / "x.exr")
    with pytest.raises(columba.InputError) as error:
        columba.load_file(missing)
    assert str(error.value) == message


def test_unused_define_warns(repo):
    with pytest.warns(columba.ColumbaWarning, match=r"nosuch=1: the scene uses no variable \$nosuch"):
        columba.load_file(repo / "examples" / "tiny_feather.xml", nosuch=1, res=8)


def test_scene_warnings_reach_python(repo):
    # A scene's warnings went to C++'s stderr alone: in a notebook two renders of different
    # thickness came out the same and nothing showed why. They are ColumbaWarnings too, naming the
    # place, and only once each.
    xml = """<scene version="3.0.0">
  <bsdf type="barbulebsdf" id="b"><float name="height" value="6"/></bsdf>
</scene>"""
    with pytest.warns(columba.ColumbaWarning, match=r"thin.xml:2: .*a film 6 um thick is implausible") as caught:
        columba.load_string(xml, name="thin.xml")
    assert sum("implausible" in str(w.message) for w in caught) == 1
    assert issubclass(columba.ColumbaWarning, UserWarning)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        columba.load_file(repo / "examples" / "tiny_feather.xml", res=8)  # warns nothing, and nothing is left over


def test_render_argument_errors(repo):
    scene = columba.load_file(repo / "examples" / "tiny_feather.xml", res=8, spp=1)
    with pytest.raises(ValueError, match="spp must be between 1 and"):
        columba.render(scene, spp=0)
    with pytest.raises(ValueError, match="threads must be between 1 and"):
        columba.render(scene, threads=0)
    with pytest.raises(TypeError):
        columba.render("not a scene")


def test_images_round_trip(tmp_path):
    rng = np.random.default_rng(1)
    image = rng.random((5, 7, 3), dtype=np.float32) * 4
    columba.write_image(tmp_path / "a.exr", image)
    back = columba.read_image(tmp_path / "a.exr")
    assert back.shape == (5, 7, 3) and back.dtype == np.float32
    np.testing.assert_array_equal(back, image)
    columba.write_image(str(tmp_path / "a.png"), image[:, :, :] / 4)  # float64 and views are accepted
    png = columba.read_image(tmp_path / "a.png")
    assert png.shape == (5, 7, 3)
    np.testing.assert_allclose(png, image / 4, atol=0.01)
    rgb, centres, bands = columba.read_image(tmp_path / "a.exr", spectral=True)
    assert centres is None and bands is None


def test_image_errors(cli, tmp_path):
    message = cli_error(cli, "render", "-o", tmp_path / "x.tif")
    with pytest.raises(RuntimeError) as error:
        columba.write_image(tmp_path / "x.tif", np.zeros((2, 2, 3), np.float32))
    assert str(error.value) == message
    with pytest.raises(ValueError, match="H x W x 3"):
        columba.write_image(tmp_path / "x.exr", np.zeros((2, 2), np.float32))
    with pytest.raises(columba.InputError, match="nothing.exr"):
        columba.read_image(tmp_path / "nothing.exr")


def test_render_releases_the_gil(repo):
    scene = columba.load_file(repo / "examples" / "tiny_feather.xml", res=128, spp=64)
    ticks = 0
    done = threading.Event()

    def count():
        nonlocal ticks
        while not done.is_set():
            ticks += 1
            time.sleep(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    start = time.perf_counter()
    columba.render(scene, threads=1)
    elapsed = time.perf_counter() - start
    done.set()
    counter.join()
    # Were the GIL held, the counter could not run while the render does.
    assert elapsed > 0.1 and ticks > 10


def test_ctrl_c_interrupts_a_render(repo):
    scene = columba.load_file(repo / "examples" / "tiny_feather.xml", res=256, spp=100000)
    sent = []

    def interrupt():
        sent.append(time.perf_counter())
        os.kill(os.getpid(), signal.SIGINT)

    timer = threading.Timer(0.5, interrupt)
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        columba.render(scene, threads=2)
    stopped = time.perf_counter()
    timer.join()
    assert sent and stopped - sent[0] < 1.0


def test_adaptive_render_equals_cli_and_reports_its_plan(cli, repo, tmp_path):
    scene_path = repo / "examples" / "tiny_feather.xml"
    out = tmp_path / "adaptive.exr"
    cli("render", scene_path, "-o", out, "-D", "res=32", "--spp", "8", "--seed", "2", "--adaptive")
    scene = columba.load_file(scene_path, res=32)
    image, info = columba.render(scene, spp=8, seed=2, adaptive=True, stats=True)
    np.testing.assert_array_equal(image, columba.read_image(out))
    assert info["pilot_samples"] == 2
    assert info["fewest_samples"] <= 8 <= info["most_samples"]
    assert info["predicted_relative_error"] > 0
    with pytest.raises(ValueError, match="target_error"):
        columba.render(scene, spp=8, target_error=2.0)
    with pytest.raises(ValueError, match="4 or more samples"):
        columba.render(scene, spp=2, adaptive=True)
