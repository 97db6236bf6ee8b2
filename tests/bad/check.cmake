# Runs one bad script and checks that edem rejects it properly:
#  - exit status 1 (not 0, not a crash or signal);
#  - the first line of stderr is "FILE.lua:LINE: command: message", with LINE the line
#    given in the script's "-- line: N" header comment;
#  - stderr matches the regular expression in the "-- expect: REGEX" header comment.
file(STRINGS ${SCRIPT} header REGEX "^-- (expect|line): ")
set(expect "")
set(line "")
foreach(h IN LISTS header)
  if(h MATCHES "^-- expect: (.*)$")
    set(expect "${CMAKE_MATCH_1}")
  elseif(h MATCHES "^-- line: ([0-9]+)$")
    set(line "${CMAKE_MATCH_1}")
  endif()
endforeach()
if(expect STREQUAL "" OR line STREQUAL "")
  message(FATAL_ERROR "${SCRIPT}: needs '-- expect: REGEX' and '-- line: N' header comments")
endif()
get_filename_component(dir ${SCRIPT} DIRECTORY)
get_filename_component(base ${SCRIPT} NAME)
execute_process(COMMAND ${EDEM} run ${base} WORKING_DIRECTORY ${dir}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 50)
if(NOT rc STREQUAL "1")
  message(FATAL_ERROR "expected exit status 1, got '${rc}'\nstderr:\n${err}")
endif()
string(REGEX MATCH "^[^\n]*" first "${err}")
if(NOT first MATCHES "^${base}:${line}: [a-z_]+: ")
  message(FATAL_ERROR "first stderr line is not '${base}:${line}: command: ...':\n${first}")
endif()
if(NOT err MATCHES "${expect}")
  message(FATAL_ERROR "stderr does not match '${expect}':\n${err}")
endif()
message(STATUS "ok: ${first}")
