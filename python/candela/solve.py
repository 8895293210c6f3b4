"""Solving a scene on a thread of its own: progress, cancelling, Ctrl-C.

The library's cdl_solve_scene runs in a Python thread made for the job
(ctypes releases the GIL for the call, so the caller's thread and any other
keep running Python). The library calls the job's progress callback from
that thread after every chunk of points; the callback answers "stop" once
the job is cancelled, and the library then ends the solve with
CDL_ERR_CANCELLED after the chunks under way, within a fraction of a second.

Who cancels:
- Scene.solve waits in the calling thread. A KeyboardInterrupt there (Ctrl-C
  in the main thread, "interrupt kernel" in Jupyter), an exception raised by
  the `progress` callable, or the `cancel` event being set cancels the job;
  solve waits for the library to stop, then raises the KeyboardInterrupt,
  the callable's exception, or candela.Cancelled.
- Scene.solve_async returns the SolveJob at once: SolveJob.cancel(), the
  `cancel` event, a KeyboardInterrupt while waiting in SolveJob.result(), or
  leaving a `with` block cancel it.
- At interpreter exit every unfinished job is cancelled before Python waits
  for its threads.
"""

from __future__ import annotations

import ctypes
import math
import numbers
import queue
import threading
import time
import weakref
from typing import TYPE_CHECKING, Callable, NamedTuple, Optional, Protocol

from . import _capi
from ._capi import lib
from .errors import UsageError, from_status
from .result import SolveResult

if TYPE_CHECKING:
    from .scene import Scene

# How often a waiting thread looks at a `cancel` event and a deadline (s).
_POLL_SECONDS = 0.05


class Progress(NamedTuple):
    """What a solve reports while it works: the `stage` ("geometry", "grid
    workplane", "cache records", ...), items `done` of `total` in that stage
    (points or records as the stage says; total 0 for a stage without
    items), irradiance-cache `records` so far, and the seconds since the
    stage began."""

    stage: str
    done: int
    total: int
    records: int
    elapsed_seconds: float


class CancelEvent(Protocol):
    """What a `cancel` argument must offer: is_set() (threading.Event does)."""

    def is_set(self) -> bool: ...


def solve_options(method, quality, target_error, threads) -> _capi.cdl_solve_options:
    """The library's options from solve()'s arguments (None: the scene's own),
    checked here so that a wrong argument is named before any work starts."""
    o = _capi.sized(_capi.cdl_solve_options)
    o.threads, o.method, o.quality, o.target_error = -1, -1, -1, 0.0
    if method is not None:
        if method not in _capi.METHODS:
            raise UsageError(f"solve: method: expected one of {', '.join(_capi.METHODS)}, found {method!r}")
        o.method = _capi.METHODS[method]
    if quality is not None:
        if quality not in _capi.QUALITIES:
            raise UsageError(f"solve: quality: expected one of {', '.join(_capi.QUALITIES)}, found {quality!r}")
        o.quality = _capi.QUALITIES[quality]
    if target_error is not None:
        # (0 would mean "the scene's" to the library: refused here instead)
        if isinstance(target_error, bool) or not isinstance(target_error, numbers.Real) or not (
            math.isfinite(target_error) and target_error > 0.0
        ):
            raise UsageError(
                f"solve: target_error: expected a relative standard error in [1e-05, 0.5], found {target_error!r}"
            )
        o.target_error = float(target_error)
    if threads is not None:
        if isinstance(threads, bool) or not isinstance(threads, numbers.Integral) or threads < 0:
            raise UsageError(f"solve: threads: expected a count >= 0 (0: all cores), found {threads!r}")
        o.threads = int(threads)
    return o


_DONE = object()
_live_jobs: "weakref.WeakSet[SolveJob]" = weakref.WeakSet()


def _cancel_live_jobs() -> None:
    for job in list(_live_jobs):
        job.cancel()


# Before Python joins the threads it did not make daemons (at exit), cancel
# the unfinished solves, as concurrent.futures does for its workers.
_register_atexit = getattr(threading, "_register_atexit", None)
if _register_atexit is not None:
    _register_atexit(_cancel_live_jobs)


