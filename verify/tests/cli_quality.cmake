# CTest tests of `dtlab quality`: the table and the JSON object (its key set, counts that add up,
# the area of data/square_with_hole.poly's `dtlab constrain` output) on Medit 2D and 3D meshes,
# Triangle and TetGen .node/.ele pairs (by the .ele path and by the base name), Gmsh .msh, a 2D
# mesh in a Dimension 3 Medit file (measured as 2D); the metric from
# --size, from a .sol at the vertices, and from a .sol on a --background mesh; an inverted
# triangle, inverted and flat tetrahedra (Medit, Gmsh) measured and counted; bad input (missing or malformed files, a .sol of the wrong
# count, a bad --size, options that do not go together, a mesh without elements) refused with a message naming the file,
# line or option. Each case runs cli/quality_check.cmake in a scratch directory of its own.
if(NOT TARGET dtlab_cli)
  return()
endif()

foreach(_dtlab_case constrain_2d triangle_2d tetgen_3d medit_3d size_metric sol_metric background inverted
                    gmsh_and_planar empty_mesh
                    missing_file malformed_file count_mismatch bad_size bad_options)
  add_test(NAME cli_quality_${_dtlab_case}
           COMMAND ${CMAKE_COMMAND} -DDTLAB=$<TARGET_FILE:dtlab_cli>
                   -DPOLY=${PROJECT_SOURCE_DIR}/data/square_with_hole.poly
                   -DWORK=${PROJECT_BINARY_DIR}/cli-quality-test/${_dtlab_case} -DCASE=${_dtlab_case}
                   -P ${CMAKE_CURRENT_LIST_DIR}/cli/quality_check.cmake)
  set_tests_properties(cli_quality_${_dtlab_case} PROPERTIES TIMEOUT 120)
endforeach()
