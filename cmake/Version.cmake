# Version and commit for `dtlab --version`, written into the build tree at configure time.
find_package(Git QUIET)
set(DTLAB_COMMIT "unknown")
if(GIT_FOUND AND EXISTS "${PROJECT_SOURCE_DIR}/.git")
  execute_process(COMMAND "${GIT_EXECUTABLE}" describe --always --dirty --abbrev=12
                  WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}" OUTPUT_VARIABLE DTLAB_COMMIT
                  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(NOT DTLAB_COMMIT)
    set(DTLAB_COMMIT "unknown")
  endif()
endif()
string(JOIN " " DTLAB_BUILD_FLAGS ${CMAKE_CXX_FLAGS} ${CMAKE_CXX_FLAGS_${CMAKE_BUILD_TYPE}} ${DTLAB_FP_FLAGS})
configure_file("${PROJECT_SOURCE_DIR}/cmake/build_info.hpp.in"
               "${PROJECT_BINARY_DIR}/generated/dtlab/build_info.hpp" @ONLY)
