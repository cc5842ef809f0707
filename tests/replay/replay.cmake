# Runs ${SSC} on ${PRM} into ${WORK}, then again on the parameters.prm that
# run wrote (as another run name), and checks with compare_summaries.py that
# the second summary.json equals the first: parameters.prm holds every
# parameter the run used.
file(REMOVE_RECURSE ${WORK})
execute_process(COMMAND ${SSC} ${PRM} -s "Run/Output directory=${WORK}"
  RESULT_VARIABLE _status OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
if(NOT _status EQUAL 0)
  message(FATAL_ERROR "first run failed (${_status}):\n${_out}\n${_err}")
endif()
execute_process(COMMAND ${SSC} ${WORK}/replay/parameters.prm
  -s "Run/Name=replay_again"
  RESULT_VARIABLE _status OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
if(NOT _status EQUAL 0)
  message(FATAL_ERROR "replay failed (${_status}):\n${_out}\n${_err}")
endif()
execute_process(COMMAND ${PYTHON} ${COMPARE} ${WORK}/replay/summary.json
  ${WORK}/replay_again/summary.json
  RESULT_VARIABLE _status OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
if(NOT _status EQUAL 0)
  message(FATAL_ERROR "${_out}${_err}")
endif()
message(STATUS "${_out}")
