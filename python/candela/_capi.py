"""libcandela's public C API as ctypes sees it: the library found and loaded,
its structs, enums and function prototypes.

Every declaration here mirrors one in the installed headers
(include/candela/candela.h and the headers it includes) of the ABI version
ABI_VERSION; nothing internal is used. Structs are declared whole, field by
field in the header's order (the test tests/python/test_layout.py compiles a
program against the installed headers and holds every field's offset and
every struct's size here to the compiler's).

ctypes.CDLL releases the GIL around every foreign call, so a solve running in
one thread leaves the others free to run Python (tests/python/test_cancel.py
checks it).
"""

from __future__ import annotations

import ctypes
import os
from ctypes import (
    CFUNCTYPE,
    POINTER,
    Structure,
    c_char,
    c_char_p,
    c_double,
    c_int,
    c_size_t,
    c_uint,
    c_uint64,
    c_void_p,
)
from typing import Optional

# The ABI version these declarations are written for: the N of
# libcandela.so.N. It moves whenever a public struct or signature changes,
# and so must this file (tests/python holds it to CMakeLists.txt's).
ABI_VERSION = 7

LIBRARY_NAME = f"libcandela.so.{ABI_VERSION}"

# ---------------------------------------------------------------------------
# base/error.h

CDL_OK = 0
CDL_ERR_INPUT = 1
CDL_ERR_USAGE = 2
CDL_ERR_INTERNAL = 3
CDL_ERR_CANCELLED = 4

CDL_ERROR_MESSAGE_SIZE = 1024


class cdl_error(Structure):
    _fields_ = [("status", c_int), ("message", c_char * CDL_ERROR_MESSAGE_SIZE)]


# ---------------------------------------------------------------------------
# radiometry/units.h and vec3.h: a quantity is a struct of one double (its
# layout that of a double; as a return value it is declared as the struct).


class cdl_quantity(Structure):
    _fields_ = [("value", c_double)]


class cdl_vec3(Structure):
    _fields_ = [("x", c_double), ("y", c_double), ("z", c_double)]


# ---------------------------------------------------------------------------
# lights/photometry/photometry.h

CDL_PHOTOMETRY_FORMAT_TABLE = 0
CDL_PHOTOMETRY_FORMAT_IES = 1
CDL_PHOTOMETRY_FORMAT_EULUMDAT = 2

CDL_PHOTOMETRY_MANUFACTURER = 0
CDL_PHOTOMETRY_LUMINAIRE = 1
CDL_PHOTOMETRY_CATALOGUE = 2
CDL_PHOTOMETRY_LAMP = 3


class cdl_photometry_read_options(Structure):
    _fields_ = [("size", c_size_t), ("strict", c_int), ("no_external_files", c_int)]


class cdl_photometry_write_options(Structure):
    _fields_ = [("size", c_size_t), ("ies_version", c_int), ("file_name", c_char_p)]


class cdl_photometry_notes(Structure):
    _fields_ = [("count", c_size_t), ("items", POINTER(c_char_p))]


# The unit-typed fields (cdl_luminous_flux, ...) are one double each.
class cdl_photometry_summary(Structure):
    _fields_ = [
        ("size", c_size_t),
        ("flux", c_double),
        ("downward_flux", c_double),
        ("upward_flux", c_double),
        ("zone_flux", c_double * 18),
        ("downward_fraction", c_double),
        ("lamp_flux_known", c_int),
        ("lamp_flux", c_double),
        ("lor_known", c_int),
        ("lor", c_double),
        ("max_intensity", c_double),
        ("max_c_deg", c_double),
        ("max_gamma_deg", c_double),
        ("max_h_deg", c_double),
        ("max_v_deg", c_double),
        ("beam_angle_deg", c_double * 2),
        ("field_angle_deg", c_double * 2),
        ("efficacy_known", c_int),
        ("efficacy", c_double),
        ("spread_about_peak", c_int),
        ("spread_axis_c_deg", c_double),
        ("spread_axis_gamma_deg", c_double),
        ("radiometric", c_int),
        ("radiant_flux", c_double),
        ("max_radiant_intensity", c_double),
        ("radiant_zone_flux", c_double * 18),
        ("output_factor", c_double),
        ("luminaire_flux", c_double),
        ("luminaire_max_intensity", c_double),
        ("upward_fraction", c_double),
    ]


