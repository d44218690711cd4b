# `cmake --install` puts the `dtlab` command on the PATH and the library where
# find_package(dtlab) finds it: a consumer links dtlab::dtlab (verify/tests/consumer/ tests it).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS dtlab dtlab_kernel dtlab_mesh dtlab_algorithms ${DTLAB_ALGORITHM_TARGETS} dtlab_verify
        EXPORT dtlabTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/dtlab)
install(TARGETS dtlab_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
foreach(layer kernel mesh algorithms verify)
  install(DIRECTORY ${layer}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/dtlab/${layer}
          FILES_MATCHING PATTERN "*.hpp" PATTERN "tests" EXCLUDE PATTERN "cgal*" EXCLUDE)
endforeach()
install(FILES "${PROJECT_BINARY_DIR}/generated/dtlab/build_info.hpp"
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/dtlab/dtlab)

set(DTLAB_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/dtlab)
install(EXPORT dtlabTargets NAMESPACE dtlab:: DESTINATION ${DTLAB_CMAKE_DIR})
configure_package_config_file(cmake/dtlabConfig.cmake.in "${PROJECT_BINARY_DIR}/dtlabConfig.cmake"
                              INSTALL_DESTINATION ${DTLAB_CMAKE_DIR})
write_basic_package_version_file("${PROJECT_BINARY_DIR}/dtlabConfigVersion.cmake"
                                 COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/dtlabConfig.cmake" "${PROJECT_BINARY_DIR}/dtlabConfigVersion.cmake"
              cmake/FindGMP.cmake cmake/FindMPFR.cmake
        DESTINATION ${DTLAB_CMAKE_DIR})
