# The Python package `candela` (python/candela/, over the shared library
# through ctypes): installed by `cmake --install` under the prefix's Python
# site folder, with a note of where the library lies relative to it, so the
# installed package finds libcandela.so.N without LD_LIBRARY_PATH and the
# prefix can move.
#
# CANDELA_PYTHON is the interpreter the site folder is asked of and the
# tests run (python/ tests): by default the system's /usr/bin/python3, for
# which scripts/setup.sh installs NumPy and pytest, else python3 on PATH.
# CANDELA_PYTHON_DIR is the folder, relative to the prefix: the one that
# interpreter searches under CMAKE_INSTALL_PREFIX when it has one (a virtual
# environment's lib/python3.X/site-packages), else the one it searches under
# /usr/local (Debian's lib/python3.X/dist-packages: the same name under every
# prefix, on the path under the default one), else the standard layout
# lib/python3.X/site-packages.
find_program(CANDELA_PYTHON NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH
             DOC "Python 3 interpreter for the Python package's site folder and tests")
find_program(CANDELA_PYTHON NAMES python3
             DOC "Python 3 interpreter for the Python package's site folder and tests")
set(_candela_site_script [=[
import os, sys, sysconfig
def searched(prefix):
    for p in sys.path:
        if os.path.basename(p) in ("site-packages", "dist-packages") and p.startswith(prefix + os.sep):
            return os.path.relpath(p, prefix)
    return None
standard = sysconfig.get_path("purelib", "posix_prefix", vars={"base": "/", "platbase": "/"})
print(searched(os.path.abspath(sys.argv[1])) or searched("/usr/local") or os.path.relpath(standard, "/"))
]=])
set(_candela_site "lib/python3/site-packages")
if(CANDELA_PYTHON)
  execute_process(COMMAND "${CANDELA_PYTHON}" -c "${_candela_site_script}" "${CMAKE_INSTALL_PREFIX}"
                  OUTPUT_VARIABLE _candela_site_found RESULT_VARIABLE _candela_site_rc
                  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(_candela_site_rc EQUAL 0 AND _candela_site_found)
    set(_candela_site "${_candela_site_found}")
  endif()
endif()
set(CANDELA_PYTHON_DIR "${_candela_site}" CACHE STRING
    "Where the Python package goes, relative to the install prefix (or absolute)")
message(STATUS "Python package: <prefix>/${CANDELA_PYTHON_DIR}/candela (interpreter ${CANDELA_PYTHON})")

if(IS_ABSOLUTE "${CANDELA_PYTHON_DIR}")
  set(_candela_python_full "${CANDELA_PYTHON_DIR}")
else()
  set(_candela_python_full "${CMAKE_INSTALL_PREFIX}/${CANDELA_PYTHON_DIR}")
endif()
file(RELATIVE_PATH _candela_lib_from_package "${_candela_python_full}/candela"
     "${CMAKE_INSTALL_FULL_LIBDIR}/libcandela.so.${CANDELA_ABI_VERSION}")
file(CONFIGURE OUTPUT "${CMAKE_BINARY_DIR}/python/_install_location.py" CONTENT [=[
"""Where `cmake --install` put libcandela, relative to this package (written at install)."""
LIBRARY_FROM_PACKAGE = "@_candela_lib_from_package@"
]=] @ONLY)

install(DIRECTORY python/candela/ DESTINATION "${CANDELA_PYTHON_DIR}/candela"
        FILES_MATCHING PATTERN "*.py" PATTERN "py.typed" PATTERN "__pycache__" EXCLUDE)
install(FILES "${CMAKE_BINARY_DIR}/python/_install_location.py" DESTINATION "${CANDELA_PYTHON_DIR}/candela")
