# adapt3d_test calls run_adapt3 (apps/adapt3.cpp) directly, before apps/adapt.cpp registers it.
if(TARGET adapt3d_test)
  target_sources(adapt3d_test PRIVATE ${PROJECT_SOURCE_DIR}/apps/adapt3.cpp ${PROJECT_SOURCE_DIR}/apps/input_files.cpp)
  target_include_directories(adapt3d_test PRIVATE ${PROJECT_SOURCE_DIR})
endif()
if(DTLAB_BUILD_TESTS OR TARGET adapt3d_test)
  add_executable(adapt3_driver ${CMAKE_CURRENT_LIST_DIR}/adapt3_driver.cpp ${PROJECT_SOURCE_DIR}/apps/adapt3.cpp
                               ${PROJECT_SOURCE_DIR}/apps/input_files.cpp)
  target_link_libraries(adapt3_driver PRIVATE dtlab_verify)
  target_include_directories(adapt3_driver PRIVATE ${PROJECT_SOURCE_DIR})
  set_target_properties(adapt3_driver PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR})
endif()
