# LAMMPS built from source (included from CMakeLists.txt here). Test names
# start with src_lammps_. Reused: ../scripts (scene.sh, run_scene.sh,
# expect_error.sh, seam_share.sh, every_test.sh, every_periodic_test.sh) and
# the packaged path's inputs (../lammps, ../stability).
set(LMP_IN ${CMAKE_SOURCE_DIR}/tests/lammps)
set(ERROR_INPUT ${LMP_IN}/errors/in.error)
set(AS_PLUGIN ${HOSTS}/as-build-plugin)
set(PLUGIN_LMP ${AS_PLUGIN}/src/lammps/lmp_reinforce)    # lmp, reinforceplugin.so auto-loaded
set(I "Illegal fix reinforce/invert command: ")
set(R "Fix reinforce/invert ")
set(F "fix r all reinforce/invert")
set(BASIC "--box 0 0.4 0 0.2 0 0.2 --radius 0.004 0.008 --fcc --bar 0.01 0.07 0.1 0.39 0.07 0.1 0.005 0.0075 --bar 0.01 0.13 0.1 0.39 0.13 0.1 0.005 0.0075 --bar 0.2 0.01 0.05 0.2 0.19 0.05 0.005 0.0075")
set(PERIODIC "--box 0 0.6 0 0.3 0 0.3 --radius 0.004 0.008 --fcc --bar 0 0.1 0.1 0.5925 0.1 0.1 0.005 0.0075 --bar 0 0.2 0.2 0.5925 0.2 0.2 0.005 0.0075 --bar 0.3 0 0.2 0.3 0.2925 0.2 0.005 0.0075 --bar 0.15 0 0.15 0.15 0.2925 0.15 0.005 0.0075 --bar 0.45 0 0.1 0.45 0.2925 0.1 0.005 0.0075")
set(RANGE "--rmin 0.004 --rmax 0.008")

# src_error(NAME NP EXPECTED FIX [-var ...]): one exact ERROR line (expect_error.sh).
include(${SCRIPTS}/error_test.cmake)
function(src_error name np expected fix)
  reinforce_error_test(src_lammps_error_${name} ${PLUGIN_LMP} ${np} ${ERROR_INPUT} "${expected}" "${fix}"
                       ${ARGN})
endfunction()

# src_scene(NAME NP AS_BUILD MAKE_ARGS VARS CHECK_ARGS [ENV]): a scene (scene.sh, run_scene.sh).
function(src_scene name np as_build make_args vars check_args)
  separate_arguments(make_args)
  separate_arguments(vars UNIX_COMMAND "${vars}")
  separate_arguments(check_args)
  add_test(NAME src_lammps_${name}_np${np}
           COMMAND ${SCRIPTS}/scene.sh lammps ${LMP_IN}/in.scene ${name} ${np} ${as_build}
                   -- ${make_args} -- ${vars} -- ${check_args})
  set_tests_properties(src_lammps_${name}_np${np} PROPERTIES TIMEOUT 300 FAIL_REGULAR_EXPRESSION "FAIL"
                       PASS_REGULAR_EXPRESSION "PASS ${name} np=${np}" ENVIRONMENT "${ARGN}")
  if(np GREATER 1)
    set_tests_properties(src_lammps_${name}_np${np} PROPERTIES PROCESSORS 2)
  endif()
endfunction()

# ---- The plugin, loaded by the input itself (plugin load), in a plain lmp.
add_test(NAME src_lammps_plugin_load
         COMMAND ${SCRIPTS}/expect_error.sh ${LMP_PLAIN} 1 ${CMAKE_CURRENT_SOURCE_DIR}/in.plugin_load
                 "${I}unknown keyword 'foo'" -var plugin ${CMAKE_BINARY_DIR}/plugin/reinforceplugin.so
                 -var errors ${ERROR_INPUT} -var fix "${F} 0 bars foo 1")
set_tests_properties(src_lammps_plugin_load PROPERTIES TIMEOUT 180 ENVIRONMENT "EXPECT_EXACT=1"
                     PASS_REGULAR_EXPRESSION "PASS: " FAIL_REGULAR_EXPRESSION "FAIL")

