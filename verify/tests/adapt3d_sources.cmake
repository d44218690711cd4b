# adapt3d_test calls run_adapt3 (apps/adapt3.cpp) directly, as `dtlab adapt` does for 3D meshes:
# the command's sources are an executable's, so the test compiles the two it needs.
if(TARGET adapt3d_test)
  target_sources(adapt3d_test PRIVATE ${PROJECT_SOURCE_DIR}/apps/adapt3.cpp)
  target_include_directories(adapt3d_test PRIVATE ${PROJECT_SOURCE_DIR})
endif()
