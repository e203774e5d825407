# A showcase scene (scenes/) rendered at 80x60 must give the kept picture byte for byte: a render is the same
# on any threads and tiles, so only a change in what a feature draws changes the bytes.
#   -DBIN=<raytrace> -DSCENE=<scene.pov> -DREFERENCE=<kept png> -DDIR=<empty working directory to use>
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
execute_process(COMMAND "${BIN}" render "${SCENE}" 80 60 -o "${DIR}/out.png" --quiet
                RESULT_VARIABLE status ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "render failed (${status}):\n${err}")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files "${DIR}/out.png" "${REFERENCE}" RESULT_VARIABLE differ)
if(differ)
  message(FATAL_ERROR "${DIR}/out.png differs from ${REFERENCE}; after an intended change, look at both and "
                      "copy the new one over the kept one")
endif()
