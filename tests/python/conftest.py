"""Shared fixtures of the Python package's tests (run by test_python.sh and
test_python_corpus.sh, which say which candela package and library they test)."""

import json
import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(os.environ["CANDELA_SOURCE_DIR"])
CANDELA = os.environ["CANDELA"]


def ies_text(lines):
    """An IES file's text from its lines, CR LF as LM-63 says."""
    return "".join(line + "\r\n" for line in lines)


@pytest.fixture
def write_ies(tmp_path):
    """write_ies(name, header_lines, record_lines): an LM-63-2002 file in
    tmp_path; header_lines are keyword lines, record_lines what follows
    TILT=NONE."""

    def write(name, keywords, records):
        path = tmp_path / name
        path.write_text(ies_text(["IESNA:LM-63-2002", *keywords, "TILT=NONE", *records]), newline="")
        return path

    return write


def run_cli(*args, check=True):
    """`candela ARGS...`: its completed process (text)."""
    done = subprocess.run([CANDELA, *map(str, args)], capture_output=True, text=True)
    if check and done.returncode != 0:
        raise AssertionError(f"candela {' '.join(map(str, args))} exited {done.returncode}: {done.stderr}")
    return done


def info_json(path):
    """`candela info --json FILE` as a dict."""
    return json.loads(run_cli("info", "--json", path).stdout)


# The probe scene of the README's C example: a 1000 cd point light 2 m
# above two probes facing up, one under it and one 1.5 m aside.
PROBE_SCENE = {
    "version": 1,
    "luminaires": [{"type": "point", "position": [0, 0, 2], "intensity_cd": 1000}],
    "grids": [
        {
            "name": "probes",
            "type": "points",
            "points": [{"p": [0, 0, 0], "n": [0, 0, 1]}, {"p": [1.5, 0, 0], "n": [0, 0, 1]}],
        }
    ],
}


def workplane_scene_dict(quality):
    """The example office with its work plane alone, interreflection path
    traced at quality: (the scene as a dict, the folder its files are in).
    At "normal" about ten seconds of work on two cores in chunks of two
    points; at "draft" a second or two."""
    office = SOURCE_DIR / "data" / "office"
    scene = json.loads((office / "office.json").read_text())
    scene["grids"] = [g for g in scene["grids"] if g["name"] == "workplane"]
    scene["solver"].update({"method": "pathtrace", "quality": quality})
    return scene, office


def write_office_draft(folder):
    """A copy of data/office/office.json at draft quality (its photometric
    files named by absolute path) in folder: its path."""
    office = SOURCE_DIR / "data" / "office"
    scene = json.loads((office / "office.json").read_text())
    for lum in scene["luminaires"]:
        if "file" in lum:
            lum["file"] = str(office / lum["file"])
    scene["solver"]["quality"] = "draft"
    path = folder / "office_draft.json"
    path.write_text(json.dumps(scene, indent=1))
    return path