# ---------------------------------------------------------------------------
# solver/scene/scene.h, progress.h, solution.h, solve_options.h, solution_write.h

METHODS = {"auto": 0, "direct": 1, "icache": 2, "pathtrace": 3}
QUALITIES = {"draft": 0, "normal": 1, "high": 2, "reference": 3}

# cdl_grid_quantity
CDL_GRID_E = 0
CDL_GRID_E_DIRECT = 1
CDL_GRID_E_INDIRECT = 2
CDL_GRID_E_STDERR = 3
CDL_GRID_AO = 4
CDL_GRID_AO_STDERR = 5
CDL_GRID_EZ = 6
CDL_GRID_EZ_STDERR = 7
CDL_GRID_ESZ = 8
CDL_GRID_ESZ_STDERR = 9
CDL_GRID_L = 10


class cdl_progress(Structure):
    _fields_ = [
        ("stage", c_char_p),
        ("done", c_size_t),
        ("total", c_size_t),
        ("records", c_size_t),
        ("elapsed_seconds", c_double),
    ]


cdl_progress_fn = CFUNCTYPE(c_int, c_void_p, POINTER(cdl_progress))


class cdl_progress_sink(Structure):
    _fields_ = [("fn", cdl_progress_fn), ("user", c_void_p)]


class cdl_solve_options(Structure):
    _fields_ = [
        ("size", c_size_t),
        ("threads", c_int),
        ("progress", cdl_progress_sink),
        ("cache_path", c_char_p),
        ("method", c_int),
        ("quality", c_int),
        ("target_error", c_double),
    ]


class cdl_grid_summary(Structure):
    _fields_ = [
        ("size", c_size_t),
        ("count", c_size_t),
        ("area_m2", c_double),
        ("E_avg_lx", c_double),
        ("E_min_lx", c_double),
        ("E_max_lx", c_double),
        ("U0", c_double),
        ("Ud", c_double),
        ("stderr_mean_rel", c_double),
        ("stderr_max_rel", c_double),
    ]


class cdl_solution_info(Structure):
    _fields_ = [
        ("size", c_size_t),
        ("method", c_int),
        ("quality", c_int),
        ("target_error", c_double),
        ("seed", c_uint64),
        ("threads", c_int),
        ("seconds", c_double),
        ("compute_seconds", c_double),
        ("rays", c_uint64),
        ("records", c_uint64),
        ("records_gathered", c_uint64),
        ("cache_reused", c_int),
        ("installed_w", c_double),
        ("luminaires_with_watts", c_size_t),
        ("luminaires_without_watts", c_size_t),
    ]


class cdl_solution_write_options(Structure):
    _fields_ = [("size", c_size_t), ("ocio_config", c_char_p), ("map_log_scale", c_int)]


# The structs whose layout tests/python/test_layout.py checks, by C name.
STRUCTS = [
    cdl_error,
    cdl_vec3,
    cdl_photometry_read_options,
    cdl_photometry_write_options,
    cdl_photometry_notes,
    cdl_photometry_summary,
    cdl_progress,
    cdl_progress_sink,
    cdl_solve_options,
    cdl_grid_summary,
    cdl_solution_info,
    cdl_solution_write_options,
]

