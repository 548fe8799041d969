# Fit representations: certified error bound against overlap/distance cost of a moving sphere and box, per shared
# mesh and Panda/UR5 link. Results: comparisons/results/fit.csv (bench_fit --date --machine --commit --out).
add_executable(bench_fit ${CMAKE_CURRENT_LIST_DIR}/bench_fit.cpp)
target_link_libraries(bench_fit PRIVATE gq::core gq::io CLI11::CLI11)
target_compile_definitions(bench_fit PRIVATE GQ_SHARED_DIR="${GQ_SHARED_DIR}")
target_compile_options(bench_fit PRIVATE -Wall -Wextra)
target_include_directories(bench_fit PRIVATE ${PROJECT_SOURCE_DIR}/tests)  # generated_meshes.h
