# Bullet scenes stepped and queried with stock Bullet and through gq's Bullet adapter, in one run: float Bullet
# (bench_bullet_adapter) and Bullet's float64 build (bench_bullet_adapter_double: libBullet*-float64, the same
# sources with BT_USE_DOUBLE_PRECISION). Results: comparisons/results/bullet_adapter.csv and
# bullet_adapter_callgrind.csv.
if(TARGET gq::bullet)
  foreach(variant IN ITEMS float double)
    if(variant STREQUAL "float")
      set(name bench_bullet_adapter)
      set(adapter gq::bullet)
    else()
      set(name bench_bullet_adapter_double)
      set(adapter gq::bullet_double)
    endif()
    add_executable(${name} ${CMAKE_CURRENT_LIST_DIR}/bench_bullet_adapter.cpp)
    target_link_libraries(${name} PRIVATE ${adapter} benchmark::benchmark)
    target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR}/tests/bullet)
    target_compile_options(${name} PRIVATE -Wall -Wextra)
  endforeach()
endif()
