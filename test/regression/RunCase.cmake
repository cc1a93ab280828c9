# Runs one Peridigm case in a fresh copy of its folder and compares the output with the gold.
# Variables: CASE_DIR, WORK_DIR, DECK, NP, MPIEXEC, PERIDOT, PERIDOT_DIFF, COMP, OUTPUT, GOLD
file(REMOVE_RECURSE "${WORK_DIR}")
file(COPY "${CASE_DIR}/" DESTINATION "${WORK_DIR}")
execute_process(COMMAND ${MPIEXEC} --oversubscribe -np ${NP} ${PERIDOT} ${DECK}
                WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "peridot failed (${rc}):\n${out}\n${err}")
endif()
execute_process(COMMAND ${PERIDOT_DIFF} ${COMP} ${OUTPUT} ${GOLD}
                WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "output differs from the gold file")
endif()
