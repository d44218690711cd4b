# What every CLI check script (cli/*_check.cmake) shares: the required -D variables, a fresh
# scratch directory WORK, and the macros
#   run(<args...>)              runs ${DTLAB} in WORK; sets rc, out, err
#   fail(<what>)                FATAL_ERROR with the command, its exit code, stdout and stderr
#   expect_success()            exit code 0
#   expect_failure(<regex...>)  non-zero exit code, stderr matching every regex
#   medit_section(file name count_var refs_var)  a Medit section's count and distinct references
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
