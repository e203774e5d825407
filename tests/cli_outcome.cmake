# Runs the real raytrace in a fresh directory and checks the whole outcome of a run that goes partly wrong:
# its exit status, its whole stderr and the files left in the directory.
#   -DBIN=<raytrace> -DARGS=<arguments> -DDIR=<working directory to make> -DSTATUS=<exit status>
#   -DEXPECTED=<stderr, without its final newline> -DFILES=<the directory's files afterwards, sorted, by commas>
#   [-DSCENE=<a file copied into DIR first>] [-DSTDOUT_FILE=<where stdout goes, e.g. /dev/full>]
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
if(DEFINED SCENE)
  file(COPY "${SCENE}" DESTINATION "${DIR}")
endif()
set(redirect)
if(DEFINED STDOUT_FILE)
  set(redirect OUTPUT_FILE "${STDOUT_FILE}")
endif()
execute_process(COMMAND "${BIN}" ${ARGS} WORKING_DIRECTORY "${DIR}" RESULT_VARIABLE status ERROR_VARIABLE err
                ${redirect})
if(NOT status STREQUAL "${STATUS}")
  message(FATAL_ERROR "exit status ${status}, expected ${STATUS}; stderr:\n${err}")
endif()
if(NOT err STREQUAL "${EXPECTED}\n")
  message(FATAL_ERROR "stderr was:\n${err}expected:\n${EXPECTED}")
endif()
file(GLOB files RELATIVE "${DIR}" "${DIR}/*")
list(SORT files)
string(REPLACE "," ";" FILES "${FILES}")
if(NOT files STREQUAL "${FILES}")
  message(FATAL_ERROR "files left: ${files}, expected ${FILES}")
endif()
file(REMOVE_RECURSE "${DIR}")
