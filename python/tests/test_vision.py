"""Avian visual models from Python: observers, cone catches and colour distances (docs/vision.md)."""
import numpy as np
import pytest

import columba

WL = np.arange(300.0, 831.0)


def test_the_blue_tit_is_built_in_with_sensitivities_of_area_one():
    assert "bluetit" in [o["name"] for o in columba.observers()]
    o = columba.observer("bluetit")
    assert o["channels"] == ["UVS", "SWS", "MWS", "LWS"]
    assert o["sensitivities"].shape == (4, 531)
    np.testing.assert_allclose(o["sensitivities"].sum(axis=1), 1.0, rtol=1e-5)  # 1 nm steps


def test_an_equal_quantum_white_catches_each_sensitivitys_integral_and_adapts_to_one():
    white = np.ones_like(WL)
    np.testing.assert_allclose(columba.cone_catches(WL, white, von_kries=False), 1.0, rtol=1e-5)
    np.testing.assert_allclose(columba.cone_catches(WL, white), 1.0, rtol=1e-6)
    # k spectra in columns, pavo's layout: one row of catches per spectrum.
    two = np.stack([white, 0.5 * white], axis=1)
    np.testing.assert_allclose(columba.cone_catches(WL, two), [[1.0] * 4, [0.5] * 4], rtol=1e-6)


def test_a_grey_is_no_colour_and_identical_spectra_are_zero_apart():
    # A grey scales every cone's catch alike: no chromatic difference however dark.
    grey = np.full_like(WL, 0.2)
    assert columba.colour_distance(WL, grey, np.ones_like(WL))["dS"] == pytest.approx(0.0, abs=1e-9)
    green = np.exp(-0.5 * ((WL - 540.0) / 30.0) ** 2)
    assert columba.colour_distance(WL, green, green)["dS"] == 0.0
    purple = 0.5 * (np.exp(-0.5 * ((WL - 420.0) / 30.0) ** 2) + np.exp(-0.5 * ((WL - 650.0) / 30.0) ** 2))
    assert columba.colour_distance(WL, green, purple)["dS"] > 5.0  # plainly different to a bird


def test_a_custom_observer_from_published_pigment_peaks():
    spec = {"name": "two cones", "lambda_max": [420.0, 540.0], "beta_band": False}
    o = columba.observer(spec)
    assert o["channels"] == ["SWS", "LWS"]
    peaks = o["wavelengths"][np.argmax(o["sensitivities"], axis=1)]
    np.testing.assert_allclose(peaks, [420.0, 540.0], atol=1.0)
    # A dichromat's distance for a known pair of catches: with noise e = (e1, e2), dS = |df1 - df2| /
    # sqrt(e1^2 + e2^2). Equal densities and a Weber fraction of 0.1 give e = (0.1, 0.1).
    a = np.ones_like(WL)
    b = np.where(WL > 480.0, 2.0, 1.0)  # doubles what the long cone catches, barely changes the short one
    catches = columba.cone_catches(WL, b, observer=spec)
    expected = abs(np.log(catches[0]) - np.log(catches[1])) / np.sqrt(0.1**2 + 0.1**2)
    assert columba.colour_distance(WL, a, b, observer=spec)["dS"] == pytest.approx(expected, rel=1e-6)


def test_mistakes_are_errors():
    with pytest.raises(ValueError, match="must cover"):
        columba.cone_catches(np.arange(400.0, 701.0), np.ones(301))
    with pytest.raises(ValueError, match="pigeon"):
        columba.observer("pigeon")
    with pytest.raises(ValueError, match="one row per wavelength"):
        columba.cone_catches(WL, np.ones(10))


def test_a_render_seen_by_a_bird_gives_its_cone_catches():
    # A grey plate (0.5) under a white (D65) directional light of irradiance pi: every cone, adapted
    # to D65, catches 0.5, as RGB is 0.5.
    xml = """<scene version="3.0.0"><integrator type="direct"/>
      <sensor type="perspective"><float name="fov" value="1"/>
        <transform name="to_world"><lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
        <film type="hdrfilm"><integer name="width" value="4"/><integer name="height" value="4"/>
          <string name="observer" value="bluetit"/></film>
        <sampler type="ldsampler"><integer name="sample_count" value="256"/></sampler></sensor>
      <shape type="rectangle"><transform name="to_world"><scale value="10"/></transform>
        <bsdf type="diffuse"><float name="reflectance" value="0.5"/></bsdf></shape>
      <emitter type="directional"><vector name="direction" x="0" y="0" z="-1"/>
        <float name="irradiance" value="3.14159265"/></emitter></scene>"""
    image, info = columba.render(columba.load_string(xml), stats=True)
    assert sorted(info["cones"]) == ["LWS", "MWS", "SWS", "UVS"]
    for name, catches in info["cones"].items():
        assert catches.shape == (4, 4)
        assert catches.mean() == pytest.approx(0.5, rel=0.01), name
    assert image.mean() == pytest.approx(0.5, rel=0.01)
    # No observer, no cones.
    plain, plain_info = columba.render(columba.load_string(xml.replace('<string name="observer" value="bluetit"/>', "")),
                                       stats=True)
    assert "cones" not in plain_info


