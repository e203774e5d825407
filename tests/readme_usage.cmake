# README.md's usage block must be exactly what `raytrace --help` prints (tools/sync_readme_usage.py writes it).
# Run as: cmake -DBIN=<raytrace> -DREADME=<README.md> -P readme_usage.cmake
set(begin "<!-- usage:begin (written by tools/sync_readme_usage.py from raytrace --help) -->\n")
set(end "<!-- usage:end -->\n")

execute_process(COMMAND ${BIN} --help OUTPUT_VARIABLE help RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${BIN} --help exited with ${status}")
endif()

file(READ "${README}" readme)
string(FIND "${readme}" "${begin}" start)
string(FIND "${readme}" "${end}" stop)
if(start EQUAL -1 OR stop EQUAL -1 OR stop LESS start)
  message(FATAL_ERROR "${README}: no usage block between the markers of tools/sync_readme_usage.py")
endif()
string(LENGTH "${begin}" skip)
math(EXPR from "${start} + ${skip}")
math(EXPR length "${stop} - ${from}")
string(SUBSTRING "${readme}" ${from} ${length} found)

set(expected "```text\n${help}```\n")
if(NOT found STREQUAL expected)
  message(FATAL_ERROR "${README}'s usage block differs from `raytrace --help`; run tools/sync_readme_usage.py "
                      "--bin ${BIN}\n--- README:\n${found}--- raytrace --help:\n${expected}")
endif()
