"""candela.read_photometry against closed forms, on files written here.

The tables are LM-63 single-plane tables at gamma 0, 90 and 180 degrees,
which the library interpolates linearly in gamma (as LM-63 readers do):
 - the cone, I(gamma) = 1000 cd (1 - gamma / 90 deg) below the horizontal
   and 0 above: flux = 2 pi I0 int_0^{pi/2} (1 - 2 g / pi) sin g dg
   = 2 pi I0 (1 - 2 / pi) = 2000 pi - 4000 lm; half its peak at gamma 45
   (beam angle 90 deg), a tenth at gamma 81 (field angle 162 deg);
 - a uniform 100 cd table: 4 pi 100 lm; in mW/sr: 0.4 pi W, and no lumens.
"""

import math

import numpy as np
import pytest

import candela
from conftest import info_json

CONE_LM = 2000 * math.pi - 4000
CONE_RECORDS = ["0 90 180", "0", "1000 0 0"]


def cone(write_ies, ballast=1.0, lamp_lm=-1, watts=0):
    """The cone table, relative to lamp_lm (absolute when -1)."""
    return write_ies("cone.ies", ["[TEST] cone"], [f"1 {lamp_lm} 1 3 1 1 2 0 0 0", f"{ballast} 1 {watts}", *CONE_RECORDS])


def test_flux_of_the_cone_is_its_integral(write_ies):
    p = candela.read_photometry(cone(write_ies))
    # The library integrates the interpolated table exactly: only round-off
    # in a few dozen operations separates it from the closed form.
    assert p.flux_lm == pytest.approx(CONE_LM, rel=1e-12)
    assert p.table_flux_lm == pytest.approx(CONE_LM, rel=1e-12)
    assert p.radiant_flux_w is None and not p.radiometric
    assert p.max_intensity_cd == 1000.0
    assert p.format == "IES" and p.ies_version == 2002
    assert p.lor is None and p.lamp_flux_lm is None  # absolute photometry: no lamp flux, no ratio
    assert p.warnings == []


def test_ballast_factor_scales_the_luminaire_not_the_table(write_ies):
    p = candela.read_photometry(cone(write_ies, ballast=0.8, lamp_lm=3000, watts=25))
    # (relative tolerances: round-off only, as above)
    assert p.output_factor == 0.8
    assert p.flux_lm == pytest.approx(0.8 * CONE_LM, rel=1e-12)
    assert p.table_flux_lm == pytest.approx(CONE_LM, rel=1e-12)
    assert p.max_intensity_cd == pytest.approx(800.0, rel=1e-15)
    # LOR is the table's flux over the rated lamps' (the ballast factor is not in it)
    assert p.lor == pytest.approx(CONE_LM / 3000, rel=1e-12)
    assert p.lamp_flux_lm == 3000.0
    assert p.input_watts == 25.0
    assert p.efficacy_lm_per_w == pytest.approx(0.8 * CONE_LM / 25, rel=1e-12)
    # and what `candela info --json` says (the same doubles through cJSON's
    # printing: a few ulp, as in test_corpus.py)
    info = info_json(p.path)
    for key in ("flux_lm", "table_flux_lm", "lor", "max_intensity_cd", "efficacy_lm_per_w"):
        assert getattr(p, key) == pytest.approx(info[key], rel=1e-15), key


def test_beam_and_field_angles_of_the_cone(write_ies):
    p = candela.read_photometry(cone(write_ies))
    # Where 1 - g / 90 = 0.5 and 0.1: g = 45 and 81 deg, twice that across
    # nadir; the library's root finding is converged to round-off.
    assert p.spread_about == "nadir"
    assert p.beam_angle_deg == {"c0_c180": pytest.approx(90.0, abs=1e-9), "c90_c270": pytest.approx(90.0, abs=1e-9)}
    assert p.field_angle_deg == {"c0_c180": pytest.approx(162.0, abs=1e-9), "c90_c270": pytest.approx(162.0, abs=1e-9)}
    assert p.downward_fraction == pytest.approx(1.0, abs=1e-15)


def test_intensity_is_vectorised_and_interpolates_linearly(write_ies):
    p = candela.read_photometry(cone(write_ies, ballast=0.5))
    gamma = np.linspace(0.0, 180.0, 37)
    expected = 0.5 * np.where(gamma <= 90.0, 1000.0 * (1.0 - gamma / 90.0), 0.0)
    # linear interpolation of an exactly linear table: round-off only
    np.testing.assert_allclose(p.intensity(0.0, gamma), expected, rtol=0, atol=1e-9)
    # broadcasting: C along rows, gamma along columns; one plane, so C does not matter
    grid = p.intensity(np.array([[0.0], [90.0], [225.0]]), gamma[np.newaxis, :])
    assert grid.shape == (3, 37)
    np.testing.assert_allclose(grid, np.broadcast_to(expected, (3, 37)), rtol=0, atol=1e-9)
    value = p.intensity(10.0, 45.0)
    assert isinstance(value, float) and value == pytest.approx(250.0, abs=1e-9)
    with pytest.raises(candela.UsageError, match="finite"):
        p.intensity(0.0, [0.0, float("nan")])


