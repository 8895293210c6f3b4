"""Bad input raises a CandelaError subclass carrying the library's message:
the file, the line or the JSON path, and what was expected. Never a crash."""

import copy
import json

import pytest

import candela
from conftest import PROBE_SCENE, SOURCE_DIR


def test_bad_value_in_a_scene_dict_names_its_json_path():
    scene = copy.deepcopy(PROBE_SCENE)
    scene["luminaires"][0]["position"] = [0, 0]
    with pytest.raises(candela.InputError) as e:
        candela.scene_from_dict(scene)
    assert "luminaires[0].position" in e.value.message and "expected" in e.value.message
    assert e.value.status == 1 and isinstance(e.value, ValueError) and isinstance(e.value, candela.CandelaError)
    assert str(e.value) == e.value.message


def test_unknown_key_is_refused_with_its_path():
    scene = copy.deepcopy(PROBE_SCENE)
    scene["grids"][0]["spacing_typo"] = 1
    with pytest.raises(candela.InputError, match=r"grids\[0\]"):
        candela.scene_from_dict(scene)


@pytest.mark.parametrize(
    "value, message",
    [
        (float("nan"), r"luminaires\[0\]\.intensity_cd: expected a finite number"),
        (float("inf"), r"luminaires\[0\]\.intensity_cd: expected a finite number"),
        (object(), r"luminaires\[0\]\.intensity_cd: expected a JSON value"),
    ],
)
def test_values_json_cannot_hold_are_refused_with_their_path(value, message):
    scene = copy.deepcopy(PROBE_SCENE)
    scene["luminaires"][0]["intensity_cd"] = value
    with pytest.raises(candela.InputError, match=message):
        candela.scene_from_dict(scene)


def test_a_scene_dict_must_be_a_dict():
    with pytest.raises(candela.UsageError, match="expected a dict"):
        candela.scene_from_dict([PROBE_SCENE])


def test_scene_file_errors_name_the_file(tmp_path):
    with pytest.raises(candela.InputError, match="missing.json"):
        candela.load_scene(tmp_path / "missing.json")
    broken = tmp_path / "broken.json"
    broken.write_text('{"version": 1,\n "luminaires": [\n}')
    with pytest.raises(candela.InputError, match=r"broken\.json:3:\d+: invalid JSON"):
        candela.load_scene(broken)


def test_a_path_with_a_nul_is_refused(tmp_path):
    # (a C string would end at the NUL and name another file)
    (tmp_path / "scene.json").write_text(json.dumps(PROBE_SCENE))
    with pytest.raises(candela.UsageError, match="NUL"):
        candela.load_scene(str(tmp_path / "scene.json") + "\0.ies")
    with pytest.raises(candela.UsageError, match="NUL"):
        candela.read_photometry(str(SOURCE_DIR / "data" / "office" / "downlight.ies") + "\0x")
    with pytest.raises(candela.UsageError, match="NUL"):
        candela.scene_from_dict(PROBE_SCENE, base_dir=str(tmp_path) + "\0x")


def test_relative_files_resolve_against_base_dir(tmp_path, monkeypatch):
    scene = copy.deepcopy(PROBE_SCENE)
    scene["luminaires"] = [{"type": "goniometric", "file": "downlight.ies", "position": [0, 0, 2]}]
    office = SOURCE_DIR / "data" / "office"
    probes = candela.scene_from_dict(scene, base_dir=office).solve().grids["probes"]
    assert probes.E[0] > 0.0
    # From another folder without base_dir the file is not there: the solve
    # (which reads photometric files) names the luminaire's JSON path.
    monkeypatch.chdir(tmp_path)
    with pytest.raises(candela.InputError) as e:
        candela.scene_from_dict(scene).solve()
    assert "luminaires[0]" in e.value.message and "downlight.ies" in e.value.message
    assert str(tmp_path) in e.value.message  # the scene's name: base folder and <scene dict>


def test_solve_error_of_a_scene_file_names_its_path(tmp_path):
    scene = copy.deepcopy(PROBE_SCENE)
    scene["luminaires"] = [{"type": "goniometric", "file": "nowhere.ies", "position": [0, 0, 2]}]
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(scene))
    with pytest.raises(candela.InputError, match=r"scene\.json.*luminaires\[0\].*nowhere\.ies"):
        candela.load_scene(path).solve()


def test_closed_scene_is_refused():
    scene = candela.scene_from_dict(PROBE_SCENE)
    scene.close()
    with pytest.raises(candela.UsageError, match="closed"):
        scene.solve()


def test_closed_result_cannot_write(tmp_path):
    with candela.scene_from_dict(PROBE_SCENE).solve() as result:
        pass
    assert list(result.grids["probes"].E) == [250.0, 128.0]  # the arrays stay (exact, as in test_solve)
    with pytest.raises(candela.UsageError, match="closed"):
        result.write(tmp_path)
