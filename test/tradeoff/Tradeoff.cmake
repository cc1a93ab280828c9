# The speed/accuracy maps of bench/tradeoff (doc/verification.md): a quick point of each in the
# default suite, with a bound that can fail.
# Static map: plate with a hole under tension, LPS at delta = 3.015 dx, QuasiStatic: the
# displacement within 3% (relative L2) of Kirsch's field (measured 1.7%).
add_test(NAME tradeoff_static_map_quick
  COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/bench/tradeoff/static_map.py --quick
    --peridot $<TARGET_FILE:peridot> --workdir ${CMAKE_CURRENT_BINARY_DIR}/tradeoff/static_map)
set_tests_properties(tradeoff_static_map_quick PROPERTIES LABELS "example" TIMEOUT 300)
