# Issue 12: what `cmake --install` puts under the prefix, and the .deb that `cpack -G DEB` makes.
#   bin/cablefilm                         the program (shaders and live page built in)
#   lib/cablefilm/cablefilm_render.so     its films and live view, loaded when used
#   lib/cablefilm/cablefilm_netcdf.so     its results.nc writer, loaded when used
#   lib/libcablefilm_core.a               cablefilm::core (physics; Eigen only)
#   include/cablefilm/core/*.h            its headers
#   lib/cmake/cablefilm/                  cablefilmConfig.cmake, ...ConfigVersion.cmake, targets
#   lib/python3.X/dist-packages/cablefilm.*.so   the Python module (when built)
#   share/cablefilm/scenes/               the example scenes (scenes/*.toml) and the motion
#                                         tables they read (scenes/*.csv)
#   share/doc/cablefilm/                  the user's manual (docs/: *.md, recipes/)
include(CMakePackageConfigHelpers)
include(GNUInstallDirs)  # CMAKE_INSTALL_DATADIR (share), CMAKE_INSTALL_DOCDIR (share/doc/cablefilm)

set(CABLEFILM_CMAKE_DIR lib/cmake/cablefilm)
install(TARGETS cablefilm RUNTIME DESTINATION bin)
# The modules the program loads on demand, where it looks for them: <bin>/../lib/cablefilm
# (src/modules/module_loader.h).
if(TARGET cablefilm_render)
  install(TARGETS cablefilm_render cablefilm_netcdf_module LIBRARY DESTINATION lib/cablefilm)
endif()
# The Python module, when built (cmake/python.cmake): into the prefix's Python folder,
# lib/python3.11/dist-packages on Debian.
if(TARGET cablefilm_python)
  install(TARGETS cablefilm_python LIBRARY DESTINATION ${CABLEFILM_PYTHON_INSTALL_DIR})
endif()
install(TARGETS cablefilm_core EXPORT cablefilmTargets
        ARCHIVE DESTINATION lib
        LIBRARY DESTINATION lib)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/core/ DESTINATION include/cablefilm/core
        FILES_MATCHING PATTERN "*.h")
install(FILES ${PROJECT_BINARY_DIR}/src/generated/core/version.h DESTINATION include/cablefilm/core)
install(EXPORT cablefilmTargets NAMESPACE cablefilm:: DESTINATION ${CABLEFILM_CMAKE_DIR})
# The example scenes beside the tables they name (a table's `file` is relative to its scene),
# so that `cablefilm run <prefix>/share/cablefilm/scenes/ship_table.toml` works as installed.
file(GLOB CABLEFILM_SCENE_FILES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/scenes/*.toml
     ${PROJECT_SOURCE_DIR}/scenes/*.csv)
install(FILES ${CABLEFILM_SCENE_FILES} DESTINATION ${CMAKE_INSTALL_DATADIR}/cablefilm/scenes)
# The manual: docs/README.md is its index; docs/recipes/ holds the recipes' scenes and table.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/cablefilmConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/cablefilmConfig.cmake
                              INSTALL_DESTINATION ${CABLEFILM_CMAKE_DIR})
# 0.x: a minor version may change the interface.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/cablefilmConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/cablefilmConfig.cmake
              ${PROJECT_BINARY_DIR}/cablefilmConfigVersion.cmake
        DESTINATION ${CABLEFILM_CMAKE_DIR})

# The .deb (cpack -G DEB): installs under /usr; its dependencies are the Debian 12 packages of
# the libraries the program links (found by dpkg-shlibdeps), the font it draws with (found
# through fontconfig at run time, so no library names it) and, recommended, Eigen for the CMake
# package.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME cablefilm)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "lumped-mass cable simulator that films the tension of a cable in a fluid")
set(CPACK_PACKAGE_DESCRIPTION
    "cablefilm simulates the transient motion of an elastic cable immersed in a fluid (mooring
lines, tow cables, tethers) with the lumped-mass model of Polachek et al. (1963) and renders,
headless, an H.264 film of its tension; it can also be watched and steered live in a browser.
The package also holds the core library (cablefilm::core) and its CMake package.")
set(CPACK_PACKAGE_CONTACT "cablefilm maintainers <cablefilm@localhost>")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "fonts-dejavu-core")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libeigen3-dev")
if(TARGET cablefilm_python)  # the Python it was built for (3.11 on Debian 12), numpy for arrays
  math(EXPR next_minor "${Python3_VERSION_MINOR} + 1")
  set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libeigen3-dev, python3 (>= \
${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}), python3 (<< \
${Python3_VERSION_MAJOR}.${next_minor}), python3-numpy")
endif()
set(CPACK_STRIP_FILES bin/cablefilm)
include(CPack)