# ---- Scenes with the checker: 1, 2, 4 processes; deletions (AtomVec::copy)
# with each atom map; periodic with seams; N > 0.
foreach(np 1 2 4)
  src_scene(scene_basic ${np} ${AS_PLUGIN} "${BASIC}" "" "${RANGE}")
endforeach()
foreach(map array hash none)
  src_scene(scene_deleting_map_${map} 2 ${AS_PLUGIN} "${BASIC}" "-var extra 'tries 4 regrow no' -var map ${map}" "${RANGE}")
  set_tests_properties(src_lammps_scene_deleting_map_${map}_np2 PROPERTIES PASS_REGULAR_EXPRESSION
                       "deleted [1-9][0-9]* kept 0.*PASS scene_deleting_map_${map} np=2")
endforeach()
src_scene(scene_keep 4 ${AS_PLUGIN} "${BASIC}" "-var extra 'unplaced keep tries 4'" "${RANGE} --kept-ok")
src_scene(scene_rigid_bars 2 ${AS_PLUGIN} "${BASIC}" "-var setup 'fix bars rebar rigid single' -var extra 'tries 4'" "${RANGE}")
set(TINY "--box 0 0.06 0 0.06 0 0.06 --radius 0.004 0.008 --fcc --bar 0 0.03 0.03 0.055 0.03 0.03 0.005 0.005 --bar 0.015 0 0.015 0.015 0.055 0.015 0.005 0.005 --bar 0.045 0.045 0 0.045 0.045 0.055 0.005 0.005")
foreach(np 1 2 4)
  src_scene(tiny_periodic ${np} ${AS_PLUGIN} "${TINY}" "-var bx p -var by p -var bz p" "${RANGE}")
endforeach()
foreach(grid "2 1 1" "2 2 1")
  string(REPLACE " " "x" tag "${grid}")
  string(REPLACE " " "*" np "${grid}")
  math(EXPR np "${np}")
  set(SEAMS_2x1x1 "x=0,0.3/y=0")
  set(SEAMS_2x2x1 "x=0,0.3/y=0,0.15")
  src_scene(periodic_${tag} ${np} ${AS_PLUGIN} "${PERIODIC}"
            "-var bx p -var by p -var procs '${grid}' -var extra 'tries 15 regrow no'" "${RANGE}"
            "SCENE_REFERENCE=1" "SCENE_POST=${SCRIPTS}/seam_share.sh 0.008 ${SEAMS_${tag}}")
  set_tests_properties(src_lammps_periodic_${tag}_np${np} PROPERTIES PASS_REGULAR_EXPRESSION
                       "deleted [1-9].*PASS: no thinning at seams.*PASS periodic_${tag} np=${np}")
endforeach()
foreach(np 1 2)
  add_test(NAME src_lammps_every_n_steps_np${np} COMMAND ${SCRIPTS}/every_test.sh ${AS_PLUGIN} ${np})
  set_tests_properties(src_lammps_every_n_steps_np${np} PROPERTIES TIMEOUT 300
                       FAIL_REGULAR_EXPRESSION "FAIL" PASS_REGULAR_EXPRESSION "PASS: relocation every N steps")
endforeach()
foreach(np 1 4)
  add_test(NAME src_lammps_every_periodic_np${np} COMMAND ${SCRIPTS}/every_periodic_test.sh ${AS_PLUGIN} ${np})
  set_tests_properties(src_lammps_every_periodic_np${np} PROPERTIES TIMEOUT 300 FAIL_REGULAR_EXPRESSION "FAIL"
                       PASS_REGULAR_EXPRESSION "PASS: relocation every N steps across seams")
endforeach()
set_tests_properties(src_lammps_every_n_steps_np2 src_lammps_every_periodic_np4 PROPERTIES PROCESSORS 2)

