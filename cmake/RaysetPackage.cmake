# The CMake package: `cmake --install build --prefix P` puts the public headers under
# P/include/rayset/, the libraries under P/lib, the tools under P/bin and rayset-config.cmake
# under P/lib/cmake/rayset, so that another project's find_package(rayset CONFIG) gives it
# rayset::core, rayset::converters, rayset::scene_language, rayset::lightmodel, rayset::tracer
# and rayset::viz (examples/consumer/ is such a project).

include(CMakePackageConfigHelpers)
include(GNUInstallDirs)

set(RAYSET_INSTALL_INCLUDEDIR "${CMAKE_INSTALL_INCLUDEDIR}/rayset")
set(RAYSET_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/rayset")

# Headers are included by their path in the repository ("lightmodel/model_file.h"), from the
# source tree when building and from P/include/rayset when installed; `name` is the target's
# name in the package (rayset::NAME).
function(rayset_library_interface target name)
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
    $<INSTALL_INTERFACE:${RAYSET_INSTALL_INCLUDEDIR}>)
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  add_library(rayset::${name} ALIAS ${target})
  set_property(GLOBAL APPEND PROPERTY RAYSET_PACKAGE_TARGETS ${target})
endfunction()

function(rayset_install_package)
  get_property(targets GLOBAL PROPERTY RAYSET_PACKAGE_TARGETS)
  install(TARGETS ${targets} EXPORT raysetTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  foreach(tool rayconv raymodel raytrace rayview)
    if(TARGET ${tool})
      install(TARGETS ${tool} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
    endif()
  endforeach()
  foreach(folder core converters lightmodel tracer viz)
    if(IS_DIRECTORY ${PROJECT_SOURCE_DIR}/${folder})
      install(DIRECTORY ${PROJECT_SOURCE_DIR}/${folder} DESTINATION ${RAYSET_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.h")
    endif()
  endforeach()
  install(EXPORT raysetTargets NAMESPACE rayset:: FILE rayset-targets.cmake
    DESTINATION ${RAYSET_INSTALL_CMAKEDIR})
  configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/rayset-config.cmake.in
    ${PROJECT_BINARY_DIR}/rayset-config.cmake INSTALL_DESTINATION ${RAYSET_INSTALL_CMAKEDIR})
  write_basic_package_version_file(${PROJECT_BINARY_DIR}/rayset-config-version.cmake
    COMPATIBILITY SameMinorVersion)
  install(FILES ${PROJECT_BINARY_DIR}/rayset-config.cmake
    ${PROJECT_BINARY_DIR}/rayset-config-version.cmake DESTINATION ${RAYSET_INSTALL_CMAKEDIR})
endfunction()
