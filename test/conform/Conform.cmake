# Peridigm conformance (issue 12): decks using Peridigm features, each checked against an
# independent result at 1-3 ranks. Included from test/CMakeLists.txt.
set(PERIDOT_CONFORM_DIR "${CMAKE_CURRENT_LIST_DIR}")

# <name>: DECK at 1, 2 and 3 ranks equals REFERENCE (another way to write the same run) at 1.
function(peridot_conform_pair name case deck reference output comp)
  add_test(NAME conform_${name}
    COMMAND ${CMAKE_COMMAND}
      -DCASE_DIR=${PERIDOT_CONFORM_DIR}/decks/${case} -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/conform/${name}
      -DREFERENCE=${reference} -DDECK=${deck} -DOUTPUT=${output}
      -DCOMP=${PERIDOT_CONFORM_DIR}/${comp} "-DNPS=1;2;3" -DMPIEXEC=${MPIEXEC_EXECUTABLE}
      -DPERIDOT=$<TARGET_FILE:peridot> -DPERIDOT_DIFF=$<TARGET_FILE:peridot-diff>
      -P ${PERIDOT_CONFORM_DIR}/RunPair.cmake)
  set_tests_properties(conform_${name} PROPERTIES
    ENVIRONMENT "${PERIDOT_MPI_ENV}" LABELS "regression" TIMEOUT 600)
endfunction()

# A group named default / Default takes the blocks no other group names.
peridot_conform_pair(default_block DefaultBlock default.yaml named.yaml out.e exact.comp)
peridot_conform_pair(Default_block DefaultBlock capitalised.yaml named.yaml out.e exact.comp)
# An XML parameter repeated with the same value runs (with a warning) as if given once.
peridot_conform_pair(repeated_key RepeatedKey repeated.xml single.xml out.e exact.comp)
