"""The barbule BSDF over numpy arrays, checked against `columba bsdf`, the scene plug-in and
its own identities (eval, pdf and sample are the C++ functions)."""
import csv

import numpy as np
import pytest

import columba


def directions(n, seed, lower=False):
    rng = np.random.default_rng(seed)
    v = rng.normal(size=(n, 3))
    if not lower:
        v[:, 2] = np.abs(v[:, 2])
    return (v / np.linalg.norm(v, axis=1, keepdims=True)).astype(np.float32)


def hemisphere(cli, tmp_path, *args):
    cli("bsdf", "--mode", "hemisphere", "-o", tmp_path, *args)


def test_scatterometer_image_equals_cli(cli, tmp_path):
    hemisphere(cli, tmp_path, "--angles", "30", "--phi", "20", "--res", "32")
    expected = columba.read_image(tmp_path / "bsdf_hemisphere_theta30.exr")
    image = columba.BarbuleBSDF().scatterometer_image(30, 20, resolution=32)
    assert image.shape == (32, 32, 3) and image.dtype == np.float32
    np.testing.assert_array_equal(image, expected)


def test_presets_and_parameters_equal_cli(cli, tmp_path):
    hemisphere(cli, tmp_path, "--angles", "10", "--res", "24", "--preset", "dove-purple", "--height", "0.55",
               "--film-ior", "1.56")
    expected = columba.read_image(tmp_path / "bsdf_hemisphere_theta10.exr")
    bsdf = columba.BarbuleBSDF(preset="dove-purple", height=0.55, film_ior=1.56)
    np.testing.assert_array_equal(bsdf.scatterometer_image(10, resolution=24), expected)
    purple = columba.presets()["dove-purple"]
    assert bsdf.parameters["b"] == pytest.approx(purple["b"]) and bsdf.parameters["height"] == pytest.approx(0.55)
    assert not np.array_equal(columba.BarbuleBSDF(preset="dove-purple").scatterometer_image(10, resolution=24), expected)


def test_presets_and_parameters_read_as_they_are_written():
    # The float32 parameters as the shortest decimals that are the same floats: 0.51, not 0.5099999904632568.
    purple = columba.presets()["dove-purple"]
    assert (purple["height"], purple["mu"], purple["phi_0"], purple["phi_1"]) == (0.51, -0.35, -0.37, 2.64)
    assert repr(purple["height"]) == "0.51"
    parameters = columba.BarbuleBSDF(preset="dove-purple", height=0.55).parameters
    assert (parameters["height"], parameters["mu"], parameters["ext_ior"]) == (0.55, -0.35, 1.000277)
    for value in parameters.values():
        assert repr(value) == repr(float(str(np.float32(value))))


def test_specular_spectra_equal_cli(cli, tmp_path):
    cli("bsdf", "--mode", "specular", "--angles", "0,40", "--preset", "dove-green", "-o", tmp_path)
    with open(tmp_path / "bsdf_specular.csv") as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    header, data = rows[0], np.array(rows[1:], dtype=np.float64)
    bsdf = columba.BarbuleBSDF(preset="dove-green")
    for angle in (0, 40):
        s = bsdf.specular_spectra(angle)
        np.testing.assert_array_equal(s["wavelengths"], data[:, 0].astype(np.float32))
        np.testing.assert_allclose(s["R"], data[:, header.index(f"R_theta{angle}")], rtol=1e-6, atol=1e-9)
        np.testing.assert_allclose(s["TRT"], data[:, header.index(f"TRT_theta{angle}")], rtol=1e-6, atol=1e-9)


def test_defaults_and_validation_match_the_scene_plugin():
    bsdf = columba.BarbuleBSDF()
    assert bsdf.parameters == pytest.approx({"b": 0.25, "H": 1.25, "mu": -0.35, "height": 0.6, "phi_0": -0.37,
                                             "phi_1": 2.64, "ext_ior": 1.000277, "profile_exponent": 2})
    xml = """<scene version="3.0.0"><shape type="sphere"><bsdf type="barbulebsdf">
      <float name="{name}" value="{value}"/></bsdf></shape></scene>"""
    for name, value in [("b", -1), ("H", 0), ("height", -0.1), ("phi_0", 3), ("profile_exponent", 1.5),
                        ("profile_exponent", 17)]:
        with pytest.raises(columba.InputError) as xml_error:
            columba.load_string(xml.format(name=name, value=value))
        with pytest.raises(ValueError) as error:
            columba.BarbuleBSDF(**{name: value})
        # The plug-in's message without its file:line.
        assert str(xml_error.value).endswith(": " + str(error.value)), (str(xml_error.value), str(error.value))
        assert str(error.value).startswith("<bsdf> 'barbulebsdf', parameter '")
    with pytest.raises(ValueError, match="unknown preset 'dove-blue' \\(known: dove-green, dove-purple"):
        columba.BarbuleBSDF(preset="dove-blue")
    with pytest.raises(ValueError, match="unknown index of refraction 'glas'"):
        columba.BarbuleBSDF(film_ior="glas")
    with pytest.raises(ValueError, match="role must be"):
        columba.BarbuleBSDF(role="eye")
    with pytest.warns(UserWarning, match="height"):
        columba.BarbuleBSDF(height=600)
    for name, value in [("trt_offsets", 0), ("trt_angles", 17)]:
        with pytest.raises(ValueError, match=f"parameter '{name}': the TRT lobe's .* must number"):
            columba.BarbuleBSDF(**{name: value})


