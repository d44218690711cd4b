# One case of the CLI tests declared in ../cli_constrain.cmake:
#   cmake -DDTLAB=<dtlab binary> -DPOLY=<data/square_with_hole.poly> -DWORK=<scratch dir>
#         -DCASE=<name> -P constrain_check.cmake
# Fails (FATAL_ERROR) with the command's exit code, stdout and stderr when a check does not hold.
set(DTLAB_CLI_REQUIRED DTLAB POLY WORK CASE)
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake)

function(list_methods result)
  run(constrain --list-methods)
  expect_success()
  # The 2D methods: the lines between the "2D" and "3D" headings.
  string(REGEX REPLACE "\n3D[^\n]*\n.*$" "" planar "${out}")
  string(REGEX MATCHALL "(^|\n)[^\t\n]+\t" lines "${planar}")
  set(names)
  foreach(l ${lines})
    string(STRIP "${l}" name)
    list(APPEND names "${name}")
  endforeach()
  foreach(expected cdt swap conforming)
    if(NOT expected IN_LIST names)
      fail("--list-methods does not list '${expected}'")
    endif()
  endforeach()
  set(${result} ${names} PARENT_SCOPE)
endfunction()

# Verified output of `file` with `method`: edges with markers `edge_refs`, triangles with
# region references `triangle_refs` (each a ;-list, sorted).
function(expect_verified file method edge_refs triangle_refs)
  run(constrain "${file}" --method ${method} --verify --stats -o ${method}.mesh)
  expect_success()
  if(NOT out MATCHES "^ok:")
    fail("--verify did not report ok")
  endif()
  string(STRIP "${out}" stripped)
  string(REGEX MATCH "[^\n]*$" json "${stripped}")
  string(JSON triangles ERROR_VARIABLE json_error GET "${json}" triangles)
  if(json_error)
    fail("last stdout line is not JSON with 'triangles': ${json_error}")
  endif()
  medit_section("${WORK}/${method}.mesh" Edges edge_count refs)
  if(NOT edge_count GREATER 0 OR NOT refs STREQUAL "${edge_refs}")
    fail("${method}.mesh: ${edge_count} Edges with references '${refs}', expected '${edge_refs}'")
  endif()
  medit_section("${WORK}/${method}.mesh" Triangles triangle_count refs)
  if(NOT triangle_count EQUAL triangles OR NOT refs STREQUAL "${triangle_refs}")
    fail("${method}.mesh: ${triangle_count} Triangles (JSON: ${triangles}) with references '${refs}', "
         "expected '${triangle_refs}'")
  endif()
  set(err "${err}" PARENT_SCOPE)
endfunction()

if(CASE STREQUAL "methods_verify")
  list_methods(methods)
  foreach(method ${methods})
    expect_verified("${POLY}" ${method} "1;2;3" "10;20")
  endforeach()
  # Without the hole the square (4..6)^2 is part of the region right of the wall.
  run(constrain "${POLY}" --keep-exterior --verify -o keep.mesh)
  expect_success()

elseif(CASE STREQUAL "medit_input")
  # The same graph as a Medit file (Vertices, Edges with references): no holes or regions, so
  # the hole is meshed and every triangle has reference 0.
  file(WRITE "${WORK}/graph.mesh"
       "MeshVersionFormatted 2\nDimension 2\nVertices\n6\n0 0 0\n4 0 0\n4 4 0\n0 4 0\n1 1 0\n3 2 0\n"
       "Edges\n5\n1 2 7\n2 3 7\n3 4 7\n4 1 7\n5 6 8\nEnd\n")
  list_methods(methods)
  foreach(method ${methods})
    expect_verified(graph.mesh ${method} "7;8" "0")
  endforeach()
  # An edge with an endpoint out of range: the reader names the file and line.
  file(WRITE "${WORK}/bad_edge.mesh"
       "MeshVersionFormatted 2\nDimension 2\nVertices\n3\n0 0 0\n1 0 0\n0 1 0\nEdges\n2\n1 2 1\n2 7 1\nEnd\n")
  run(constrain bad_edge.mesh)
  expect_failure("bad_edge\\.mesh:11[^0-9]")
  # A zero-length edge: named by its number in the file (from 1).
  file(WRITE "${WORK}/zero_edge.mesh"
       "MeshVersionFormatted 2\nDimension 2\nVertices\n3\n0 0 0\n1 0 0\n0 1 0\nEdges\n2\n1 2 1\n3 3 1\nEnd\n")
  run(constrain zero_edge.mesh)
  expect_failure("zero_edge\\.mesh" "segment 2 has zero length" "endpoints 3 and 3")

elseif(CASE STREQUAL "crossings")
  # Two crossing diagonals of a square, and a segment overlapping a side: one Steiner point at
  # the crossing, the overlap merged; every method verifies, messages number from 1.
  file(WRITE "${WORK}/cross.poly"
       "5 2 0 0\n1 0 0\n2 3 0\n3 3 3\n4 0 3\n5 1 0\n"
       "7 1\n1 1 2 1\n2 2 3 1\n3 3 4 1\n4 4 1 1\n5 1 3 2\n6 2 4 3\n7 5 2 4\n0\n")
  list_methods(methods)
  foreach(method ${methods})
    expect_verified(cross.poly ${method} "1;2;3" "0")
    if(NOT err MATCHES "segments 5 and 6 cross" OR NOT err MATCHES "segments 1 and 7 overlap")
      fail("stderr does not report the crossing of segments 5 and 6 and the overlap of 1 and 7 (numbered from 1)")
    endif()
  endforeach()

elseif(CASE STREQUAL "missing_file")
  run(constrain "${WORK}/no_such_input.poly")
  expect_failure("no_such_input\\.poly")

elseif(CASE STREQUAL "malformed_line")
  file(WRITE "${WORK}/bad.poly" "3 2 0 0\n1 0 0\n2 1 0\n3 0 zero\n3 0\n1 1 2\n2 2 3\n3 3 1\n0\n")
  run(constrain bad.poly)
  expect_failure("bad\\.poly:4[^0-9]" "zero")
  file(WRITE "${WORK}/short.poly" "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n2 2\n3 3 1\n0\n")
  run(constrain short.poly)
  expect_failure("short\\.poly:7[^0-9]")

elseif(CASE STREQUAL "zero_length")
  # Segment 3 joins vertex 2 to vertex 4, which repeats vertex 2's coordinates.
  file(WRITE "${WORK}/zero.poly" "4 2 0 0\n1 0 0\n2 1 0\n3 0 1\n4 1 0\n3 0\n1 1 2\n2 2 3\n3 2 4\n0\n")
  run(constrain zero.poly)
  expect_failure("zero\\.poly" "segment 3 has zero length" "endpoints 2 and 4")
  # Numbered from 0 in the file: the message numbers from 0 too.
  file(WRITE "${WORK}/zero0.poly" "3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n2 0\n0 0 1\n1 2 2\n0\n")
  run(constrain zero0.poly)
  expect_failure("zero0\\.poly" "segment 1 has zero length" "endpoints 2 and 2")

elseif(CASE STREQUAL "out_of_range")
  file(WRITE "${WORK}/range.poly" "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n2 2 3\n3 3 9\n0\n")
  run(constrain range.poly)
  expect_failure("range\\.poly:8[^0-9]" "9")

elseif(CASE STREQUAL "unknown_method")
  list_methods(methods)
  run(constrain "${POLY}" --method no_such_method)
  expect_failure("no_such_method" ${methods})

else()
  message(FATAL_ERROR "unknown CASE '${CASE}'")
endif()
