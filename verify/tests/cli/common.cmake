# What every CLI check script (cli/*_check.cmake) shares: the required -D variables, a fresh
# scratch directory WORK, and the macros
#   run(<args...>)              runs ${DTLAB} in WORK; sets rc, out, err
#   fail(<what>)                FATAL_ERROR with the command, its exit code, stdout and stderr
#   expect_success()            exit code 0
#   expect_failure(<regex...>)  non-zero exit code, stderr matching every regex
#   expect_input_error(<regex...>)  exit code 1 (refused input), stderr matching every regex and
#                               holding no C++ library text (std::, filesystem error, terminate)
#   expect_no_output(<file...>) none of the files in WORK, and no scratch folder (.dtlab-partial-*)
#   medit_section(file name count_var refs_var)  a Medit section's count and distinct references
#   expect_number(what value op bound)  a JSON number compared with a bound (python3)
#   expect_count_and_unit(key low high unit_low)  after run_mesh_verified: count and unit edges
#   run_mesh_verified(key <args...>)  dtlab mesh --verify --stats: the ok line, `quality` and
#                               the count `key` (triangles, tetrahedra) of the last JSON line
# Include it after setting DTLAB_CLI_REQUIRED to the variables the script needs.
cmake_minimum_required(VERSION 3.25)
foreach(v ${DTLAB_CLI_REQUIRED})
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "pass -D${v}=...")
  endif()
endforeach()
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

macro(run)
  execute_process(COMMAND "${DTLAB}" ${ARGN} WORKING_DIRECTORY "${WORK}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(last_command "dtlab ${ARGN}")
endmacro()

function(fail what)
  message(FATAL_ERROR "${what}\n  command: ${last_command}\n  exit: ${rc}\n  stdout: ${out}\n  stderr: ${err}")
endfunction()

# Fails unless files a and b of WORK hold the same bytes; the optional third argument says why
# they should.
function(expect_same_file a b)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${WORK}/${a}" "${WORK}/${b}" RESULT_VARIABLE differ)
  if(differ)
    fail("${a} and ${b} differ ${ARGN}")
  endif()
endfunction()

macro(expect_success)
  if(NOT rc EQUAL 0)
    fail("expected exit code 0")
  endif()
endmacro()

macro(expect_failure)
  if(rc EQUAL 0)
    fail("expected a non-zero exit code")
  endif()
  foreach(regex ${ARGN})
    if(NOT err MATCHES "${regex}")
      fail("stderr does not match '${regex}'")
    endif()
  endforeach()
endmacro()

# As expect_failure, with the exit code of refused input (1) and no C++ library text.
macro(expect_input_error)
  if(NOT rc EQUAL 1)
    fail("expected exit code 1 (refused input)")
  endif()
  expect_failure(${ARGN})
  if(err MATCHES "std::|filesystem error|terminate called")
    fail("stderr holds C++ library text")
  endif()
endmacro()

function(expect_no_output)
  foreach(name ${ARGN})
    if(EXISTS "${WORK}/${name}")
      fail("${name} was written by a command that failed")
    endif()
  endforeach()
  file(GLOB scratch LIST_DIRECTORIES true RELATIVE "${WORK}" "${WORK}/.dtlab-partial-*" "${WORK}/*/.dtlab-partial-*")
  if(scratch)
    fail("scratch folders left behind: ${scratch}")
  endif()
endfunction()

# The entries of section `name` (Edges, Triangles) of a Medit file: their count and the sorted
# distinct references (the last number of each entry line).
function(medit_section file name count_var refs_var)
  file(STRINGS "${file}" lines)
  set(in_section OFF)
  set(remaining -1)
  set(refs)
  set(${count_var} 0 PARENT_SCOPE)
  foreach(line ${lines})
    string(STRIP "${line}" line)
    if(line STREQUAL "" OR line MATCHES "^#")
      continue()
    endif()
    if(NOT in_section)
      if(line STREQUAL "${name}")
        set(in_section ON)
      endif()
      continue()
    endif()
    if(remaining EQUAL -1)
      set(remaining ${line})
      set(${count_var} ${line} PARENT_SCOPE)
      if(remaining EQUAL 0)
        break()
      endif()
      continue()
    endif()
    string(REGEX MATCH "[-0-9]+$" ref "${line}")
    list(APPEND refs ${ref})
    math(EXPR remaining "${remaining} - 1")
    if(remaining EQUAL 0)
      break()
    endif()
  endforeach()
  list(REMOVE_DUPLICATES refs)
  list(SORT refs COMPARE NATURAL)
  set(${refs_var} "${refs}" PARENT_SCOPE)
endfunction()

# Fails unless `value` (a JSON number) compares as asked with `bound`.
function(expect_number what value op bound)
  if(NOT value MATCHES "^[-0-9.eE+]+$")
    fail("${what} is not a number: ${value}")
  endif()
  execute_process(COMMAND python3 -c "import sys; v=${value}; b=${bound}; sys.exit(0 if (v ${op} b) else 1)" RESULT_VARIABLE bad)
  if(bad)
    fail("${what} = ${value}, expected ${op} ${bound}")
  endif()
endfunction()

# Runs dtlab mesh with --verify --stats; expects success and the verifier's ok line; sets
# `quality` (the quality object of the last stdout line, a JSON object) and the variable `key`
# to that line's count of elements, which must be at least 10.
# After run_mesh_verified(key ...): the count `key` within (low, high) and the share of unit
# edges above unit_low (a domain with no interior edge still meshed to the size: issue 42).
macro(expect_count_and_unit key low high unit_low)
  expect_number("${key}" "${${key}}" ">" ${low})
  expect_number("${key}" "${${key}}" "<" ${high})
  string(JSON unit GET "${quality}" unit_edge_share)
  expect_number("unit edge share" "${unit}" ">" ${unit_low})
endmacro()

macro(run_mesh_verified key)
  run(mesh ${ARGN} --verify --stats)
  expect_success()
  if(NOT out MATCHES "(^|\n)ok: ")
    fail("no ok line from --verify")
  endif()
  string(REGEX MATCH "[^\n]+\n?$" json "${out}")
  string(JSON quality GET "${json}" quality)
  string(JSON ${key} GET "${json}" ${key})
  if(${key} LESS 10)
    fail("too few ${key}: ${${key}}")
  endif()
endmacro()
