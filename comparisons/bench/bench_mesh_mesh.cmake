# Bunny vs bunny mesh overlap: gq (dual BVH4) vs FCL BVHModel<OBBRSS>. Results: comparisons/results/mesh_mesh.csv.
find_package(fcl REQUIRED)
add_executable(bench_mesh_mesh ${CMAKE_CURRENT_LIST_DIR}/bench_mesh_mesh.cpp)
target_link_libraries(bench_mesh_mesh PRIVATE gq::core gq::io fcl benchmark::benchmark)
target_compile_definitions(bench_mesh_mesh PRIVATE GQ_SHARED_DIR="${GQ_SHARED_DIR}")
target_compile_options(bench_mesh_mesh PRIVATE -Wall -Wextra)
