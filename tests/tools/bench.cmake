# The direct-illuminance benchmark (tools/bench/bench_direct.c), run small so
# it cannot rot: it must complete and report its ratio. No time is asserted
# (labels bench and no-sanitize). The specified size is the default:
#   build/bench_direct      # 1e5 points, 50 goniometric luminaires, 1e6 triangles
add_test(NAME tools/bench_direct COMMAND bench_direct --points 4000 --luminaires 8 --triangles 20000)
set_tests_properties(tools/bench_direct PROPERTIES LABELS "tools;bench;no-sanitize" TIMEOUT 300
                     PASS_REGULAR_EXPRESSION "ratio \\(solver / Embree, per core\\): [0-9.]+")
