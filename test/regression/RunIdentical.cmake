# Runs a deck at several rank counts and requires every output to equal the 1-rank output to
# the bit (peridot-diff with zero tolerances). Variables: CASE_DIR, WORK_DIR, DECK, OUTPUT,
# COMP, NPS (list), MPIEXEC, PERIDOT, PERIDOT_DIFF, ALL_IDS (optional: write all_points.txt
# with ids 1..ALL_IDS).
set(reference "")
foreach(np ${NPS})
  set(dir "${WORK_DIR}/np${np}")
  file(REMOVE_RECURSE "${dir}")
  file(COPY "${CASE_DIR}/" DESTINATION "${dir}")
  if(ALL_IDS)
    set(ids "")
    foreach(i RANGE 1 ${ALL_IDS})
      string(APPEND ids "${i}\n")
    endforeach()
    file(WRITE "${dir}/all_points.txt" "${ids}")
  endif()
  execute_process(COMMAND ${MPIEXEC} --oversubscribe -np ${np} ${PERIDOT} ${DECK}
                  WORKING_DIRECTORY "${dir}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "peridot failed at ${np} ranks (${rc}):\n${out}\n${err}")
  endif()
  if(reference STREQUAL "")
    set(reference "${dir}/${OUTPUT}")
  else()
    execute_process(COMMAND ${PERIDOT_DIFF} ${COMP} "${dir}/${OUTPUT}" "${reference}"
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    message("${np} ranks vs 1 rank: ${out}${err}")
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "results at ${np} ranks differ from 1 rank")
    endif()
  endif()
endforeach()
