"""Columba from Python: render scenes to numpy arrays and evaluate the barbule model.

Everything is computed by Columba's C++ library (the extension ``columba._columba``); this
module only adapts arguments. See docs/python.md for the API with examples.
"""
import functools as _functools
import numbers as _numbers
import os as _os
import tempfile as _tempfile
import warnings as _warnings

try:
    import numpy as _np

    from ._columba import (  # noqa: F401
        BARB_VERTICES,
        COLOUR_BLEND,
        GREEN_CORTEX_THICKNESS,
        PURPLE_BELOW,
        PURPLE_CORTEX_THICKNESS,
        BarbuleArmsBSDF,
        BarbuleBSDF,
        ColumbaWarning,
        InputError,
        Scene,
        __version__,
        colour_distance,
        cone_catches,
        direction,
        fresnel,
        human_colour_difference,
        melanin_reflectance,
        observer,
        observers,
        presets,
        from_srgb,
        to_srgb,
    )
except ImportError as _error:
    import sys as _sys

    from ._built_for import INTERPRETER as _BUILT_FOR

    raise ImportError(
        f"columba was built for {_BUILT_FOR} (Debian's Python, with python3-numpy), and this Python "
        f"({_sys.executable}) cannot load it: {_error}. Run {_BUILT_FOR}, or the build's "
        "columba-python (build/columba-python), which runs it with this package found."
    ) from _error
from . import _columba  # noqa: E402

__all__ = [
    "load_file", "load_string", "load_default", "render", "write_image", "read_image", "read_cones",
    "BarbuleBSDF", "BarbuleArmsBSDF", "presets", "direction", "thin_film", "ior", "keratin_ior", "melanin_reflectance",
    "fresnel", "fresnel_amplitudes", "multilayer", "generate_feathers", "read_feather_ply", "write_feather_ply", "feather_barbs",
    "Scene", "InputError", "ColumbaWarning", "to_srgb", "from_srgb", "fit", "fit_spectra",
    "observers", "observer", "cone_catches", "colour_distance", "human_colour_difference",
]


def _define_text(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)
    return str(value)


def _defines(defines, extra=None):
    merged = dict(extra or {})
    merged.update(defines)
    return {name: _define_text(value) for name, value in merged.items()}


def _warn_unused(scene, defines):
    for name in scene.unused_defines:
        _warnings.warn(f"{name}={defines[name]}: the scene uses no variable ${name}, so it has no effect",
                       ColumbaWarning, stacklevel=3)


def _reissue_warnings():
    """Columba's warnings about what was just loaded, rendered or fitted (also printed on stderr)
    as Python warnings of category ColumbaWarning, so that a notebook shows them."""
    for text in _columba._take_warnings():
        _warnings.warn(text, ColumbaWarning, stacklevel=3)


def load_file(path, defines=None, **kwargs):
    """Loads a Mitsuba-style scene file; keyword arguments (and the dict `defines`, for names
    that are not Python identifiers) set its $variables, as -D name=value does.

    Malformed input raises columba.InputError (a ValueError) with the CLI's file:line message.
    """
    d = _defines(kwargs, defines)
    try:
        scene = _columba._load_file(_os.fspath(path), d)
    finally:
        _reissue_warnings()
    _warn_unused(scene, d)
    return scene


def load_string(xml, base_dir=None, name="<string>", defines=None, **kwargs):
    """Loads a scene from XML text; relative file names resolve against base_dir (default: the
    current directory), messages name it `name`; $variables as for load_file."""
    d = _defines(kwargs, defines)
    try:
        scene = _columba._load_string(xml, name, _os.fspath(base_dir) if base_dir is not None else _os.getcwd(), d)
    finally:
        _reissue_warnings()
    _warn_unused(scene, d)
    return scene


def load_default(defines=None, **kwargs):
    """The scene `columba render` draws without a scene file (a generated rock dove)."""
    d = _defines(kwargs, defines)
    try:
        scene = _columba._load_default(d)
    finally:
        _reissue_warnings()
    _warn_unused(scene, d)
    return scene


