"""Scenes and solves from Python: closed forms, and the arrays against the
files `candela solve` writes for the same scene and seed."""

import copy
import csv
import json
import math

import numpy as np
import pytest

import candela
from conftest import PROBE_SCENE, SOURCE_DIR, run_cli, write_office_draft


def test_probe_scene_gives_the_inverse_square_and_cosine_laws():
    result = candela.scene_from_dict(PROBE_SCENE).solve()
    probes = result.grids["probes"]
    # E = I cos(theta) / d^2: 1000 / 2^2 = 250 lx under the light; 1.5 m
    # aside d = 2.5 m, cos = 0.8: 128 lx. A point light's direct light is
    # computed in closed form: exact to round-off, its stated error 0.
    np.testing.assert_allclose(probes.E, [250.0, 128.0], rtol=1e-14)
    np.testing.assert_array_equal(probes.E_stderr, [0.0, 0.0])
    np.testing.assert_array_equal(probes.E_indirect, [0.0, 0.0])
    np.testing.assert_array_equal(probes.E_direct, probes.E)
    np.testing.assert_array_equal(probes.points, [[0, 0, 0], [1.5, 0, 0]])
    np.testing.assert_array_equal(probes.normals, [[0, 0, 1], [0, 0, 1]])
    assert probes.points.shape == (2, 3) and probes.E.dtype == np.float64
    # a points grid's Em is the plain mean; U0 = Emin / Em, Ud = Emin / Emax
    s = probes.stats
    assert s.Em_lx == pytest.approx(189.0, rel=1e-14)
    assert (s.Emin_lx, s.Emax_lx, s.count) == (pytest.approx(128.0, rel=1e-14), pytest.approx(250.0, rel=1e-14), 2)
    assert s.U0 == pytest.approx(128.0 / 189.0, rel=1e-14) and s.Ud == pytest.approx(128.0 / 250.0, rel=1e-14)
    assert probes.Ez is None and probes.Esz is None and probes.L is None and probes.AO is None
    assert result.info.method == "direct" and result.warnings == []
    assert result.plan["direct"][0]["light"] == "luminaires[0]"


def test_cylindrical_illuminance_of_a_point_light():
    scene = copy.deepcopy(PROBE_SCENE)
    scene["grids"][0]["outputs"] = ["cylindrical"]
    probes = candela.scene_from_dict(scene).solve().grids["probes"]
    # The mean of the vertical illuminance over all horizontal directions:
    # (I / d^2) sin(theta) times the mean of max(cos phi, 0), 1 / pi. Under
    # the light sin(theta) = 0; 1.5 m aside sin(theta) = 0.6, d = 2.5 m:
    # 1000 x 0.6 / (pi 6.25) = 30.56 lx; exact for a point light.
    np.testing.assert_allclose(probes.Ez, [0.0, 1000 * 0.6 / (math.pi * 6.25)], rtol=1e-12, atol=1e-12)
    assert probes.Ez_stderr is None  # exact: no error array
    np.testing.assert_allclose(probes.E, [250.0, 128.0], rtol=1e-14)


def test_numpy_values_are_accepted_in_a_scene_dict():
    scene = copy.deepcopy(PROBE_SCENE)
    scene["luminaires"][0]["position"] = np.array([0.0, 0.0, 2.0])
    scene["luminaires"][0]["intensity_cd"] = np.float32(1000.0)
    probes = candela.scene_from_dict(scene).solve().grids["probes"]
    np.testing.assert_allclose(probes.E, [250.0, 128.0], rtol=1e-14)  # (as above: exact)


def test_solve_arguments_override_the_scene():
    scene = candela.scene_from_dict(PROBE_SCENE)
    assert (scene.method, scene.quality, scene.target_error) == ("auto", "normal", 0.005)
    assert candela.scene_from_dict(PROBE_SCENE).solve(quality="draft").info.target_error == 0.02
    info = scene.solve(quality="high", threads=1).info
    assert (info.quality, info.target_error, info.threads) == ("high", 0.001, 1)
    assert scene.solve(target_error=0.01).info.target_error == 0.01
    assert scene.solve(method="pathtrace").info.method == "pathtrace"


@pytest.mark.parametrize(
    "kwargs, message",
    [
        ({"method": "raytrace"}, "method: expected one of auto, direct, icache, pathtrace"),
        ({"quality": "best"}, "quality: expected one of draft, normal, high, reference"),
        ({"target_error": 0}, "target_error"),
        ({"target_error": float("nan")}, "target_error"),
        ({"threads": -1}, "threads"),
        ({"threads": 1.5}, "threads"),
    ],
)
def test_bad_solve_arguments_are_refused_before_any_work(kwargs, message):
    with pytest.raises(candela.UsageError, match=message):
        candela.scene_from_dict(PROBE_SCENE).solve(**kwargs)


def test_target_error_out_of_the_library_range_is_its_usage_error():
    with pytest.raises(candela.UsageError) as e:
        candela.scene_from_dict(PROBE_SCENE).solve(target_error=0.9)
    assert e.value.status == 2 and "0.9" in e.value.message


def test_a_luminaire_that_lights_nothing_is_a_warning():
    scene = copy.deepcopy(PROBE_SCENE)
    scene["luminaires"][0]["position"] = [0, 0, -2]  # below the probes, which face up
    result = candela.scene_from_dict(scene).solve()
    np.testing.assert_array_equal(result.grids["probes"].E, [0.0, 0.0])
    assert any("probes" in w for w in result.warnings), result.warnings


# ---------------------------------------------------------------------------
# The example office at draft quality, solved once from Python and once by
# the command, with the same scene file and seed.

