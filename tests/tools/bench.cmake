# The direct-illuminance benchmark (tools/bench/bench_direct.c), run small so
# it cannot rot: it must complete and report its ratio. No time is asserted
# (labels bench and no-sanitize). The specified size is the default:
#   build/bench_direct      # 1e5 points, 50 goniometric luminaires, 1e6 triangles
add_test(NAME tools/bench_direct COMMAND bench_direct --points 4000 --luminaires 8 --triangles 20000)
set_tests_properties(tools/bench_direct PROPERTIES LABELS "tools;bench;no-sanitize" TIMEOUT 300
                     PASS_REGULAR_EXPRESSION "ratio \\(solver / Embree, per core\\): [0-9.]+")

# The dense-map benchmark (tools/bench/bench_icache.c), run small: 20 x 20
# and 10 x 10 grids, two rungs a method, a reference to 0.2 %. It must
# complete, report its ratio and give the same bytes on one thread and on
# all (it exits 1 otherwise). No time is asserted. Full size: build/bench_icache
add_test(NAME tools/bench_icache COMMAND bench_icache --small --reference-target 0.002)
set_tests_properties(tools/bench_icache PROPERTIES LABELS "tools;bench;no-sanitize" TIMEOUT 600
                     PASS_REGULAR_EXPRESSION "ratio \\(pathtrace / icache, equal RMS\\): [0-9.]+")

# The annual study's hours once the coefficients exist (tools/bench/bench_annual.c),
# run small: the product and the metrics must complete, report their ratio to
# the issue's minute and agree with a plain loop (it exits 1 otherwise). No time
# is asserted. Full size: build/bench_annual (8760 hours x 10^4 points, MF 1;
# --mf 4 for 2305 sky patches).
add_test(NAME tools/bench_annual COMMAND bench_annual --points 400)
set_tests_properties(tools/bench_annual PROPERTIES LABELS "tools;bench;no-sanitize" TIMEOUT 300
                     PASS_REGULAR_EXPRESSION "ratio to one minute \\(8760 hours x 10\\^4 points scaled\\): [0-9.]+")
