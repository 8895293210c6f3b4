"""Solves run with the GIL released and can be stopped: by a threading.Event,
SolveJob.cancel, an exception from the progress callable, leaving a `with`
block, and Ctrl-C (a KeyboardInterrupt in the main thread, simulated here
and sent as a real SIGINT to a child process).

The scene: the example office's work plane, interreflection path traced to
0.5 % per point, about ten seconds of work on two cores (more under the
sanitizers) in chunks of two points of a fraction of a second each. A
cancelled solve is recognised by what the library did, not by what reached
the caller: its job's outcome is candela.Cancelled (the library's
CDL_ERR_CANCELLED) and the last report the library made, in the solve's own
thread, is inside the grid, before its last point (a finished stage always
reports its last point). A solve that ignored the cancel would end with a
result and a last report at the grid's end, and fail these tests."""

import ctypes
import json
import signal
import subprocess
import sys
import threading
import time
import _thread

import pytest

import candela
from candela import _capi
from candela.solve import solve_options
from conftest import workplane_scene_dict

# How long a test waits before calling a solve stuck (a guard against a
# hang, far beyond a cancelled solve's fraction of a second; not a limit on
# speed: a solve that ignored the cancel would run its whole minute).
GUARD_SECONDS = 300


def long_scene_dict():
    return workplane_scene_dict("normal")


@pytest.fixture
def long_scene():
    scene, office = long_scene_dict()
    return candela.scene_from_dict(scene, base_dir=office)


class Recorder:
    """A progress callable that records every report and the thread it was
    called in, and sets `computing` once points of the grid are done."""

    def __init__(self):
        self.reports = []
        self.threads = set()
        self.computing = threading.Event()

    def __call__(self, p):
        self.reports.append(p)
        self.threads.add(threading.get_ident())
        if p.stage.startswith("grid") and p.done > 0:
            self.computing.set()


def no_solve_thread_left():
    return not any(t.name == "candela solve" for t in threading.enumerate())


@pytest.fixture
def jobs(monkeypatch):
    """The SolveJobs that Scene.solve makes, in order (solve keeps its job
    to itself: a test looks at what the library did through it)."""
    made = []

    class Recorded(candela.SolveJob):
        def __init__(self, *args, **kwargs):
            super().__init__(*args, **kwargs)
            made.append(self)

    monkeypatch.setattr(candela.scene, "SolveJob", Recorded)
    return made


def stopped_early(job):
    """True when the library cancelled the job's solve inside the grid."""
    assert job.done()
    last = job.progress
    if not (last.stage.startswith("grid") and last.done < last.total):
        return False
    with pytest.raises(candela.Cancelled, match="cancelled by the caller"):
        job.result()
    return True


def test_cancel_event_stops_the_solve(long_scene, jobs):
    cancel = threading.Event()
    record = Recorder()

    def set_when_computing():
        record.computing.wait(GUARD_SECONDS)
        cancel.set()

    setter = threading.Thread(target=set_when_computing)
    setter.start()
    with pytest.raises(candela.Cancelled, match="cancelled by the caller") as e:
        long_scene.solve(progress=record, cancel=cancel)
    setter.join()
    assert e.value.status == 4
    assert len(jobs) == 1 and stopped_early(jobs[0])
    # progress is relayed to the thread that called solve
    assert record.threads == {threading.get_ident()}
    assert no_solve_thread_left()


def test_keyboard_interrupt_in_the_main_thread_cancels_the_solve(long_scene, jobs):
    assert threading.current_thread() is threading.main_thread()
    record = Recorder()

    def interrupt_when_computing():
        if record.computing.wait(GUARD_SECONDS):
            _thread.interrupt_main()  # as Ctrl-C: SIGINT's handler raises KeyboardInterrupt in the main thread

    interrupter = threading.Thread(target=interrupt_when_computing)
    interrupter.start()
    with pytest.raises(KeyboardInterrupt):
        long_scene.solve(progress=record)
    interrupter.join()
    assert len(jobs) == 1 and stopped_early(jobs[0])
    assert no_solve_thread_left()


def test_exception_in_progress_cancels_and_propagates(long_scene, jobs):
    class Enough(Exception):
        pass

    record = Recorder()

    def progress(p):
        record(p)
        if record.computing.is_set():
            raise Enough()

    with pytest.raises(Enough):
        long_scene.solve(progress=progress)
    assert len(jobs) == 1 and stopped_early(jobs[0])
    assert no_solve_thread_left()