def test_the_trt_quadrature_is_the_scenes():
    # trt_offsets and trt_angles as in a scene: more nodes integrate TRT on a squarer cross-section
    # more finely, changing it by about the default's error.
    wi, wo = directions(200, 4), directions(200, 5)
    wl = np.full((200, 4), [450.0, 520.0, 610.0, 680.0], dtype=np.float32)
    usual = columba.BarbuleBSDF(profile_exponent=8).eval_lobes(wi, wo, wl)["TRT"]
    fine = columba.BarbuleBSDF(profile_exponent=8, trt_offsets=16, trt_angles=2).eval_lobes(wi, wo, wl)["TRT"]
    assert np.any(fine != usual)
    # The same lobe, better integrated: over these directions the two agree within 2 % (0.5 % seen).
    assert abs(usual.sum() / fine.sum() - 1.0) < 0.02


def test_eval_is_the_lobes_times_cosine_and_wavelength_layouts_agree():
    bsdf = columba.BarbuleBSDF()
    wi, wo = directions(500, 1), directions(500, 2, lower=True)
    wl = np.random.default_rng(3).uniform(380, 780, size=(500, 4)).astype(np.float32)
    f = bsdf.eval(wi, wo, wl)
    assert f.shape == (500, 4) and f.dtype == np.float32
    lobes = bsdf.eval_lobes(wi, wo, wl)
    np.testing.assert_allclose(f, (lobes["R"] + lobes["TRT"]) * np.abs(wo[:, 2:3]), rtol=1e-5, atol=1e-7)
    assert f.max() > 0 and (f >= 0).all()
    # One wavelength per row is the four-lane evaluation with that wavelength everywhere.
    one = bsdf.eval(wi, wo, wl[:, 0])
    assert one.shape == (500,)
    np.testing.assert_array_equal(one, bsdf.eval(wi, wo, np.repeat(wl[:, :1], 4, axis=1))[:, 0])
    # The light-incident twin evaluates the lobes with omega_i = wo.
    ev = columba.BarbuleBSDF(role="light").eval(wi, wo, wl)
    assert not np.allclose(ev, f)


