# Light-layering benchmark (graph build + colouring per frame). Included from
# bench/CMakeLists.txt with include(${CMAKE_CURRENT_SOURCE_DIR}/layering.cmake).
add_executable(antumbra_bench_layering ${CMAKE_CURRENT_LIST_DIR}/layering_bench.cpp)
target_link_libraries(antumbra_bench_layering PRIVATE antumbra_layering benchmark::benchmark
  benchmark::benchmark_main)
antumbra_target_defaults(antumbra_bench_layering)
