# CTest tests of `dtlab delaunay POINTS --remove FILE | --remove-random F` (apps/delaunay_remove.cpp),
# 2D and 3D: the survivors' mesh written after removal holds the same bytes as `dtlab delaunay`
# on the survivors' file (cocircular / cospherical grids, so the perturbation decides), --verify
# and --stats, and the refusals (index out of range, repeated, not a number, all removed, both
# options). Each case runs cli/delaunay_remove_check.cmake in a scratch directory of its own.
if(NOT TARGET dtlab_cli)
  return()
endif()

foreach(_dtlab_case same_as_survivors_2d same_as_survivors_3d random_verify_stats bad_lists)
  add_test(NAME cli_remove_${_dtlab_case}
           COMMAND ${CMAKE_COMMAND} -DDTLAB=$<TARGET_FILE:dtlab_cli>
                   -DWORK=${PROJECT_BINARY_DIR}/cli-remove-test/${_dtlab_case} -DCASE=${_dtlab_case}
                   -P ${CMAKE_CURRENT_LIST_DIR}/cli/delaunay_remove_check.cmake)
  set_tests_properties(cli_remove_${_dtlab_case} PROPERTIES TIMEOUT 300)
endforeach()
