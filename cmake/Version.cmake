# Version and commit for `dtlab --version`, written into the build tree at configure time (again
# whenever the checked-out commit changes).
find_package(Git QUIET)
set(DTLAB_COMMIT "unknown")
if(GIT_FOUND AND EXISTS "${PROJECT_SOURCE_DIR}/.git")
  execute_process(COMMAND "${GIT_EXECUTABLE}" describe --always --dirty --abbrev=12
                  WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}" OUTPUT_VARIABLE DTLAB_COMMIT
                  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(NOT DTLAB_COMMIT)
    set(DTLAB_COMMIT "unknown")
  endif()
  # Configure again when HEAD moves (a commit, a checkout), so that a rebuild never reports the
  # commit of an older configure. (A tree made dirty after configuring still shows clean.)
  execute_process(COMMAND "${GIT_EXECUTABLE}" rev-parse --git-path HEAD WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}"
                  OUTPUT_VARIABLE _dtlab_head OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  execute_process(COMMAND "${GIT_EXECUTABLE}" symbolic-ref -q HEAD WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}"
                  OUTPUT_VARIABLE _dtlab_ref OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(_dtlab_ref)
    execute_process(COMMAND "${GIT_EXECUTABLE}" rev-parse --git-path "${_dtlab_ref}"
                    WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}" OUTPUT_VARIABLE _dtlab_ref_file
                    OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  endif()
  foreach(_dtlab_file IN ITEMS "${_dtlab_head}" "${_dtlab_ref_file}")
    if(_dtlab_file)
      cmake_path(ABSOLUTE_PATH _dtlab_file BASE_DIRECTORY "${PROJECT_SOURCE_DIR}")
      if(EXISTS "${_dtlab_file}")
        set_property(DIRECTORY "${PROJECT_SOURCE_DIR}" APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${_dtlab_file}")
      endif()
    endif()
  endforeach()
endif()
string(JOIN " " DTLAB_BUILD_FLAGS ${CMAKE_CXX_FLAGS} ${CMAKE_CXX_FLAGS_${CMAKE_BUILD_TYPE}} ${DTLAB_FP_FLAGS})
configure_file("${PROJECT_SOURCE_DIR}/cmake/build_info.hpp.in"
               "${PROJECT_BINARY_DIR}/generated/dtlab/build_info.hpp" @ONLY)
