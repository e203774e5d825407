# Renders a .cli scene with the raytrace executable in an empty folder and checks that its `write` produced a
# PNG of the requested size. Run by CTest:
#   cmake -DRAYTRACE=… -DSCENE=… -DIMAGE=name.png -DWIDTH=… -DHEIGHT=… -DWORKDIR=… -P render_cli_scene.cmake
file(REMOVE_RECURSE "${WORKDIR}")
file(MAKE_DIRECTORY "${WORKDIR}")
execute_process(COMMAND "${RAYTRACE}" render "${SCENE}" ${WIDTH} ${HEIGHT}
                WORKING_DIRECTORY "${WORKDIR}" RESULT_VARIABLE status ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "raytrace render exited with ${status}: ${err}")
endif()
if(NOT EXISTS "${WORKDIR}/${IMAGE}")
  message(FATAL_ERROR "the scene's write did not produce ${IMAGE}")
endif()
# A PNG starts with its 8-byte signature, then the IHDR chunk: length, "IHDR", width, height (big-endian).
file(READ "${WORKDIR}/${IMAGE}" header LIMIT 24 HEX)
string(SUBSTRING "${header}" 0 16 signature)
string(SUBSTRING "${header}" 32 8 widthHex)
string(SUBSTRING "${header}" 40 8 heightHex)
math(EXPR gotWidth "0x${widthHex}")
math(EXPR gotHeight "0x${heightHex}")
if(NOT signature STREQUAL "89504e470d0a1a0a" OR NOT gotWidth EQUAL WIDTH OR NOT gotHeight EQUAL HEIGHT)
  message(FATAL_ERROR "${IMAGE} is not a ${WIDTH}x${HEIGHT} PNG (header ${header})")
endif()
