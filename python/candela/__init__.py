"""Candela from Python: photometric files, scenes and illuminance solves.

A thin layer over the installed shared library libcandela (through ctypes),
with NumPy arrays for every per-point result:

    import candela
    downlight = candela.read_photometry("data/office/downlight.ies")
    print(downlight.flux_lm, downlight.beam_angle_deg)
    scene = candela.load_scene("data/office/office.json")
    result = scene.solve(quality="draft")
    workplane = result.grids["workplane"]
    print(workplane.stats.Em_lx, workplane.E.max())   # lux
    result.write("out/office")                        # as `candela solve` writes

Units are in the names: flux_lm (lumens), radiant_flux_w (watts),
max_intensity_cd (candela); E, E_direct, E_indirect, E_stderr are lux. A
radiometric file (its table in W/sr) never answers in lumens or candela.

Errors raise CandelaError subclasses (InputError, UsageError, InternalError,
Cancelled) carrying the library's message, which names the file and line or
the scene's JSON path.
"""

from ._capi import ABI_VERSION, LIBRARY_PATH, lib as _lib
from .errors import CandelaError, Cancelled, InputError, InternalError, UsageError
from .photometry import Photometry, PhotometryWarning, read_photometry
from .result import GridResult, GridStats, SolveInfo, SolveResult
from .scene import Scene, load_scene, scene_from_dict
from .solve import Progress, SolveJob

#: The release of the library in use ("MAJOR.MINOR.PATCH", as `candela --version` prints).
__version__ = _lib.cdl_version().decode("ascii")

__all__ = [
    "ABI_VERSION",
    "LIBRARY_PATH",
    "CandelaError",
    "Cancelled",
    "GridResult",
    "GridStats",
    "InputError",
    "InternalError",
    "Photometry",
    "PhotometryWarning",
    "Progress",
    "Scene",
    "SolveInfo",
    "SolveJob",
    "SolveResult",
    "UsageError",
    "load_scene",
    "read_photometry",
    "scene_from_dict",
]