def test_sample_matches_eval_and_pdf():
    bsdf = columba.BarbuleBSDF(preset="dove-green")
    n = 2000
    rng = np.random.default_rng(4)
    wi = directions(n, 5)
    wl = rng.uniform(380, 780, size=(n, 4)).astype(np.float32)
    s = bsdf.sample(wi, rng.random(n, dtype=np.float32), rng.random((n, 2), dtype=np.float32), wl)
    assert s["wo"].shape == (n, 3) and s["weight"].shape == (n, 4) and s["pdf"].shape == (n,)
    assert s["valid"].dtype == bool
    scattered = s["valid"] & ~s["pass_through"] & ~s["delta"]
    assert scattered.sum() > n // 4 and s["pass_through"].sum() > 0
    wo = s["wo"][scattered]
    np.testing.assert_allclose(np.linalg.norm(wo, axis=1), 1, rtol=1e-4)
    pdf = bsdf.pdf(wi[scattered], wo, wl[scattered])
    # A sample reports the density it was drawn with; pdf() recomputes R's share of visible
    # longitudinal angles at the half vector's normal, which rounding can move slightly.
    close = np.isclose(s["pdf"][scattered], pdf, rtol=1e-4, atol=0)
    assert close.mean() > 0.998
    np.testing.assert_allclose(s["pdf"][scattered], pdf, rtol=0.02)
    # Each lobe is estimated by its own samples: the weight is R's or TRT's value over that lobe's
    # share of the density, and the two shares sum to pdf().
    lobes = bsdf.eval_lobes(wi[scattered], wo, wl[scattered])
    cos = np.abs(wo[:, 2])[:, None]
    weight = s["weight"][scattered]
    as_trt = lobes["TRT"] * cos
    as_r = lobes["R"] * cos
    # weight x density = value for the lobe that drew the sample; the densities are positive.
    share_r = as_r / np.maximum(weight, 1e-30)
    share_trt = as_trt / np.maximum(weight, 1e-30)
    total = s["pdf"][scattered][:, None]
    is_r = np.all(np.isclose(share_r, share_r[:, :1], rtol=1e-3), axis=1) & (share_r[:, 0] > 0)
    is_trt = np.all(np.isclose(share_trt, share_trt[:, :1], rtol=1e-3), axis=1) & (share_trt[:, 0] > 0)
    carries = weight.max(axis=1) > 0
    assert (is_r | is_trt)[carries].all() and is_r.sum() > 100 and is_trt.sum() > 100
    assert (share_r[is_r, 0] <= total[is_r, 0] * (1 + 1e-4)).all()
    assert (share_trt[is_trt, 0] <= total[is_trt, 0] * (1 + 1e-4)).all()
    # The light-side twin weighs eval over pdf.
    light = columba.BarbuleBSDF(preset="dove-green", role="light")
    t = light.sample(wi, rng.random(n, dtype=np.float32), rng.random((n, 2), dtype=np.float32), wl)
    ok = t["valid"] & ~t["pass_through"] & ~t["delta"]
    f = light.eval(wi[ok], t["wo"][ok], wl[ok])
    np.testing.assert_allclose(t["weight"][ok], f / t["pdf"][ok][:, None], rtol=1e-3, atol=1e-6)
    # The pass-through samples continue along -wi with the T lobe's weight.
    passing = s["pass_through"]
    np.testing.assert_allclose(s["wo"][passing], -wi[passing], atol=1e-6)


def test_coverage_and_pass_through():
    bsdf = columba.BarbuleBSDF()
    wi = directions(100, 6)
    r = bsdf.coverage(wi)
    assert r.shape == (100,) and ((0 <= r) & (r <= 1)).all() and r.max() > 0.5
    t = bsdf.pass_through(wi, np.full(100, 550, np.float32))
    np.testing.assert_allclose(t, 1 - r, atol=1e-6)


def test_albedo_is_below_coverage():
    bsdf = columba.BarbuleBSDF()
    lambdas = np.arange(400, 701, 50, dtype=np.float32)
    a = bsdf.lobe_reflectance(30, wavelengths=lambdas)
    assert a["R"].shape == (7,) and (a["R"] > 0).all()
    r = bsdf.coverage(columba.direction(30)[None, :])[0]
    assert (a["R"] + a["TRT"] <= r * 1.001).all()
    np.testing.assert_allclose(columba.direction(90, 90), [0, 1, 0], atol=1e-6)


def test_shape_errors():
    bsdf = columba.BarbuleBSDF()
    wi = directions(4, 7)
    with pytest.raises(ValueError, match="wi must be an N x 3 array"):
        bsdf.eval(wi[:, :2], wi, np.full(4, 500))
    with pytest.raises(ValueError, match="same number of rows"):
        bsdf.eval(wi, wi[:3], np.full(4, 500))
    with pytest.raises(ValueError, match=r"wavelengths must have shape \(N,\) or \(N, 4\) for N = 4"):
        bsdf.eval(wi, wi, np.full(3, 500))
    with pytest.raises(ValueError, match=r"u2 must have shape \(N, 2\)"):
        bsdf.sample(wi, np.zeros(4), np.zeros(4), np.full(4, 500))