# The enum values used here, by C name (checked the same way).
CONSTANTS = {
    "CDL_OK": CDL_OK,
    "CDL_ERR_INPUT": CDL_ERR_INPUT,
    "CDL_ERR_USAGE": CDL_ERR_USAGE,
    "CDL_ERR_INTERNAL": CDL_ERR_INTERNAL,
    "CDL_ERR_CANCELLED": CDL_ERR_CANCELLED,
    "CDL_ERROR_MESSAGE_SIZE": CDL_ERROR_MESSAGE_SIZE,
    "CDL_PHOTOMETRY_FORMAT_TABLE": CDL_PHOTOMETRY_FORMAT_TABLE,
    "CDL_PHOTOMETRY_FORMAT_IES": CDL_PHOTOMETRY_FORMAT_IES,
    "CDL_PHOTOMETRY_FORMAT_EULUMDAT": CDL_PHOTOMETRY_FORMAT_EULUMDAT,
    "CDL_PHOTOMETRY_MANUFACTURER": CDL_PHOTOMETRY_MANUFACTURER,
    "CDL_PHOTOMETRY_LUMINAIRE": CDL_PHOTOMETRY_LUMINAIRE,
    "CDL_PHOTOMETRY_CATALOGUE": CDL_PHOTOMETRY_CATALOGUE,
    "CDL_PHOTOMETRY_LAMP": CDL_PHOTOMETRY_LAMP,
    "CDL_METHOD_AUTO": METHODS["auto"],
    "CDL_METHOD_DIRECT": METHODS["direct"],
    "CDL_METHOD_ICACHE": METHODS["icache"],
    "CDL_METHOD_PATHTRACE": METHODS["pathtrace"],
    "CDL_QUALITY_DRAFT": QUALITIES["draft"],
    "CDL_QUALITY_NORMAL": QUALITIES["normal"],
    "CDL_QUALITY_HIGH": QUALITIES["high"],
    "CDL_QUALITY_REFERENCE": QUALITIES["reference"],
    "CDL_GRID_E": CDL_GRID_E,
    "CDL_GRID_E_DIRECT": CDL_GRID_E_DIRECT,
    "CDL_GRID_E_INDIRECT": CDL_GRID_E_INDIRECT,
    "CDL_GRID_E_STDERR": CDL_GRID_E_STDERR,
    "CDL_GRID_AO": CDL_GRID_AO,
    "CDL_GRID_AO_STDERR": CDL_GRID_AO_STDERR,
    "CDL_GRID_EZ": CDL_GRID_EZ,
    "CDL_GRID_EZ_STDERR": CDL_GRID_EZ_STDERR,
    "CDL_GRID_ESZ": CDL_GRID_ESZ,
    "CDL_GRID_ESZ_STDERR": CDL_GRID_ESZ_STDERR,
    "CDL_GRID_L": CDL_GRID_L,
}

# ---------------------------------------------------------------------------
# Finding the library


def _candidates() -> list[str]:
    """Where libcandela.so.N is looked for, in order: $CANDELA_LIBRARY (a
    file), the library beside this package when `cmake --install` put both
    in one prefix, then the system's search (LD_LIBRARY_PATH, the ld.so
    cache, /usr/local/lib after ldconfig)."""
    found = []
    explicit = os.environ.get("CANDELA_LIBRARY")
    if explicit:
        return [explicit]
    try:
        from . import _install_location  # written by cmake --install only

        here = os.path.dirname(os.path.abspath(__file__))
        found.append(os.path.normpath(os.path.join(here, _install_location.LIBRARY_FROM_PACKAGE)))
    except ImportError:
        pass
    found.append(LIBRARY_NAME)
    return found


def _load() -> ctypes.CDLL:
    tried = []
    for candidate in _candidates():
        try:
            lib = ctypes.CDLL(candidate)
        except OSError as e:
            tried.append(f"{candidate} ({e})")
            continue
        lib.cdl_abi_version.restype = c_int
        lib.cdl_abi_version.argtypes = []
        abi = lib.cdl_abi_version()
        if abi != ABI_VERSION:
            raise ImportError(
                f"candela: {candidate} is libcandela ABI {abi}, but this Python package is written for "
                f"ABI {ABI_VERSION}: install the package from the same Candela build as the library"
            )
        return lib
    raise ImportError(
        "candela: cannot load libcandela: tried "
        + "; ".join(tried)
        + ". Set CANDELA_LIBRARY to the file PREFIX/lib/"
        + LIBRARY_NAME
        + " of your `cmake --install`, or put PREFIX/lib on LD_LIBRARY_PATH"
    )


lib = _load()
LIBRARY_PATH: Optional[str] = getattr(lib, "_name", None)


def _declare(name: str, restype, *argtypes) -> None:
    fn = getattr(lib, name)
    fn.restype = restype
    fn.argtypes = list(argtypes)


_p = c_void_p  # an opaque handle (cdl_photometry *, cdl_scene *, cdl_solution *)
_err = POINTER(cdl_error)

_declare("cdl_version", c_char_p)
_declare("cdl_status_name", c_char_p, c_int)

