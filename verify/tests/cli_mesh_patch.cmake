# CTest tests of `dtlab mesh PATCH.json --surface-only` (book chapter 6): a sphere and a torus meshed
# to a size (closed: every edge of the Medit output in two triangles; unit edges in the metric
# >= 90 %), the book's sigma under the anisotropic geometric metric (stats), and bad input each
# refused with a message naming it: an unknown patch type, a degenerate patch (zero radius, a
# cone through its apex, a torus that meets itself), an unknown key, a patch without
# --surface-only, no size, options that do not apply. Each case runs cli/mesh_patch_check.cmake.
if(NOT TARGET dtlab_cli)
  return()
endif()

foreach(_dtlab_case sphere torus sigma_geometric unknown_type degenerate unknown_key bad_options)
  add_test(NAME cli_mesh_patch_${_dtlab_case}
           COMMAND ${CMAKE_COMMAND} -DDTLAB=$<TARGET_FILE:dtlab_cli>
                   -DWORK=${PROJECT_BINARY_DIR}/cli-mesh-patch-test/${_dtlab_case} -DCASE=${_dtlab_case}
                   -P ${CMAKE_CURRENT_LIST_DIR}/cli/mesh_patch_check.cmake)
  set_tests_properties(cli_mesh_patch_${_dtlab_case} PROPERTIES TIMEOUT 120)
endforeach()
