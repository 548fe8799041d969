# DART: a 27-body pile stepped with the gq, bullet and fcl collision detectors (bench_dart.cpp). Results:
# comparisons/results/dart.csv (bench_dart.to_csv.py).
if(TARGET gq::dart AND TARGET dart-collision-bullet)
  add_executable(bench_dart ${CMAKE_CURRENT_LIST_DIR}/bench_dart.cpp)
  # The detectors are asked for by name only: --no-as-needed keeps DART's Bullet detector linked.
  target_link_libraries(bench_dart PRIVATE gq::dart "-Wl,--no-as-needed" dart-collision-bullet "-Wl,--as-needed"
                        benchmark::benchmark)
  target_include_directories(bench_dart PRIVATE ${PROJECT_SOURCE_DIR}/tests/dart)
  target_compile_options(bench_dart PRIVATE -Wall -Wextra)
endif()
