# Test: `cmake --install` the build into a scratch prefix, then build and run a separate project
# that does find_package(dtlab) and links dtlab::dtlab.
add_test(NAME consumer_package
         COMMAND ${CMAKE_COMMAND} -DBUILD_DIR=${PROJECT_BINARY_DIR}
                 -DSOURCE_DIR=${CMAKE_CURRENT_SOURCE_DIR}/consumer
                 -DWORK_DIR=${PROJECT_BINARY_DIR}/consumer-test
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/consumer/run.cmake)
set_tests_properties(consumer_package PROPERTIES TIMEOUT 600)
