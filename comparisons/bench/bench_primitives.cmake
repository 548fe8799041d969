# Primitive pairs (sphere, capsule, box): overlap, contact and signed distance, gq vs FCL.
# Results: comparisons/results/primitives.csv (callgrind instructions: primitives_callgrind.csv).
find_package(fcl REQUIRED)
add_executable(bench_primitives ${CMAKE_CURRENT_LIST_DIR}/bench_primitives.cpp)
target_link_libraries(bench_primitives PRIVATE gq::core fcl benchmark::benchmark)
target_compile_options(bench_primitives PRIVATE -Wall -Wextra)
