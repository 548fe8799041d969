# Sweeps of box, capsule and convex against the bunny mesh and against a convex hull: gq (double, float) vs Bullet
# btCollisionWorld::convexSweepTest (float Bullet libraries). Results: comparisons/results/sweep_bullet.csv.
add_executable(bench_sweep ${CMAKE_CURRENT_LIST_DIR}/bench_sweep.cpp)
target_link_libraries(bench_sweep PRIVATE gq::core gq::io benchmark::benchmark GeomQuery::bullet_float)
target_compile_definitions(bench_sweep PRIVATE GQ_SHARED_DIR="${GQ_SHARED_DIR}")
target_compile_options(bench_sweep PRIVATE -Wall -Wextra)
