"""The README's Python scripts, taken from README.md as printed there, run
headless: the probe scene's closed forms (250 and 128 lx), and the office
script with matplotlib (its plot written) and without it (skipped, the rest
done)."""

import csv
import os
import re
import subprocess
import sys

import pytest

from conftest import SOURCE_DIR


def readme_block(first_line_start):
    """The README's code block whose first line starts so."""
    text = (SOURCE_DIR / "README.md").read_text()
    for block in re.findall(r"^```python\n(.*?)^```", text, re.S | re.M):
        if block.startswith(first_line_start):
            return block
    raise AssertionError(f"README.md has no python block starting with {first_line_start!r}")


def run_script(tmp_path, source, prelude=""):
    """Run source (after prelude) in tmp_path, which sees the repository's
    data/ as its own, headless (matplotlib's Agg backend)."""
    script = tmp_path / "script.py"
    script.write_text(prelude + source)
    (tmp_path / "data").symlink_to(SOURCE_DIR / "data")
    env = dict(os.environ, MPLBACKEND="Agg", MPLCONFIGDIR=str(tmp_path / "mpl"))
    done = subprocess.run([sys.executable, str(script)], cwd=tmp_path, env=env, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_probe_script(tmp_path):
    out = run_script(tmp_path, readme_block("# probes.py"))
    # point light: exact closed forms, stated error 0 (test_solve.py)
    assert out.splitlines() == ["[0. 0. 0.]: 250 lx +- 0", "[1.5 0.  0. ]: 128 lx +- 0"]


def workplane_em(tmp_path):
    """Em of the work plane from the CSV the script wrote (its cells are
    equal, so the plain mean)."""
    with open(tmp_path / "out" / "office-draft" / "workplane.csv", newline="") as f:
        E = [float(row["E_lx"]) for row in csv.DictReader(f)]
    return sum(E) / len(E)


def test_office_script_plots_with_matplotlib(tmp_path):
    pytest.importorskip("matplotlib")  # (scripts/setup.sh installs it: the plot is tested there)
    out = run_script(tmp_path, readme_block("# office.py"))
    m = re.search(r"work plane: Em (\d+) lx", out)
    assert m, out
    # the printed Em is the CSV's, rounded to the lux
    assert abs(int(m.group(1)) - workplane_em(tmp_path)) <= 0.5
    assert "plot: out/office-draft/workplane-plot.png" in out
    assert (tmp_path / "out" / "office-draft" / "workplane-plot.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_office_script_without_matplotlib(tmp_path):
    # matplotlib made unimportable, as where it is not installed
    prelude = "import sys\nsys.modules['matplotlib'] = None\nsys.modules['matplotlib.pyplot'] = None\n"
    out = run_script(tmp_path, readme_block("# office.py"), prelude)
    assert "matplotlib is not installed: no plot" in out
    assert not (tmp_path / "out" / "office-draft" / "workplane-plot.png").exists()
    assert (tmp_path / "out" / "office-draft" / "summary.json").exists()