def test_values_outside_their_range_are_value_errors():
    # A NaN u1, or a NaN or 0 nm wavelength, crashed the interpreter in sample; -5 nm gave R = 4.6.
    bsdf = columba.BarbuleBSDF()
    wi = directions(4, 7)
    u1, u2, wl = np.full(4, 0.5), np.full((4, 2), 0.5), np.full(4, 550.0)
    for bad in (np.nan, 0.0, -5.0, 299.0, 831.0, np.inf):
        lambdas = np.array([550.0, bad, 550.0, 550.0])
        with pytest.raises(ValueError, match=r"wavelengths \(nm\) must lie in \[300, 830\]"):
            bsdf.sample(wi, u1, u2, lambdas)
        with pytest.raises(ValueError, match="element 1"):
            bsdf.eval(wi, wi, lambdas)
        with pytest.raises(ValueError, match="wavelengths"):
            bsdf.specular_spectra(30, wavelengths=[500.0, bad])
        with pytest.raises(ValueError, match="wavelengths"):
            bsdf.lobe_reflectance(30, wavelengths=[bad])
    for bad in (np.nan, -0.1, 1.0 + 1e-9):
        with pytest.raises(ValueError, match=r"u1 must lie in \[0, 1\], not .* \(element 2\)"):
            bsdf.sample(wi, np.array([0.5, 0.5, bad, 0.5]), u2, wl)
        with pytest.raises(ValueError, match=r"u2 must lie in \[0, 1\]"):
            bsdf.sample(wi, u1, np.array([[0.5, 0.5]] * 3 + [[0.5, bad]]), wl)
    # Birds see from 300 nm: the model is evaluated there (keratin's Cauchy fit extrapolated).
    ends = bsdf.specular_spectra(30, wavelengths=[300.0, 360.0, 830.0])
    assert np.all(np.isfinite(ends["R"])) and np.all(ends["R"] > 0)


def test_sampling_takes_numpys_random_numbers_as_they_come():
    # numpy's random() draws 1 - 2**-53, which rounds to 1 in float32: such numbers, and 1 itself,
    # are held below 1 as the samplers' own are (about 9 % of runs of 10**6 samples raised before).
    bsdf = columba.BarbuleBSDF()
    wi = directions(4, 7)
    top = 1.0 - 2.0**-53
    for u in (top, 1.0):
        s = bsdf.sample(wi, np.full(4, u), np.full((4, 2), u), np.full(4, 550.0))
        held = bsdf.sample(wi, np.full(4, np.nextafter(np.float32(1), np.float32(0))),
                           np.full((4, 2), np.nextafter(np.float32(1), np.float32(0))), np.full(4, 550.0))
        np.testing.assert_array_equal(s["wo"], held["wo"])
        np.testing.assert_array_equal(s["valid"], held["valid"])
    rng = np.random.default_rng(3)
    n = 1000
    s = bsdf.sample(directions(n, 5), rng.random(n), rng.random((n, 2)), np.full(n, 550.0))
    assert np.all(np.isfinite(s["pdf"]))


def test_directions_are_normalised_and_a_zero_or_nan_one_is_refused():
    # A direction scaled by 3 read 0.0346 where its value is 0.0976; a zero or NaN one gave 0.
    bsdf = columba.BarbuleBSDF()
    wi, wo = directions(6, 11), directions(6, 12)
    wl = np.full(6, 500.0)
    np.testing.assert_allclose(bsdf.eval(3 * wi, 0.25 * wo, wl), bsdf.eval(wi, wo, wl), rtol=1e-5)
    np.testing.assert_allclose(bsdf.pdf(3 * wi, wo, wl), bsdf.pdf(wi, wo, wl), rtol=1e-5)
    for bad in ([0.0, 0.0, 0.0], [np.nan, 0.0, 1.0], [np.inf, 0.0, 1.0]):
        given = wo.copy()
        given[4] = bad
        with pytest.raises(ValueError, match=r"wo row 4 .* is not a direction"):
            bsdf.eval(wi, given, wl)


def test_a_film_index_beyond_any_material_is_refused():
    # A Cauchy b of 1e10 (an index of 1.1e5 at 300 nm) gave NaN from eval and the spectra.
    for make in (lambda **k: columba.BarbuleBSDF(**k), lambda **k: columba.BarbuleArmsBSDF(arm_tilts="0", **k)):
        with pytest.raises(ValueError, match=r"film_cauchy_b': the film's index reaches 111113"):
            make(film_ior=(1.5, 1e10))
    with pytest.raises(ValueError, match=r"the index must lie in \(0, 100\]"):
        columba.multilayer(0.0, [500.0], [((1.5, 1e10), 0.1)])


def test_spectral_hemisphere_reads_back(cli, tmp_path):
    hemisphere(cli, tmp_path, "--angles", "20", "--res", "16", "--spectral", "--bins", "4",
               "--spectral-range", "400:700")
    rgb, centres, bands = columba.read_image(tmp_path / "bsdf_hemisphere_theta20.exr", spectral=True)
    np.testing.assert_array_equal(rgb, columba.BarbuleBSDF().scatterometer_image(20, resolution=16))
    np.testing.assert_allclose(centres, [437.5, 512.5, 587.5, 662.5])
    assert bands.shape == (16, 16, 4) and bands.dtype == np.float32 and bands.max() > 0


