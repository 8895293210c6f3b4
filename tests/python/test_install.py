"""How the package is installed and finds the library: `cmake --install`
(the prefix this test run installed, and the same prefix moved), and
`pip install --no-build-isolation ./python` from a copy of the checkout,
in a virtual environment and as Debian's system-wide command (under a
--root of our own)."""

import json
import os
import pathlib
import shutil
import subprocess
import sys

import candela
from conftest import PROBE_SCENE, SOURCE_DIR

PREFIX = pathlib.Path(os.environ["CANDELA_TEST_PREFIX"])
SITE = PREFIX / os.environ["CANDELA_PYTHON_DIR"]
LIBRARY = PREFIX / os.environ["CANDELA_INSTALL_LIBDIR"] / f"libcandela.so.{os.environ['CANDELA_ABI_VERSION']}"

# A child's check: where candela and its library came from, and the probe
# scene's illuminance (250 and 128 lx: test_solve.py).
PROBE = f"""
import json, candela
scene = candela.scene_from_dict({PROBE_SCENE!r})
E = scene.solve().grids["probes"].E
print(json.dumps({{"package": candela.__file__, "library": candela.LIBRARY_PATH, "E": E.tolist()}}))
"""


def run_probe(python, env_extra=None, cwd=None):
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "CANDELA_LIBRARY", "LD_LIBRARY_PATH")}
    env.update(env_extra or {})
    done = subprocess.run([str(python), "-c", PROBE], env=env, cwd=cwd, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def test_cmake_install_puts_the_package_beside_its_library():
    package = pathlib.Path(candela.__file__).parent
    assert package == SITE / "candela"
    assert pathlib.Path(candela.LIBRARY_PATH) == LIBRARY
    assert "CANDELA_LIBRARY" not in os.environ and "LD_LIBRARY_PATH" not in os.environ
    installed = sorted(p.name for p in package.iterdir() if p.name != "__pycache__")
    source = sorted(p.name for p in (SOURCE_DIR / "python" / "candela").iterdir() if p.name != "__pycache__")
    assert installed == sorted(source + ["_install_location.py"])


def test_the_installed_prefix_can_move(tmp_path):
    moved = tmp_path / "elsewhere"
    shutil.copytree(PREFIX, moved, symlinks=True)
    out = run_probe(sys.executable, {"PYTHONPATH": str(moved / os.environ["CANDELA_PYTHON_DIR"])}, cwd=tmp_path)
    assert out["package"].startswith(str(moved))
    assert pathlib.Path(out["library"]).resolve() == (moved / LIBRARY.relative_to(PREFIX)).resolve()
    assert out["E"] == [250.0, 128.0]  # exact: a point light's closed form


def checkout_copy(tmp_path):
    """The checkout's python/ folder, copied (pip builds in the tree it is given)."""
    copy = tmp_path / "python"
    shutil.copytree(SOURCE_DIR / "python", copy, ignore=shutil.ignore_patterns("build", "*.egg-info", "__pycache__"))
    return copy


def pip_install(python, *args):
    """pip install --no-build-isolation ARGS, never from the index (a test
    does not reach the network; the install needs nothing from it)."""
    done = subprocess.run(
        [str(python), "-m", "pip", "install", "--no-build-isolation", "--no-index", *map(str, args)],
        capture_output=True,
        text=True,
    )
    assert done.returncode == 0, done.stdout + done.stderr


def test_pip_install_into_a_virtual_environment(tmp_path):
    # as the README says: the venv's own pip (python3-venv's), Debian's NumPy
    # and setuptools through --system-site-packages
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(venv)], check=True)
    pip_install(venv / "bin" / "python", checkout_copy(tmp_path))
    out = run_probe(venv / "bin" / "python", {"CANDELA_LIBRARY": str(LIBRARY)}, cwd=tmp_path)
    assert out["package"].startswith(str(venv)) and out["library"] == str(LIBRARY)
    assert out["E"] == [250.0, 128.0]
    # without a pointer to the library, the import says how to give one
    done = subprocess.run(
        [str(venv / "bin" / "python"), "-c", "import candela"],
        env={k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "CANDELA_LIBRARY", "LD_LIBRARY_PATH")},
        cwd=tmp_path,
        capture_output=True,
        text=True,
    )
    if done.returncode != 0:  # (a libcandela in the system's folders would be found instead)
        assert "CANDELA_LIBRARY" in done.stderr and "ImportError" in done.stderr


def test_pip_install_system_wide_with_break_system_packages(tmp_path):
    # Debian 12's pip refuses the system's Python without the flag; --root
    # keeps the files under tmp_path, laid out as they would be under /.
    root = tmp_path / "root"
    pip_install(sys.executable, "--break-system-packages", "--root", root, checkout_copy(tmp_path))
    found = list(root.rglob("candela/__init__.py"))
    assert len(found) == 1
    site = "/" + str(found[0].parent.parent.relative_to(root))
    assert site in sys.path, f"{site} is not on {sys.executable}'s path"
    out = run_probe(sys.executable, {"PYTHONPATH": str(found[0].parent.parent), "CANDELA_LIBRARY": str(LIBRARY)}, cwd=tmp_path)
    assert out["E"] == [250.0, 128.0]
