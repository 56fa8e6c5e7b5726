# register_layer.cmd under Wine, as a runtime vendor's installer would run it on Windows: it registers the
# manifest beside it in HKLM\SOFTWARE\Khronos\OpenXR\1\ApiLayers\Implicit as a DWORD 0; the layer loads and
# negotiates from the manifest that value names (layer_loads.exe); /remove takes the value away again.
# cmake -DWINE=... -DWINEPREFIX=... -DBIN=<build>/bin -P check_registration.cmake
set(key "HKLM\\SOFTWARE\\Khronos\\OpenXR\\1\\ApiLayers\\Implicit")
string(REPLACE "/" "\\" bin_windows "Z:${BIN}")  # Wine's drive Z: is the host's /
set(wine ${CMAKE_COMMAND} -E env WINEPREFIX=${WINEPREFIX} WINEDEBUG=-all ${WINE})

function(run out_var)
  execute_process(COMMAND ${wine} ${ARGN} OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
  string(REPLACE "\r" "" out "${out}")
  set(${out_var} "${out}" PARENT_SCOPE)
  set(${out_var}_rc ${rc} PARENT_SCOPE)
  set(${out_var}_err "${err}" PARENT_SCOPE)
endfunction()

function(registered_manifests out_var)
  run(query reg query "${key}")
  string(REGEX MATCHALL "[^\n]*XR_APILAYER_ROOMSENSE_room_understanding\\.json[ \t]+REG_DWORD[ \t]+0x0" lines "${query}")
  set(${out_var} "${lines}" PARENT_SCOPE)
endfunction()

run(reg cmd /c "${bin_windows}\\register_layer.cmd")
if(NOT reg_rc EQUAL 0 OR NOT reg MATCHES "registered ")
  message(FATAL_ERROR "register_layer.cmd failed (${reg_rc}): ${reg}${reg_err}")
endif()
message(STATUS "register_layer.cmd: ${reg}")
registered_manifests(lines)
list(LENGTH lines n)
if(NOT n EQUAL 1)
  message(FATAL_ERROR "expected one enabled (DWORD 0) value for the manifest under ${key}, found: ${lines}")
endif()
string(REGEX REPLACE "^[ \t]*(.+\\.json)[ \t]+REG_DWORD.*$" "\\1" manifest "${lines}")
message(STATUS "the registry names ${manifest} (REG_DWORD 0x0: enabled)")

run(loads "${BIN}/layer_loads.exe" "${manifest}")
message(STATUS "layer_loads.exe:\n${loads}")
if(NOT loads_rc EQUAL 0)
  message(FATAL_ERROR "the layer does not load and negotiate from the registered manifest (${loads_rc}) ${loads_err}")
endif()

run(again cmd /c "${bin_windows}\\register_layer.cmd")  # a second registration replaces, not duplicates
registered_manifests(lines)
list(LENGTH lines n)
if(NOT n EQUAL 1)
  message(FATAL_ERROR "registering twice left ${n} values")
endif()
run(unreg cmd /c "${bin_windows}\\register_layer.cmd" /remove)
registered_manifests(lines)
if(NOT unreg_rc EQUAL 0 OR lines)
  message(FATAL_ERROR "register_layer.cmd /remove failed (${unreg_rc}): ${unreg}${unreg_err} ${lines}")
endif()
message(STATUS "register_layer.cmd /remove: ${unreg}")
run(twice cmd /c "${bin_windows}\\register_layer.cmd" /remove)
if(twice_rc EQUAL 0)
  message(FATAL_ERROR "removing what is not registered should fail")
endif()
message(STATUS "a second /remove fails: ${twice_err}")