def render(scene, spp=None, seed=0, threads=None, stats=False, adaptive=False, target_error=None):
    """Renders `scene` to an H x W x 3 float32 array of linear Rec.709 RGB.

    spp overrides the scene sampler's sample count; the same seed and spp give the same image
    (bit for bit, the CLI's too) for any number of threads (default: all cores). The GIL is
    released while rendering; Ctrl-C stops the render and raises KeyboardInterrupt. With
    stats=True returns (image, dict of seconds, samples, rays, ...).

    adaptive=True (as `columba render --adaptive`) makes spp the mean budget per pixel, spent
    where the pilot's neighbouring samples vary most; target_error (e.g. 0.02, implies adaptive)
    stops at the budget its plan predicts for that relative RMSE. The stats then also hold the
    pilot, the fewest and most samples per pixel and the predicted relative error. A scene whose
    film has a bird's observer (docs/vision.md) adds "cones": its cone catches as a dict of H x W
    arrays named after the cones.
    """
    if spp is not None and spp < 1:
        raise ValueError(f"spp must be between 1 and {1 << 24}, not {spp}")
    if threads is not None and threads < 1:
        raise ValueError(f"threads must be between 1 and 65536, not {threads}")
    try:
        image, info = _columba._render(scene, 0 if spp is None else int(spp), int(seed),
                                       0 if threads is None else int(threads), bool(adaptive),
                                       0.0 if target_error is None else float(target_error))
    finally:
        _reissue_warnings()
    return (image, info) if stats else image


def _reissuing(function):
    """`function` of the extension, followed by _reissue_warnings whether it returns or raises."""
    @_functools.wraps(function)
    def call(*args, **kwargs):
        try:
            return function(*args, **kwargs)
        finally:
            _reissue_warnings()
    return call


fit = _reissuing(_columba.fit)
fit_spectra = _reissuing(_columba.fit_spectra)


def write_image(path, image):
    """Writes an H x W x 3 array of linear RGB as .exr (float32) or .png (8-bit sRGB, clamped),
    through a temporary file renamed into place."""
    _columba.write_image(_os.fspath(path), image)


def read_feather_ply(path):
    """A feather PLY's faces (the rachis and barbs, 64 vertices each) as arrays: positions and
    normals (B x 64 x 3), H, mu and height (B x 64, in the file's convention, or None), stack (B x
    64 uint8, each vertex's layer stack, or None) and the recorded barb_width (or None)."""
    return _columba.read_feather_ply(_os.fspath(path))


def read_image(path, spectral=False):
    """Reads an .exr or .png image as an H x W x 3 float32 array (linear values). With
    spectral=True returns (rgb, wavelength bin centres or None, H x W x K bands or None)."""
    rgb, centres, bands = _columba._read_image(_os.fspath(path))
    return (rgb, centres, bands) if spectral else rgb


def read_cones(path):
    """The cone catches an .exr image records (a render whose film has a bird's observer) as a dict
    of H x W float32 arrays named after the cones (UVS or VS, SWS, MWS, LWS, DBL); empty for
    images without them."""
    return _columba._read_cones(_os.fspath(path))


def thin_film(theta_deg, wavelength, thickness, film_ior="keratin", n_outside=1.000277, substrate_ior=None):
    """Airy thin-film intensity reflectance and transmittance.

    theta_deg: angle of incidence (degrees) in the outer medium; wavelength in nm; thickness in µm;
    all broadcast against each other. film_ior: "keratin", a named index, a number or (a, b) of
    Cauchy's law; substrate_ior: the medium behind the film (default: the outer medium).
    Returns a dict of float64 arrays Rs, Rp, R (their mean), Ts, Tp, T.
    """
    t, w, d = _np.broadcast_arrays(_np.asarray(theta_deg, dtype=_np.float64), _np.asarray(wavelength, dtype=_np.float64),
                                   _np.asarray(thickness, dtype=_np.float64))
    shape = t.shape
    out = _columba._thin_film(t.ravel(), w.ravel(), d.ravel(), film_ior, float(n_outside), substrate_ior)
    return {k: v.reshape(shape) for k, v in out.items()}


