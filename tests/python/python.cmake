# What the Python tests need beyond the common test environment: the
# interpreter (CANDELA_PYTHON, python/install.cmake), where the package goes
# under a prefix, the ABI and release the package must match, and whether
# the library is built with the sanitizers (its runtimes must then be loaded
# into Python first).
set(_candela_python_env
  "CANDELA_PYTHON=${CANDELA_PYTHON}"
  "CANDELA_PYTHON_DIR=${CANDELA_PYTHON_DIR}"
  "CANDELA_INSTALL_LIBDIR=${CMAKE_INSTALL_LIBDIR}"
  "CANDELA_ABI_VERSION=${CANDELA_ABI_VERSION}"
  "CANDELA_PROJECT_VERSION=${PROJECT_VERSION}"
  "CANDELA_LIBRARY_BUILT=$<TARGET_FILE:candela_shared>"
  "CANDELA_SANITIZE=$<BOOL:${CANDELA_SANITIZE}>"
  "CMAKE_COMMAND=${CMAKE_COMMAND}")
foreach(_src IN LISTS _sh_tests)
  candela_test_name("${_src}" _short)
  set_property(TEST "${_short}" APPEND PROPERTY ENVIRONMENT ${_candela_python_env})
endforeach()
