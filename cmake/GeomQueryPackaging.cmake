# Debian packages (`cpack -G DEB` in the build folder):
#   geomquery      the tools (gq-query, gq-query-bullet, gq-query-bullet64, gq-compare, gq-pairs, gq-urdf) and, in a
#                  BUILD_SHARED_LIBS build, the shared libraries; dependencies from dpkg-shlibdeps
#   geomquery-dev  headers, libraries, the CMake package (find_package(GeomQuery COMPONENTS ...)); depends on the
#                  Debian -dev packages the installed config finds
set(CPACK_PACKAGE_NAME geomquery)
set(CPACK_PACKAGE_VENDOR "GeomQuery")
set(CPACK_PACKAGE_CONTACT "GeomQuery <geomquery@invalid>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Geometry queries in float and double, with FCL and Bullet adapters and URDF self-collision")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_INSTALL_DIRECTORY GeomQuery)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
if(EXISTS ${PROJECT_SOURCE_DIR}/LICENSE)
  set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
  install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/geomquery RENAME copyright
    COMPONENT runtime)
  install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/geomquery-dev RENAME copyright
    COMPONENT dev)
endif()

set(CPACK_COMPONENTS_ALL runtime dev)
set(CPACK_COMPONENT_RUNTIME_DISPLAY_NAME "GeomQuery tools")
set(CPACK_COMPONENT_DEV_DISPLAY_NAME "GeomQuery development files")
if(BUILD_SHARED_LIBS)
  set(CPACK_COMPONENT_DEV_DEPENDS runtime)  # the -dev package's namelinks point into the runtime package
endif()

set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_ENABLE_COMPONENT_DEPENDS ON)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME geomquery)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SECTION science)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_DEV_PACKAGE_NAME geomquery-dev)
set(CPACK_DEBIAN_DEV_PACKAGE_SECTION libdevel)
# The installed GeomQueryConfig.cmake finds these (static libraries carry their private dependencies).
set(CPACK_DEBIAN_DEV_PACKAGE_DEPENDS
  "libeigen3-dev (>= 3.3), libqhull-dev, libassimp-dev, libtinyobjloader-dev, libfcl-dev, libccd-dev, libbullet-dev, liburdfdom-dev, libtinyxml-dev, libtinyxml2-dev")
include(CPack)
