# The dependencies of a cross build (the MinGW-w64 Windows build), where Debian has no packages for the target:
# - the header-only ones (GLM, nlohmann-json, the OpenXR and Vulkan headers, tinyobjloader's header) are the
#   host's Debian packages: headers do not depend on the architecture. Only their folders are staged in the
#   build tree, so the cross compiler never sees the rest of the host's /usr/include.
# - tinyobjloader's implementation is compiled from that header into scanio (Debian ships it as a Linux .so);
# - GoogleTest is built from Debian's sources (/usr/src/googletest, package googletest);
# - assimp is absent: the glTF reader is left out and says so (scanio), and the report tests are not built.
# Each becomes the imported target the native build gets from find_package, so no CMakeLists differs.
set(_staged ${PROJECT_BINARY_DIR}/cross-include)
file(MAKE_DIRECTORY ${_staged})
foreach(entry glm nlohmann openxr vulkan vk_video tiny_obj_loader.h)
  if(NOT EXISTS /usr/include/${entry})
    message(FATAL_ERROR "cross build: /usr/include/${entry} is missing (Debian: libglm-dev nlohmann-json3-dev "
                        "libopenxr-dev libvulkan-dev libtinyobjloader-dev)")
  endif()
  file(CREATE_LINK /usr/include/${entry} ${_staged}/${entry} SYMBOLIC)
endforeach()

function(_roomsense_header_target name)
  add_library(${name} INTERFACE IMPORTED GLOBAL)
  set_target_properties(${name} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${_staged})
endfunction()
_roomsense_header_target(glm::glm)
_roomsense_header_target(nlohmann_json::nlohmann_json)
_roomsense_header_target(OpenXR::headers)
_roomsense_header_target(tinyobjloader::tinyobjloader)
set(VULKAN_HEADERS_DIR ${_staged} CACHE PATH "Vulkan headers (staged from the host's libvulkan-dev)")

find_package(Threads REQUIRED)
if(ROOMSENSE_BUILD_TESTS)
  set(_gtest_src /usr/src/googletest)
  if(NOT EXISTS ${_gtest_src}/CMakeLists.txt)
    message(FATAL_ERROR "cross build: ${_gtest_src} is missing (Debian: googletest)")
  endif()
  set(BUILD_GMOCK OFF CACHE BOOL "" FORCE)
  set(INSTALL_GTEST OFF CACHE BOOL "" FORCE)
  add_subdirectory(${_gtest_src} ${PROJECT_BINARY_DIR}/googletest EXCLUDE_FROM_ALL SYSTEM)
  # its CMakeLists defines GTest::gtest and GTest::gtest_main itself
endif()

# Wine's prefix made now, quietly: otherwise the first test program that runs (gtest discovery, at build time)
# makes it and prints Wine's setup chatter into the build log.
if(ROOMSENSE_WINEPREFIX AND CMAKE_CROSSCOMPILING_EMULATOR AND NOT EXISTS ${ROOMSENSE_WINEPREFIX})
  execute_process(COMMAND ${CMAKE_CROSSCOMPILING_EMULATOR} wineboot --init OUTPUT_QUIET ERROR_QUIET)
endif()
