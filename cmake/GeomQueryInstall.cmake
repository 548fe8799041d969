# Installation of the CMake package GeomQuery: one export set per component (GeomQuery<Comp>Targets.cmake, read by
# GeomQueryConfig.cmake only when that component is asked for), so a user of gq::core needs none of the adapters'
# dependencies. Install components (CPack packages): `runtime` (tools, shared libraries) and `dev` (headers, static
# libraries, CMake files).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
set(GQ_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/GeomQuery)

# GeomQuery<Comp>Targets: the component name with a capital first letter (core -> Core).
function(gq_component_export_name comp out_var)
  string(SUBSTRING "${comp}" 0 1 first)
  string(SUBSTRING "${comp}" 1 -1 rest)
  string(TOUPPER "${first}" first)
  set(${out_var} "GeomQuery${first}${rest}Targets" PARENT_SCOPE)
endfunction()

# gq_install_component(<component> TARGETS <target>... [HEADERS <include-folder>...]): installs the libraries and
# their public headers (the folders' contents go to include/) and exports them as gq::<EXPORT_NAME>.
function(gq_install_component comp)
  cmake_parse_arguments(ARG "" "" "TARGETS;HEADERS" ${ARGN})
  gq_component_export_name(${comp} export_name)
  install(TARGETS ${ARG_TARGETS} EXPORT ${export_name}
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT dev
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT runtime NAMELINK_COMPONENT dev
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime
    INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  foreach(dir ${ARG_HEADERS})
    install(DIRECTORY ${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT dev)
  endforeach()
  install(EXPORT ${export_name} NAMESPACE gq:: DESTINATION ${GQ_INSTALL_CMAKEDIR} COMPONENT dev)
  set_property(GLOBAL APPEND PROPERTY GQ_INSTALLED_COMPONENTS ${comp})
endfunction()

# The package's config and version files, and the helper modules the config includes. Called once, after every
# component is added.
function(gq_install_package_config)
  get_property(components GLOBAL PROPERTY GQ_INSTALLED_COMPONENTS)
  set(GQ_PACKAGE_COMPONENTS "${components}")
  # Static libraries carry their private dependencies to the user's link: the config must find those too.
  get_target_property(core_type gq_core TYPE)
  if(core_type STREQUAL "STATIC_LIBRARY")
    set(GQ_STATIC_LIBRARIES TRUE)
  else()
    set(GQ_STATIC_LIBRARIES FALSE)
  endif()
  configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/GeomQueryConfig.cmake.in
    ${PROJECT_BINARY_DIR}/GeomQueryConfig.cmake INSTALL_DESTINATION ${GQ_INSTALL_CMAKEDIR})
  write_basic_package_version_file(${PROJECT_BINARY_DIR}/GeomQueryConfigVersion.cmake
    COMPATIBILITY SameMinorVersion)
  install(FILES ${PROJECT_BINARY_DIR}/GeomQueryConfig.cmake ${PROJECT_BINARY_DIR}/GeomQueryConfigVersion.cmake
    ${PROJECT_SOURCE_DIR}/cmake/GeomQueryBullet.cmake
    DESTINATION ${GQ_INSTALL_CMAKEDIR} COMPONENT dev)
  message(STATUS "GeomQuery: installable components: ${components}")
endfunction()
