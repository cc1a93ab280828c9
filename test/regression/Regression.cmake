# Peridigm's own cases (from shared/peridigm-cases), run unmodified from a copy of the case
# folder at 1, 2 and 3 ranks, each output compared with the gold file by peridot-diff.
set(PERIDOT_CASES_DIR "${PERIDOT_SHARED_DIR}/peridigm-cases")

function(peridot_case name deck comp discretization_comp)
  foreach(np 1 2 3)
    # The discretization alone (ids, blocks, coordinates, volumes, neighbour counts).
    add_test(NAME discretization_${name}_np${np}
      COMMAND ${CMAKE_COMMAND}
        -DCASE_DIR=${PERIDOT_CASES_DIR}/${name}
        -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/discretization/${name}_np${np}
        -DDECK=${deck} -DNP=${np} -DMPIEXEC=${MPIEXEC_EXECUTABLE}
        -DPERIDOT=$<TARGET_FILE:peridot> -DPERIDOT_DIFF=$<TARGET_FILE:peridot-diff>
        -DCOMP=${CMAKE_CURRENT_SOURCE_DIR}/regression/${discretization_comp} -DOUTPUT=${name}.e -DGOLD=${name}_gold.e
        -P ${CMAKE_CURRENT_SOURCE_DIR}/regression/RunCase.cmake)
    set_tests_properties(discretization_${name}_np${np} PROPERTIES
      ENVIRONMENT "${PERIDOT_MPI_ENV}" LABELS "regression" TIMEOUT 600)
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
  peridot_case(WaveInBar WaveInBar.xml WaveInBar.comp points.comp)
  peridot_case(ElasticBondBased3D ElasticBondBased3D.yaml ElasticBondBased.comp discretization.comp)
  peridot_case(BondBreakingInitialVelocity BondBreakingInitialVelocity.xml BondBreakingInitialVelocity.comp points.comp)
  peridot_case(Compression_2x1x1 Compression_2x1x1.yaml Compression_2x1x1.comp points.comp)
  peridot_case(Contact_Cubes Contact_Cubes.xml Contact_Cubes.comp points.comp)
else()
  message(WARNING "Peridigm cases not found at ${PERIDOT_CASES_DIR}: regression tests skipped")
endif()

# Nodal results must not depend on the rank count, to the bit. An optional last argument is a
# regular expression every run's output must match (that the code path under test ran).
function(peridot_identical name case_dir deck output comp all_ids)
  set(expect_log "${ARGV6}")
  add_test(NAME identical_${name}
    COMMAND ${CMAKE_COMMAND}
      -DCASE_DIR=${case_dir} -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/identical/${name}
      -DDECK=${deck} -DOUTPUT=${output} -DCOMP=${CMAKE_CURRENT_SOURCE_DIR}/regression/${comp}
      "-DNPS=1;2;3;4" -DMPIEXEC=${MPIEXEC_EXECUTABLE} -DALL_IDS=${all_ids}
      "-DEXPECT_LOG=${expect_log}"
      -DPERIDOT=$<TARGET_FILE:peridot> -DPERIDOT_DIFF=$<TARGET_FILE:peridot-diff>
      -P ${CMAKE_CURRENT_SOURCE_DIR}/regression/RunIdentical.cmake)
  set_tests_properties(identical_${name} PROPERTIES
    ENVIRONMENT "${PERIDOT_MPI_ENV}" LABELS "regression" TIMEOUT 900)
endfunction()

if(EXISTS "${PERIDOT_CASES_DIR}")
  peridot_identical(WaveInBar ${PERIDOT_CASES_DIR}/WaveInBar WaveInBar.xml WaveInBar.e exact_wave.comp 0)
