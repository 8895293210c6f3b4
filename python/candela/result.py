"""A solve's results in NumPy arrays, and writing them as `candela solve` does."""

from __future__ import annotations

import ctypes
import json
import os
from typing import TYPE_CHECKING, NamedTuple, Optional, Union

import numpy as np

from . import _capi
from ._handle import Owned
from ._capi import lib
from .errors import UsageError, check

if TYPE_CHECKING:
    from .scene import Scene


class GridStats(NamedTuple):
    """A grid's statistics in EN 12464-1's terms, as summary.json gives them:
    Em_lx (the area-weighted mean of E; the plain mean for a points grid),
    Emin_lx, Emax_lx, U0 = Emin / Em, Ud = Emin / Emax, the point count, the
    area the points stand for (m^2; 0 for a points grid) and the mean and
    worst relative standard error of E over the lit points."""

    Em_lx: float
    Emin_lx: float
    Emax_lx: float
    U0: float
    Ud: float
    count: int
    area_m2: float
    stderr_mean_rel: float
    stderr_max_rel: float


class SolveInfo(NamedTuple):
    """What the solve did: the method used (its name), the quality and the
    target relative standard error of E per point, the seed, the worker
    threads, the time (s) of the whole solve and of the grids' points, rays
    traced, irradiance-cache records, and the installed power (W) of the
    luminaires whose files state it."""

    method: str
    quality: str
    target_error: float
    seed: int
    threads: int
    seconds: float
    compute_seconds: float
    rays: int
    records: int
    installed_w: float


def _copy(pointer, count: int, width: int = 1, always: bool = False) -> Optional[np.ndarray]:
    """count x width doubles the solution owns, copied into a new array
    (None when the library has none: an output the grid did not ask for;
    an empty array for a grid without points when `always`)."""
    if not pointer or count == 0:
        return np.empty((0, width) if width > 1 else 0) if always else None
    flat = np.ctypeslib.as_array(pointer, shape=(count * width,)).copy()
    return flat.reshape(count, width) if width > 1 else flat


class GridResult:
    """One grid's results, every per-point quantity a NumPy array in the
    grid's point order (the order of its CSV rows).

    Attributes:
        name: the grid's name in the scene.
        points: (N, 3) positions in metres.
        normals: (N, 3) unit normals: E is the illuminance on the plane of each.
        area_m2: (N,) the area each point stands for (1 for a points grid).
        E: (N,) illuminance in lux, E_direct + E_indirect.
        E_stderr: (N,) its one-sigma standard error in lux (0 where exact).
        E_direct: (N,) from the lights directly, lux.
        E_indirect: (N,) interreflected, lux (0 when not modelled).
        Ez, Ez_stderr: cylindrical illuminance and its error, lux ("outputs":
            ["cylindrical"]; the error None where every part is exact).
        Esz, Esz_stderr: semicylindrical illuminance, lux ("semicylindrical").
        L: luminance rho E / pi of the surface under each point, cd/m^2 ("luminance").
        AO, AO_stderr: ambient occlusion, a fraction in [0, 1] ("ao").
        stats: GridStats (Em_lx, Emin_lx, Emax_lx, U0, Ud, ...).
    Outputs the grid did not ask for are None.
    """

    def __init__(self, solution: int, index: int):
        n = lib.cdl_solution_grid_point_count(solution, index)
        self.name = _capi.text(lib.cdl_solution_grid_name(solution, index))

        def values(q: int, always: bool = False) -> Optional[np.ndarray]:
            return _copy(lib.cdl_solution_grid_values(solution, index, q), n, always=always)

        self.points = _copy(lib.cdl_solution_grid_points(solution, index), n, 3, always=True)
        self.normals = _copy(lib.cdl_solution_grid_normals(solution, index), n, 3, always=True)
        self.area_m2 = _copy(lib.cdl_solution_grid_weights(solution, index), n, always=True)
        self.E = values(_capi.CDL_GRID_E, always=True)
        self.E_stderr = values(_capi.CDL_GRID_E_STDERR, always=True)
        self.E_direct = values(_capi.CDL_GRID_E_DIRECT, always=True)
        self.E_indirect = values(_capi.CDL_GRID_E_INDIRECT, always=True)
        self.Ez = values(_capi.CDL_GRID_EZ)
        self.Ez_stderr = values(_capi.CDL_GRID_EZ_STDERR)
        self.Esz = values(_capi.CDL_GRID_ESZ)
        self.Esz_stderr = values(_capi.CDL_GRID_ESZ_STDERR)
        self.L = values(_capi.CDL_GRID_L)
        self.AO = values(_capi.CDL_GRID_AO)
        self.AO_stderr = values(_capi.CDL_GRID_AO_STDERR)
        s = _capi.sized(_capi.cdl_grid_summary)
        lib.cdl_solution_grid_summary(solution, index, ctypes.byref(s))
        self.stats = GridStats(
            Em_lx=s.E_avg_lx,
            Emin_lx=s.E_min_lx,
            Emax_lx=s.E_max_lx,
            U0=s.U0,
            Ud=s.Ud,
            count=int(s.count),
            area_m2=s.area_m2,
            stderr_mean_rel=s.stderr_mean_rel,
            stderr_max_rel=s.stderr_max_rel,
        )

    def __len__(self) -> int:
        return len(self.E)

    def __repr__(self) -> str:
        s = self.stats
        return (
            f"<candela.GridResult {self.name!r}: {s.count} points, Em {s.Em_lx:.4g} lx, "
            f"Emin {s.Emin_lx:.4g} lx, Emax {s.Emax_lx:.4g} lx, U0 {s.U0:.3f}>"
        )


