# Shared by the CLI contract tests (run with cmake -P and -DSHELFDOCK=<binary>):
# expect_shelfdock(<exit code> <regex> <subcommand and arguments...>) runs the CLI and fails
# unless it exits with <exit code> and its stdout + stderr match <regex>.
function(expect_shelfdock expected_code must_match)
  execute_process(COMMAND ${SHELFDOCK} ${ARGN}
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL expected_code)
    message(FATAL_ERROR "shelfdock ${ARGN}: exit ${code}, expected ${expected_code}\n${out}\n${err}")
  endif()
  if(NOT "${out}${err}" MATCHES "${must_match}")
    message(FATAL_ERROR "shelfdock ${ARGN}: output does not match '${must_match}'\n${out}\n${err}")
  endif()
endfunction()
