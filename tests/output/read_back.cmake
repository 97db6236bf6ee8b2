# Runs scene.lua with edem in WORKDIR, then read_back.py with Debian's python3 (h5py).
execute_process(COMMAND ${EDEM} --quiet --threads 1 run ${SOURCE}/scene.lua WORKING_DIRECTORY ${WORKDIR}
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "edem failed (${status})")
endif()
if(NOT EXISTS ${PYTHON})
  message(FATAL_ERROR "no ${PYTHON}: install python3-h5py (scripts/install-deps.sh)")
endif()
execute_process(COMMAND ${PYTHON} ${SOURCE}/read_back.py ${WORKDIR} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "read_back.py failed (${status})")
endif()
