# run_or_fail(WHAT COMMAND...): runs COMMAND, and stops the `cmake -P` script
# with an error naming WHAT and the command if it fails.
function (run_or_fail what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result)
  if (NOT result EQUAL 0)
    message(FATAL_ERROR "${what} failed (${result}): ${ARGN}")
  endif ()
endfunction ()
