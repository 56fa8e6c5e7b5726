# roomsense_bench_compute: the voxel stage on the CPU against Vulkan, per stage and end to end, with
# transfer against compute time (compute/README.md has the table). Included by bench/CMakeLists.txt.
if(TARGET roomsense_compute)
  find_package(benchmark REQUIRED)
  add_executable(roomsense_bench_compute ${CMAKE_CURRENT_LIST_DIR}/bench_compute.cpp)
  target_link_libraries(roomsense_bench_compute PRIVATE
    roomsense_compute roomsense_core roomsense_scanio roomsense_synthetic benchmark::benchmark)
  target_compile_definitions(roomsense_bench_compute PRIVATE
    ROOMSENSE_BENCH_ROOMS_DIR="${PROJECT_SOURCE_DIR}/../shared/rooms")
endif()