class SolveResult(Owned):
    """The results of Scene.solve.

    Attributes:
        grids: the grids' GridResult by name, in the scene's order.
        plan: what was modelled for every light and grid and why, and which
            method each grid's interreflection took (summary.json's "plan").
        warnings: what a user must hear about (a luminaire that lights no
            grid point, a dark grid, points where two surfaces meet), one
            sentence each.
        info: SolveInfo (method, target error, seed, threads, seconds, rays, ...).
    """

    _release = "cdl_solution_release"
    _what = "the result"

    def __init__(self, scene: "Scene", scene_handle: int, solution: int):
        # write() needs the scene beside the solution: the result takes over
        # a borrow of it (Owned._acquire) that its solve made, and ends it
        # when the solution is freed.
        self._scene = scene
        self._scene_handle = scene_handle
        self._own(solution)
        self.grids: dict[str, GridResult] = {}
        for g in range(lib.cdl_solution_grid_count(solution)):
            grid = GridResult(solution, g)
            self.grids[grid.name] = grid
        self.plan = json.loads(_capi.text(lib.cdl_solution_plan_json(solution)) or "{}")
        self.warnings = [
            _capi.text(lib.cdl_solution_warning(solution, i)) for i in range(lib.cdl_solution_warning_count(solution))
        ]
        i = _capi.sized(_capi.cdl_solution_info)
        lib.cdl_solution_get_info(solution, ctypes.byref(i))
        self.info = SolveInfo(
            method=_capi.text(lib.cdl_method_name(i.method)),
            quality=_capi.text(lib.cdl_quality_name(i.quality)),
            target_error=i.target_error,
            seed=int(i.seed),
            threads=int(i.threads),
            seconds=i.seconds,
            compute_seconds=i.compute_seconds,
            rays=int(i.rays),
            records=int(i.records),
            installed_w=i.installed_w,
        )

    def _free(self, handle: Optional[int]) -> None:
        super()._free(handle)
        if handle is not None:
            self._scene._unacquire()

    def __repr__(self) -> str:
        return f"<candela.SolveResult {len(self.grids)} grids, method {self.info.method}, {self.info.seconds:.3g} s>"

    def write(self, outdir: Union[str, os.PathLike], map_scale: str = "linear", ocio_config: Optional[str] = None) -> None:
        """Write the results into outdir (created with its parents when
        missing) as `candela solve -o outdir` does: NAME.csv per grid, NAME.exr
        and the false-colour NAME.png for rect and polygon grids, and
        summary.json, each file written atomically. map_scale "linear" or
        "log" for the maps; ocio_config an OpenColorIO config (default:
        Candela's). Raises InputError when outdir cannot be the folder."""
        if map_scale not in ("linear", "log"):
            raise UsageError(f"write: map_scale: expected 'linear' or 'log', found {map_scale!r}")
        err = _capi.cdl_error()
        out = _capi.encode_path(outdir)
        check(lib.cdl_solution_prepare_folder(out, ctypes.byref(err)), err)
        options = _capi.sized(_capi.cdl_solution_write_options)
        options.ocio_config = _capi.encode_path(ocio_config) if ocio_config is not None else lib.cdl_default_ocio_config()
        options.map_log_scale = 1 if map_scale == "log" else 0
        with self._use() as solution:
            st = lib.cdl_solution_write(self._scene_handle, solution, out, ctypes.byref(options), ctypes.byref(err))
        check(st, err)
