# ctest labels for day-to-day selections (`ctest -L unit`, `-L scene`,
# `-L mpi`, `-L quality`, `-L bench`, `-LE slow`); the README's test
# command runs every test whatever its labels. A test gets its labels from
# its name and its PROCESSORS, by the rules here, in one place: each
# directory that defines tests calls reinforce_label_tests() at its end
# (CMake 3.25 sets a test's properties only in its own directory); the
# core unit tests get `unit` where they are discovered.
#   unit     core unit tests (GoogleTest)
#   scene    a host runs an input script (LAMMPS, LIGGGHTS, source-built)
#   mpi      more than one process
#   quality  scene quality against a packing grown around the bars
#   bench    the benchmark harness and its report
#   tools    the checker, the layout command, the docs and the test command
#   slow     over about 20 s on 2 cores

set(REINFORCE_SLOW_TESTS
    "^quality_(make_dense_scenes|dense_np[0-9]+|fibres_small_np[0-9]+)$"
    "_np8$" "^lammps_seams_" "^stability_big_bars_" "^test_command_selfcheck$" "^bench_quick$"
    "^lammps_identical_every_np[3-9]$" "^lammps_removed_volume_beam_" "^src_")

function(reinforce_label_tests)
  get_property(tests DIRECTORY PROPERTY TESTS)
  foreach(t ${tests})
    set(labels "")
    if(t MATCHES "^quality_")
      list(APPEND labels quality)
    elseif(t MATCHES "^(bench_|stiff_)")
      list(APPEND labels bench)
    elseif(t MATCHES "^(lammps_|liggghts_|stability_|src_|layout_(read|scene|clumps)_)")
      list(APPEND labels scene)
    else()
      list(APPEND labels tools)
    endif()
    get_test_property(${t} PROCESSORS np)
    if(t MATCHES "_np([2-9]|[1-9][0-9]+)$" OR (np AND np GREATER 1))
      list(APPEND labels mpi)
    endif()
    foreach(slow ${REINFORCE_SLOW_TESTS})
      if(t MATCHES "${slow}")
        list(APPEND labels slow)
        break()
      endif()
    endforeach()
    set_tests_properties(${t} PROPERTIES LABELS "${labels}")
  endforeach()
endfunction()