def test_an_observer_is_read_from_a_table_of_its_sensitivities(tmp_path):
    # The blue tit's own curves written as a table read back as the blue tit; a bad table names its line.
    o = columba.observer("bluetit")
    table = tmp_path / "tit.csv"
    rows = ["wl,UVS,SWS,MWS,LWS"] + [",".join([f"{w:g}"] + [f"{v:.9g}" for v in o["sensitivities"][:, i]])
                                      for i, w in enumerate(o["wavelengths"])]
    table.write_text("\n".join(rows) + "\n")
    t = columba.observer(str(table))
    assert t["channels"] == o["channels"]
    np.testing.assert_allclose(t["sensitivities"], o["sensitivities"], atol=1e-6)
    grey = np.full_like(WL, 0.5)
    assert columba.colour_distance(WL, grey, grey, observer=str(table))["dS"] == pytest.approx(0.0, abs=1e-9)
    bad = tmp_path / "bad.csv"
    bad.write_text("wl,UVS,green\n300,1,1\n")
    with pytest.raises(ValueError, match="bad.csv:1"):
        columba.observer(str(bad))


def test_a_human_sees_greys_by_their_lightness_and_colours_apart():
    wl = np.arange(380.0, 781.0, 5.0)
    white, grey = np.ones_like(wl), np.full_like(wl, 0.18)
    r = columba.human_colour_difference(wl, white, grey)
    # A flat grey under D65 has the white's chromaticity: L* = 116 * 0.18^(1/3) - 16, a* = b* = 0.
    assert r["lab_a"] == pytest.approx((100.0, 0.0, 0.0), abs=1e-3)
    assert r["lab_b"] == pytest.approx((116.0 * 0.18 ** (1 / 3) - 16.0, 0.0, 0.0), abs=1e-3)
    assert r["dEab"] == pytest.approx(100.0 - r["lab_b"][0], abs=1e-3)
    assert r["jnd"] == pytest.approx(r["dEab"] / 2.3)
    assert columba.human_colour_difference(wl, grey, grey)["dE2000"] == 0.0
    # Long-pass (reddish) against short-pass (bluish): far apart, with a* of opposite sign.
    red, blue = (wl > 600).astype(float), (wl < 480).astype(float)
    far = columba.human_colour_difference(wl, red, blue)
    assert far["lab_a"][1] > 20 and far["dE2000"] > 30
    with pytest.raises(ValueError, match="cover 400-700 nm"):
        columba.human_colour_difference(wl[wl > 450], grey[wl > 450], grey[wl > 450])


WEBER = "weber (the reference cone's Weber fraction) "
DENSITY = "densities[1] (a cone's relative density) "


@pytest.mark.parametrize("key, value, shown", [
    ("weber", 0.0, WEBER + "0 "), ("weber", float("nan"), WEBER + "nan"), ("weber", float("inf"), WEBER + "inf"),
    ("weber", -0.1, WEBER + "-0.1"), ("densities", [1.0, 1e-300], DENSITY + "1e-300"),
    ("densities", [1.0, float("inf")], DENSITY + "inf"), ("weber_cone", -1, "weber_cone -1 names no cone: give 0 to 1"),
    ("weber_cone", 2, "weber_cone 2 names no cone: give 0 to 1"),
])
def test_an_observer_dicts_receptor_noise_out_of_range_is_a_value_error_naming_it(key, value, shown):
    # dS was inf, NaN or 0 for these, and weber_cone=-1 a raw cast error.
    spec = {"name": "two cones", "lambda_max": [420.0, 540.0], key: value}
    with pytest.raises(ValueError, match="weber|densities") as error:
        columba.observer(spec)
    assert shown in str(error.value)


def _error(call):
    with pytest.raises(ValueError) as error:
        call()
    return str(error.value)


@pytest.mark.parametrize("value, shown", [(float("nan"), "nan"), (-1.0, "-1"), (1e300, "1e+300")])
def test_every_vision_function_refuses_a_spectrum_value_naming_argument_index_and_wavelength(value, shown):
    # cone_catches and human_colour_difference returned NaN or negative values for these.
    bad, ones = np.where(WL == 500.0, value, 1.0), np.ones_like(WL)
    expected = f"[200] at 500 nm is {shown}"
    assert "spectra" + expected in _error(lambda: columba.cone_catches(WL, bad))
    assert "spectra[200, 1] at 500 nm" in _error(lambda: columba.cone_catches(WL, np.stack([ones, bad], axis=1)))
    assert "a" + expected in _error(lambda: columba.colour_distance(WL, bad, ones))
    assert "b" + expected in _error(lambda: columba.human_colour_difference(WL, ones, bad))
    assert "illuminant" + expected in _error(lambda: columba.cone_catches(WL, ones, illuminant=bad))
    assert "illuminant" + expected in _error(lambda: columba.human_colour_difference(WL, ones, ones, illuminant=bad))


def test_wavelengths_must_be_positive_and_finite_and_an_illuminant_must_light_the_cones():
    wl = WL.copy()
    wl[0] = -300.0
    assert "wavelengths[0] is -300" in _error(lambda: columba.cone_catches(wl, np.ones_like(WL)))
    wl[0] = np.nan
    assert "wavelengths[0] is nan" in _error(lambda: columba.human_colour_difference(wl, np.ones_like(WL), np.ones_like(WL)))
    # A dark illuminant: its white catches nothing to adapt to (NaN catches and colours before).
    dark, ones = np.zeros_like(WL), np.ones_like(WL)
    assert "the background's catch in UVS is 0" in _error(lambda: columba.cone_catches(WL, ones, illuminant=dark))
    assert "the background's catch" in _error(lambda: columba.colour_distance(WL, ones, ones, illuminant=dark))
    assert "no light the CIE 1931 observer sees" in _error(
        lambda: columba.human_colour_difference(WL, ones, ones, illuminant=dark))
    # Unadapted, a dark illuminant's catches are 0, as they are.
    np.testing.assert_array_equal(columba.cone_catches(WL, ones, illuminant=dark, von_kries=False), 0.0)