# CSV column -> (attribute, column of a 2-D array or None)
COLUMNS = {
    "x": ("points", 0),
    "y": ("points", 1),
    "z": ("points", 2),
    "nx": ("normals", 0),
    "ny": ("normals", 1),
    "nz": ("normals", 2),
    "E_lx": ("E", None),
    "E_direct_lx": ("E_direct", None),
    "E_indirect_lx": ("E_indirect", None),
    "E_stderr_lx": ("E_stderr", None),
    "area_m2": ("area_m2", None),
    "AO": ("AO", None),
    "AO_stderr": ("AO_stderr", None),
    "Ez_lx": ("Ez", None),
    "Ez_stderr_lx": ("Ez_stderr", None),
    "Esz_lx": ("Esz", None),
    "Esz_stderr_lx": ("Esz_stderr", None),
    "L_cd_m2": ("L", None),
}


@pytest.fixture(scope="module")
def office(tmp_path_factory):
    """(scene path, its Python SolveResult, the command's output folder)."""
    folder = tmp_path_factory.mktemp("office")
    path = write_office_draft(folder)
    result = candela.load_scene(path).solve()
    run_cli("solve", path, "-o", folder / "cli", "--quiet")
    return path, result, folder / "cli"


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], np.array([[float(v) for v in row] for row in rows[1:]])


def test_office_arrays_equal_the_command_csv(office):
    path, result, cli = office
    scene = candela.load_scene(path)
    assert list(result.grids) == scene.grid_names == ["workplane", "floor", "north_wall", "desk_probes"]
    for name, grid in result.grids.items():
        header, table = read_csv(cli / f"{name}.csv")
        assert len(grid) == table.shape[0]
        for k, column in enumerate(header):
            attribute, index = COLUMNS[column]
            values = getattr(grid, attribute)
            assert values is not None, f"{name}: {column} in the CSV, {attribute} None"
            values = values[:, index] if index is not None else values
            # Same scene, seed and library: the same doubles; the CSV's 17
            # significant digits give each back exactly.
            np.testing.assert_array_equal(values, table[:, k], err_msg=f"{name}.{column}")
        # an output the CSV does not have is None (area_m2, in the CSV of
        # polygon grids only, is every grid's)
        present = {COLUMNS[c][0] for c in header} | {"area_m2"}
        for column, (attribute, _) in COLUMNS.items():
            if attribute not in present:
                assert getattr(grid, attribute) is None, f"{name}.{attribute}"
    # a rect grid's point stands for its cell: 5 m x 3 m over 20 x 12 cells
    np.testing.assert_array_equal(result.grids["workplane"].area_m2, 15.0 / 240.0)
    np.testing.assert_array_equal(result.grids["desk_probes"].area_m2, 1.0)


def test_office_statistics_follow_from_the_arrays(office):
    _, result, cli = office
    summary = json.loads((cli / "summary.json").read_text())["grids"]
    for name, grid in result.grids.items():
        s = grid.stats
        weights = grid.area_m2 if name != "desk_probes" else np.ones(len(grid))
        # Em: the area-weighted mean (plain for a points grid); a sum over a
        # few hundred points in another order: round-off well below 1e-12
        Em = np.sum(grid.E * weights) / np.sum(weights)
        assert s.Em_lx == pytest.approx(Em, rel=1e-12)
        assert s.Emin_lx == grid.E.min() and s.Emax_lx == grid.E.max()
        assert s.U0 == pytest.approx(s.Emin_lx / s.Em_lx, rel=1e-15)
        assert s.Ud == pytest.approx(s.Emin_lx / s.Emax_lx, rel=1e-15)
        assert s.count == len(grid)
        # the same figures summary.json gives: the same doubles, printed by
        # cJSON with 15 digits where they read back within a few ulp, else 17
        for key, value in (("E_avg_lx", s.Em_lx), ("E_min_lx", s.Emin_lx), ("E_max_lx", s.Emax_lx), ("U0", s.U0), ("Ud", s.Ud)):
            assert value == pytest.approx(summary[name][key], rel=1e-15), (name, key)
    assert result.info.quality == "draft" and result.info.seed == 1 and result.info.rays > 0
    assert set(result.plan) >= {"direct", "interreflection", "method"}


def test_write_gives_the_command_files(office, tmp_path):
    _, result, cli = office
    result.write(tmp_path / "out" / "office")
    out = tmp_path / "out" / "office"
    for name in result.grids:
        # deterministic: the same bytes as `candela solve`
        assert (out / f"{name}.csv").read_bytes() == (cli / f"{name}.csv").read_bytes(), name
    for name in ("workplane", "floor", "north_wall"):  # rect and polygon grids
        assert (out / f"{name}.exr").stat().st_size > 0 and (out / f"{name}.png").stat().st_size > 0
    ours = json.loads((out / "summary.json").read_text())
    theirs = json.loads((cli / "summary.json").read_text())
    assert ours["grids"] == theirs["grids"]
    assert ours["plan"] == theirs["plan"]
    with pytest.raises(candela.InputError, match="summary.json"):
        result.write(out / "summary.json")  # a file, not a folder


def test_direct_method_leaves_interreflection_out(office):
    path, _, _ = office
    result = candela.load_scene(path).solve(method="direct")
    assert result.info.method == "direct"
    for grid in result.grids.values():
        np.testing.assert_array_equal(grid.E_indirect, 0.0)
        np.testing.assert_array_equal(grid.E, grid.E_direct)


def test_scene_attributes():
    scene = candela.load_scene(SOURCE_DIR / "data" / "office" / "office.json")
    assert scene.path.endswith("office.json")
    assert scene.grid_names == ["workplane", "floor", "north_wall", "desk_probes"]
    assert (scene.luminaire_count, scene.surface_count) == (7, 4)
    assert (scene.method, scene.quality, scene.target_error, scene.seed) == ("auto", "normal", 0.005, 1)