endif()
# PMB + critical stretch over the half bond list (each bond once; ghost rows walked in curve order).
peridot_identical(DamageCube ${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/DamageCube DamageCube.yaml
                  DamageCube.e exact.comp 10000 "Bond loop: each bond once")
# The same with normalized PMB, computed |xi| and broken-bond flags (Bond Storage: Compact).
peridot_identical(DamageCubeCompact ${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/DamageCube
                  DamageCubeCompact.yaml DamageCubeCompact.e exact.comp 10000
                  "Bond loop: each bond once")
# LPS with omega = 1/|xi| over the half bond list (dilatation and force, omega per pair).
peridot_identical(DamageCubeLps ${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/DamageCube
                  DamageCubeLps.yaml DamageCubeLps.e exact.comp 10000
                  "Bond loop: each bond once")
# Partial volumes (bond weights from cell-horizon overlaps, PMB + damage): bitwise equal too.
peridot_identical(PartialVolumes ${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/PartialVolumes
                  PartialVolumes.yaml PartialVolumes.e exact.comp 10000)
# A planar run (2D generator, plane-stress LPS over the half list, damage): bitwise equal at
# 1-4 ranks.
peridot_identical(Plate2D ${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/Plate2D Plate2D.yaml
                  Plate2D.e exact_2d.comp 600 "Bond loop: each bond once")
# A planar plate under Traction (the force per point divides by the loaded layer's volume, a sum
# over ranks, now exact), Linearized LPS with LSJ-T: bitwise equal at 1-4 ranks.
peridot_identical(TractionPlate ${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/TractionPlate
                  TractionPlate.yaml TractionPlate.e exact_2d.comp 600)
# Elastic-plastic decks (ordinary state-based plasticity, history in bond fields): bitwise equal
# at 1-4 ranks; the cube's bulk values are also checked against a hand computation
# (test/mpi/test_plastic_cube.cpp).
peridot_identical(PlasticCube ${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/PlasticCube
                  PlasticCube.xml PlasticCube.e exact_plastic.comp 2744)
peridot_identical(PlasticBar ${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/PlasticBar
                  PlasticBar.xml PlasticBar.e exact_plastic.comp 0)
# Correspondence decks (shape tensor, F and P K^-1 ghosted, hourglass forces, plastic history in
# node fields): bitwise equal at 1-4 ranks; the cube's stresses and plastic strains are also
# checked against a scalar return mapping (test/mpi/test_correspondence_cube.cpp).
peridot_identical(CorrespondenceCube ${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/CorrespondenceCube
                  CorrespondenceCube.xml CorrespondenceCube.e exact_correspondence.comp 2744)
peridot_identical(CorrespondenceBar ${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/CorrespondenceBar
                  CorrespondenceBar.xml CorrespondenceBar.e exact_correspondence.comp 0)
# "Johnson Cook" damage on a plastic correspondence bar pulled until it breaks at its flaw
# (damage history ghosted each step, points cut loose): bitwise equal at 1-4 ranks.
peridot_identical(DuctileBar ${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/DuctileBar
                  DuctileBar.xml DuctileBar.e exact_ductile.comp 864)
# The same bar with "Von Mises Stress" damage (bonds about half damaged, none broken).
peridot_identical(VonMisesBar ${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/DuctileBar
                  VonMisesBar.xml VonMisesBar.e exact_ductile.comp 864)
# Bond-associated correspondence decks (point F, Fdot, 1/m ghosted inside precompute, B = S K^-1
# after it, a stress and plastic history per bond): bitwise equal at 1-4 ranks; the cube's
# stresses and plastic strains are also checked against a scalar return mapping
# (test/mpi/test_bond_associated_cube.cpp).
peridot_identical(BondAssociatedCube ${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/BondAssociatedCube
                  BondAssociatedCube.xml BondAssociatedCube.e exact_bondassociated.comp 1000)
peridot_identical(BondAssociatedBar ${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/BondAssociatedBar
                  BondAssociatedBar.xml BondAssociatedBar.e exact_bondassociated.comp 0)
# The same bar with Gradient Order Of Accuracy 2 (higher-order weights, B = S Zs ghosted by
# columns, the reverse weight of each bond from the far end's columns): bitwise equal too.
peridot_identical(BondAssociatedBarOrder2 ${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/BondAssociatedBar
                  BondAssociatedBarOrder2.xml BondAssociatedBarOrder2.e exact_bondassociated.comp 0)
# Viscoplastic Needleman Correspondence with a flaw: bitwise equal at 1-4 ranks; every point is
# also checked against a scalar return with its own yield stress (test/mpi/test_needleman_cube.cpp).
peridot_identical(NeedlemanCube ${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/NeedlemanCube
                  NeedlemanCube.xml NeedlemanCube.e exact_correspondence.comp 1728)
peridot_identical(NeedlemanBar ${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/NeedlemanBar
                  NeedlemanBar.xml NeedlemanBar.e exact_correspondence.comp 0)
# Isotropic Hardening Hypoelastic Correspondence (second-order gradient, bond-level stresses and
# plastic history, B = N Z ghosted inside the force): bitwise equal at 1-4 ranks; the model's
# homogeneous responses are checked in test/unit/test_hypoelastic_correspondence.cpp.
peridot_identical(HypoelasticBar ${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/HypoelasticBar
                  HypoelasticBar.xml HypoelasticBar.e exact_hypoelastic.comp 0)
peridot_identical(ViscoBar ${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/ViscoBar
                  ViscoBar.xml ViscoBar.e exact_visco.comp 0)
# Thermal loading (Prescribed Temperature, LPS thermal expansion) with a time-dependent
# critical stretch: bitwise equal at 1-4 ranks.
peridot_identical(ThermalCrack ${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/ThermalCrack
                  ThermalCrack.yaml ThermalCrack.e exact_thermal.comp 0)

# Pals (position-aware linear solid) with Interface Aware damage under simple shear: bitwise
# equal at 1-4 ranks; the energy at every point is checked against the continuum in
# test/mpi/test_pals_deck.cpp.
peridot_identical(PalsSimpleShear ${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/PalsSimpleShear
                  PalsSimpleShear.yaml PalsSimpleShear.e exact.comp 343)

# QuasiStatic (Peridigm's XML deck form): the same nodal results at 1, 2 and 3 ranks within the
# solver tolerances of quasistatic.comp (not bitwise: see there).
add_test(NAME ranks_QuasiStaticBar
  COMMAND ${CMAKE_COMMAND}
    -DCASE_DIR=${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/QuasiStaticBar
    -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/identical/QuasiStaticBar
    -DDECK=QuasiStaticBar.xml -DOUTPUT=QuasiStaticBar.e
    -DCOMP=${CMAKE_CURRENT_SOURCE_DIR}/regression/quasistatic.comp
    "-DNPS=1;2;3" -DMPIEXEC=${MPIEXEC_EXECUTABLE}
    -DPERIDOT=$<TARGET_FILE:peridot> -DPERIDOT_DIFF=$<TARGET_FILE:peridot-diff>
    -P ${CMAKE_CURRENT_SOURCE_DIR}/regression/RunIdentical.cmake)
set_tests_properties(ranks_QuasiStaticBar PROPERTIES
  ENVIRONMENT "${PERIDOT_MPI_ENV}" LABELS "regression" TIMEOUT 900)
# QuasiStatic with Elastic Plastic (finite-difference tangent, trial evaluations, one commit per
# load step) loaded past yield and unloaded: the same at 1, 2 and 3 ranks within
# quasistatic_plastic.comp.
add_test(NAME ranks_QuasiStaticPlasticBar
  COMMAND ${CMAKE_COMMAND}
    -DCASE_DIR=${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/QuasiStaticPlasticBar
    -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/identical/QuasiStaticPlasticBar
    -DDECK=QuasiStaticPlasticBar.xml -DOUTPUT=QuasiStaticPlasticBar.e
    -DCOMP=${CMAKE_CURRENT_SOURCE_DIR}/regression/quasistatic_plastic.comp
    "-DNPS=1;2;3" -DMPIEXEC=${MPIEXEC_EXECUTABLE}
    -DPERIDOT=$<TARGET_FILE:peridot> -DPERIDOT_DIFF=$<TARGET_FILE:peridot-diff>
    -P ${CMAKE_CURRENT_SOURCE_DIR}/regression/RunIdentical.cmake)
set_tests_properties(ranks_QuasiStaticPlasticBar PROPERTIES
  ENVIRONMENT "${PERIDOT_MPI_ENV}" LABELS "regression" TIMEOUT 900)
# QuasiStatic with Adaptive Load-Stepping on a notched bar with critical stretch damage (Newton
# stalls as bonds break; the steps are halved, then Switch to Verlet carries the crack on): the
# same step sequence, damage and iterations at 1, 2 and 3 ranks, displacements within
# adaptive.comp.
add_test(NAME ranks_AdaptiveNotchedBar
  COMMAND ${CMAKE_COMMAND}
    -DCASE_DIR=${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/AdaptiveNotchedBar
    -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/identical/AdaptiveNotchedBar
    -DDECK=AdaptiveNotchedBar.xml -DOUTPUT=AdaptiveNotchedBar.e
    -DCOMP=${CMAKE_CURRENT_SOURCE_DIR}/regression/adaptive.comp
    "-DNPS=1;2;3" -DMPIEXEC=${MPIEXEC_EXECUTABLE}
    -DPERIDOT=$<TARGET_FILE:peridot> -DPERIDOT_DIFF=$<TARGET_FILE:peridot-diff>
    -P ${CMAKE_CURRENT_SOURCE_DIR}/regression/RunIdentical.cmake)
set_tests_properties(ranks_AdaptiveNotchedBar PROPERTIES
  ENVIRONMENT "${PERIDOT_MPI_ENV}" LABELS "regression" TIMEOUT 900)
# The same deck without Switch to Verlet: reductions exhausted, exit status 3, the message, the
# outputs of the converged steps readable.
add_test(NAME adaptive_exhausted_AdaptiveNotchedBar
  COMMAND ${CMAKE_COMMAND}
    -DCASE_DIR=${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/AdaptiveNotchedBar
    -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/adaptive_exhausted
    -DDECK=AdaptiveNotchedBar.xml -DOUTPUT=AdaptiveNotchedBar.e
    -DCOMP=${CMAKE_CURRENT_SOURCE_DIR}/regression/adaptive.comp
    -DPERIDOT=$<TARGET_FILE:peridot> -DPERIDOT_DIFF=$<TARGET_FILE:peridot-diff>
    -P ${CMAKE_CURRENT_SOURCE_DIR}/regression/RunAdaptiveExhausted.cmake)
set_tests_properties(adaptive_exhausted_AdaptiveNotchedBar PROPERTIES
  ENVIRONMENT "${PERIDOT_MPI_ENV}" LABELS "regression" TIMEOUT 600)
# Chained solvers (QuasiStatic then Implicit, Peridigm's XML form): the same at 1, 2 and 3 ranks
# within implicitchain.comp, all records in one file.
add_test(NAME ranks_ImplicitChainBar
  COMMAND ${CMAKE_COMMAND}
    -DCASE_DIR=${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/ImplicitChainBar
    -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/identical/ImplicitChainBar
    -DDECK=ImplicitChainBar.xml -DOUTPUT=ImplicitChainBar.e
    -DCOMP=${CMAKE_CURRENT_SOURCE_DIR}/regression/implicitchain.comp
    "-DNPS=1;2;3" -DMPIEXEC=${MPIEXEC_EXECUTABLE}
    -DPERIDOT=$<TARGET_FILE:peridot> -DPERIDOT_DIFF=$<TARGET_FILE:peridot-diff>
    -P ${CMAKE_CURRENT_SOURCE_DIR}/regression/RunIdentical.cmake)
set_tests_properties(ranks_ImplicitChainBar PROPERTIES
  ENVIRONMENT "${PERIDOT_MPI_ENV}" LABELS "regression" TIMEOUT 900)
# NOXQuasiStatic (Peridigm's XML forms: matrix-free Newton, preconditioned nonlinear CG) on the
# QuasiStatic bar: the same nodal results at 1, 2 and 3 ranks within nox.comp (not bitwise).
foreach(deck NOXBar NOXCGBar)
  add_test(NAME ranks_${deck}
    COMMAND ${CMAKE_COMMAND}
      -DCASE_DIR=${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/${deck}
      -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/identical/${deck}
      -DDECK=${deck}.xml -DOUTPUT=${deck}.e
      -DCOMP=${CMAKE_CURRENT_SOURCE_DIR}/regression/nox.comp
      "-DNPS=1;2;3" -DMPIEXEC=${MPIEXEC_EXECUTABLE}
      -DPERIDOT=$<TARGET_FILE:peridot> -DPERIDOT_DIFF=$<TARGET_FILE:peridot-diff>
      -P ${CMAKE_CURRENT_SOURCE_DIR}/regression/RunIdentical.cmake)
  set_tests_properties(ranks_${deck} PROPERTIES
    ENVIRONMENT "${PERIDOT_MPI_ENV}" LABELS "regression" TIMEOUT 900)
endforeach()
# Adaptive dynamic relaxation with bonds breaking (exact global sums): bitwise equal at 1-4 ranks.
peridot_identical(RelaxationBar ${CMAKE_CURRENT_SOURCE_DIR}/regression/decks/RelaxationBar
                  RelaxationBar.yaml RelaxationBar.e exact.comp 0)