# photometry.h
_declare("cdl_photometry_read_file", c_int, c_char_p, POINTER(cdl_photometry_read_options), POINTER(_p), _err)
_declare("cdl_photometry_release", None, _p)
_declare("cdl_photometry_intensity_c_gamma", cdl_quantity, _p, c_double, c_double)
_declare("cdl_photometry_max_intensity", cdl_quantity, _p)
_declare("cdl_photometry_summarize", None, _p, POINTER(cdl_photometry_summary))
_declare("cdl_photometry_get_format", c_int, _p)
_declare("cdl_photometry_ies_version", c_int, _p)
_declare("cdl_photometry_input_watts", c_double, _p)
_declare("cdl_photometry_is_radiometric", c_int, _p)
_declare("cdl_photometry_get_text", c_char_p, _p, c_int)
_declare("cdl_photometry_warning_count", c_size_t, _p)
_declare("cdl_photometry_warning", c_char_p, _p, c_size_t)
_declare("cdl_photometry_warning_code", c_char_p, _p, c_size_t)
_declare("cdl_photometry_warning_line", c_uint, _p, c_size_t)
_declare("cdl_photometry_notes_free", None, POINTER(cdl_photometry_notes))
_declare(
    "cdl_photometry_write_file",
    c_int,
    _p,
    c_char_p,
    c_int,
    POINTER(cdl_photometry_write_options),
    POINTER(cdl_photometry_notes),
    _err,
)

# scene.h
_declare("cdl_scene_load", c_int, c_char_p, POINTER(_p), _err)
_declare("cdl_scene_load_string", c_int, c_char_p, c_char_p, POINTER(_p), _err)
_declare("cdl_scene_release", None, _p)
_declare("cdl_scene_path", c_char_p, _p)
_declare("cdl_scene_grid_count", c_size_t, _p)
_declare("cdl_scene_grid_name", c_char_p, _p, c_size_t)
_declare("cdl_scene_luminaire_count", c_size_t, _p)
_declare("cdl_scene_surface_count", c_size_t, _p)
_declare("cdl_scene_method", c_int, _p)
_declare("cdl_scene_quality", c_int, _p)
_declare("cdl_scene_target_error", c_double, _p)
_declare("cdl_scene_seed", c_uint64, _p)
_declare("cdl_method_name", c_char_p, c_int)
_declare("cdl_quality_name", c_char_p, c_int)

# solve.h, solution.h
_declare("cdl_solve_scene", c_int, _p, POINTER(cdl_solve_options), POINTER(_p), _err)
_declare("cdl_solution_release", None, _p)
_declare("cdl_solution_get_info", None, _p, POINTER(cdl_solution_info))
_declare("cdl_solution_grid_count", c_size_t, _p)
_declare("cdl_solution_grid_name", c_char_p, _p, c_size_t)
_declare("cdl_solution_grid_point_count", c_size_t, _p, c_size_t)
_declare("cdl_solution_grid_points", POINTER(c_double), _p, c_size_t)
_declare("cdl_solution_grid_normals", POINTER(c_double), _p, c_size_t)
_declare("cdl_solution_grid_weights", POINTER(c_double), _p, c_size_t)
_declare("cdl_solution_grid_values", POINTER(c_double), _p, c_size_t, c_int)
_declare("cdl_solution_grid_summary", None, _p, c_size_t, POINTER(cdl_grid_summary))
_declare("cdl_solution_plan_json", c_char_p, _p)
_declare("cdl_solution_warning_count", c_size_t, _p)
_declare("cdl_solution_warning", c_char_p, _p, c_size_t)

# solution_write.h
_declare("cdl_solution_prepare_folder", c_int, c_char_p, _err)
_declare(
    "cdl_solution_write", c_int, _p, _p, c_char_p, POINTER(cdl_solution_write_options), _err
)
_declare("cdl_default_ocio_config", c_char_p)


def sized(struct_type):
    """A struct that begins with its size, zeroed and its size set (what the
    headers' _INIT macros do before they set their defaults)."""
    s = struct_type()
    s.size = ctypes.sizeof(struct_type)
    return s


def text(raw: Optional[bytes]) -> str:
    """A string the library returned (UTF-8; bytes that are not are kept as
    escapes rather than refused)."""
    return "" if raw is None else raw.decode("utf-8", errors="backslashreplace")


def encode_path(path) -> bytes:
    """A path for the library: str or os.PathLike, as the file system
    encodes it. A NUL inside would end the C string early and name another
    file: refused (UsageError, as open() refuses it)."""
    raw = os.fsencode(os.fspath(path))
    if b"\0" in raw:
        from .errors import UsageError  # (errors imports this module)

        raise UsageError(f"{os.fspath(path)!r}: expected a path, found a NUL character in it")
    return raw
