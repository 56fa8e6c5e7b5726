# roomsense_bench_layer: the layer's overhead on calls it does not intercept (xrLocateSpace through the loader
# and the simulated runtime, with and without the layer). Included by bench/CMakeLists.txt.
if(TARGET XrApiLayer_roomsense)
  find_package(benchmark REQUIRED)
  add_executable(roomsense_bench_layer ${CMAKE_CURRENT_LIST_DIR}/layer_overhead.cpp)
  target_link_libraries(roomsense_bench_layer PRIVATE OpenXR::openxr_loader roomsense_extx_header roomsense_xrsupport benchmark::benchmark
                        ${CMAKE_DL_LIBS})
  target_compile_definitions(roomsense_bench_layer PRIVATE
    ROOMSENSE_BENCH_RUNTIME_MANIFEST="${ROOMSENSE_SIMRUNTIME_MANIFEST}"
    ROOMSENSE_BENCH_LAYER_SEARCH_DIR="${PROJECT_BINARY_DIR}/share")
  add_dependencies(roomsense_bench_layer XrApiLayer_roomsense roomsense_simruntime)
endif()
