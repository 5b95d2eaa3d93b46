# The CMake package: `cmake --install build --prefix P` puts the public headers (include/rayset/)
# in P/include/rayset/ and the internal ones they include beside them (P/include/rayset/core/,
# converters/, lightmodel/, tracer/, viz/), the libraries under P/lib, the modules loaded at run
# time (the image reader) under P/lib/rayset, the tools under P/bin and
# rayset-config.cmake under P/lib/cmake/rayset, so that another project's
# find_package(rayset CONFIG) gives it rayset::core, rayset::converters, rayset::scene_language,
# rayset::lightmodel, rayset::tracer and rayset::viz (examples/consumer/ is such a project).

include(CMakePackageConfigHelpers)
include(GNUInstallDirs)

set(RAYSET_INSTALL_INCLUDEDIR "${CMAKE_INSTALL_INCLUDEDIR}/rayset")
set(RAYSET_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/rayset")
# Modules loaded at run time (the image reader), at the same place in the build tree.
set(RAYSET_INSTALL_MODULEDIR "${CMAKE_INSTALL_LIBDIR}/rayset")

# Two include directories, in the source tree and installed alike: include/ (P/include), where
# the public headers are <rayset/NAME.h> (docs/api.md), and the source root (P/include/rayset),
# where the internal headers they include are found by their path in the repository
# ("lightmodel/model_file.h"). `name` is the target's name in the package (rayset::NAME).
function(rayset_library_interface target name)
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>
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
  # The public headers beside the internal folders: P/include/rayset/*.h.
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/rayset DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
    FILES_MATCHING PATTERN "*.h")
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
