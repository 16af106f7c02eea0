# LIGGGHTS-PUBLIC built from source with the fix dropped in (included from
# CMakeLists.txt here). Test names start with src_liggghts_. Reused: the
# packaged path's scripts and inputs (../scripts, ../liggghts).
set(LIG_IN ${CMAKE_SOURCE_DIR}/tests/liggghts)
set(AS_LIG ${HOSTS}/as-build-liggghts)
set(BASIC --box 0 0.4 0 0.2 0 0.2 --radius 0.004 0.008 --fcc --bar 0.01 0.07 0.1 0.39 0.07 0.1 0.005 0.0075
          --bar 0.01 0.13 0.1 0.39 0.13 0.1 0.005 0.0075 --bar 0.2 0.01 0.05 0.2 0.19 0.05 0.005 0.0075)
foreach(np 1 2)
  add_test(NAME src_liggghts_scene_basic_np${np}
           COMMAND ${SCRIPTS}/scene.sh liggghts ${LIG_IN}/in.scene liggghts_basic ${np} ${AS_LIG}
                   -- ${BASIC} -- -var procs "* * *" -var extra "size fit radius 0.007 0.008" -- --rmin 0.007 --rmax 0.008)
  set_tests_properties(src_liggghts_scene_basic_np${np} PROPERTIES PROCESSORS 2 TIMEOUT 300
                       FAIL_REGULAR_EXPRESSION "FAIL|deleted 0 kept" PASS_REGULAR_EXPRESSION "PASS liggghts_basic np=${np}")
endforeach()
add_test(NAME src_liggghts_error_unknown_keyword
         COMMAND ${SCRIPTS}/expect_error.sh ${AS_LIG}/src/liggghts/liggghts_reinforce 1 ${LIG_IN}/errors/in.error
                 "Illegal fix reinforce/invert command: unknown keyword 'foo'" -var fix "fix r all reinforce/invert 0 bars foo 1")
set_tests_properties(src_liggghts_error_unknown_keyword PROPERTIES TIMEOUT 180
                     PASS_REGULAR_EXPRESSION "PASS: " FAIL_REGULAR_EXPRESSION "FAIL")
# Matrix spheres in a fix multisphere body refused (as on
# the packaged path, ../adapters).
add_test(NAME src_liggghts_error_matrix_in_multisphere_body
         COMMAND ${SCRIPTS}/expect_error.sh ${CMAKE_SOURCE_DIR}/tests/adapters/screen_devnull.sh 1
                 ${CMAKE_SOURCE_DIR}/tests/adapters/in.liggghts_multisphere
                 "Fix reinforce/invert cannot move atoms of rigid bodies: matrix atoms belong to fix clumps (multisphere); leave the bodies out of the fix group")
set_tests_properties(src_liggghts_error_matrix_in_multisphere_body PROPERTIES TIMEOUT 180
                     ENVIRONMENT "EXPECT_EXACT=1;REINFORCE_WRAPPED_EXE=${HOSTS}/liggghts/build/liggghts"
                     PASS_REGULAR_EXPRESSION "PASS: " FAIL_REGULAR_EXPRESSION "FAIL")
