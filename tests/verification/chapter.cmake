# The verification chapter (tests/verification/README.md, made by scripts/make-docs.sh) has a
# section, with its chart, for every verification script: a new script without a regenerated
# chapter fails here.
file(GLOB scripts ${DIR}/*.lua)
file(READ ${DIR}/README.md chapter)
set(missing "")
foreach(script IN LISTS scripts)
  get_filename_component(name ${script} NAME_WE)
  string(FIND "${chapter}" "## ${name}\n" at)
  if(at EQUAL -1 OR NOT EXISTS ${DIR}/report/${name}.png)
    list(APPEND missing ${name})
  endif()
endforeach()
if(missing)
  message(FATAL_ERROR "tests/verification/README.md lacks ${missing}: run bash scripts/make-docs.sh")
endif()