def multilayer(theta_deg, wavelength, layers, n_outside=1.000277, substrate_ior=1.000277):
    """Intensity reflectance and transmittance of a stack of plane layers (transfer matrices).

    theta_deg: angle of incidence (degrees) in the outer medium, within [0, 90] (at 90, grazing, the
    limit R = 1, T = 0); wavelength in nm, positive; both broadcast. Others (NaN included) raise a
    ValueError naming theta_deg and wavelength.
    layers: a list of (index, thickness_um) from the outer side; an index is a complex number
    n + ik (k > 0 absorbs), "keratin", "melanin" (Stavenga et al. 2015's n(lambda) + i k(lambda)),
    a named index, a number or Cauchy's (a, b). Or the text a barbule BSDF's `layers` takes, e.g.
    "[rods(melanin, 0.11, 0.15), keratin:0.04] x 9" or "parotia-occipital".
    substrate_ior: the medium behind the stack (complex allowed). Returns a dict of float64 arrays
    Rs, Rp, R, Ts, Tp, T and A (absorbed, 1 - R - T).
    """
    t, w = _np.broadcast_arrays(_np.asarray(theta_deg, dtype=_np.float64), _np.asarray(wavelength, dtype=_np.float64))
    out = _columba._multilayer(t.ravel(), w.ravel(), layers if isinstance(layers, str) else list(layers), n_outside,
                               substrate_ior)
    return {k: v.reshape(t.shape) for k, v in out.items()}


def ior(index, wavelength):
    """Refractive index at wavelength (nm): index "keratin", a named index, a number or (a, b)."""
    w = _np.asarray(wavelength, dtype=_np.float32)
    return _columba._ior(index, w.ravel()).reshape(w.shape)


def keratin_ior(wavelength):
    """Feather keratin: n = 1.532 + 5890 / lambda^2 (lambda in nm)."""
    return ior("keratin", wavelength)


def fresnel_amplitudes(cos_i, eta):
    """Fresnel amplitude coefficients rs, rp, ts, tp, the refracted cosine cos_t and
    total_internal_reflection, broadcast over cos_i and eta = n_t / n_i."""
    c, e = _np.broadcast_arrays(_np.asarray(cos_i, dtype=_np.float32), _np.asarray(eta, dtype=_np.float32))
    out = _columba._fresnel_amplitudes(c.ravel(), e.ravel())
    return {k: v.reshape(c.shape) for k, v in out.items()}


def generate_feathers(path, neck=False, feathers=None, barbs=None, seed=1, binary=False,
                      height=GREEN_CORTEX_THICKNESS, purple_height=None, height_spread=0.0, purple_below=None,
                      colour_blend=None, purple_stack=None):
    """Writes procedural feathers as a feather PLY (as `columba feather`): one feather, or with
    neck=True a neck of `feathers` (60) feathers. barbs: per side (default: edge to edge).
    The colour: height, the cortex thickness of the green barbules (a single feather's, µm);
    height_spread, how much each feather's thickness varies (±, µm); on a neck purple_height
    (PURPLE_CORTEX_THICKNESS), the purple barbules' thickness, purple_below (PURPLE_BELOW), the
    height y on the neck around which green turns purple, and colour_blend (COLOUR_BLEND), the
    width of that change on either side (0: sharp), and purple_stack (1 to 15, or None), the layer
    stack the purple barbules choose (written per vertex as `stack`; docs/feather-ply.md).
    Returns a summary dict (feathers, barbs, faces, vertices, tiling_barb_width)."""
    for name, value in (("feathers", feathers), ("purple_height", purple_height), ("purple_below", purple_below),
                        ("colour_blend", colour_blend), ("purple_stack", purple_stack)):
        if value is not None and not neck:
            raise ValueError(f"{name} applies to a neck (neck=True)")
    if feathers is not None and feathers < 1:
        raise ValueError(f"feathers must be positive, not {feathers}")
    if barbs is not None and barbs < 1:
        raise ValueError(f"barbs must be positive, not {barbs}")
    if purple_stack is not None and not (isinstance(purple_stack, _numbers.Integral) and not isinstance(purple_stack, bool)
                                         and 1 <= purple_stack <= 15):
        raise ValueError(f"purple_stack must be a whole number from 1 to 15, not {purple_stack}")
    return _columba._generate_feathers(
        _os.fspath(path), bool(neck), 60 if feathers is None else int(feathers), 0 if barbs is None else int(barbs),
        int(seed), bool(binary), float(height), float(PURPLE_CORTEX_THICKNESS if purple_height is None else purple_height),
        float(height_spread), float(PURPLE_BELOW if purple_below is None else purple_below),
        float(COLOUR_BLEND if colour_blend is None else colour_blend), 0 if purple_stack is None else int(purple_stack))