# ---- The same relocation as lmp_reinforce (packaged LAMMPS 2021) on the same scene.
if(TARGET lmp_reinforce)
  foreach(extra "" "radius 0.007 0.008 choose first tries 200")
    string(MAKE_C_IDENTIFIER "same_as_packaged_${extra}" tname)
    string(REGEX REPLACE "_+$" "" tname "${tname}")
    separate_arguments(basic_list UNIX_COMMAND "${BASIC}")
    add_test(NAME src_lammps_${tname}
             COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/same_as_packaged.sh ${PLUGIN_LMP} $<TARGET_FILE:lmp_reinforce>
                     ${CMAKE_BINARY_DIR}/tests "${extra}" ${basic_list})
    set_tests_properties(src_lammps_${tname} PROPERTIES TIMEOUT 300 FAIL_REGULAR_EXPRESSION "FAIL"
                         PASS_REGULAR_EXPRESSION "PASS: the same relocation")
  endforeach()
  # With a pair style whose cutoff reaches matrix-rebar contact
  # (in.scene_pair: gran/hooke), the plugin finds the targets with LAMMPS's
  # occasional full neighbor list (its log says so), lmp_reinforce with the
  # engine's grid: the same targets, statistics and atoms. Serially, and on
  # 4 processes with periodic seams (ghost rebar spheres in the list); and
  # once with the in-tree package's lmp.
  # src_same_host_list(NAME LMP NP "keywords" "-var ..." MAKE_SCENE_ARGS...)
  function(src_same_host_list name lmp np extra vars)
    set(test src_lammps_same_as_packaged_host_list_${name}_np${np})
    add_test(NAME ${test}
             COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/same_as_packaged.sh ${lmp} $<TARGET_FILE:lmp_reinforce>
                     ${CMAKE_BINARY_DIR}/tests "${extra}" ${ARGN})
    set_tests_properties(${test} PROPERTIES TIMEOUT 300 FAIL_REGULAR_EXPRESSION "FAIL"
                         PASS_REGULAR_EXPRESSION "PASS: the same relocation"
                         ENVIRONMENT "${MPI_ENV};SAME_INPUT=${CMAKE_CURRENT_SOURCE_DIR}/in.scene_pair;SAME_TARGETS_BY=list;SAME_NP=${np};SAME_VARS=${vars}")
    if(np GREATER 1)
      set_tests_properties(${test} PROPERTIES PROCESSORS 2)
    endif()
  endfunction()
  separate_arguments(periodic_list UNIX_COMMAND "${PERIODIC}")
  src_same_host_list(basic ${PLUGIN_LMP} 1 "" "" ${basic_list})
  src_same_host_list(basic_fit ${PLUGIN_LMP} 1 "size fit radius 0.007 0.008 choose first tries 200" "" ${basic_list})
  src_same_host_list(periodic ${PLUGIN_LMP} 4 "tries 15" "-var bx p -var by p" ${periodic_list})
  src_same_host_list(package_basic ${HOSTS}/as-build-package/src/lammps/lmp_reinforce 1 "" "" ${basic_list})
endif()

# ---- Bad input: the fix's own ERROR lines, exactly as on the packaged path.
# The parser's message reaches the ERROR line (every text: the unit test
# FixOptions.EveryParserErrorText).
src_error(unknown_keyword 1 "${I}unknown keyword 'foo'" "${F} 0 bars foo 1")
src_error(rebar_group_missing 1 "${R}rebar group 'nosuch' does not exist" "${F} 0 nosuch")
src_error(rebar_group_same 1 "${R}rebar group must differ from the fix group" "fix r bars reinforce/invert 0 bars")
src_error(rebar_group_empty 2 "${R}rebar group 'nothing' is empty" "${F} 0 nothing")
src_error(rebar_group_deleted_before_run 1 "${R}rebar group 'bars' does not exist" "${F} 0 bars"
          -var post "group bars delete")
src_error(rebar_group_emptied_between_runs 2 "${R}rebar group 'bars' is empty" "${F} 1 bars"
          -var nrun 2 -var between "delete_atoms group bars" -var halfway no)
src_error(region_unknown 1 "${R}region 'nowhere' does not exist" "${F} 0 bars region nowhere")
src_error(region_deleted_before_run 1 "${R}region 'r1' does not exist" "${F} 0 bars region r1"
          -var pre "region r1 block 0 1 0 1 0 1" -var post "region r1 delete")
src_error(atom_style_without_radius 1 "${R}requires atom attributes radius and rmass" "${F} 0 bars"
          -var style atomic -var setd no)
