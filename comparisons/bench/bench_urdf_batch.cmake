# gq::urdf self-collision batches of Panda configurations on 1 and 2 threads, when the URDF plugin is built.
# Results: comparisons/results/urdf_batch.csv (bench_urdf_batch.to_csv.py).
if(TARGET gq::urdf)
  add_executable(bench_urdf_batch ${CMAKE_CURRENT_LIST_DIR}/bench_urdf_batch.cpp)
  target_link_libraries(bench_urdf_batch PRIVATE gq::urdf benchmark::benchmark)
  target_compile_definitions(bench_urdf_batch PRIVATE GQ_SHARED_DIR="${GQ_SHARED_DIR}")
  target_compile_options(bench_urdf_batch PRIVATE -Wall -Wextra)
endif()
