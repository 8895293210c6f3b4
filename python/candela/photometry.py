"""Photometric files (IES LM-63 of every version, EULUMDAT): read, summarise,
evaluate, write."""

from __future__ import annotations

import ctypes
import math
import os
from typing import NamedTuple, Optional, Union

import numpy as np

from . import _capi
from ._handle import Owned
from ._capi import lib
from .errors import InputError, UsageError, check

ArrayLike = Union[float, "np.typing.ArrayLike"]

_FORMATS = {
    _capi.CDL_PHOTOMETRY_FORMAT_TABLE: "table",
    _capi.CDL_PHOTOMETRY_FORMAT_IES: "IES",
    _capi.CDL_PHOTOMETRY_FORMAT_EULUMDAT: "EULUMDAT",
}

# write(format=...): the names accepted, and the file extensions that imply them.
_WRITE_FORMATS = {
    "ies": _capi.CDL_PHOTOMETRY_FORMAT_IES,
    "ldt": _capi.CDL_PHOTOMETRY_FORMAT_EULUMDAT,
    "eulumdat": _capi.CDL_PHOTOMETRY_FORMAT_EULUMDAT,
}


class PhotometryWarning(NamedTuple):
    """What a checker expects and the file does not give: a stable `code`
    (docs/photometry-warnings.md lists them), the file's `line` (None when
    the warning is about the file as a whole) and the `message`."""

    code: str
    line: Optional[int]
    message: str


def _known(flag: int, value: float) -> Optional[float]:
    """A figure the library marks as known and finite, else None."""
    return float(value) if flag and math.isfinite(value) else None


def _angles(values, about_peak: bool) -> dict[str, Optional[float]]:
    """Beam or field angles by plane, keyed as `candela info --json` keys
    them; None where undefined (the library's -1)."""
    keys = ("vertical_plane", "across") if about_peak else ("c0_c180", "c90_c270")
    return {k: (float(v) if v >= 0.0 else None) for k, v in zip(keys, values)}


