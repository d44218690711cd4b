# The layering, enforced: every #include of the tree's own headers goes down the layer map of
# docs/architecture.md (kernel -> mesh -> algorithms, verify -> apps, mpi, python, bench, fuzz, papers;
# verify/ beside algorithms/, not on it), and inside algorithms/ only to a capability declared in
# algorithms/CMakeLists.txt.
# A violation fails with the file, the line and the rule it breaks.
set(_layering_args "")
foreach(capability ${DTLAB_CAPABILITIES})
  string(REPLACE ";" "," _deps "${DTLAB_CAPABILITY_DEPENDS_${capability}}")
  list(APPEND _layering_args "-DDEPENDS_${capability}=${_deps}")
endforeach()
string(REPLACE ";" "," _capabilities "${DTLAB_CAPABILITIES}")
add_test(NAME layering
         COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DCAPABILITIES=${_capabilities} ${_layering_args}
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/layering/check.cmake)
