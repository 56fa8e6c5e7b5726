# roomsense_bench_layer: the layer's overhead on calls it does not intercept (xrLocateSpace through the loader
# and the simulated runtime, with and without the layer), and its xrComputeRoomEXTX as an application sees it
# (layer_compute.cpp). Included by bench/CMakeLists.txt.
if(TARGET XrApiLayer_roomsense)
  find_package(benchmark REQUIRED)
  add_executable(roomsense_bench_layer ${CMAKE_CURRENT_LIST_DIR}/layer_overhead.cpp ${CMAKE_CURRENT_LIST_DIR}/layer_compute.cpp)
  target_link_libraries(roomsense_bench_layer PRIVATE OpenXR::openxr_loader roomsense_extx_header roomsense_xrsupport benchmark::benchmark
                        ${CMAKE_DL_LIBS})
  target_compile_definitions(roomsense_bench_layer PRIVATE
    ROOMSENSE_BENCH_RUNTIME_MANIFEST="${ROOMSENSE_SIMRUNTIME_MANIFEST}"
    ROOMSENSE_BENCH_LAYER_SEARCH_DIR="${PROJECT_BINARY_DIR}/share")
  add_dependencies(roomsense_bench_layer XrApiLayer_roomsense roomsense_simruntime)
endif()

# The layer's way into the analysis (layer/src/chunk_feed.h), timed in roomsense_bench's update_object_layer/ cases.
if(TARGET XrApiLayer_roomsense)
  target_sources(roomsense_bench PRIVATE ${PROJECT_SOURCE_DIR}/layer/src/chunk_feed.cpp ${PROJECT_SOURCE_DIR}/layer/src/mesh.cpp)
  target_link_libraries(roomsense_bench PRIVATE roomsense_xrsupport OpenXR::headers)
  target_compile_definitions(roomsense_bench PRIVATE ROOMSENSE_BENCH_LAYER_FEED=1)
endif()
