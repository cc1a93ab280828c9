# The Python post-processing package (python/peridot_post) on a small run's output, and the
# Gmsh example from its .geo to PNGs. Debian's python3 (python3-netcdf4, numpy, matplotlib).
set(PERIDOT_PYTHON /usr/bin/python3 CACHE FILEPATH "Python 3 with netCDF4, numpy and matplotlib")
file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/post)
add_test(NAME post_processing
  COMMAND ${PERIDOT_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/post/test_post.py $<TARGET_FILE:peridot>
          ${PROJECT_SOURCE_DIR}/python ${CMAKE_CURRENT_SOURCE_DIR}/post/small.yaml
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/post)
set_tests_properties(post_processing PROPERTIES LABELS "post" TIMEOUT 300)
add_test(NAME example_gmsh_plate COMMAND bash ${PROJECT_SOURCE_DIR}/examples/gmsh_plate/run.sh)
set_tests_properties(example_gmsh_plate PROPERTIES LABELS "post;example" TIMEOUT 300
  SKIP_RETURN_CODE 77
  ENVIRONMENT "PERIDOT=$<TARGET_FILE:peridot>;WORK=${CMAKE_CURRENT_BINARY_DIR}/examples/gmsh_plate")
# cmake --install into a temporary prefix: executables, launcher, package and docs in place, and
# the installed peridot-post runs.
add_test(NAME install_prefix
  COMMAND bash -c "set -e; p='${CMAKE_CURRENT_BINARY_DIR}/install_prefix'; rm -rf \"$p\"; \
'${CMAKE_COMMAND}' --install '${CMAKE_BINARY_DIR}' --prefix \"$p\" > /dev/null; \
for f in bin/peridot bin/peridot-diff bin/peridot-post share/peridot/python/peridot_post/__main__.py \
share/doc/peridot/README.md share/doc/peridot/deck-reference.md share/doc/peridot/references.md \
share/doc/peridot/examples/gmsh_plate/plate.geo; do test -s \"$p/$f\" || { echo missing $f; exit 1; }; done; \
\"$p/bin/peridot\" --version; \"$p/bin/peridot-post\" --help > /dev/null")
set_tests_properties(install_prefix PROPERTIES LABELS "post" TIMEOUT 300)
