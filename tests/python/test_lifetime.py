"""Closing an object while another thread's call uses it: the library frees a
handle only when no call uses it (its headers' rule), so close() then marks
the object closed, the call finishes with correct figures, and the last
user frees it. Under the sanitizers (scripts/test.sh's second pass) a handle
freed under a running call is a heap-use-after-free that aborts the test;
in the plain build the figures and the handle's state are checked."""

import threading
import time

import numpy as np
import pytest

import candela
from conftest import workplane_scene_dict

# A guard against a hang, not a limit on speed.
GUARD_SECONDS = 300


def wait_until(condition):
    deadline = time.monotonic() + GUARD_SECONDS
    while not condition():
        assert time.monotonic() < deadline, "waited too long"
        time.sleep(0.001)


def test_closing_a_scene_while_it_solves_lets_the_solve_finish(tmp_path):
    scene_dict, office = workplane_scene_dict("draft")
    scene = candela.scene_from_dict(scene_dict, base_dir=office)
    job = scene.solve_async()
    wait_until(lambda: job.progress is not None and job.progress.stage.startswith("grid"))
    scene.close()  # while the library computes the grid from it
    assert scene.closed and not job.done()
    with pytest.raises(candela.UsageError, match="closed"):
        scene.solve()
    result = job.result(timeout=GUARD_SECONDS)
    # the figures of the same scene, seed and threads solved untouched: the same doubles
    again = candela.scene_from_dict(scene_dict, base_dir=office).solve()
    np.testing.assert_array_equal(result.grids["workplane"].E, again.grids["workplane"].E)
    assert result.grids["workplane"].E.min() > 0.0
    # the result still needs the scene to write: it holds it until closed
    assert scene._handle is not None
    result.write(tmp_path / "out")
    assert (tmp_path / "out" / "workplane.csv").exists()
    result.close()
    assert scene._handle is None  # freed by the last user


def test_closing_a_photometry_while_it_evaluates(write_ies):
    # the cone of test_photometry.py: 1000 cd (1 - gamma / 90 deg) below the horizontal
    path = write_ies("cone.ies", ["[TEST] cone"], ["1 -1 1 3 1 1 2 0 0 0", "1 1 0", "0 90 180", "0", "1000 0 0"])
    p = candela.read_photometry(path)
    gamma = np.linspace(0.0, 90.0, 300_000)  # a fraction of a second of calls
    out = {}
    worker = threading.Thread(target=lambda: out.setdefault("I", p.intensity(0.0, gamma)))
    worker.start()
    wait_until(lambda: p._borrowers > 0 or "I" in out)
    assert "I" not in out, "the evaluation ended before the test could close under it"
    p.close()
    worker.join(GUARD_SECONDS)
    # linear interpolation of an exactly linear table: round-off only
    np.testing.assert_allclose(out["I"], 1000.0 * (1.0 - gamma / 90.0), rtol=0, atol=1e-9)
    assert p.closed and p._handle is None
    with pytest.raises(candela.UsageError, match="closed"):
        p.intensity(0.0, 0.0)