def test_layers_under_the_cortex_change_the_film_and_an_empty_one_does_not():
    plain = columba.BarbuleBSDF(preset="dove-green")
    empty = columba.BarbuleBSDF(preset="dove-green", layers="1.7+0.1i:0")
    layered = columba.BarbuleBSDF(preset="dove-green", layers="1.7+0.1i:0.12, air:0.1")
    a, b, c = (x.specular_spectra(20.0) for x in (plain, empty, layered))
    np.testing.assert_allclose(b["R"], a["R"], rtol=1e-4, atol=1e-6)
    np.testing.assert_allclose(b["TRT"], a["TRT"], rtol=1e-4, atol=1e-6)
    assert np.max(np.abs(c["R"] - a["R"])) > 0.01
    with pytest.raises(ValueError, match="layers"):
        columba.BarbuleBSDF(layers="0.1")


def test_a_published_stack_is_named_and_peaks_where_it_was_measured():
    # parotia-occipital (Stavenga et al. 2015): seven 0.2 um melanin layers between 0.2 um keratin
    # layers; measured peak ~1.3 um. Written out for multilayer, its normal-incidence peak lies
    # within 5 % of it; the named stack loads in the BSDF and changes its reflection.
    layers = []
    for i in range(7):
        layers.append(("melanin", 0.2))
        if i < 6:
            layers.append(("keratin", 0.2))
    wavelengths = np.arange(900.0, 1701.0)
    r = columba.multilayer(0.0, wavelengths, layers, n_outside=1.0, substrate_ior=1.0)["R"]
    assert abs(wavelengths[np.argmax(r)] - 1300.0) < 65.0
    plain = columba.BarbuleBSDF(preset="dove-green").specular_spectra(20.0)
    stacked = columba.BarbuleBSDF(preset="dove-green", layers="parotia-occipital").specular_spectra(20.0)
    assert np.max(np.abs(stacked["R"] - plain["R"])) > 0.01


def test_barbules_of_arms_sample_as_they_evaluate_and_one_arm_covers_its_width():
    roof = columba.BarbuleArmsBSDF(arm_tilts="-30, 0, 30", b=0.2, profile_exponent=2.5, height=0.18,
                                   layers="melanin:0.3")
    assert roof.spacing > 5.0  # packed at contact: three arms of half-length 1 side by side
    n = 2000
    rng = np.random.default_rng(8)
    wi = directions(n, 9)
    wl = rng.uniform(380, 780, size=(n, 4)).astype(np.float32)
    s = roof.sample(wi, rng.random(n, dtype=np.float32), rng.random((n, 2), dtype=np.float32), wl)
    scattered = s["valid"] & ~s["pass_through"]
    assert scattered.sum() > n // 2
    wo = s["wo"][scattered]
    # A sample's density is pdf() and its weight eval over it, at every wavelength.
    pdf = roof.pdf(wi[scattered], wo, wl[scattered])
    np.testing.assert_allclose(s["pdf"][scattered], pdf, rtol=1e-6)
    f = roof.eval(wi[scattered], wo, wl[scattered])
    np.testing.assert_allclose(s["weight"][scattered], f / pdf[:, None], rtol=1e-5)
    # Coverage and pass-through are complements; one flat arm of half-length 1 seen along the
    # vane normal covers 2 of every H.
    cover = roof.coverage(wi)
    np.testing.assert_allclose(roof.pass_through(wi, wl)[:, 0], 1 - cover, atol=1e-6)
    one = columba.BarbuleArmsBSDF(arm_tilts=[0], H=8.0, profile_exponent=4)
    assert one.coverage(np.array([[0.0, 0.0, 1.0]]))[0] == pytest.approx(2.0 / 8.0, abs=1e-6)
    with pytest.raises(ValueError, match="arm_tilts"):
        columba.BarbuleArmsBSDF(arm_tilts="0, 95")
    # One arm (an ellipse) is the ellipse barbule with its upper half reflective, through the other
    # model's code: the same R in the mirror direction, and no TRT.
    arm = columba.BarbuleArmsBSDF(arm_tilts=[0], profile_exponent=2, b=0.25, mu=-0.35, H=1.25, height=0.58)
    ellipse = columba.BarbuleBSDF(b=0.25, mu=-0.35, H=1.25, height=0.58, phi_0=-np.pi / 2, phi_1=np.pi / 2)
    a, e = arm.specular_spectra(30.0), ellipse.specular_spectra(30.0)
    np.testing.assert_allclose(a["R"], e["R"], rtol=1e-4, atol=1e-7)
    assert not a["TRT"].any()
    assert arm.scatterometer_image(30.0, resolution=16).shape == (16, 16, 3)
