# The dynamic symbols libRoomCreatorLibrary.so defines must be exactly the global names of its version
# script: the six thesis functions and the handle API, nothing of core, glm or the C++ runtime.
# cmake -DNM=... -DLIB=... -DMAP=... -P check_exports.cmake
execute_process(COMMAND ${NM} -D --defined-only ${LIB} OUTPUT_VARIABLE out RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${NM} failed on ${LIB}")
endif()
string(REPLACE "\n" ";" lines "${out}")
set(exported)
foreach(line IN LISTS lines)
  # "0000000000012340 T StartRoomUnderstanding"; names may carry a version ("@@V1")
  if(line MATCHES "^[0-9a-fA-F]* *[A-Za-z] ([^ @]+)")
    list(APPEND exported ${CMAKE_MATCH_1})
  endif()
endforeach()
list(SORT exported)

file(READ ${MAP} map)
string(REGEX REPLACE "/\\*.*\\*/" "" map "${map}")  # the comment
string(REGEX MATCH "global:([^}]*)local:" globals "${map}")
string(REGEX MATCHALL "[A-Za-z_][A-Za-z0-9_]*" expected "${CMAKE_MATCH_1}")
list(SORT expected)

message(STATUS "exported: ${exported}")
if(NOT exported STREQUAL expected)
  set(extra ${exported})
  list(REMOVE_ITEM extra ${expected})
  set(missing ${expected})
  list(REMOVE_ITEM missing ${exported})
  message(FATAL_ERROR "exported symbols differ from ${MAP}\n  not in the map: ${extra}\n  missing: ${missing}")
endif()
list(LENGTH exported n)
message(STATUS "${n} symbols, as in the version script")
