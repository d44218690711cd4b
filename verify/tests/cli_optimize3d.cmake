# CTest tests of `dtlab optimize` on 3D meshes: TetGen (the Debian binary `tetgen`) meshes the
# bundled closed surface data/quad_cube.off; dtlab optimize must raise its min dihedral angle,
# lower its worst Q and leave its boundary triangles exactly as they were (same coordinates, same
# references), with TetGen's .ele and with Medit .mesh input; bad 3D input fails naming the file.
# Each case runs cli/optimize3d_check.cmake in a scratch directory. Skipped without tetgen.
if(NOT TARGET dtlab_cli)
  return()
endif()
find_program(DTLAB_TETGEN tetgen)

foreach(_dtlab_case tetgen_ele medit_input tetgen_every_face bad_input)
  if(NOT DTLAB_TETGEN AND NOT _dtlab_case STREQUAL "bad_input")
    continue()
  endif()
  add_test(NAME cli_optimize3d_${_dtlab_case}
           COMMAND ${CMAKE_COMMAND} -DDTLAB=$<TARGET_FILE:dtlab_cli> -DTETGEN=${DTLAB_TETGEN}
                   -DSURFACE=${PROJECT_SOURCE_DIR}/data/quad_cube.off
                   -DWORK=${PROJECT_BINARY_DIR}/cli-optimize3d-test/${_dtlab_case} -DCASE=${_dtlab_case}
                   -P ${CMAKE_CURRENT_LIST_DIR}/cli/optimize3d_check.cmake)
  set_tests_properties(cli_optimize3d_${_dtlab_case} PROPERTIES TIMEOUT 300)
endforeach()