def test_radiometric_file_never_answers_in_lumens(write_ies):
    path = write_ies("uv.ies", ["[TEST] uv", "[_INTENSITYUNITS] mW/sr"], ["1 -1 1 3 1 1 2 0 0 0", "1 1 0", "0 90 180", "0", "100 100 100"])
    p = candela.read_photometry(path)
    assert p.radiometric
    assert p.flux_lm is None and p.table_flux_lm is None and p.max_intensity_cd is None
    assert p.efficacy_lm_per_w is None
    # 100 mW/sr everywhere: 4 pi x 0.1 W (round-off only)
    assert p.radiant_flux_w == pytest.approx(0.4 * math.pi, rel=1e-12)
    assert p.max_radiant_intensity_w_sr == pytest.approx(0.1, rel=1e-15)
    np.testing.assert_allclose(p.radiant_intensity([0.0, 90.0, 180.0], [0.0, 45.0, 180.0]), 0.1, rtol=1e-15)
    with pytest.raises(candela.InputError, match="radiant intensity"):
        p.intensity(0.0, 0.0)
    info = info_json(path)  # the command agrees: no lumens
    assert info["radiometric"] and info["flux_lm"] is None
    assert p.radiant_flux_w == pytest.approx(info["radiant_flux_w"], rel=1e-15)
    photometric = candela.read_photometry(cone(write_ies))
    with pytest.raises(candela.InputError, match="spectrum"):
        photometric.radiant_intensity(0.0, 0.0)


def test_warnings_carry_code_line_and_message(write_ies):
    # 100 cd everywhere over one 1000 lm lamp: flux 400 pi = 1257 lm, LOR 1.26 > 1
    path = write_ies("lor.ies", ["[TEST] lor"], ["1 1000 1 3 1 1 2 0 0 0", "1 1 0", "0 90 180", "0", "100 100 100"])
    p = candela.read_photometry(path)
    assert p.lor == pytest.approx(0.4 * math.pi, rel=1e-12)
    codes = [w.code for w in p.warnings]
    assert "lor-above-1" in codes
    w = p.warnings[codes.index("lor-above-1")]
    assert "lor.ies" in w.message and (w.line is None or w.line > 0)
    with pytest.raises(candela.InputError, match="lor.ies"):
        candela.read_photometry(path, strict=True)


def test_write_converts_and_keeps_the_light(write_ies, tmp_path):
    p = candela.read_photometry(cone(write_ies, ballast=0.8, lamp_lm=3000, watts=25))
    lost = p.write(tmp_path / "cone.ldt")
    # EULUMDAT has no ballast factor: folded into the lamp flux, and said so
    assert any("ballast factor" in note for note in lost)
    ldt = candela.read_photometry(tmp_path / "cone.ldt")
    assert ldt.format == "EULUMDAT"
    # the same light: EULUMDAT holds cd/klm to 10 significant digits
    # (text_buffer.c), so each value, and the flux, within 5e-10 relative
    assert ldt.flux_lm == pytest.approx(p.flux_lm, rel=1e-9)
    assert p.write(tmp_path / "back.txt", format="ies", ies_version=2002) == []
    back = candela.read_photometry(tmp_path / "back.txt")
    assert back.format == "IES" and back.ies_version == 2002
    assert back.flux_lm == pytest.approx(p.flux_lm, rel=1e-9)  # (10 significant digits, as above)
    with pytest.raises(candela.UsageError, match=r"\.ies or \.ldt"):
        p.write(tmp_path / "cone.txt")
    with pytest.raises(candela.UsageError, match="format"):
        p.write(tmp_path / "cone.ies", format="pdf")
    with pytest.raises(candela.CandelaError, match="no_such_folder"):
        p.write(tmp_path / "no_such_folder" / "cone.ies")


def test_bad_files_name_file_and_line(tmp_path, write_ies):
    with pytest.raises(candela.InputError, match="missing.ies") as e:
        candela.read_photometry(tmp_path / "missing.ies")
    assert e.value.status == 1 and isinstance(e.value, ValueError)
    # three candela values promised, two given
    bad = write_ies("short.ies", ["[TEST] short"], ["1 -1 1 3 1 1 2 0 0 0", "1 1 0", "0 90 180", "0", "1000 0"])
    with pytest.raises(candela.InputError, match=r"short\.ies:\d+"):
        candela.read_photometry(bad)


def test_closed_photometry_is_refused(write_ies):
    p = candela.read_photometry(cone(write_ies))
    with p:
        assert p.intensity(0.0, 0.0) == 1000.0
    with pytest.raises(candela.UsageError, match="closed"):
        p.intensity(0.0, 0.0)
