# The photometry benchmark: reads and summarises every file of the corpus
# folder and prints files/s and MB/s. The one figure asserted: reading the
# largest file (the 1.3 MB one) as a ratio to a strtod pass over the same
# bytes in the same process (labels: bench, corpus; no-sanitize keeps it out
# of the sanitizer pass, where timings mean nothing).
add_executable(bench_photometry "${CMAKE_CURRENT_LIST_DIR}/bench_photometry.c")
target_compile_options(bench_photometry PRIVATE ${CANDELA_WARNINGS})
target_compile_definitions(bench_photometry PRIVATE CANDELA_PHOTOMETRIC_DIR="${CANDELA_PHOTOMETRIC_DIR}")
target_link_libraries(bench_photometry PRIVATE candela)
set_target_properties(bench_photometry PROPERTIES LINKER_LANGUAGE CXX)
add_test(NAME lights/bench_photometry COMMAND bench_photometry)
set_tests_properties(lights/bench_photometry PROPERTIES LABELS "lights;bench;corpus;no-sanitize" TIMEOUT 300
                     ENVIRONMENT "${CANDELA_TEST_ENV}" SKIP_RETURN_CODE 77)
