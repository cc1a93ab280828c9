# Peridigm's own test decks (doc/peridigm-decks.md): the vocabulary they needed and the survey
# script (scripts/peridigm_deck_survey.py) on three small cases. Debian's python3 with netCDF4.
set(PERIDOT_PYTHON /usr/bin/python3 CACHE FILEPATH "Python 3 with netCDF4, numpy and matplotlib")
file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/decksurvey)
add_test(NAME peridigm_deck_vocabulary
  COMMAND ${PERIDOT_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/decksurvey/test_decksurvey.py
          $<TARGET_FILE:peridot> ${PROJECT_SOURCE_DIR}/scripts/peridigm_deck_survey.py
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/decksurvey)
set_tests_properties(peridigm_deck_vocabulary PROPERTIES LABELS "post" TIMEOUT 300)
