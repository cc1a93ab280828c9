# Divergence detection (src/solvers/DivergenceMonitor.hpp), on the V2 bar of
# doc/verification.md with Fixed dt a multiple of its stable time step estimate:
#   divergence_v2_2.1x      diverges: non-zero exit, the message names the step, the point and
#                           the ratio, and the records written before read back (serial)
#   divergence_v2_2.1x_np2  the same on 2 ranks (the message is shared by every rank)
#   divergence_v2_1.5x      stable: finishes with "Done." and no divergence reported
#   divergence_v2_prescribed_2.1x  every component's motion prescribed: no warning, a note
find_program(PERIDOT_NCDUMP_EXECUTABLE ncdump)
set(PERIDOT_DIVERGENCE_DIR "${CMAKE_CURRENT_LIST_DIR}")
function(peridot_divergence_test name ratio expect np)
  set(args
    -DPERIDOT=$<TARGET_FILE:peridot> -DPERIDOT_DIFF=$<TARGET_FILE:peridot-diff>
    -DSOURCE_DIR=${PERIDOT_DIVERGENCE_DIR}
    -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/divergence/${name}
    -DCOMP=${CMAKE_CURRENT_SOURCE_DIR}/regression/points.comp
    -DRATIO=${ratio} -DEXPECT=${expect})
  if(PERIDOT_NCDUMP_EXECUTABLE)
    list(APPEND args -DNCDUMP=${PERIDOT_NCDUMP_EXECUTABLE})
  endif()
  set(labels divergence)
  if(np GREATER 1)
    list(APPEND args -DNP=${np} -DMPIEXEC=${MPIEXEC_EXECUTABLE})
    list(APPEND labels mpi)
  endif()
  add_test(NAME divergence_${name}
    COMMAND ${CMAKE_COMMAND} ${args} -P ${PERIDOT_DIVERGENCE_DIR}/RunDivergence.cmake)
  set_tests_properties(divergence_${name} PROPERTIES
    ENVIRONMENT "${PERIDOT_MPI_ENV}" LABELS "${labels}" TIMEOUT 180)
endfunction()

peridot_divergence_test(v2_2.1x 2.1 diverge 1)
peridot_divergence_test(v2_1.5x 1.5 finish 1)
peridot_divergence_test(v2_prescribed_2.1x 2.1 prescribed 1)
if(MPIEXEC_EXECUTABLE)
  peridot_divergence_test(v2_2.1x_np2 2.1 diverge 2)
endif()