class SolveJob:
    """A solve running on a thread of its own (Scene.solve_async).

    done() says whether it finished, `progress` is its latest report,
    cancel() asks it to stop, result() waits for its SolveResult. As a
    context manager it cancels the solve when the block is left before the
    solve is done (and waits for it to stop)."""

    def __init__(
        self,
        scene: "Scene",
        options: _capi.cdl_solve_options,
        cancel: Optional[CancelEvent] = None,
        relay: bool = False,
    ):
        self._scene = scene
        self._user_cancel = cancel
        self._stop = threading.Event()
        self._finished = threading.Event()
        self._reports: Optional[queue.SimpleQueue] = queue.SimpleQueue() if relay else None
        self._latest: Optional[Progress] = None
        self._result: Optional[SolveResult] = None
        self._error: Optional[BaseException] = None
        # The ctypes callback must live as long as the library may call it.
        self._callback = _capi.cdl_progress_fn(self._on_progress)
        self._options = options
        self._options.progress.fn = self._callback
        self._options.progress.user = None
        self._thread = threading.Thread(target=self._run, name="candela solve")
        # The scene is borrowed from here (UsageError now if it is closed)
        # until the solve ends, or for the life of its result (which needs
        # it to write): scene.close() meanwhile frees it after them.
        self._scene_handle = scene._acquire()
        try:
            self._thread.start()
        except BaseException:
            scene._unacquire()
            raise
        _live_jobs.add(self)

    # -- in the solve's thread -------------------------------------------------

    def _on_progress(self, user, report) -> int:
        """The library's progress callback: 0 to go on, 1 to stop. No
        exception may cross the library's frames: anything raised here stops
        the solve instead."""
        try:
            r = report.contents
            p = Progress(_capi.text(r.stage), int(r.done), int(r.total), int(r.records), float(r.elapsed_seconds))
            self._latest = p
            if self._reports is not None:
                self._reports.put(p)
            if self._user_cancel is not None and self._user_cancel.is_set():
                self._stop.set()
            return 1 if self._stop.is_set() else 0
        except BaseException:  # (a failing cancel object): stop rather than go on unasked
            self._stop.set()
            return 1

    def _run(self) -> None:
        borrowing = True
        try:
            handle = ctypes.c_void_p()
            err = _capi.cdl_error()
            st = lib.cdl_solve_scene(self._scene_handle, ctypes.byref(self._options), ctypes.byref(handle), ctypes.byref(err))
            if st == _capi.CDL_OK:
                borrowing = False  # the result takes the scene's borrow over
                self._result = SolveResult(self._scene, self._scene_handle, handle.value)
            else:
                self._error = from_status(st, err)
        except BaseException as e:
            self._error = e
        finally:
            if borrowing:
                self._scene._unacquire()
            self._finished.set()
            if self._reports is not None:
                self._reports.put(_DONE)

    # -- in any thread -----------------------------------------------------------

    def cancel(self) -> None:
        """Ask the solve to stop; it ends with candela.Cancelled after the
        chunks of work under way. Does not wait (result() does)."""
        self._stop.set()

    def done(self) -> bool:
        """True once the solve has finished, failed or stopped."""
        return self._finished.is_set()

    @property
    def progress(self) -> Optional[Progress]:
        """The latest progress report (None before the first)."""
        return self._latest

    def _watch_cancel(self) -> None:
        if self._user_cancel is not None and self._user_cancel.is_set():
            self._stop.set()

    def _wait(self, progress: Optional[Callable[[Progress], object]], timeout: Optional[float]) -> bool:
        """Wait until the job ends (True) or timeout seconds pass (False),
        calling progress with each report in this thread. Anything raised
        meanwhile (KeyboardInterrupt, the callable's exception) cancels the
        job, waits for it to stop, and propagates."""
        deadline = None if timeout is None else time.monotonic() + timeout
        try:
            while True:
                if self._reports is not None and progress is not None:
                    try:
                        item = self._reports.get(timeout=_POLL_SECONDS)
                    except queue.Empty:
                        item = None
                    if item is _DONE:
                        return True
                    if item is not None:
                        progress(item)
                elif self._finished.wait(_POLL_SECONDS):
                    return True
                self._watch_cancel()
                if deadline is not None and time.monotonic() >= deadline:
                    return False
        except BaseException:
            self.cancel()
            self._thread.join()
            raise

    def _outcome(self) -> SolveResult:
        self._thread.join()
        if self._error is not None:
            raise self._error
        assert self._result is not None
        return self._result

    def result(self, timeout: Optional[float] = None) -> SolveResult:
        """Wait for the solve and return its SolveResult; raise its error
        (candela.Cancelled when it was cancelled). A KeyboardInterrupt while
        waiting cancels the solve, waits for it to stop and propagates.
        TimeoutError when timeout seconds pass first (the solve goes on)."""
        if not self._wait(None, timeout):
            raise TimeoutError(f"the solve of {self._scene.path} did not finish within {timeout} s")
        return self._outcome()

    def __enter__(self) -> "SolveJob":
        return self

    def __exit__(self, *exc) -> None:
        if not self.done():
            self.cancel()
        self._thread.join()
