# An image command must write exactly IMAGE, a PNG of the requested size, into its working directory: raycast
# and render write output.png, render of a .cli scene the file its `write` names.
#   -DBIN=<raytrace> -DCOMMAND=<raycast|render> -DSCENE=<scene> -DWIDTH=… -DHEIGHT=… -DIMAGE=<name.png>
#   -DDIR=<empty working directory to use> [-DFLAGS=<more arguments>] [-DULIMIT=<ulimit arguments>]
#   [-DERRORS=<the one line it must print on stderr>]
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
set(command "${BIN}" ${COMMAND} "${SCENE}" ${WIDTH} ${HEIGHT} ${FLAGS})
if(ULIMIT)
  set(command sh -c "ulimit ${ULIMIT} && exec \"$0\" \"$@\"" ${command})
endif()
execute_process(COMMAND ${command} WORKING_DIRECTORY "${DIR}" RESULT_VARIABLE status ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${COMMAND} failed (${status}):\n${err}")
endif()
if(DEFINED ERRORS AND NOT err STREQUAL "${ERRORS}\n")
  message(FATAL_ERROR "${COMMAND} printed '${err}', expected '${ERRORS}'")
endif()
file(GLOB written RELATIVE "${DIR}" "${DIR}/*")
if(NOT written STREQUAL "${IMAGE}")
  message(FATAL_ERROR "${COMMAND} left '${written}' in its directory, expected only ${IMAGE}")
endif()
# The PNG signature, then the IHDR chunk: length, "IHDR", width and height as big-endian 32-bit numbers.
file(READ "${DIR}/${IMAGE}" header LIMIT 24 HEX)
string(SUBSTRING "${header}" 0 32 start)
string(SUBSTRING "${header}" 32 8 widthHex)
string(SUBSTRING "${header}" 40 8 heightHex)
math(EXPR width "0x${widthHex}")
math(EXPR height "0x${heightHex}")
if(NOT start STREQUAL "89504e470d0a1a0a0000000d49484452" OR NOT width EQUAL WIDTH OR NOT height EQUAL HEIGHT)
  message(FATAL_ERROR "${IMAGE} is not a ${WIDTH}x${HEIGHT} PNG: ${header}")
endif()
