# roomsense_export_only(TARGET MAP): a shared library exports exactly the global names of the version script
# MAP and leaves nothing unresolved. ELF: the script itself. Windows: a module-definition file made from it
# (GNU ld then exports only what it lists), and every runtime linked in statically (-static in the toolchain
# file), so a DLL needs nothing but Windows' own.
include(${CMAKE_CURRENT_LIST_DIR}/export_names.cmake)

function(roomsense_export_only target map)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${map})
  if(WIN32)
    roomsense_export_names(${map} names)
    list(JOIN names "\n  " lines)
    set(def ${CMAKE_CURRENT_BINARY_DIR}/${target}.def)
    file(CONFIGURE OUTPUT ${def} CONTENT "EXPORTS\n  ${lines}\n")
    target_sources(${target} PRIVATE ${def})
  else()
    target_link_options(${target} PRIVATE "-Wl,--version-script=${map}" -Wl,--no-undefined -Wl,--as-needed)
    set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS ${map})
  endif()
endfunction()
