# CTest tests of `dtlab convert`: chains through every format that holds the data (Medit .mesh
# and .meshb, Gmsh .msh ASCII and binary, Triangle/TetGen .node/.ele) that end in the file they
# began with, byte for byte; Gmsh's names carried from .msh to .msh; warnings naming what a target
# cannot hold (names in Medit, references and tetrahedra in OFF/STL, edges in Triangle's .ele);
# .vtu output with the quality field; bad input (quadrangles, second order, a malformed file, an
# unknown extension, an output folder that is missing or a file) refused with exit 1, a message
# naming the item, and nothing written;
# --help. Each case runs cli/convert_check.cmake in a scratch directory of its own. The files
# written are also read by meshio and Gmsh (cli/convert_external_check.py), skipped, not
# failed, where they are not installed.
if(NOT TARGET dtlab_cli)
  return()
endif()

foreach(_dtlab_case chain_3d chain_2d names_kept warn_names warn_surface warn_edges vtu bad_elements
                    bad_file bad_extension unwritable_output help)
  add_test(NAME cli_convert_${_dtlab_case}
           COMMAND ${CMAKE_COMMAND} -DDTLAB=$<TARGET_FILE:dtlab_cli> -DDATA=${PROJECT_SOURCE_DIR}/data/gmsh
                   -DWORK=${PROJECT_BINARY_DIR}/cli-convert-test/${_dtlab_case} -DCASE=${_dtlab_case}
                   -P ${CMAKE_CURRENT_LIST_DIR}/cli/convert_check.cmake)
  set_tests_properties(cli_convert_${_dtlab_case} PROPERTIES TIMEOUT 120)
endforeach()

foreach(_dtlab_tool meshio gmsh)
  add_test(NAME cli_convert_read_by_${_dtlab_tool}
           COMMAND /usr/bin/python3 ${CMAKE_CURRENT_LIST_DIR}/cli/convert_external_check.py ${_dtlab_tool}
                   $<TARGET_FILE:dtlab_cli> ${PROJECT_SOURCE_DIR}/data/gmsh
                   ${PROJECT_BINARY_DIR}/cli-convert-test/read_by_${_dtlab_tool})
  set_tests_properties(cli_convert_read_by_${_dtlab_tool} PROPERTIES TIMEOUT 300 SKIP_RETURN_CODE 77)
endforeach()