def write_feather_ply(path, barbs, binary=False):
    """Writes a feather PLY from arrays as read_feather_ply returns them (a dict, or anything with
    those keys): positions and normals (B x 64 x 3), H, mu and height (B x 64, the file's
    convention, all three or None), stack (B x 64 whole numbers 0 to 255, the barbule BSDF's layer
    stack at each vertex; optional) and barb_width (or None). read_feather_ply reads back the same."""
    positions = _np.ascontiguousarray(barbs["positions"], dtype=_np.float32)
    normals = _np.ascontiguousarray(barbs["normals"], dtype=_np.float32)
    if positions.ndim != 3 or positions.shape[1:] != (BARB_VERTICES, 3) or normals.shape != positions.shape:
        raise ValueError(f"positions and normals must both be B x {BARB_VERTICES} x 3, not {positions.shape} and "
                         f"{normals.shape}")
    values = [barbs.get(name) for name in ("H", "mu", "height")]
    if any(v is None for v in values) and not all(v is None for v in values):
        raise ValueError("give all of H, mu and height, or none of them")
    if values[0] is not None:
        values = [_np.ascontiguousarray(v, dtype=_np.float32) for v in values]
        for name, v in zip(("H", "mu", "height"), values):
            if v.shape != positions.shape[:2]:
                raise ValueError(f"{name} must be B x {BARB_VERTICES} ({positions.shape[:2]}), not {v.shape}")
    for name, v in [("positions", positions), ("normals", normals)] + list(zip(("H", "mu", "height"), values)):
        if v is not None and not _np.all(_np.isfinite(v)):
            raise ValueError(f"{name} must be finite numbers")
    if values[0] is not None and not (_np.all(values[0] > 0) and _np.all(values[2] >= 0)):
        raise ValueError("H must be positive and height at least 0 (docs/feather-ply.md)")
    stack = barbs.get("stack")
    if stack is not None:
        stack = _np.asarray(stack)
        if stack.dtype.kind not in "iuf":
            raise ValueError(f"stack must hold whole numbers from 0 to 255, not values of type {stack.dtype}")
        if stack.shape != positions.shape[:2]:
            raise ValueError(f"stack must be B x {BARB_VERTICES} ({positions.shape[:2]}), not {stack.shape}")
        if not (_np.all(_np.isfinite(stack)) and _np.all(stack == _np.floor(stack)) and _np.all(stack >= 0)
                and _np.all(stack <= 255)):
            raise ValueError("stack must hold whole numbers from 0 to 255")
        stack = _np.ascontiguousarray(stack, dtype=_np.uint8)
    width = barbs.get("barb_width")
    if width is not None and not (_np.isfinite(width) and width > 0):
        raise ValueError(f"barb_width must be positive, not {width}")
    _columba._write_feather_ply(_os.fspath(path), positions, normals, values[0], values[1], values[2], stack,
                                None if width is None else float(width), bool(binary))


def feather_barbs(neck=False, feathers=None, barbs=None, seed=1):
    """The generator's feathers as arrays (see read_feather_ply): positions, normals, H, mu,
    height per barb vertex (B x 64 [x 3])."""
    with _tempfile.TemporaryDirectory() as tmp:
        path = _os.path.join(tmp, "feathers.ply")
        generate_feathers(path, neck=neck, feathers=feathers, barbs=barbs, seed=seed, binary=True)
        return read_feather_ply(path)
