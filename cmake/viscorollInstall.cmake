# Install rules and the relocatable CMake package (viscorollConfig.cmake, viscoroll::viscoroll).
# Included from the top-level CMakeLists.txt after the viscoroll target is defined.
include(CMakePackageConfigHelpers)

set(VISCOROLL_INSTALL_CMAKEDIR ${CMAKE_INSTALL_DATADIR}/cmake/viscoroll
    CACHE STRING "Where viscorollConfig.cmake is installed, relative to the prefix")

install(TARGETS viscoroll EXPORT viscorollTargets)
if(TARGET viscoroll_compiled)
  install(TARGETS viscoroll_compiled viscoroll_compiled_double EXPORT viscorollTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
endif()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp")
install(EXPORT viscorollTargets
        NAMESPACE viscoroll::
        DESTINATION ${VISCOROLL_INSTALL_CMAKEDIR})

configure_package_config_file(
  ${PROJECT_SOURCE_DIR}/cmake/viscorollConfig.cmake.in
  ${PROJECT_BINARY_DIR}/viscorollConfig.cmake
  INSTALL_DESTINATION ${VISCOROLL_INSTALL_CMAKEDIR})
# Header-only, the package does not depend on the consumer's architecture; with the compiled
# library (viscoroll::compiled) it does.
if(TARGET viscoroll_compiled)
  set(_viscoroll_arch_independent)
else()
  set(_viscoroll_arch_independent ARCH_INDEPENDENT)
endif()
write_basic_package_version_file(
  ${PROJECT_BINARY_DIR}/viscorollConfigVersion.cmake
  COMPATIBILITY SameMinorVersion
  ${_viscoroll_arch_independent})
install(FILES ${PROJECT_BINARY_DIR}/viscorollConfig.cmake
              ${PROJECT_BINARY_DIR}/viscorollConfigVersion.cmake
        DESTINATION ${VISCOROLL_INSTALL_CMAKEDIR})