src_error(atom_ids_off 1 "${R}requires atom IDs" "${F} 0 bars" -var ids no -var map none)
src_error(triclinic_box 1 "${R}does not support triclinic boxes" "${F} 0 bars" -var shape prism)
src_error(comm_style_tiled 2 "${R}requires comm_style brick" "${F} 0 bars" -var commstyle tiled)
src_error(comm_mode_multi 1 "${R}requires comm_modify mode single" "${F} 0 bars"
          -var commmode multi -var neigh multi)
src_error(zero_radius_matrix 1 "Fix reinforce/invert: matrix atom 1 has radius 0; matrix spheres need a radius > 0"
          "${F} 0 bars" -var matrixd 0)
# Refusals (the same tests run on lmp_reinforce: ../adapters).
src_error(rebar_group_dynamic 1 "${R}rebar group 'dbars' is dynamic: make it static first (group dbars static)"
          "${F} 0 dbars" -var pre "if 1 then \"variable isbar atom type==2\" \"group dbars dynamic all var isbar\"")
src_error(matrix_in_rigid_body 1 "${R}cannot move atoms of rigid bodies: matrix atoms belong to fix rb (rigid); leave the bodies out of the fix group"
          "${F} 0 bars" -var pre "fix rb all rigid single")
src_error(matrix_in_rigid_small_body 2 "${R}cannot move atoms of rigid bodies: matrix atoms belong to fix rb (rigid/small); leave the bodies out of the fix group"
          "${F} 0 bars" -var pre "variable one atom 1" -var post "fix rb all rigid/small custom v_one")
# N = 0 done, then its rebar group and region gone: the
# next runs go on (no re-check in init()).
add_test(NAME src_lammps_done_fix_never_stops_a_run
         COMMAND ${CMAKE_SOURCE_DIR}/tests/adapters/expect_success.sh ${PLUGIN_LMP} 1 ${ERROR_INPUT}
                 -var pre "region r1 block 0 1 0 1 0 1" -var fix "${F} 0 bars region r1"
                 -var between "if 1 then 'group bars delete' 'region r1 delete'")
set_tests_properties(src_lammps_done_fix_never_stops_a_run PROPERTIES TIMEOUT 180
                     PASS_REGULAR_EXPRESSION "PASS: " FAIL_REGULAR_EXPRESSION "FAIL")

# ---- The in-tree package (cmake -D PKG_REINFORCE=on), one scene; the
# bigbig host (64-bit atom IDs) with its plugin, one scene.
src_scene(package_scene_basic 2 ${HOSTS}/as-build-package "${BASIC}" "-var extra 'tries 4'" "${RANGE}")
src_scene(bigbig_scene_basic 2 ${HOSTS}/as-build-bigbig "${BASIC}" "-var extra 'tries 4 regrow no' -var map hash" "${RANGE}")
set_tests_properties(src_lammps_bigbig_scene_basic_np2 PROPERTIES PASS_REGULAR_EXPRESSION
                     "deleted [1-9][0-9]* kept 0.*PASS bigbig_scene_basic np=2")
add_test(NAME src_lammps_package_registered
         COMMAND sh -c "${LMP_PACKAGE} -h | grep -A40 '^\\* Fix styles' | grep -q 'reinforce/invert' && echo 'PASS: reinforce/invert is a fix style of the package build'")
set_tests_properties(src_lammps_package_registered PROPERTIES PASS_REGULAR_EXPRESSION "PASS: ")
add_test(NAME src_lammps_package_make_install
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/make_install_test.sh ${REINFORCE_LAMMPS_SOURCE_DIR})
set_tests_properties(src_lammps_package_make_install PROPERTIES TIMEOUT 120
                     PASS_REGULAR_EXPRESSION "PASS: " FAIL_REGULAR_EXPRESSION "FAIL")

# ---- An ERROR thrown during the relocation (this LAMMPS
# throws them) leaves the ghost cutoff as it was. A program linked with the
# plain host's liblammps.a, loading the plugin.
find_package(OpenMP REQUIRED COMPONENTS CXX)
find_package(PNG REQUIRED)
find_package(ZLIB REQUIRED)
add_executable(error_restores_cutoff error_restores_cutoff.cpp)
target_include_directories(error_restores_cutoff SYSTEM PRIVATE ${REINFORCE_LAMMPS_SOURCE_DIR}/src)
target_compile_definitions(error_restores_cutoff PRIVATE LAMMPS_SMALLBIG)
target_link_libraries(error_restores_cutoff PRIVATE ${HOSTS}/lammps-plain/build/liblammps.a MPI::MPI_CXX
                      OpenMP::OpenMP_CXX PNG::PNG ZLIB::ZLIB ${CMAKE_DL_LIBS})
