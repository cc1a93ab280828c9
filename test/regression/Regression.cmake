# Peridigm's own cases (from shared/peridigm-cases), run unmodified from a copy of the case
# folder at 1, 2 and 3 ranks, each output compared with the gold file by peridot-diff.
set(PERIDOT_CASES_DIR "${PERIDOT_SHARED_DIR}/peridigm-cases")

function(peridot_case name deck comp)
  foreach(np 1 2 3)
    add_test(NAME regression_${name}_np${np}
      COMMAND ${CMAKE_COMMAND}
        -DCASE_DIR=${PERIDOT_CASES_DIR}/${name}
        -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/regression/${name}_np${np}
        -DDECK=${deck} -DNP=${np} -DMPIEXEC=${MPIEXEC_EXECUTABLE}
        -DPERIDOT=$<TARGET_FILE:peridot> -DPERIDOT_DIFF=$<TARGET_FILE:peridot-diff>
        -DCOMP=${comp} -DOUTPUT=${name}.e -DGOLD=${name}_gold.e
        -P ${CMAKE_CURRENT_SOURCE_DIR}/regression/RunCase.cmake)
    set_tests_properties(regression_${name}_np${np} PROPERTIES
      ENVIRONMENT "${PERIDOT_MPI_ENV}" LABELS "regression" TIMEOUT 600)
  endforeach()
endfunction()

if(EXISTS "${PERIDOT_CASES_DIR}")
  peridot_case(WaveInBar WaveInBar.xml WaveInBar.comp)
  peridot_case(ElasticBondBased3D ElasticBondBased3D.yaml ElasticBondBased.comp)
  peridot_case(BondBreakingInitialVelocity BondBreakingInitialVelocity.xml BondBreakingInitialVelocity.comp)
  peridot_case(Compression_2x1x1 Compression_2x1x1.yaml Compression_2x1x1.comp)
else()
  message(WARNING "Peridigm cases not found at ${PERIDOT_CASES_DIR}: regression tests skipped")
endif()
