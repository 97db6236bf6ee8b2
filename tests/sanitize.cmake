# Configure, build and run the test suite with -DEDEM_SANITIZE=ON (ASan + UBSan).
# Run with: ctest -L sanitize   (it is also labelled "long", so CI's default run skips it).
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${BINARY_DIR} -G Ninja
                        -DCMAKE_BUILD_TYPE=RelWithDebInfo -DEDEM_SANITIZE=ON -DEDEM_BENCHMARKS=OFF
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "sanitize: configure failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BINARY_DIR} -j2 RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "sanitize: build failed")
endif()
set(ENV{ASAN_OPTIONS} "detect_leaks=1:abort_on_error=1")
set(ENV{UBSAN_OPTIONS} "print_stacktrace=1:halt_on_error=1")
execute_process(COMMAND ${CMAKE_CTEST_COMMAND} --output-on-failure -LE long -j2
                WORKING_DIRECTORY ${BINARY_DIR} RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "sanitize: tests failed under ASan/UBSan")
endif()
