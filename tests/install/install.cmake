# The install tests share one installed prefix: install/prefix installs the
# build into it (a ctest fixture, set up once), the others read it, and
# install/remove_prefix deletes it. The prefix is outside the build tree (a
# library inside the build tree would take its data from the source tree,
# solver/output/ocio_config_path.c).
string(MD5 _candela_build_hash "${CMAKE_BINARY_DIR}")
string(SUBSTRING "${_candela_build_hash}" 0 12 _candela_build_hash)
set(_candela_tmp "$ENV{TMPDIR}")
if(NOT _candela_tmp)
  set(_candela_tmp /tmp)
endif()
set(CANDELA_TEST_PREFIX "${_candela_tmp}/candela-install-${_candela_build_hash}")
# In the sanitizer build the programs built against the installed library
# are instrumented too (the instrumented library needs the runtimes first).
set(_candela_sanitize_flags "")
if(CANDELA_SANITIZE)
  set(_candela_sanitize_flags "-fsanitize=address,undefined -fno-omit-frame-pointer")
endif()
set(_candela_install_env
  "CANDELA_TEST_PREFIX=${CANDELA_TEST_PREFIX}"
  "CANDELA_INSTALL_LIBDIR=${CMAKE_INSTALL_LIBDIR}"
  "CANDELA_PROJECT_VERSION=${PROJECT_VERSION}"
  "CANDELA_ABI_VERSION=${CANDELA_ABI_VERSION}"
  "CANDELA_CONFIGURED_DATA_DIR=${CMAKE_INSTALL_FULL_DATADIR}/candela"
  "CANDELA_APIDOC=$<TARGET_FILE:cdl_apidoc>"
  "CANDELA_SANITIZE_FLAGS=${_candela_sanitize_flags}"
  "CMAKE_COMMAND=${CMAKE_COMMAND}"
  "CXX=${CMAKE_CXX_COMPILER}")
foreach(_src IN LISTS _sh_tests)
  candela_test_name("${_src}" _short)
  set_property(TEST "${_short}" APPEND PROPERTY ENVIRONMENT ${_candela_install_env})
  if(_short STREQUAL "install/prefix")
    set_property(TEST "${_short}" PROPERTY FIXTURES_SETUP candela_prefix)
  else()
    set_property(TEST "${_short}" PROPERTY FIXTURES_REQUIRED candela_prefix)
  endif()
endforeach()
add_test(NAME install/remove_prefix COMMAND ${CMAKE_COMMAND} -E rm -rf "${CANDELA_TEST_PREFIX}")
set_tests_properties(install/remove_prefix PROPERTIES LABELS install FIXTURES_CLEANUP candela_prefix)
