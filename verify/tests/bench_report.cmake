# Test bench_report_ci: `scripts/bench_report.py --size ci` (issue 6's report command at its CI
# size, about a minute) measures the predicate, 2D and 3D suites with their peers and must write
# report.md with every section and a measured row, and the five PNG plots.
#
# One file, two roles: included from verify/tests/CMakeLists.txt it registers the test (only
# with the benchmarks built and a Python that has matplotlib); run by that test with
# `cmake -P`, it runs the report and checks what it wrote.
if(CMAKE_SCRIPT_MODE_FILE)
  file(REMOVE_RECURSE "${OUT}")
  execute_process(COMMAND "${PYTHON}" "${SOURCE_DIR}/scripts/bench_report.py" --size ci --no-build
                          --build "${BUILD_DIR}" --out "${OUT}"
                  RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "bench_report.py --size ci failed (${status})")
  endif()
  foreach(f report.md report.json delaunay2d_rate.png delaunay2d_memory.png delaunay3d_rate.png
            delaunay3d_memory.png predicates.png)
    if(NOT EXISTS "${OUT}/${f}")
      message(FATAL_ERROR "the report did not write ${f}")
    endif()
    file(SIZE "${OUT}/${f}" size)
    if(size EQUAL 0)
      message(FATAL_ERROR "${f} is empty")
    endif()
  endforeach()
  file(READ "${OUT}/report.md" report)
  foreach(section "## 3D Delaunay" "## 2D Delaunay" "## Heap per element" "## Predicate stages" "## Predicates"
                  "| 10^4 | uniform | incremental | " "| orient3d | random | branch | filtered | ")
    string(FIND "${report}" "${section}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "report.md lacks '${section}'")
    endif()
  endforeach()
  string(FIND "${report}" "error:" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "report.md reports a failed run: see ${OUT}/report.md")
  endif()
  return()
endif()

if(DTLAB_BUILD_BENCH)
  find_package(Python3 COMPONENTS Interpreter)
  # The report re-runs itself under /usr/bin/python3 when the first python3 lacks matplotlib.
  set(has_matplotlib OFF)
  foreach(python "${Python3_EXECUTABLE}" /usr/bin/python3)
    if(python AND EXISTS "${python}")
      execute_process(COMMAND "${python}" -c "import matplotlib" RESULT_VARIABLE status OUTPUT_QUIET ERROR_QUIET)
      if(status EQUAL 0)
        set(has_matplotlib ON)
      endif()
    endif()
  endforeach()
  if(Python3_FOUND AND has_matplotlib)
    add_test(NAME bench_report_ci
             COMMAND ${CMAKE_COMMAND} -DPYTHON=${Python3_EXECUTABLE} -DSOURCE_DIR=${PROJECT_SOURCE_DIR}
                     -DBUILD_DIR=${PROJECT_BINARY_DIR} -DOUT=${PROJECT_BINARY_DIR}/bench-report-ci
                     -P ${CMAKE_CURRENT_LIST_FILE})
    set_tests_properties(bench_report_ci PROPERTIES TIMEOUT 600 LABELS bench)
  else()
    message(STATUS "bench_report_ci: no Python 3 with matplotlib (Debian: python3-matplotlib), test left out")
  endif()
endif()
