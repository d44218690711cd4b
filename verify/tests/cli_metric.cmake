# CTest tests of `dtlab metric`: a scalar field with a layer, written at the vertices of a mesh
# made by `dtlab mesh` (2D: data/square_disc.poly; 3D: data/quad_cube.off), gives a tensor .sol
# of the mesh's vertex count whose complexity before clipping is the one asked; in 2D it is then
# handed to `dtlab adapt`, whose output has about that many vertices. Bad input (neither or both
# of --complexity and --error, a tensor as --solution, a count that differs, a constant field
# with a complexity) fails with a message naming it; so do a field linear to round-off, NaN
# values and size bounds out of range, while a field scaled by 1e300 gets the complexity asked
# (round_off). The complexity asked is delivered after the clipping to [--hmin, --hmax] (x^2,
# curved along x only, whose floored direction the clipping inflated), and one the sizes cannot
# reach is refused naming the bound (clipped).
if(NOT TARGET dtlab_cli)
  return()
endif()

foreach(_dtlab_case two_d three_d bad_input round_off clipped)
  add_test(NAME cli_metric_${_dtlab_case}
           COMMAND ${CMAKE_COMMAND} -DDTLAB=$<TARGET_FILE:dtlab_cli> -DDATA=${PROJECT_SOURCE_DIR}/data
                   -DFIELD=${CMAKE_CURRENT_LIST_DIR}/cli/analytic_sol.py
                   -DWORK=${PROJECT_BINARY_DIR}/cli-metric-test/${_dtlab_case} -DCASE=${_dtlab_case}
                   -P ${CMAKE_CURRENT_LIST_DIR}/cli/metric_check.cmake)
  set_tests_properties(cli_metric_${_dtlab_case} PROPERTIES TIMEOUT 120)
endforeach()
