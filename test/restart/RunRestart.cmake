# Driver of the restart tests (see Restart.cmake). Variables: MODE (split, signal,
# signal_implicit, refused),
# CASE_DIR, DECK_IN (a deck template with @INITIAL@ @FINAL@ @OUTPUT@ @FREQUENCY@ @RESTART@),
# WORK_DIR, FINAL, HALF, FREQUENCY, NONZERO (variables that must be nonzero at the end), MPIEXEC,
# PERIDOT, LAST_RECORD_DIFF, SIGNAL_RUN.
file(REMOVE_RECURSE "${WORK_DIR}")
file(COPY "${CASE_DIR}/" DESTINATION "${WORK_DIR}")

# deck(<file> <initial> <final> <output> <restart block>)
function(deck file initial final output restart)
  set(INITIAL ${initial})
  set(FINAL ${final})
  set(OUTPUT ${output})
  set(RESTART "${restart}")
  configure_file("${WORK_DIR}/${DECK_IN}" "${WORK_DIR}/${file}" @ONLY)
endfunction()

# run(<np> <deck> <expected status> <log variable>)
function(run np deckfile expect logvar)
  execute_process(COMMAND ${MPIEXEC} --oversubscribe -np ${np} ${PERIDOT} ${deckfile}
                  WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  message("---- ${deckfile} on ${np} ranks: status ${rc}\n${out}${err}")
  if(expect STREQUAL "0" AND NOT rc EQUAL 0)
    message(FATAL_ERROR "${deckfile} failed on ${np} ranks")
  elseif(NOT expect STREQUAL "0" AND rc EQUAL 0)
    message(FATAL_ERROR "${deckfile} succeeded on ${np} ranks but should have failed")
  endif()
  set(${logvar} "${out}${err}" PARENT_SCOPE)
endfunction()

function(expect_in text fragment)
  string(FIND "${text}" "${fragment}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "expected \"${fragment}\" in the log above")
  endif()
endfunction()

# signal_log(<log file> <variable>): what signal_run.sh wrote, stdout then stderr.
function(signal_log file var)
  file(READ "${WORK_DIR}/${file}" out)
  file(READ "${WORK_DIR}/${file}.err" err)
  set(${var} "${out}${err}" PARENT_SCOPE)
endfunction()

function(compare result gold)
  set(args)
  foreach(v ${NONZERO})
    list(APPEND args --nonzero ${v})
  endforeach()
  execute_process(COMMAND ${LAST_RECORD_DIFF} ${args} ${result} ${gold}
                  WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  message("---- ${result} vs ${gold}: ${out}${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the continued run does not end on the uninterrupted run's bits")
  endif()
endfunction()

set(restart_on "  Restart:\n    Restart: true")

if(MODE STREQUAL "peridigm")
  # Peridigm's form: XML decks, an Exodus mesh, `Restart` as a list, Run2 starting at Run1's
  # Final Time with its own output file. Run1 on 2 ranks, Run2 on 3, the whole run on 1.
  execute_process(COMMAND ${MAKE_MESH} Contact_Perforation.g WORKING_DIRECTORY "${WORK_DIR}"
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "make_perforation_mesh failed")
  endif()
  set(restart_xml "  <ParameterList name=\"Restart\">\n    <Parameter name=\"Restart\" type=\"bool\" value=\"true\"/>\n  </ParameterList>")
  deck(Full.xml 0.0 ${FINAL} Full "")
  deck(Run1.xml 0.0 ${HALF} Run1 "${restart_xml}")
  deck(Run2.xml ${HALF} ${FINAL} Run2 "${restart_xml}")
  run(1 Full.xml 0 log)
  run(2 Run1.xml 0 log)
  expect_in("${log}" "checkpoint at step")
  run(3 Run2.xml 0 log)
  expect_in("${log}" "Restart: continuing from checkpoint")
  compare(Run2.e Full.e)
  return()
endif()

if(MODE STREQUAL "signal_implicit")
  # The implicit solvers write no checkpoint, but a stop signal still ends the run after the
  # step under way, on every rank alike, with the records of the completed steps readable.
  deck(Long.yaml 0.0 ${FINAL} Long "")
  execute_process(COMMAND bash ${SIGNAL_RUN} ${MPIEXEC} 2 ${PERIDOT} Long.yaml Long.e long.log
                  WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE rc)
  signal_log(long.log all)
  file(READ "${WORK_DIR}/long.log.err" log)  # the error line, whole (see signal_run.sh)
  message("---- Long.yaml (Implicit) on 2 ranks, SIGTERM once under way: status ${rc}\n${all}")
  if(NOT rc EQUAL 5)
    message(FATAL_ERROR "the implicit run stopped by SIGTERM should exit with status 5")
  endif()
  expect_in("${log}" "write no checkpoint")
  string(REGEX MATCH "stopped after SIGTERM at step ([0-9]+)" found "${log}")
  if(NOT found)
    message(FATAL_ERROR "expected \"stopped after SIGTERM at step N\" in the log above")
  endif()
  set(step "${CMAKE_MATCH_1}")
  execute_process(COMMAND ncdump -h Long.e WORKING_DIRECTORY "${WORK_DIR}" OUTPUT_VARIABLE header
                  RESULT_VARIABLE rc)
  string(REGEX MATCH "time_step = UNLIMITED ; // \\(([0-9]+) currently\\)" found "${header}")
  math(EXPR expected "${step} + 1")
  if(NOT rc EQUAL 0 OR NOT CMAKE_MATCH_1 EQUAL expected)
    message(FATAL_ERROR "Long.e should be readable with the records of steps 0-${step} "
                        "(${expected}), it has '${CMAKE_MATCH_1}'")
  endif()
  return()
endif()

deck(Full.yaml 0.0 ${FINAL} Full "")
run(1 Full.yaml 0 log)

if(MODE STREQUAL "split")
  deck(Run1.yaml 0.0 ${HALF} Part1 "${restart_on}")
  deck(Run2.yaml ${HALF} ${FINAL} Part2 "${restart_on}")
  run(2 Run1.yaml 0 log)
  expect_in("${log}" "checkpoint at step")
  run(3 Run2.yaml 0 log)
  expect_in("${log}" "Restart: continuing from checkpoint")
  compare(Part2.e Full.e)
elseif(MODE STREQUAL "signal")
  # Periodic checkpoints let the script know the run is under way; SIGTERM then goes to the
  # ranks themselves (a batch system's --signal does the same).
  deck(Cut.yaml 0.0 ${FINAL} Cut "${restart_on}\n    Checkpoint Frequency: 20")
  execute_process(COMMAND bash ${SIGNAL_RUN} ${MPIEXEC} 2 ${PERIDOT} Cut.yaml peridot.checkpoint
                          cut.log
                  WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE rc)
  signal_log(cut.log log)
  message("---- Cut.yaml on 2 ranks, SIGTERM after the first checkpoint: status ${rc}\n${log}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the run stopped by SIGTERM should exit with status 0")
  endif()
  expect_in("${log}" "Stopped after SIGTERM")
  expect_in("${log}" "run the same command again")
  run(3 Cut.yaml 0 log)
  expect_in("${log}" "Restart: continuing from checkpoint")
  expect_in("${log}" "Done.")
  compare(Cut.e Full.e)
  # The rerun continued Cut.e: it holds every record of the uninterrupted run, no more.
  foreach(f Cut.e Full.e)
    execute_process(COMMAND ncdump -h ${f} WORKING_DIRECTORY "${WORK_DIR}" OUTPUT_VARIABLE header)
    string(REGEX MATCH "time_step = UNLIMITED ; // \\(([0-9]+) currently\\)" found "${header}")
    set(records_${f} "${CMAKE_MATCH_1}")
  endforeach()
  if(NOT records_Cut.e STREQUAL records_Full.e OR records_Cut.e STREQUAL "")
    message(FATAL_ERROR "Cut.e holds ${records_Cut.e} records, Full.e ${records_Full.e}")
  endif()
  # Without Restart a signal stops the run with an error status and a clear message.
  deck(NoRestart.yaml 0.0 ${FINAL} NoRestart "")
  execute_process(COMMAND bash ${SIGNAL_RUN} ${MPIEXEC} 2 ${PERIDOT} NoRestart.yaml NoRestart.e
                          norestart.log
                  WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE rc)
  signal_log(norestart.log log)
  message("---- NoRestart.yaml on 2 ranks, SIGTERM: status ${rc}\n${log}")
  if(rc EQUAL 0)
    message(FATAL_ERROR "a run without Restart stopped by a signal must exit non-zero")
  endif()
  expect_in("${log}" "without a checkpoint")
  # A Wall Clock Limit already reached at start-up: checkpoint and stop after the first step
  # (exit 0); the same deck with the limit lifted (the Restart list may change) completes.
  file(REMOVE "${WORK_DIR}/peridot.checkpoint")
  deck(Limit.yaml 0.0 ${FINAL} Limit "${restart_on}\n    Wall Clock Limit: 0.0001")
  run(2 Limit.yaml 0 log)
  expect_in("${log}" "Stopped before the Wall Clock Limit at step 1,")
  deck(Limit.yaml 0.0 ${FINAL} Limit "${restart_on}")
  run(1 Limit.yaml 0 log)
  expect_in("${log}" "Restart: continuing from checkpoint ./peridot.checkpoint at step 1,")
  compare(Limit.e Full.e)
  # Run again once complete: nothing to do, the outputs are left alone.
  file(SIZE "${WORK_DIR}/Limit.e" before)
  run(2 Limit.yaml 0 log)
  expect_in("${log}" "nothing to do")
  file(SIZE "${WORK_DIR}/Limit.e" after)
  if(NOT before EQUAL after)
    message(FATAL_ERROR "rerunning a complete run changed its output")
  endif()
elseif(MODE STREQUAL "refused")
  deck(Run1.yaml 0.0 ${HALF} Part1 "${restart_on}")
  deck(Run2.yaml ${HALF} ${FINAL} Part2 "${restart_on}")
  run(2 Run1.yaml 0 log)
  file(RENAME "${WORK_DIR}/peridot.checkpoint" "${WORK_DIR}/good.checkpoint")
  # Truncated: a run killed while the file was copied, or a full disk.
  execute_process(COMMAND head -c 20000 good.checkpoint OUTPUT_FILE peridot.checkpoint
                  WORKING_DIRECTORY "${WORK_DIR}")
  run(3 Run2.yaml 1 log)
  expect_in("${log}" "checkpoint ./peridot.checkpoint is truncated or damaged")
  # Another deck: a different critical stretch.
  file(COPY_FILE "${WORK_DIR}/good.checkpoint" "${WORK_DIR}/peridot.checkpoint")
  file(READ "${WORK_DIR}/Run2.yaml" text)
  string(REPLACE "Critical Stretch: 0.002" "Critical Stretch: 0.003" text "${text}")
  file(WRITE "${WORK_DIR}/Other.yaml" "${text}")
  run(2 Other.yaml 1 log)
  expect_in("${log}" "checkpoint ./peridot.checkpoint was written by a different deck")
  # Another mesh (same deck): one point's volume changed.
  file(READ "${WORK_DIR}/perforation.txt" mesh)
  string(REGEX REPLACE "1 1e-09\n" "1 1.1e-09\n" mesh "${mesh}")
  file(WRITE "${WORK_DIR}/perforation.txt" "${mesh}")
  run(2 Run2.yaml 1 log)
  expect_in("${log}" "checkpoint ./peridot.checkpoint was written for another mesh")
  # A corrupted byte inside the data: the checksum catches it.
  file(COPY_FILE "${WORK_DIR}/good.checkpoint" "${WORK_DIR}/peridot.checkpoint")
  execute_process(COMMAND bash -c "printf X | dd of=peridot.checkpoint bs=1 seek=6000 conv=notrunc"
                  WORKING_DIRECTORY "${WORK_DIR}")
  file(WRITE "${WORK_DIR}/perforation.txt" "")
  file(COPY "${CASE_DIR}/perforation.txt" DESTINATION "${WORK_DIR}")
  run(3 Run2.yaml 1 log)
  expect_in("${log}" "checkpoint ./peridot.checkpoint is damaged (data checksum mismatch)")
else()
  message(FATAL_ERROR "unknown MODE ${MODE}")
endif()
