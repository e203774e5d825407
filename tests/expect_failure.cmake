# Runs RAYTRACE with ARGS in a fresh WORK directory holding the files of SOURCE and a previous output.png
# (under `ulimit ULIMIT` if given; SCENE_NAME below adds a generated scene), and checks what every failure must look like: a non-zero exit, exactly
# EXPECTED as the one line on stderr (or a line matching EXPECTED_MATCH when it holds a machine-dependent
# number), nothing on stdout, the previous output.png unchanged and no file written.
file(REMOVE_RECURSE "${WORK}")
file(COPY "${SOURCE}/" DESTINATION "${WORK}")
file(WRITE "${WORK}/output.png" "previous render")
# A scene too big to keep in the repository is made here: SCENE_HEAD, then SCENE_BODY SCENE_TIMES times, then
# SCENE_TAIL, with ';' between lines.
if(DEFINED SCENE_NAME)
  string(REPEAT "${SCENE_BODY};" ${SCENE_TIMES} body)
  string(REPLACE ";" "\n" text "${SCENE_HEAD};${body}${SCENE_TAIL}")
  file(WRITE "${WORK}/${SCENE_NAME}" "${text}")
endif()
file(GLOB before RELATIVE "${WORK}" "${WORK}/*")

set(command "${RAYTRACE}" ${ARGS})
if(ULIMIT)
  set(command sh -c "ulimit ${ULIMIT} && exec \"$0\" \"$@\"" ${command})
endif()
execute_process(COMMAND ${command} WORKING_DIRECTORY "${WORK}"
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)

if(status EQUAL 0)
  message(FATAL_ERROR "exit status 0, expected a failure")
endif()
if(DEFINED EXPECTED AND NOT err STREQUAL "${EXPECTED}\n")
  message(FATAL_ERROR "stderr was:\n${err}expected:\n${EXPECTED}")
endif()
if(DEFINED EXPECTED_MATCH AND NOT err MATCHES "^${EXPECTED_MATCH}\n$")
  message(FATAL_ERROR "stderr was:\n${err}expected a line matching:\n${EXPECTED_MATCH}")
endif()
if(NOT out STREQUAL "")
  message(FATAL_ERROR "stdout was not empty:\n${out}")
endif()
file(READ "${WORK}/output.png" previous)
if(NOT previous STREQUAL "previous render")
  message(FATAL_ERROR "the previous output.png was overwritten")
endif()
file(GLOB after RELATIVE "${WORK}" "${WORK}/*")
if(NOT after STREQUAL before)
  message(FATAL_ERROR "files written: ${after}, expected only ${before}")
endif()
file(REMOVE_RECURSE "${WORK}")
