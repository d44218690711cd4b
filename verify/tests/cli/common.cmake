# What every CLI check script (cli/*_check.cmake) shares: the required -D variables, a fresh
# scratch directory WORK, and the macros
#   run(<args...>)              runs ${DTLAB} in WORK; sets rc, out, err
#   fail(<what>)                FATAL_ERROR with the command, its exit code, stdout and stderr
#   expect_success()            exit code 0
#   expect_failure(<regex...>)  non-zero exit code, stderr matching every regex
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
