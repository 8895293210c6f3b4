"""Every file of the corpus of real photometric files, read from Python,
gives what `candela info --json` gives: the same flux (lumens, or watts for a
radiometric file and then no lumens), LOR, peak intensity, beam and field
angles and warning codes; a file the command refuses raises InputError with
the command's message. Both read the file through the same library, so the
figures are the same doubles; JSON carries them within a few ulp (cJSON
prints 15 significant digits where they read back within its epsilon, else
17), hence the tolerance of 1e-15 relative."""

import json
import os
import pathlib

import pytest

import candela
from conftest import run_cli

CORPUS = pathlib.Path(os.environ["CANDELA_PHOTOMETRIC_DIR"])
SUFFIXES = {".ies", ".ldt"}
FILES = sorted(p for p in CORPUS.iterdir() if p.suffix.lower() in SUFFIXES)
# (cJSON's printing of a double: a few ulp)
REL = 1e-15


@pytest.fixture(scope="module")
def info():
    """`candela info --json` of every file at once, by path (exit 1 is
    expected: the corpus holds malformed files on purpose)."""
    done = run_cli("info", "--json", *FILES, check=False)
    assert done.returncode in (0, 1), done.stderr
    return {entry["file"]: entry for entry in json.loads(done.stdout)}


def test_corpus_is_there():
    assert len(FILES) >= 20, f"expected the corpus's files in {CORPUS}"


def same(python_value, json_value):
    if json_value is None:
        return python_value is None
    return python_value == pytest.approx(json_value, rel=REL, abs=1e-300)


@pytest.mark.parametrize("path", FILES, ids=[p.name for p in FILES])
def test_file_reads_as_candela_info_reads_it(path, info):
    expected = info[str(path)]
    if "error" in expected:
        with pytest.raises(candela.InputError) as e:
            candela.read_photometry(path)
        assert e.value.message == expected["error"]
        return
    p = candela.read_photometry(path)
    assert p.radiometric == expected["radiometric"]
    if p.radiometric:
        assert p.flux_lm is None and expected["flux_lm"] is None
        assert same(p.radiant_flux_w, expected["radiant_flux_w"])
        assert same(p.max_radiant_intensity_w_sr, expected["max_radiant_intensity_w_sr"])
    else:
        assert same(p.flux_lm, expected["flux_lm"]), (p.flux_lm, expected["flux_lm"])
        assert same(p.table_flux_lm, expected["table_flux_lm"])
        assert same(p.max_intensity_cd, expected["max_intensity_cd"])
    assert same(p.lor, expected["lor"])
    assert same(p.efficacy_lm_per_w, expected["efficacy_lm_per_w"])
    assert p.spread_about == expected["spread_about"]
    for key in ("beam_angle_deg", "field_angle_deg"):
        got = getattr(p, key)
        assert set(got) == set(expected[key])
        for plane, value in expected[key].items():
            assert same(got[plane], value), (key, plane)
    assert [w.code for w in p.warnings] == [w["code"] for w in expected["warnings"]]
    assert [w.line for w in p.warnings] == [w["line"] for w in expected["warnings"]]
