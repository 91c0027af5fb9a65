"""Thin film, Fresnel, dispersion and melanin through Python."""
import numpy as np
import pytest

import columba


def test_thin_film_broadcasts_and_is_consistent():
    theta = np.array([0, 20, 40, 60, 80])[:, None, None]
    lam = np.linspace(380, 780, 9)[None, :, None]
    d = np.array([0.0, 0.3, 0.6])[None, None, :]
    f = columba.thin_film(theta, lam, d)
    assert set(f) == {"Rs", "Rp", "R", "Ts", "Tp", "T"}
    for v in f.values():
        assert v.shape == (5, 9, 3) and v.dtype == np.float64
    # R (thinFilmReflectance) is the mean of the polarisations (thinFilmAmplitudes); a lossless
    # film between equal media reflects what it does not transmit; no film, no reflection.
    np.testing.assert_allclose(f["R"], (f["Rs"] + f["Rp"]) / 2, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(f["T"], (f["Ts"] + f["Tp"]) / 2, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(f["Rs"] + f["Ts"], 1, atol=1e-12)
    np.testing.assert_allclose(f["R"][..., 0], 0, atol=1e-12)
    np.testing.assert_allclose(f["Rs"][0], f["Rp"][0], atol=1e-12)


def test_thin_film_against_airy():
    # Airy at normal incidence for a free-standing film of index n: R = F s / (1 + F s),
    # F = 4 R12 / (1 - R12)^2, s = sin^2(2 pi n d / lambda).
    lam, d, n = np.linspace(400, 700, 31), 0.5, 1.5
    f = columba.thin_film(0, lam, d, film_ior=n, n_outside=1.0)
    r12 = ((n - 1) / (n + 1)) ** 2
    F = 4 * r12 / (1 - r12) ** 2
    s = np.sin(2 * np.pi * n * d * 1000 / lam) ** 2
    np.testing.assert_allclose(f["R"], F * s / (1 + F * s), rtol=1e-9)
    # A denser substrate changes the reflectance.
    assert not np.allclose(columba.thin_film(30, lam, d, substrate_ior=2.0)["R"], columba.thin_film(30, lam, d)["R"])
    np.testing.assert_allclose(columba.thin_film(0, 500, 0.2, film_ior=(1.5, 0))["R"],
                               columba.thin_film(0, 500, 0.2, film_ior=1.5)["R"])
    with pytest.raises(ValueError, match="unknown index of refraction 'glas'"):
        columba.thin_film(0, 500, 0.5, film_ior="glas")


def test_keratin_dispersion_and_named_indices():
    lam = np.array([400.0, 550.0, 700.0])
    n = columba.keratin_ior(lam)
    assert n.dtype == np.float32 and n.shape == (3,)
    np.testing.assert_allclose(n, 1.532 + 5890 / lam**2, rtol=1e-6)
    np.testing.assert_allclose(columba.ior("air", lam), 1.000277, rtol=1e-6)
    np.testing.assert_allclose(columba.ior((1.5, 4000), [[500]]), [[1.516]], rtol=1e-6)


def test_melanin_table():
    # Rows of the measured table (optics/melanin.cpp) and constant beyond its ends.
    r = columba.melanin_reflectance(np.array([249.7909, 501.3511, 200.0]))
    np.testing.assert_allclose(r, [0.0300, 0.0496, 0.0300], rtol=1e-5)
    assert columba.melanin_reflectance(550.0) == pytest.approx(float(columba.melanin_reflectance([550.0])[0]))


def test_fresnel():
    eta = 1.5
    assert columba.fresnel(1.0, eta) == pytest.approx(((eta - 1) / (eta + 1)) ** 2, rel=1e-6)
    cos = np.linspace(0.05, 1, 20)
    a = columba.fresnel_amplitudes(cos, eta)
    np.testing.assert_allclose(columba.fresnel(cos, eta), (a["rs"] ** 2 + a["rp"] ** 2) / 2, rtol=1e-5)
    # Arriving from inside: total internal reflection beyond the critical angle.
    assert columba.fresnel(-0.1, eta) == pytest.approx(1.0)
    assert columba.fresnel_amplitudes(0.1, 1 / eta)["total_internal_reflection"]
    assert not a["total_internal_reflection"].any()
