# New BVHModels: the first query on a model just built and a MoveIt-like pattern (100 new models, 3 queries each),
# gq::fcl against FCL; comparisons/results/fcl_new_mesh.csv (bench_fcl_new_mesh.to_csv.py).
if(TARGET gq::fcl)
  add_executable(bench_fcl_new_mesh ${CMAKE_CURRENT_LIST_DIR}/bench_fcl_new_mesh.cpp)
  target_link_libraries(bench_fcl_new_mesh PRIVATE gq::fcl benchmark::benchmark)
  target_compile_options(bench_fcl_new_mesh PRIVATE -Wall -Wextra)
endif()
