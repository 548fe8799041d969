# Rays against a 512 x 512 heightfield terrain: gq (double, float, prepared shapes) vs Bullet's (float)
# btHeightfieldTerrainShape::performRaycast, plain and with buildAccelerator(); every gq answer checked against a
# long-double reference first. Results: comparisons/results/raycast_heightfield.csv (bench_raycast_heightfield.to_csv.py).
add_executable(bench_raycast_heightfield ${CMAKE_CURRENT_LIST_DIR}/bench_raycast_heightfield.cpp)
target_link_libraries(bench_raycast_heightfield PRIVATE gq::core benchmark::benchmark GeomQuery::bullet_float)
target_compile_options(bench_raycast_heightfield PRIVATE -Wall -Wextra)
