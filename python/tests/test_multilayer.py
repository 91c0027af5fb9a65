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
