# The bad-input matrix (issue 42): every dtlab subcommand, and the Python twin of each (skipped,
# said, where the module cannot be imported from build/python), on malformed and degenerate inputs generated at test time
# (cli/bad_input_matrix.py), each run under a 20 s and 2 GB limit: exit 0 with an output that
# reads back, or exit 1 with one `dtlab:` line naming the file or option and no output; nothing
# else. Fails on a failure not in the script's KNOWN_FAILURES. About 25 seconds on 2 cores (Release).
# Under the sanitizers no address-space limit (ASan's shadow memory needs terabytes of it): the
# runs are bounded by time, and ASan reports memory errors and leaks as signals.
if(NOT TARGET dtlab_cli)
  return()
endif()
set(_dtlab_matrix_memory 2048)
if(DTLAB_SANITIZE)
  set(_dtlab_matrix_memory 0)
endif()
add_test(NAME cli_bad_input_matrix
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_LIST_DIR}/cli/bad_input_matrix.py --dtlab $<TARGET_FILE:dtlab_cli>
                 --python ${PROJECT_BINARY_DIR}/python --work ${PROJECT_BINARY_DIR}/bad-input-matrix --jobs 2
                 --memory-limit-mb ${_dtlab_matrix_memory})
set_tests_properties(cli_bad_input_matrix PROPERTIES TIMEOUT 400 PROCESSORS 2)
