# gq::fcl vs FCL 0.7 on the same ::fcl objects: collide/distance per pair family, broadphase self collision of
# 1000 objects. Results: comparisons/results/fcl_adapter.csv (bench_fcl_adapter.to_csv.py from the benchmark's JSON)
# and fcl_adapter_callgrind.csv (bench_fcl_adapter.callgrind.py: instructions per call).
if(TARGET gq::fcl)
  add_executable(bench_fcl_adapter ${CMAKE_CURRENT_LIST_DIR}/bench_fcl_adapter.cpp)
  target_link_libraries(bench_fcl_adapter PRIVATE gq::fcl benchmark::benchmark)
  target_compile_options(bench_fcl_adapter PRIVATE -Wall -Wextra)
endif()
