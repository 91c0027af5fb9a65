"""columba.fit and columba.fit_spectra: the fits of `columba fit`, the same numbers from Python."""
import json

import numpy as np
import pytest

import columba


def test_fit_recovers_the_film_and_matches_the_cli(cli, repo, tmp_path):
    scene = repo / "examples" / "fit_scatterometer.xml"
    truth = columba.render(columba.load_file(scene, res=24, spp=64, height=0.61), seed=3)
    target = tmp_path / "target.exr"
    columba.write_image(target, 1.7 * truth)
    args = dict(vary=["height=0.5:0.7:0.55"], defines={"res": "24"}, spp=32, max_evals=100, max_seconds=60)
    result = columba.fit(scene, columba.read_image(target), **args)
    assert result["values"]["height"] == pytest.approx(0.61, abs=0.003)
    assert result["scale"] == pytest.approx(1.7, rel=0.05)
    lo, hi = result["intervals"]["height"]
    assert lo <= result["values"]["height"] <= hi
    assert result["render"].shape == (24, 24, 3) and result["render"].dtype == np.float32
    # The command line finds the same values: one implementation.
    cli("fit", scene, "--target", target, "--vary", "height=0.5:0.7:0.55", "-D", "res=24", "--spp", 32,
        "--max-evals", 100, "--max-seconds", 60, "-o", tmp_path / "fit")
    record = json.loads((tmp_path / "fit" / "fit.json").read_text())
    fitted = {p["name"]: p["value"] for p in record["parameters"]}
    assert fitted["height"] == pytest.approx(result["values"]["height"], abs=1e-9)
    assert record["evaluations"] == result["evaluations"]
    # Each parameter's loss profile as vector figures too, for papers.
    assert (tmp_path / "fit" / "profile_height.pdf").read_bytes().startswith(b"%PDF-")
    assert b"<svg" in (tmp_path / "fit" / "profile_height.svg").read_bytes()


def test_fit_errors_are_python_exceptions(repo):
    scene = repo / "examples" / "fit_scatterometer.xml"
    with pytest.raises(Exception, match="NAME=LO:HI"):
        columba.fit(scene, np.zeros((4, 4, 3), np.float32), vary=["height"])
    with pytest.raises(ValueError, match="at least one parameter"):
        columba.fit(scene, np.zeros((4, 4, 3), np.float32), vary=[])


def test_fit_settings_are_checked_as_the_command_checks_them(repo, tmp_path):
    # max_evals=0, negative budgets, rises, threads and spp, a name varied twice or also fixed were
    # accepted; the fit library checks them for the command and Python alike.
    scene = repo / "examples" / "fit_scatterometer.xml"
    target = np.zeros((4, 4, 3), np.float32)
    vary = ["height=0.5:0.7"]
    for kwargs, message in [(dict(max_evals=0), "at least 3"), (dict(max_seconds=-1.0), "not -1"),
                            (dict(rise=-0.5), "rise must be positive"), (dict(threads=-1), "not -1"),
                            (dict(spp=-4), "not -4"), (dict(vary=vary * 2), "'height' is varied twice"),
                            (dict(defines={"height": "0.6"}), "'height' is both held fixed")]:
        args = dict(vary=vary, **kwargs) if "vary" not in kwargs else kwargs
        with pytest.raises(ValueError, match=message):
            columba.fit(scene, target, **args)
    spectra = tmp_path / "spectra.csv"
    spectra.write_text("theta_i,phi_i,theta_o,phi_o,wavelength_nm,reflectance\n10,0,10,180,500,0.2\n")
    for kwargs, message in [(dict(max_evals=0), "at least 3"), (dict(max_seconds=-1.0), "not -1"),
                            (dict(rise=-0.5), "rise must be positive")]:
        with pytest.raises(ValueError, match=message):
            columba.fit_spectra(spectra, vary=vary, **kwargs)
    with pytest.raises(ValueError, match="varied twice"):
        columba.fit_spectra(spectra, vary=vary * 2)


def test_fit_spectra_returns_the_model_with_its_wavelengths_and_directions(tmp_path):
    spectra = tmp_path / "spectra.csv"
    wavelengths = np.arange(400, 701, 20)
    measured = 0.1 + 0.3 * np.exp(-0.5 * ((wavelengths - 540) / 40.0) ** 2)
    rows = [f"{t},0,{t},180,{w},{r:.6f}" for t in (10, 30) for w, r in zip(wavelengths, measured)]
    spectra.write_text("theta_i,phi_i,theta_o,phi_o,wavelength_nm,reflectance\n" + "\n".join(rows) + "\n")
    r = columba.fit_spectra(spectra, ["height=0.5:0.7"], max_evals=30)
    model = r["model"]
    assert sorted(model) == ["measured", "phi_i", "phi_o", "reflectance", "theta_i", "theta_o", "wavelength_nm"]
    n = 2 * len(wavelengths)
    assert all(model[k].shape == (n,) for k in model)
    # One entry a sample, in the file's order: the model can be drawn against the data as it is.
    np.testing.assert_array_equal(model["wavelength_nm"], np.tile(wavelengths, 2).astype(np.float32))
    np.testing.assert_array_equal(model["theta_i"], np.repeat([10, 30], len(wavelengths)).astype(np.float32))
    np.testing.assert_array_equal(model["phi_o"], np.full(n, 180, np.float32))
    np.testing.assert_allclose(model["measured"], np.tile(measured, 2), rtol=1e-5)
    residual = r["scale"] * model["reflectance"].astype(np.float64) - model["measured"]
    assert np.mean(residual ** 2) == pytest.approx(r["loss"], rel=1e-4)


def test_fit_spectra_reads_a_two_column_spectrum_with_its_geometry_given():
    import pathlib

    example = pathlib.Path(__file__).resolve().parents[2] / "examples" / "two_column_spectrum.csv"
    r = columba.fit_spectra(str(example), ["height=0.4:0.8"], theta_i=[20.0])
    assert r["values"]["height"] == pytest.approx(0.55, abs=0.002)
    assert set(r["model"]["theta_o"]) == {20.0} and set(r["model"]["phi_o"]) == {180.0}
    assert len(r["solutions"]["height"]) >= 1
    with pytest.raises(ValueError, match="without directions"):
        columba.fit_spectra(str(example), ["height=0.4:0.8"])
    with pytest.raises(ValueError, match="geometry must be"):
        columba.fit_spectra(str(example), ["height=0.4:0.8"], theta_i=[20.0], geometry="side")
