# Runs a reference deck on 1 rank, then a deck written another way at each rank count in NPS,
# and requires each output to equal the reference to the bit (peridot-diff, zero tolerances):
# the second deck's feature is checked against a second code path. Variables: CASE_DIR,
# WORK_DIR, REFERENCE, DECK, OUTPUT, COMP, NPS, MPIEXEC, PERIDOT, PERIDOT_DIFF.
set(ref "${WORK_DIR}/reference")
file(REMOVE_RECURSE "${WORK_DIR}")
file(COPY "${CASE_DIR}/" DESTINATION "${ref}")
execute_process(COMMAND ${MPIEXEC} --oversubscribe -np 1 ${PERIDOT} ${REFERENCE}
                WORKING_DIRECTORY "${ref}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "reference ${REFERENCE} failed (${rc}):\n${out}\n${err}")
endif()
foreach(np ${NPS})
  set(dir "${WORK_DIR}/np${np}")
  file(COPY "${CASE_DIR}/" DESTINATION "${dir}")
  execute_process(COMMAND ${MPIEXEC} --oversubscribe -np ${np} ${PERIDOT} ${DECK}
                  WORKING_DIRECTORY "${dir}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${DECK} failed at ${np} ranks (${rc}):\n${out}\n${err}")
  endif()
  message("${out}${err}")
  execute_process(COMMAND ${PERIDOT_DIFF} ${COMP} "${dir}/${OUTPUT}" "${ref}/${OUTPUT}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${DECK} at ${np} ranks vs ${REFERENCE}: ${out}${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${DECK} at ${np} ranks differs from ${REFERENCE}")
  endif()
endforeach()
