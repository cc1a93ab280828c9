# Adaptive Load-Stepping with its reductions exhausted and no Switch to Verlet: the run must stop
# with exit status 3 and the documented message (the step, the limit, the residual, what to
# try), and the output written so far must stay readable. Variables: CASE_DIR, WORK_DIR, DECK,
# OUTPUT, COMP, PERIDOT, PERIDOT_DIFF.
file(REMOVE_RECURSE "${WORK_DIR}")
file(COPY "${CASE_DIR}/" DESTINATION "${WORK_DIR}")
# The same deck without its Switch to Verlet list.
file(READ "${WORK_DIR}/${DECK}" deck)
string(FIND "${deck}" "<ParameterList name=\"Switch to Verlet\">" begin)
if(begin LESS 0)
  message(FATAL_ERROR "${DECK} has no Switch to Verlet list")
endif()
string(SUBSTRING "${deck}" ${begin} -1 rest)
string(FIND "${rest}" "</ParameterList>" length)
string(LENGTH "</ParameterList>" closing)
math(EXPR end "${begin} + ${length} + ${closing}")
string(SUBSTRING "${deck}" 0 ${begin} head)
string(SUBSTRING "${deck}" ${end} -1 tail)
file(WRITE "${WORK_DIR}/${DECK}" "${head}${tail}")
execute_process(COMMAND ${PERIDOT} ${DECK} WORKING_DIRECTORY "${WORK_DIR}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(problems "")
if(NOT rc EQUAL 3)
  string(APPEND problems "expected exit status 3, got ${rc}\n")
endif()
foreach(fragment "peridot: error: QuasiStatic: load step 13 " "did not converge after"
                 "the limit of Maximum total load step reductions (6)" "residual"
                 "Switch to Verlet" "The outputs of the 12 converged load step(s)")
  string(FIND "${err}" "${fragment}" at)
  if(at LESS 0)
    string(APPEND problems "stderr lacks: ${fragment}\n")
  endif()
endforeach()
if(NOT EXISTS "${WORK_DIR}/${OUTPUT}")
  string(APPEND problems "no output file ${OUTPUT}\n")
else()
  execute_process(COMMAND ${PERIDOT_DIFF} -q ${COMP} "${WORK_DIR}/${OUTPUT}" "${WORK_DIR}/${OUTPUT}"
                  RESULT_VARIABLE diffrc OUTPUT_VARIABLE diffout ERROR_VARIABLE differr)
  if(NOT diffrc EQUAL 0)
    string(APPEND problems "the output is not readable: ${diffout}${differr}\n")
  endif()
endif()
if(problems)
  message(FATAL_ERROR "${problems}stdout:\n${out}\nstderr:\n${err}")
endif()
message("exit ${rc}: ${err}")