set_target_properties(error_restores_cutoff PROPERTIES ENABLE_EXPORTS ON)
add_dependencies(error_restores_cutoff host_lammps)
add_dependencies(source_hosts_lammps error_restores_cutoff)
separate_arguments(basic_list UNIX_COMMAND "${BASIC}")
add_test(NAME src_lammps_error_restores_ghost_cutoff
         COMMAND sh -c "'${CMAKE_BINARY_DIR}/tests/make_scene' \"$0\" ${BASIC} >/dev/null && '$<TARGET_FILE:error_restores_cutoff>' '${CMAKE_BINARY_DIR}/plugin/reinforceplugin.so' \"$0\"; s=$?; rm -f \"$0\"; exit $s"
                 ${CMAKE_CURRENT_BINARY_DIR}/error_restores_cutoff.data)
set_tests_properties(src_lammps_error_restores_ghost_cutoff PROPERTIES TIMEOUT 120 ENVIRONMENT "${MPI_ENV}"
                     PASS_REGULAR_EXPRESSION "PASS: " FAIL_REGULAR_EXPRESSION "FAIL")

# ---- LAMMPS since its August 2026 feature release names
# NeighRequest::set_cutoff(double) set_cutoff_fixed(double). The plugin, made
# by the same function as reinforceplugin (src/lammps/plugin: its sources,
# include folders, definitions and link), against a copy of this tree's src/
# with that method renamed (renamed_set_cutoff.sh tree). Not part of the
# build: the test builds it, so that a compile error (the old call
# ->set_cutoff(list_cutoff)) fails the test; it then checks which setter each
# plugin calls (this one set_cutoff_fixed, reinforceplugin set_cutoff).
set(RENAMED_TREE ${HOSTS}/lammps-renamed-set-cutoff)
add_custom_command(OUTPUT ${RENAMED_TREE}/src/neigh_request.h
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/renamed_set_cutoff.sh tree
          ${REINFORCE_LAMMPS_SOURCE_DIR}/src ${RENAMED_TREE}/src
  DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/renamed_set_cutoff.sh ${REINFORCE_LAMMPS_SOURCE_DIR}/src/neigh_request.h
  COMMENT "LAMMPS src/ with NeighRequest::set_cutoff renamed set_cutoff_fixed: ${RENAMED_TREE}/src")
add_custom_target(lammps_renamed_set_cutoff_tree DEPENDS ${RENAMED_TREE}/src/neigh_request.h)
function(reinforce_plugin_renamed_set_cutoff target)
  set(REINFORCE_LAMMPS_SOURCE_DIR ${RENAMED_TREE})    # read by reinforce_lammps_plugin
  reinforce_lammps_plugin(${target} ${REINFORCE_LAMMPS_SIZES} ${CMAKE_BINARY_DIR}/plugin-renamed-set-cutoff)
  set_target_properties(${target} PROPERTIES EXCLUDE_FROM_ALL ON)
  add_dependencies(${target} lammps_renamed_set_cutoff_tree)
endfunction()
reinforce_plugin_renamed_set_cutoff(reinforceplugin_renamed_set_cutoff)
set(NM ${CMAKE_NM})
if(NOT NM)
  set(NM nm)
endif()
add_test(NAME src_lammps_plugin_builds_against_renamed_set_cutoff
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/renamed_set_cutoff.sh test ${CMAKE_BINARY_DIR}
                 reinforceplugin_renamed_set_cutoff $<TARGET_FILE:reinforceplugin_renamed_set_cutoff>
                 $<TARGET_FILE:reinforceplugin> ${NM})
set_tests_properties(src_lammps_plugin_builds_against_renamed_set_cutoff PROPERTIES TIMEOUT 600
                     PASS_REGULAR_EXPRESSION "PASS: " FAIL_REGULAR_EXPRESSION "FAIL")
