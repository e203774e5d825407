# `raycast` must write output.png, a PNG of the requested size, into its working directory.
#   -DBIN=<raytrace> -DSCENE=<scene> -DDIR=<empty working directory to use>
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
execute_process(COMMAND "${BIN}" raycast "${SCENE}" 301 201 WORKING_DIRECTORY "${DIR}" RESULT_VARIABLE status
                ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "raycast failed (${status}):\n${err}")
endif()
file(GLOB written RELATIVE "${DIR}" "${DIR}/*")
if(NOT written STREQUAL "output.png")
  message(FATAL_ERROR "raycast left '${written}' in its directory, expected only output.png")
endif()
# PNG signature, then the IHDR chunk: width and height as big-endian 32-bit numbers (301 = 0x12d, 201 = 0xc9).
file(READ "${DIR}/output.png" header LIMIT 24 HEX)
if(NOT header STREQUAL "89504e470d0a1a0a0000000d494844520000012d000000c9")
  message(FATAL_ERROR "output.png is not a 301x201 PNG: ${header}")
endif()