def test_solve_async_cancel_and_context_manager(long_scene):
    job = long_scene.solve_async()
    # result(timeout) gives up waiting without stopping the solve
    with pytest.raises(TimeoutError):
        job.result(timeout=0.01)
    assert not job.done()
    job.cancel()
    with pytest.raises(candela.Cancelled):
        job.result(timeout=GUARD_SECONDS)
    assert job.done() and job.progress is not None

    with long_scene.solve_async() as job:
        pass  # leaving the block before the solve is done cancels it
    assert job.done()
    with pytest.raises(candela.Cancelled):
        job.result()
    assert no_solve_thread_left()


def test_gil_is_released_during_a_solve():
    """While cdl_solve_scene computes in another thread, the main thread
    keeps running Python: in most 50 ms windows of the call it gets through
    its loop. The call is made as SolveJob makes it (the package's CDLL
    function) but without a progress callback, whose Python would hand the
    GIL around between chunks even if the call held it: held by the
    foreign call, the GIL would let the main thread through no window."""
    scene_dict, office = workplane_scene_dict("draft")  # a second or two of work
    scene = candela.scene_from_dict(scene_dict, base_dir=office)
    options = solve_options(None, None, None, None)
    span = {}

    def call():
        handle, err = ctypes.c_void_p(), _capi.cdl_error()
        span["start"] = time.monotonic()
        with scene._use() as scene_handle:
            span["status"] = _capi.lib.cdl_solve_scene(scene_handle, ctypes.byref(options), ctypes.byref(handle), ctypes.byref(err))
        span["end"] = time.monotonic()
        _capi.lib.cdl_solution_release(handle)

    worker = threading.Thread(target=call)
    ticks = []
    worker.start()
    while worker.is_alive():
        ticks.append(time.monotonic())
    worker.join()
    assert span["status"] == _capi.CDL_OK
    duration = span["end"] - span["start"]
    assert duration > 0.25, "the call must last some windows for the measure to mean anything"
    windows = int(duration / 0.05)
    ran = {int((t - span["start"]) / 0.05) for t in ticks if span["start"] <= t < span["start"] + windows * 0.05}
    # a loaded machine may take a few windows away from this thread
    assert len(ran) >= windows // 2, f"the main thread ran in {len(ran)} of {windows} windows of the call"


# The child: the long solve, "computing" printed once the grid's first
# points are done; after Ctrl-C, what the library did (as `stopped_early`
# looks at it, the job recorded as the `jobs` fixture does) and the threads
# left.
CHILD = r"""
import json, sys, threading
import candela
jobs = []
class Recorded(candela.SolveJob):
    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        jobs.append(self)
candela.scene.SolveJob = Recorded
scene = candela.scene_from_dict(json.loads(sys.argv[1]), base_dir=sys.argv[2])
said = []
def progress(p):
    if p.stage.startswith("grid") and p.done > 0 and not said:
        said.append(p)
        print("computing", flush=True)
try:
    scene.solve(progress=progress)
    print(json.dumps({"outcome": "finished"}))
except KeyboardInterrupt:
    last = jobs[0].progress
    try:
        jobs[0].result()
        library = "finished"
    except candela.Cancelled:
        library = "cancelled"
    threads = [t.name for t in threading.enumerate() if t is not threading.current_thread()]
    print(json.dumps({"outcome": "interrupted", "library": library, "stage": last.stage, "done": last.done,
                      "total": last.total, "threads": threads}))
"""


def test_ctrl_c_stops_a_solve_in_a_child_process():
    scene, office = long_scene_dict()
    child = subprocess.Popen(
        [sys.executable, "-c", CHILD, json.dumps(scene), str(office)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        line = child.stdout.readline()
        assert line.strip() == "computing", child.stderr.read()
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=GUARD_SECONDS)
    finally:
        if child.poll() is None:
            child.kill()
            child.wait()
    assert child.returncode == 0, err
    outcome = json.loads(out.strip().splitlines()[-1])
    assert outcome["outcome"] == "interrupted" and outcome["library"] == "cancelled"
    assert outcome["stage"].startswith("grid") and outcome["done"] < outcome["total"]
    assert outcome["threads"] == []
