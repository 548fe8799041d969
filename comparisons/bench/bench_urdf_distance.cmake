# gq::urdf selfDistance on Panda's collision meshes (mesh and hull representations), when the URDF plugin is built.
# Results: comparisons/results/urdf_self_distance.csv.
if(TARGET gq::urdf)
  add_executable(bench_urdf_distance ${CMAKE_CURRENT_LIST_DIR}/bench_urdf_distance.cpp)
  target_link_libraries(bench_urdf_distance PRIVATE gq::urdf benchmark::benchmark)
  target_compile_definitions(bench_urdf_distance PRIVATE GQ_SHARED_DIR="${GQ_SHARED_DIR}")
  target_compile_options(bench_urdf_distance PRIVATE -Wall -Wextra)
endif()
