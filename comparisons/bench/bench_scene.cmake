# Scenes and batches: scene raycast of 100k rays into 1000 mixed objects vs the loop over every object, batch rays
# on 1 and 2 threads (scene and bunny), scene self pairs vs every pair (double).
add_executable(bench_scene ${CMAKE_CURRENT_LIST_DIR}/bench_scene.cpp)
target_link_libraries(bench_scene PRIVATE gq::core gq::io benchmark::benchmark)
target_compile_definitions(bench_scene PRIVATE GQ_SHARED_DIR="${GQ_SHARED_DIR}")
target_compile_options(bench_scene PRIVATE -Wall -Wextra)
