# CTest tests of `dtlab adapt`: a mesh of data/square_disc.poly made by `dtlab mesh` is adapted
# to the 2D UGAWG linear field (unit edges, references kept, the same bytes twice, the metric at
# the output written), generated anew for it (--method reconstruct: the hole kept) and coarsened to a size (boundary vertices removed, corners kept); a cube's
# tetrahedral mesh (data/quad_cube.off) is refined to a size; bad input
# (missing file, a .sol of the wrong count, a metric that is not positive definite, --hgrad below
# 1) fails with a message naming it. Each case runs cli/adapt_check.cmake in a scratch directory.
if(NOT TARGET dtlab_cli)
  return()
endif()

foreach(_dtlab_case linear_layer coarsen reconstruct three_d bad_input)
  add_test(NAME cli_adapt_${_dtlab_case}
           COMMAND ${CMAKE_COMMAND} -DDTLAB=$<TARGET_FILE:dtlab_cli>
                   -DPOLY=${PROJECT_SOURCE_DIR}/data/square_disc.poly
                   -DFIELD=${CMAKE_CURRENT_LIST_DIR}/cli/analytic_sol.py
                   -DWORK=${PROJECT_BINARY_DIR}/cli-adapt-test/${_dtlab_case} -DCASE=${_dtlab_case}
                   -P ${CMAKE_CURRENT_LIST_DIR}/cli/adapt_check.cmake)
  set_tests_properties(cli_adapt_${_dtlab_case} PROPERTIES TIMEOUT 120)
endforeach()
