# CTest cargo_build_stages_what_cargo_reported: cmake/cargo_build.cmake against a stand-in for
# cargo that prints a chosen JSON output, in WORK. Checks that the staging takes the file cargo
# reported and nothing else: not a library lying at the usual path, not an older staged copy
# when the reported file is older, and that it fails, naming the cause, when cargo reports no
# library or one outside the target directory.
#   cmake -DSCRIPT=cmake/cargo_build.cmake -DWORK=<dir> -P cmake/check_cargo_build.cmake
foreach(v SCRIPT WORK)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "check_cargo_build.cmake: ${v} is not set")
  endif()
endforeach()
file(REMOVE_RECURSE "${WORK}")
set(td "${WORK}/target")
set(to "${WORK}/lib")
file(MAKE_DIRECTORY "${td}/release" "${td}/other" "${WORK}/elsewhere")
set(fake "${WORK}/cargo")
file(WRITE "${fake}" "#!/bin/sh\ncat \"${WORK}/cargo.json\"\n")
file(CHMOD "${fake}" PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
set(failures 0)

# One cargo_build.cmake run; `a` is the path the stand-in reports ("" for none).
function(run_stage a result_var output_var)
  set(msg "{\"reason\":\"compiler-artifact\",\"target\":{\"kind\":[\"staticlib\"],\"name\":\"interfacial\"},\"filenames\":[\"${a}\"],\"fresh\":true}\n")
  if(a STREQUAL "")
    set(msg "{\"reason\":\"build-finished\",\"success\":true}\n")
  endif()
  file(WRITE "${WORK}/cargo.json" "${msg}")
  execute_process(
    COMMAND "${CMAKE_COMMAND}" "-DCARGO=${fake}" "-DSOURCE_DIR=${WORK}" "-DTARGET_DIR=${td}"
            "-DTO=${to}" -DSTEM=libinterfacial -DVERSION=1.2.3 -DSOVERSION=1 -P "${SCRIPT}"
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(${result_var} "${rc}" PARENT_SCOPE)
  set(${output_var} "${out}${err}" PARENT_SCOPE)
endfunction()

function(expect what cond)
  if(${cond})
    message(STATUS "ok: ${what}")
  else()
    message(STATUS "FAILED: ${what}")
    math(EXPR n "${failures} + 1")
    set(failures ${n} PARENT_SCOPE)
  endif()
endfunction()

function(staged_is content what)
  set(ok FALSE)
  if(EXISTS "${to}/libinterfacial.a")
    file(READ "${to}/libinterfacial.a" got)
    if(got STREQUAL content)
      set(ok TRUE)
    endif()
  endif()
  expect("${what}" ok)
  set(failures ${failures} PARENT_SCOPE)
endfunction()

# 1. cargo succeeds but names no library: fail, saying so, and stage nothing.
run_stage("" rc out)
set(c FALSE)
if(NOT rc EQUAL 0 AND out MATCHES "reported[ \n]+no[ \n]+libinterfacial\\.a" AND NOT EXISTS "${to}/libinterfacial.a")
  set(c TRUE)
endif()
expect("no reported library: fails naming the cause" c)

# 2. A library at the usual path (an old build) is ignored; the reported one is staged.
file(WRITE "${td}/release/libinterfacial.a" "old build at the usual path")
file(WRITE "${td}/other/libinterfacial.a" "this build")
run_stage("${td}/other/libinterfacial.a" rc out)
set(c FALSE)
if(rc EQUAL 0)
  set(c TRUE)
endif()
expect("reported library staged (exit 0)" c)
staged_is("this build" "the reported file is staged, not the one at the usual path")

# 3. The reported file is older than the staged copy (another target directory's build):
#    copied all the same, since its content differs.
file(WRITE "${td}/release/libinterfacial.a" "older build, other content")
execute_process(COMMAND touch -d "2001-01-01" "${td}/release/libinterfacial.a")
run_stage("${td}/release/libinterfacial.a" rc out)
staged_is("older build, other content" "an older reported file replaces a newer staged copy")

# 4. A reported file outside the target directory: refused.
file(WRITE "${WORK}/elsewhere/libinterfacial.a" "elsewhere")
run_stage("${WORK}/elsewhere/libinterfacial.a" rc out)
set(c FALSE)
if(NOT rc EQUAL 0 AND out MATCHES "outside[ \n]+the[ \n]+target[ \n]+directory")
  set(c TRUE)
endif()
expect("a file outside the target directory: fails naming the cause" c)
staged_is("older build, other content" "and the staged copy is left alone")

if(failures GREATER 0)
  message(FATAL_ERROR "cargo_build.cmake: ${failures} check(s) failed")
endif()
message(STATUS "cargo_build.cmake: all checks passed")
