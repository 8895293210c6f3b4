"""Scenes: from a file or a dict in the same JSON format, and their solves."""

from __future__ import annotations

import ctypes
import json
import math
import numbers
import os
from collections.abc import Mapping
from typing import Any, Callable, Optional, Union

import numpy as np

from . import _capi
from ._handle import Owned
from ._capi import lib
from .errors import InputError, UsageError, check
from .result import SolveResult
from .solve import CancelEvent, Progress, SolveJob, solve_options

# The name a scene from a dict goes by in messages (under its base folder).
DICT_SCENE_NAME = "<scene dict>"


class Scene(Owned):
    """A scene loaded and checked by libcandela (the format of `candela help
    scene`): its surfaces, luminaires, grids and solver settings.

    Attributes:
        path: the scene file (for a scene from a dict, BASE_DIR/<scene dict>).
        grid_names: the grids' names in the scene's order.
        luminaire_count: luminaires placed (each copy of an array counts).
        surface_count: surfaces listed.
        method, quality: the solver settings the scene asks for ("auto", "normal", ...).
        target_error: the relative standard error of E per point it asks for.
        seed: the seed of its random numbers.
    Photometric files and images are read when the scene is solved.
    """

    _release = "cdl_scene_release"

    def __init__(self, handle: int):
        self._own(handle)
        self.path = _capi.text(lib.cdl_scene_path(handle))
        self._what = f"{self.path}: the scene"
        self.grid_names = [_capi.text(lib.cdl_scene_grid_name(handle, i)) for i in range(lib.cdl_scene_grid_count(handle))]
        self.luminaire_count = int(lib.cdl_scene_luminaire_count(handle))
        self.surface_count = int(lib.cdl_scene_surface_count(handle))
        self.method = _capi.text(lib.cdl_method_name(lib.cdl_scene_method(handle)))
        self.quality = _capi.text(lib.cdl_quality_name(lib.cdl_scene_quality(handle)))
        self.target_error = float(lib.cdl_scene_target_error(handle))
        self.seed = int(lib.cdl_scene_seed(handle))

    def __repr__(self) -> str:
        return f"<candela.Scene {self.path!r}: {self.luminaire_count} luminaires, grids {self.grid_names}>"

    def solve(
        self,
        method: Optional[str] = None,
        quality: Optional[str] = None,
        target_error: Optional[float] = None,
        threads: Optional[int] = None,
        progress: Optional[Callable[[Progress], object]] = None,
        cancel: Optional[CancelEvent] = None,
    ) -> SolveResult:
        """Solve every grid: illuminance in lux per point, with its standard error.

        Args:
            method: "auto", "direct", "icache" or "pathtrace" (None: the scene's).
            quality: "draft", "normal", "high" or "reference" (None: the
                scene's); it replaces the scene's target_error too.
            target_error: a relative standard error of E per point in
                [1e-5, 0.5] (None: the scene's, or the quality's).
            threads: worker threads, 0 for all cores (None: the scene's).
                Results do not depend on it.
            progress: called in this thread with each Progress report, in
                order; an exception it raises cancels the solve and propagates.
            cancel: a threading.Event (anything with is_set()): setting it
                from another thread stops the solve with candela.Cancelled.

        The solve runs on a thread of its own while this one waits: Ctrl-C
        (KeyboardInterrupt) cancels it, waits for it to stop (a fraction of a
        second) and propagates. Raises InputError (a photometric file or image
        the scene names cannot be read; the message gives its JSON path),
        UsageError (an argument out of range), Cancelled, InternalError.
        """
        options = solve_options(method, quality, target_error, threads)
        job = SolveJob(self, options, cancel=cancel, relay=progress is not None)
        job._wait(progress, None)
        return job._outcome()

    def solve_async(
        self,
        method: Optional[str] = None,
        quality: Optional[str] = None,
        target_error: Optional[float] = None,
        threads: Optional[int] = None,
        cancel: Optional[CancelEvent] = None,
    ) -> SolveJob:
        """Start the solve on a thread of its own and return its SolveJob at
        once (arguments as for solve): job.progress, job.cancel(),
        job.result()."""
        return SolveJob(self, solve_options(method, quality, target_error, threads), cancel=cancel)


def load_scene(path: Union[str, os.PathLike]) -> Scene:
    """Load and check a scene file; relative paths in it resolve against its
    folder. Raises InputError naming the file and the JSON path (or line and
    column for a syntax error) and what was expected."""
    handle = ctypes.c_void_p()
    err = _capi.cdl_error()
    check(lib.cdl_scene_load(_capi.encode_path(path), ctypes.byref(handle), ctypes.byref(err)), err)
    return Scene(handle.value)


def _json_value(value: Any, where: str, name: str) -> Any:
    """value as plain JSON data: NumPy arrays and scalars become lists and
    numbers; anything JSON cannot hold (NaN, infinity, other objects, keys
    that are not strings) is refused with its JSON path, as the library
    names paths ("luminaires[0].position")."""
    if isinstance(value, Mapping):
        out = {}
        for k, v in value.items():
            if not isinstance(k, str):
                raise InputError(f"{name}: {where or '(top)'}: expected string keys, found {k!r}")
            out[k] = _json_value(v, f"{where}.{k}" if where else k, name)
        return out
    if isinstance(value, np.ndarray):
        value = value.tolist()
    elif isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, (list, tuple)):
        return [_json_value(v, f"{where}[{i}]", name) for i, v in enumerate(value)]
    if value is None or isinstance(value, (str, bool)):
        return value
    if isinstance(value, numbers.Integral):
        return int(value)
    if isinstance(value, numbers.Real):
        if not math.isfinite(value):
            raise InputError(f"{name}: {where}: expected a finite number, found {value!r}")
        return float(value)
    raise InputError(
        f"{name}: {where or '(top)'}: expected a JSON value (dict, list, str, number, bool or None), "
        f"found {type(value).__name__}"
    )


def scene_from_dict(d: Mapping[str, Any], base_dir: Union[str, os.PathLike, None] = None) -> Scene:
    """A scene from a dict in the scene file's format (what json.load of a
    scene file gives; NumPy arrays and numbers are accepted where lists and
    numbers go). Relative paths in it (photometric files, meshes, images)
    resolve against base_dir (default: the current folder, taken now).
    Messages name the scene BASE_DIR/<scene dict> and the JSON path.

    `candela report` needs the scene as a file: for a report, save the dict
    with json.dump and use load_scene."""
    if not isinstance(d, Mapping):
        raise UsageError(f"scene_from_dict: expected a dict, found {type(d).__name__}")
    base = os.path.abspath(os.fspath(base_dir) if base_dir is not None else os.getcwd())
    name = os.path.join(base, DICT_SCENE_NAME)
    text = json.dumps(_json_value(d, "", name))
    handle = ctypes.c_void_p()
    err = _capi.cdl_error()
    st = lib.cdl_scene_load_string(text.encode("utf-8"), _capi.encode_path(name), ctypes.byref(handle), ctypes.byref(err))
    check(st, err)
    return Scene(handle.value)
