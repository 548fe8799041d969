# Bullet scenes stepped and queried with stock Bullet and through gq's Bullet adapter, in one run (float Bullet).
# Results: comparisons/results/bullet_adapter.csv.
if(TARGET gq::bullet)
  add_executable(bench_bullet_adapter ${CMAKE_CURRENT_LIST_DIR}/bench_bullet_adapter.cpp)
  target_link_libraries(bench_bullet_adapter PRIVATE gq::bullet benchmark::benchmark)
  target_include_directories(bench_bullet_adapter PRIVATE ${PROJECT_SOURCE_DIR}/tests/bullet)
  target_compile_options(bench_bullet_adapter PRIVATE -Wall -Wextra)
endif()
