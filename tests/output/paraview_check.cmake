# Runs scene.lua with edem in WORKDIR, then paraview_check.py with pvpython (Debian's paraview,
# installed by scripts/install-deps.sh --paraview, which this long test runs first).
execute_process(COMMAND bash ${ROOT}/scripts/install-deps.sh --paraview RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "scripts/install-deps.sh --paraview failed (${status})")
endif()
execute_process(COMMAND ${EDEM} --quiet --threads 1 run ${SOURCE}/scene.lua WORKING_DIRECTORY ${WORKDIR}
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "edem failed (${status})")
endif()
execute_process(COMMAND pvpython --force-offscreen-rendering ${SOURCE}/paraview_check.py ${WORKDIR} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "paraview_check.py failed (${status})")
endif()
