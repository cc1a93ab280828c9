# Restart tests (included from test/CMakeLists.txt). Each runs peridot under mpirun through
# RunRestart.cmake and compares the last output record with an uninterrupted run, bit for bit:
#   restart_split_<deck>: 0 -> T/2 on 2 ranks with Restart, then T/2 -> T on 3 ranks with
#                         Peridigm's continuation deck (Initial Time T/2, another output name)
#   restart_peridigm_perforation: the same in Peridigm's form (XML decks, an Exodus mesh)
#   restart_signal:       a run cut by SIGTERM after its first periodic checkpoint, then the same
#                         command again on another rank count
#   restart_signal_implicit: an Implicit run (no checkpoint) cut by SIGTERM: it stops after the
#                         step under way with status 5 and a readable output
#   restart_refused:      a truncated checkpoint, one from another deck and one from another mesh
#                         are refused with messages naming the file and the mismatch
add_executable(last_record_diff ${CMAKE_CURRENT_LIST_DIR}/last_record_diff.cpp)
target_link_libraries(last_record_diff PRIVATE peridot_core)
add_executable(make_perforation_mesh ${CMAKE_CURRENT_LIST_DIR}/make_perforation_mesh.cpp)
target_link_libraries(make_perforation_mesh PRIVATE ExodusII::ExodusII peridot_warnings)

set(PERIDOT_RESTART_DIR "${CMAKE_CURRENT_LIST_DIR}")
function(peridot_restart_test name mode deck final half frequency nonzero)
  add_test(NAME restart_${name}
    COMMAND ${CMAKE_COMMAND}
      -DMODE=${mode} -DCASE_DIR=${PERIDOT_RESTART_DIR}/decks -DDECK_IN=${deck}
      -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/restart/${name}
      -DFINAL=${final} -DHALF=${half} -DFREQUENCY=${frequency} "-DNONZERO=${nonzero}"
      -DMPIEXEC=${MPIEXEC_EXECUTABLE} -DPERIDOT=$<TARGET_FILE:peridot>
      -DLAST_RECORD_DIFF=$<TARGET_FILE:last_record_diff>
      -DSIGNAL_RUN=${PERIDOT_RESTART_DIR}/signal_run.sh
      -DMAKE_MESH=$<TARGET_FILE:make_perforation_mesh>
      -P ${PERIDOT_RESTART_DIR}/RunRestart.cmake)
  set_tests_properties(restart_${name} PROPERTIES
    ENVIRONMENT "${PERIDOT_MPI_ENV}" LABELS "restart" TIMEOUT 300)
endfunction()

peridot_restart_test(split_perforation split Perforation.yaml.in 2.0e-5 1.0e-5 10
                     "Damage;Contact_Force_Density")
peridot_restart_test(peridigm_perforation peridigm PeridigmPerforation.xml.in 4.0e-2 2.0e-2 20
                     "Damage")
peridot_restart_test(split_lsjt split LSJT.yaml.in 1.0e-5 5.0e-6 10 "Damage")
# PMB + critical stretch over the half bond list: the pairs' copy of the bond damage must be read
# again from the checkpoint (bonds break before and after it).
peridot_restart_test(split_pmb split PMB.yaml.in 4.0e-6 2.0e-6 10 "Damage")
peridot_restart_test(signal signal Perforation.yaml.in 6.0e-5 0 10 "Damage")
peridot_restart_test(refused refused Perforation.yaml.in 2.0e-5 1.0e-5 10 "")
# An Implicit run of 10^5 steps stopped by SIGTERM: status 5, the completed steps' records.
peridot_restart_test(signal_implicit signal_implicit ImplicitLong.yaml.in 10.0 0 1 "")
# Elastic-plastic history (bond fields and the node field Lambda) across a restart.
peridot_restart_test(split_plastic split Plastic.yaml.in 16.0 8.0 10 "Lambda")
peridot_restart_test(split_visco split Visco.yaml.in 16.0 8.0 10 "Dilatation")
# Pals (multipliers recomputed at start-up, per-bond influence tabulated again) with Interface
# Aware damage breaking bonds on both sides of the checkpoint.
peridot_restart_test(split_pals split Pals.yaml.in 16.0 8.0 10 "Damage")
# Correspondence history (the rate form's sigma_u, R, V, 9 components each, and eps_p) across a
# restart.
peridot_restart_test(split_correspondence split Correspondence.yaml.in 16.0 8.0 10
                     "Equivalent_Plastic_Strain")
# The same bar with "Viscoplastic Needleman Correspondence": its flow rule reads the step and the
# committed eps_p, both of which a restart must carry.
peridot_restart_test(split_needleman split Needleman.yaml.in 16.0 8.0 10
                     "Equivalent_Plastic_Strain")
# "Johnson Cook" damage: its per-point damage parameter and the plastic strain it was integrated
# to are history the checkpoint must carry; bonds are partly damaged at the checkpoint and break
# after it.
peridot_restart_test(split_johnsoncook split JohnsonCook.yaml.in 16.0 8.0 10 "Damage")
# The hypoelastic correspondence family: its bond history (27 bond fields and eps_p per bond)
# and node history (J, F, sigma_u, R, V, eps_p) across a restart.
peridot_restart_test(split_hypoelastic split Hypoelastic.yaml.in 16.0 8.0 10
                     "Equivalent_Plastic_Strain")