class Photometry(Owned):
    """A luminaire's photometric file, read by libcandela.

    Every flux and intensity is the luminaire's as it lights a scene: the
    table times its output (ballast) factor, as `candela solve` applies it
    and `candela info` prints it (`table_flux_lm` is the table's own
    integral). A radiometric file (its table in W/sr: UV and infrared) has
    no lumens and no candela: its `flux_lm`, `max_intensity_cd` and
    `efficacy_lm_per_w` are None, `radiant_flux_w` and
    `max_radiant_intensity_w_sr` hold its figures, and `intensity()` refuses
    it in favour of `radiant_intensity()`.

    Attributes:
        path: the file as given.
        format: "IES" or "EULUMDAT".
        ies_version: 1986, 1991, 1995, 2002 or 2019 for an IES file, else None.
        radiometric: True when the table is radiant intensity (W/sr).
        output_factor: the ballast factor (times LM-63-1995's ballast-lamp factor).
        flux_lm: luminous flux in lumens, the exact integral of the
            interpolated table times the output factor; None when radiometric.
        table_flux_lm: the table's own integral in lumens; None when radiometric.
        radiant_flux_w: radiant flux in watts of a radiometric file; None otherwise.
        lamp_flux_lm: the rated lamp flux (all lamps); None for absolute
            photometry and radiometric files.
        lor: light output ratio, flux / lamp flux; None when unknown.
        max_intensity_cd: the largest tabulated intensity times the output
            factor, in candela; None when radiometric.
        max_radiant_intensity_w_sr: its counterpart for a radiometric file, in W/sr.
        beam_angle_deg, field_angle_deg: full angles in degrees where the
            intensity falls to 50 % (10 %) of the peak, by plane: keys
            "c0_c180" and "c90_c270" when measured through nadir,
            "vertical_plane" and "across" when about an off-nadir peak
            (`spread_about`); None where undefined.
        spread_about: "nadir" or "peak".
        downward_fraction, upward_fraction: shares of the flux below and
            above the horizontal.
        input_watts: the input power the file states, W; None when unknown.
        efficacy_lm_per_w: flux / input watts; None when unknown or radiometric.
        manufacturer, luminaire, catalogue, lamp: what the file names ("" if nothing).
        warnings: what a checker expects and the file does not give.
    """

    _release = "cdl_photometry_release"

    def __init__(self, handle: int, path: str):
        self._own(handle)
        self.path = path
        self._what = f"{path}: the photometry"
        s = _capi.sized(_capi.cdl_photometry_summary)
        lib.cdl_photometry_summarize(handle, ctypes.byref(s))
        self.format = _FORMATS.get(lib.cdl_photometry_get_format(handle), "table")
        self.ies_version = lib.cdl_photometry_ies_version(handle) or None
        self.radiometric = bool(s.radiometric)
        luminous = not self.radiometric
        self.output_factor = float(s.output_factor)
        self.flux_lm = _known(luminous, s.luminaire_flux)
        self.table_flux_lm = _known(luminous, s.flux)
        self.radiant_flux_w = _known(self.radiometric, s.radiant_flux * s.output_factor)
        self.lamp_flux_lm = _known(s.lamp_flux_known and luminous, s.lamp_flux)
        self.lor = _known(s.lor_known, s.lor)
        self.max_intensity_cd = _known(luminous, s.luminaire_max_intensity)
        self.max_radiant_intensity_w_sr = _known(self.radiometric, s.max_radiant_intensity * s.output_factor)
        self.beam_angle_deg = _angles(s.beam_angle_deg, bool(s.spread_about_peak))
        self.field_angle_deg = _angles(s.field_angle_deg, bool(s.spread_about_peak))
        self.spread_about = "peak" if s.spread_about_peak else "nadir"
        self.downward_fraction = float(s.downward_fraction)
        self.upward_fraction = float(s.upward_fraction)
        watts = lib.cdl_photometry_input_watts(handle)
        self.input_watts = float(watts) if watts > 0.0 else None
        self.efficacy_lm_per_w = _known(s.efficacy_known and luminous, s.efficacy)
        self.manufacturer = _capi.text(lib.cdl_photometry_get_text(handle, _capi.CDL_PHOTOMETRY_MANUFACTURER))
        self.luminaire = _capi.text(lib.cdl_photometry_get_text(handle, _capi.CDL_PHOTOMETRY_LUMINAIRE))
        self.catalogue = _capi.text(lib.cdl_photometry_get_text(handle, _capi.CDL_PHOTOMETRY_CATALOGUE))
        self.lamp = _capi.text(lib.cdl_photometry_get_text(handle, _capi.CDL_PHOTOMETRY_LAMP))
        self.warnings = [
            PhotometryWarning(
                code=_capi.text(lib.cdl_photometry_warning_code(handle, i)),
                line=lib.cdl_photometry_warning_line(handle, i) or None,
                message=_capi.text(lib.cdl_photometry_warning(handle, i)),
            )
            for i in range(lib.cdl_photometry_warning_count(handle))
        ]
        # W/sr per table unit of a radiometric file (1e-3 for a table in
        # mW/sr): the summary's peak in W/sr over the table's own peak.
        table_max = lib.cdl_photometry_max_intensity(handle).value
        self._radiant_scale = s.max_radiant_intensity / table_max if self.radiometric and table_max > 0.0 else 1.0

    def __repr__(self) -> str:
        flux = f"{self.radiant_flux_w:.6g} W" if self.radiometric else f"{self.flux_lm:.6g} lm"
        return f"<candela.Photometry {self.path!r} {self.format} {flux}>"

    def _evaluate(self, c_deg: ArrayLike, gamma_deg: ArrayLike, scale: float):
        c, g = np.broadcast_arrays(np.asarray(c_deg, dtype=float), np.asarray(gamma_deg, dtype=float))
        if not (np.all(np.isfinite(c)) and np.all(np.isfinite(g))):
            raise UsageError(f"{self.path}: intensity: expected finite angles in degrees, found NaN or infinity")
        out = np.empty(c.shape, dtype=float)
        flat = out.reshape(-1)
        fn = lib.cdl_photometry_intensity_c_gamma
        with self._use() as handle:
            for i, (a, b) in enumerate(zip(c.reshape(-1).tolist(), g.reshape(-1).tolist())):
                flat[i] = fn(handle, a, b).value
        out *= scale
        return float(out) if out.ndim == 0 else out

    def intensity(self, c_deg: ArrayLike, gamma_deg: ArrayLike):
        """Luminous intensity in candela towards (C, gamma) in degrees (type C
        angles of the photometric frame: gamma from nadir, C counter-clockwise
        from +x seen from above, whatever the table's type), interpolated
        bilinearly as the solver does, times the output factor. Scalars give
        a float; arrays (broadcast against each other) an array of their
        shape. Raises InputError for a radiometric file (no candela: see
        radiant_intensity) and UsageError for NaN or infinite angles."""
        if self.radiometric:
            raise InputError(
                f"{self.path}: the table is radiant intensity (W/sr), not candela: use radiant_intensity()"
            )
        return self._evaluate(c_deg, gamma_deg, self.output_factor)

    def radiant_intensity(self, c_deg: ArrayLike, gamma_deg: ArrayLike):
        """Radiant intensity in W/sr of a radiometric file, as intensity()
        evaluates candela. Raises InputError for a photometric file, whose
        watts need a spectrum."""
        if not self.radiometric:
            raise InputError(
                f"{self.path}: the table is luminous intensity (cd); its radiant intensity needs a spectrum: "
                "use intensity()"
            )
        return self._evaluate(c_deg, gamma_deg, self.output_factor * self._radiant_scale)

    def write(self, path: Union[str, os.PathLike], format: Optional[str] = None, ies_version: int = 2019) -> list[str]:
        """Write the file as IES LM-63 (`ies_version` 2019 or 2002) or EULUMDAT,
        atomically; `format` "ies", "ldt" (or "eulumdat"), or None to take it
        from the extension (.ies, .ldt). Returns what the format could not
        hold, one line each (EULUMDAT has no ballast factor: it is folded
        into the lamp flux, and said so). Raises InputError when the file
        cannot be written (a radiometric table as EULUMDAT, a folder that
        does not exist) and UsageError for an unknown format."""
        if format is None:
            ext = os.path.splitext(os.fspath(path))[1].lower().lstrip(".")
            if ext not in _WRITE_FORMATS:
                raise UsageError(f"{os.fspath(path)}: expected the extension .ies or .ldt, or format='ies' or 'ldt'")
            code = _WRITE_FORMATS[ext]
        elif isinstance(format, str) and format.lower() in _WRITE_FORMATS:
            code = _WRITE_FORMATS[format.lower()]
        else:
            raise UsageError(f"write: format: expected 'ies', 'ldt' or None, found {format!r}")
        options = _capi.sized(_capi.cdl_photometry_write_options)
        options.ies_version = int(ies_version)
        notes = _capi.cdl_photometry_notes()
        err = _capi.cdl_error()
        with self._use() as handle:
            st = lib.cdl_photometry_write_file(
                handle, _capi.encode_path(path), code, ctypes.byref(options), ctypes.byref(notes), ctypes.byref(err)
            )
        try:
            lost = [_capi.text(notes.items[i]) for i in range(notes.count)]
        finally:
            lib.cdl_photometry_notes_free(ctypes.byref(notes))
        check(st, err)
        return lost


def read_photometry(path: Union[str, os.PathLike], strict: bool = False) -> Photometry:
    """Read an IES (any LM-63 version) or EULUMDAT file; the format is found
    from the content. With strict=True, warnings (inconsistent header
    values) are errors. Raises InputError naming the file and line."""
    options = _capi.sized(_capi.cdl_photometry_read_options)
    options.strict = 1 if strict else 0
    handle = ctypes.c_void_p()
    err = _capi.cdl_error()
    st = lib.cdl_photometry_read_file(
        _capi.encode_path(path), ctypes.byref(options), ctypes.byref(handle), ctypes.byref(err)
    )
    check(st, err)
    return Photometry(handle.value, os.fspath(path))
