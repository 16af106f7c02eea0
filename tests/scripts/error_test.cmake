# reinforce_error_test(TEST EXE NP INPUT EXPECTED FIX [more -var args]): bad
# input stops EXE (on NP processes) with exactly one ERROR line whose
# message is exactly EXPECTED, a non-zero exit, no hang, nothing written
# (expect_error.sh). Shared by the hosts' error tests.
function(reinforce_error_test test exe np input expected fix)
  add_test(NAME ${test}
           COMMAND ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/expect_error.sh ${exe} ${np} ${input} "${expected}"
                   -var fix "${fix}" ${ARGN})
  set_tests_properties(${test} PROPERTIES TIMEOUT 180 ENVIRONMENT "EXPECT_EXACT=1"
                       PASS_REGULAR_EXPRESSION "PASS: " FAIL_REGULAR_EXPRESSION "FAIL")
  if(np GREATER 1)
    set_tests_properties(${test} PROPERTIES PROCESSORS 2)
  endif()
endfunction()
