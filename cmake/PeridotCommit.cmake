# Writes OUT (a header defining PERIDOT_COMMIT) from `git describe` of SOURCE_DIR, at build
# time so that `peridot --version` names the commit it was built from. The file is rewritten
# only when the text changes, so an unchanged tree recompiles nothing.
#   cmake -DSOURCE_DIR=... -DOUT=... [-DGIT=...] -P PeridotCommit.cmake
set(commit "unknown (not built from a git checkout)")
if(GIT)
  execute_process(COMMAND "${GIT}" -C "${SOURCE_DIR}" describe --always --dirty --abbrev=12
                  OUTPUT_VARIABLE described RESULT_VARIABLE rc ERROR_QUIET
                  OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(rc EQUAL 0 AND described)
    set(commit "${described}")
  endif()
endif()
set(text "#pragma once\n#define PERIDOT_COMMIT \"${commit}\"\n")
if(EXISTS "${OUT}")
  file(READ "${OUT}" old)
endif()
if(NOT "${old}" STREQUAL "${text}")
  file(WRITE "${OUT}" "${text}")
endif()
