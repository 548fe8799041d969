# Scenes and batches: scene raycast of 100k rays into 1000 mixed objects vs the loop over every object and vs Embree's
# BVH over the same objects, batch rays on 1 and 2 threads (scene and bunny; the bunny's 1M rays also against
# Embree's rtcIntersect1 and rtcIntersect1M), scene self pairs vs every pair and vs FCL's dynamic AABB tree manager
# (double). Results: comparisons/results/scene.csv (bench_scene.to_csv.py from the JSON of several runs).
find_package(fcl QUIET)
add_executable(bench_scene ${CMAKE_CURRENT_LIST_DIR}/bench_scene.cpp ${CMAKE_CURRENT_LIST_DIR}/bench_scene_peers.cpp)
target_link_libraries(bench_scene PRIVATE gq::core gq::io benchmark::benchmark embree fcl)
target_compile_definitions(bench_scene PRIVATE GQ_SHARED_DIR="${GQ_SHARED_DIR}")
target_compile_options(bench_scene PRIVATE -Wall -Wextra)
