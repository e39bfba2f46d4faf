# Runs a Python example, SCRIPT (cmake -P, from CTest). Without numpy it SKIPS, except in CI (the CI
# environment variable set), where the example must run.
execute_process(COMMAND ${PYTHON} -c "import numpy" RESULT_VARIABLE numpy_missing OUTPUT_QUIET ERROR_QUIET)
if(NOT numpy_missing EQUAL 0)
  if(NOT "$ENV{CI}" STREQUAL "")
    message(FATAL_ERROR "numpy does not import with ${PYTHON}; the Python example must run in CI")
  endif()
  message("PERISTEP_SKIP: numpy does not import with ${PYTHON}")
  return()
endif()
execute_process(COMMAND ${PYTHON} ${SCRIPT} ${LIBRARY} RESULT_VARIABLE failed)
if(NOT failed EQUAL 0)
  message(FATAL_ERROR "${SCRIPT} failed (${failed})")
endif()
