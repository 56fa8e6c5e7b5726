# Windows x86-64 from Linux with Debian's MinGW-w64 (g++-mingw-w64-x86-64-posix: the POSIX thread model,
# which std::thread and std::jthread need). Tests run under Wine (Debian's wine) as the emulator, so ctest and
# gtest_discover_tests work as on Linux. Use: scripts/windows.sh, or
#   cmake -B build-win -G Ninja -DCMAKE_TOOLCHAIN_FILE=cmake/toolchains/mingw-w64-x86_64.cmake
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(_triple x86_64-w64-mingw32)
set(CMAKE_C_COMPILER ${_triple}-gcc-posix)
set(CMAKE_CXX_COMPILER ${_triple}-g++-posix)
set(CMAKE_RC_COMPILER ${_triple}-windres)
set(CMAKE_FIND_ROOT_PATH /usr/${_triple})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)  # glslangValidator and friends run here
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# Wine's own prefix in the build tree (the user's ~/.wine is left alone) and none of its debug chatter.
find_program(ROOMSENSE_WINE NAMES wine64 wine)
set(ROOMSENSE_WINEPREFIX ${CMAKE_BINARY_DIR}/wineprefix)
if(ROOMSENSE_WINE)
  set(CMAKE_CROSSCOMPILING_EMULATOR /usr/bin/env WINEPREFIX=${ROOMSENSE_WINEPREFIX} WINEDEBUG=-all ${ROOMSENSE_WINE})
endif()
# The C++ runtime, libgcc and winpthreads linked in: the DLLs and programs need no MinGW DLLs beside them
# (a layer must not bring a libstdc++ that conflicts with the app's).
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static")
set(CMAKE_SHARED_LINKER_FLAGS_INIT "-static")
