# What `cmake --install build --prefix P` puts under P (docs/install.md):
#   bin/lenslab
#   share/lenslab/assets/           the bundled scenes (the shaders are compiled in)
#   include/lenslab/<folder>/*.h    the libraries' headers, included as the code does:
#                                   #include "camera/Camera.h" with include/lenslab on the path
#   lib/liblenslab_*.a              the static libraries
#   lib/cmake/lenslab/              lenslabConfig.cmake, its version file and the exported targets:
#                                   find_package(lenslab) gives lenslab::lenslab
# Nothing installed names the source or build tree, so P can be moved (tests/install/).
include(CMakePackageConfigHelpers)

set(LENSLAB_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/lenslab")
set(LENSLAB_INSTALL_INCLUDEDIR "${CMAKE_INSTALL_INCLUDEDIR}/lenslab")
set(LENSLAB_INSTALL_DATADIR "${CMAKE_INSTALL_DATADIR}/lenslab")
# The executable finds its data through the relative path from bin to share (core/DataPaths.cpp).
foreach(dir BINDIR DATADIR)
  if(IS_ABSOLUTE "${CMAKE_INSTALL_${dir}}")
    message(FATAL_ERROR "CMAKE_INSTALL_${dir} is ${CMAKE_INSTALL_${dir}}: lenslab's install is relocatable and needs "
                        "it relative to the prefix (e.g. bin, share)")
  endif()
endforeach()

install(TARGETS lenslab RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The scenes only: assets/report and assets/screenshots are pictures for the documentation.
install(DIRECTORY assets/rows assets/occluder assets/grid assets/depth-range
        DESTINATION ${LENSLAB_INSTALL_DATADIR}/assets)
install(FILES assets/README.md DESTINATION ${LENSLAB_INSTALL_DATADIR}/assets)

# ---- the library: the static libraries without the command line and the viewer ----
# lenslab::lenslab links them all; each is exported too (lenslab::core, lenslab::gl, ...), as a
# static library's own dependencies must be. lenslab_warnings comes along because the libraries
# link it privately (it only adds warning flags to lenslab's own build; a consumer gets none).
add_library(lenslab_library INTERFACE)
target_link_libraries(lenslab_library INTERFACE lenslab_report lenslab_render lenslab_gl lenslab_raycast lenslab_plan lenslab_io lenslab_core)
add_library(lenslab::lenslab ALIAS lenslab_library)
set_target_properties(lenslab_library PROPERTIES EXPORT_NAME lenslab)
set(LENSLAB_EXPORTED core io plan gl render raycast report glad warnings)
foreach(part IN LISTS LENSLAB_EXPORTED)
  set_target_properties(lenslab_${part} PROPERTIES EXPORT_NAME ${part})
endforeach()
list(TRANSFORM LENSLAB_EXPORTED PREPEND lenslab_ OUTPUT_VARIABLE exported_targets)
install(TARGETS lenslab_library ${exported_targets}
        EXPORT lenslabTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${LENSLAB_INSTALL_INCLUDEDIR})
install(EXPORT lenslabTargets NAMESPACE lenslab:: DESTINATION ${LENSLAB_INSTALL_CMAKEDIR})

# The headers of the exported libraries, in their folders (the app and the viewer stay out).
foreach(folder core camera lens scene plan io gl render raycast report)
  install(DIRECTORY src/${folder} DESTINATION ${LENSLAB_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h")
endforeach()
install(DIRECTORY src/external/glad/include/ DESTINATION ${LENSLAB_INSTALL_INCLUDEDIR})

configure_package_config_file(cmake/lenslabConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/lenslabConfig.cmake
  INSTALL_DESTINATION ${LENSLAB_INSTALL_CMAKEDIR}
  PATH_VARS LENSLAB_INSTALL_DATADIR)
# 0.x: a minor version may change the API, so only the same major and minor are compatible.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/lenslabConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/lenslabConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/lenslabConfigVersion.cmake
        DESTINATION ${LENSLAB_INSTALL_CMAKEDIR})
