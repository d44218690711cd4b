# CTest tests of `dtlab plot`: SVG pictures of 2D meshes (well-formed XML, one <polygon> per
# triangle, the same bytes twice) coloured by quality and by reference, with a metric on a
# background mesh; the quality histogram of 2D and 3D meshes; every 2D format the other
# subcommands read; PNG through scripts/plot_png.py when matplotlib is there (else refused naming
# the package); --help; bad input refused with exit code 1 and a message naming the problem.
# Each case runs cli/plot_check.cmake in a scratch directory of its own.
if(NOT TARGET dtlab_cli)
  return()
endif()
find_program(DTLAB_PLOT_PYTHON NAMES python3)

foreach(_dtlab_case help quality_svg reference_svg metric_svg histogram formats png bad_input)
  add_test(NAME cli_plot_${_dtlab_case}
           COMMAND ${CMAKE_COMMAND} -DDTLAB=$<TARGET_FILE:dtlab_cli> -DPYTHON=${DTLAB_PLOT_PYTHON}
                   -DDATA=${PROJECT_SOURCE_DIR}/data
                   -DWORK=${PROJECT_BINARY_DIR}/cli-plot-test/${_dtlab_case} -DCASE=${_dtlab_case}
                   -P ${CMAKE_CURRENT_LIST_DIR}/cli/plot_check.cmake)
  set_tests_properties(cli_plot_${_dtlab_case} PROPERTIES TIMEOUT 120)
endforeach()
