# Runs ${SSC} on ${PRM} and checks that it exits with status 1, that its
# message contains the text in ${EXPECT} and that this message is the first
# thing on stderr (no banner or trace before it). Each case runs under its
# own Run/Name ${NAME}: two runs into one output folder are refused.
execute_process(COMMAND ${SSC} ${PRM} -s "Run/Name=${NAME}"
  RESULT_VARIABLE _status OUTPUT_VARIABLE _out ERROR_VARIABLE _err
  TIMEOUT 60)
file(READ ${EXPECT} _expected)
string(STRIP "${_expected}" _expected)
if(NOT "${_status}" STREQUAL "1")
  message(FATAL_ERROR "expected exit status 1, got '${_status}'\n${_out}\n${_err}")
endif()
string(FIND "${_out}${_err}" "${_expected}" _pos)
if(_pos EQUAL -1)
  message(FATAL_ERROR "message does not contain '${_expected}':\n${_out}\n${_err}")
endif()
string(FIND "${_err}" "ssc: error:" _error_pos)
if(NOT _error_pos EQUAL 0)
  message(FATAL_ERROR "stderr does not start with 'ssc: error:':\n${_err}")
endif()
message(STATUS "exit status 1 with: ${_expected}")
