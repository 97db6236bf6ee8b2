# Runs checksum.lua with one and with two threads; the printed checksums must be equal.
foreach(threads 1 2)
  execute_process(COMMAND ${EDEM} --threads ${threads} run ${SCRIPT}
                  OUTPUT_VARIABLE out_${threads} ERROR_VARIABLE err RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "edem --threads ${threads} failed (${rc}):\n${out_${threads}}${err}")
  endif()
  string(REGEX MATCH "checksum [0-9a-f]+" sum_${threads} "${out_${threads}}")
  message(STATUS "--threads ${threads}: ${sum_${threads}}")
endforeach()
if(NOT sum_1 OR NOT sum_1 STREQUAL sum_2)
  message(FATAL_ERROR "results differ between 1 and 2 threads:\n${out_1}\n${out_2}")
endif()
