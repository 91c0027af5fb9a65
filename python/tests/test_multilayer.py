"""Layered films from Python (columba.multilayer): one film is the Airy film, energy is conserved
without absorption, melanin absorbs, and bad layers are value errors."""
import numpy as np
import pytest

import columba

WL = np.arange(300.0, 831.0, 5.0)


def test_a_single_keratin_film_is_the_airy_film():
    for theta in (0.0, 30.0, 60.0):
        stack = columba.multilayer(theta, WL, [("keratin", 0.58)])
        film = columba.thin_film(theta, WL, 0.58)
        np.testing.assert_allclose(stack["R"], film["R"], atol=1e-6)
        np.testing.assert_allclose(stack["T"], film["T"], atol=1e-6)


def test_energy_is_conserved_without_absorption_and_melanin_absorbs():
    lossless = columba.multilayer(25.0, WL, [("keratin", 0.2), (1.0, 0.1), ("keratin", 0.2)])
    np.testing.assert_allclose(lossless["R"] + lossless["T"], 1.0, atol=1e-9)
    np.testing.assert_allclose(lossless["A"], 0.0, atol=1e-9)
    melanin = columba.multilayer(25.0, WL, [("keratin", 0.2), (1.7 + 0.3j, 0.2)], substrate_ior=1.56)
    assert np.all(melanin["A"] > 0.05) and np.all(melanin["A"] < 1.0)


def test_bad_layers_are_value_errors():
    with pytest.raises(ValueError, match="thickness"):
        columba.multilayer(0.0, 500.0, [("keratin", -0.1)])
    with pytest.raises(ValueError, match="index"):
        columba.multilayer(0.0, 500.0, [(1.5 - 0.1j, 0.1)])
    with pytest.raises(ValueError, match="layer"):
        columba.multilayer(0.0, 500.0, [("keratin",)])


def test_grazing_incidence_is_the_limit_and_bad_angles_and_wavelengths_are_value_errors():
    # 90 degrees gave NaN in Rp, R, Tp, T and A, a NaN angle NaN, a negative wavelength a result.
    m = columba.multilayer([89.999, 90.0], 500.0, [("keratin", 0.2), (1.7 + 0.3j, 0.1)], substrate_ior=1.33)
    np.testing.assert_array_equal([m["R"][1], m["Rs"][1], m["Rp"][1], m["T"][1], m["A"][1]], [1, 1, 1, 0, 0])
    assert m["R"][0] == pytest.approx(1.0, abs=1e-2)
    with pytest.raises(ValueError, match=r"theta_deg nan, wavelength 500 \(element 0\): the angle of incidence nan"):
        columba.multilayer(float("nan"), 500.0, [("keratin", 0.2)])
    with pytest.raises(ValueError, match=r"theta_deg 90.5, .*lies outside \[0, 90\]"):
        columba.multilayer(90.5, 500.0, [("keratin", 0.2)])
    for wavelength in (-500.0, 0.0, float("inf")):
        with pytest.raises(ValueError, match=f"the wavelength {wavelength:g} nm is not positive and finite"):
            columba.multilayer([10.0, 20.0], [500.0, wavelength], [("keratin", 0.2)])


def test_layer_text_is_the_stack_it_describes():
    # Plain layers as text and as a list: the same numbers.
    text = columba.multilayer(25.0, WL, "keratin:0.2, 1.7+0.3i:0.2, air:0.1")
    listed = columba.multilayer(25.0, WL, [("keratin", 0.2), (1.7 + 0.3j, 0.2), ("air", 0.1)])
    for key in ("R", "T", "A"):
        np.testing.assert_allclose(text[key], listed[key], rtol=1e-6, atol=1e-9)
    # Repeats and rows of rods as written out.
    rows = columba.multilayer(10.0, WL, "[rods(melanin, 0.11, 0.15), keratin:0.04] x 3")
    once = "rods(melanin, 0.11, 0.15), keratin:0.04"
    written = columba.multilayer(10.0, WL, ", ".join([once] * 3))
    np.testing.assert_allclose(rows["R"], written["R"], atol=1e-9)
    # The named stack peaks where the C++ test finds it (docs/model.md: 1281 nm).
    wl = np.arange(900.0, 1701.0)
    peak = wl[np.argmax(columba.multilayer(0.0, wl, "parotia-occipital")["R"])]
    assert abs(peak - 1281.0) <= 1.0
    with pytest.raises(ValueError, match="rods"):
        columba.multilayer(0.0, WL, "rods(melanin, 0.2, 0.1)")
