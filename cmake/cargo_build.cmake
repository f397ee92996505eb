# One cargo build and the staging of what it made (cmake -P, run by CMakeLists.txt every build):
#
#   cargo build --release --locked --lib --target-dir TARGET_DIR ARGS --message-format=json...
#
# then the files cargo *reported* for the `interfacial` library (its compiler-artifact message,
# printed whether it rebuilt them or found them fresh) are staged under their installed names:
#   libinterfacial.a   -> TO/STEM.a: WEAK symbols made weak, no debug information, no bitcode
#   libinterfacial.so  -> TO/STEM.so.VERSION stripped, TO/STEM.so.VERSION.debug its debug
#                         information, links TO/STEM.so.SOVERSION and TO/STEM.so
# Nothing is looked up by a guessed path, so a library left in some directory by an older build
# is never staged: either cargo names the file of this build or the build fails saying so.
# A staged file is copied again whenever its source's content differs from the last copy
# (a SHA-256 stamp beside it), newer or not.
#
# Variables: CARGO, SOURCE_DIR, TARGET_DIR, TO, STEM, VERSION, SOVERSION; optional ARGS (extra
# cargo arguments, comma-separated), OBJCOPY, WEAK (comma-separated symbols).
foreach(v CARGO SOURCE_DIR TARGET_DIR TO STEM VERSION SOVERSION)
  if(NOT DEFINED ${v} OR "${${v}}" STREQUAL "")
    message(FATAL_ERROR "cargo_build.cmake: ${v} is not set")
  endif()
endforeach()

# --target-dir beats CARGO_TARGET_DIR, CARGO_BUILD_TARGET_DIR and build.target-dir: an
# exported variable cannot send this build elsewhere. Say so when one is set to another place.
foreach(var CARGO_TARGET_DIR CARGO_BUILD_TARGET_DIR)
  if(DEFINED ENV{${var}} AND NOT "$ENV{${var}}" STREQUAL "")
    get_filename_component(env_dir "$ENV{${var}}" ABSOLUTE BASE_DIR "${SOURCE_DIR}")
    string(FIND "${TARGET_DIR}/" "${env_dir}/" at)
    if(NOT at EQUAL 0)
      message(STATUS "interfacial: ${var}=$ENV{${var}} is ignored: this build directory uses "
        "INTERFACIAL_CARGO_TARGET_DIR (cargo --target-dir ${TARGET_DIR}); configure with "
        "-DINTERFACIAL_CARGO_TARGET_DIR=... to change it")
    endif()
  endif()
endforeach()

string(REPLACE "," ";" args "${ARGS}")
execute_process(
  COMMAND "${CARGO}" build --release --locked --lib --target-dir "${TARGET_DIR}" ${args}
          --message-format=json-render-diagnostics
  WORKING_DIRECTORY "${SOURCE_DIR}"
  OUTPUT_VARIABLE json RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cargo_build.cmake: cargo build failed (${rc}); nothing staged")
endif()

# One JSON object a line; the interfacial library's artifact message names its files.
set(a_in "")
set(so_in "")
string(REPLACE ";" "<semicolon>" json "${json}")
string(REPLACE "\n" ";" lines "${json}")
foreach(line IN LISTS lines)
  if(NOT line MATCHES "\"reason\":\"compiler-artifact\"" OR
     NOT line MATCHES "\"target\":{[^}]*\"name\":\"interfacial\"" OR
     NOT line MATCHES "\"filenames\":\\[([^]]*)\\]")
    continue()
  endif()
  string(REPLACE "<semicolon>" "\\;" names "${CMAKE_MATCH_1}")
  string(REGEX MATCHALL "\"[^\"]*\"" names "${names}")
  foreach(name IN LISTS names)
    string(REGEX REPLACE "^\"(.*)\"$" "\\1" name "${name}")
    if(name MATCHES "/libinterfacial\\.a$")
      set(a_in "${name}")
    elseif(name MATCHES "/libinterfacial\\.so$")
      set(so_in "${name}")
    endif()
  endforeach()
endforeach()
if(a_in STREQUAL "")
  message(FATAL_ERROR "cargo_build.cmake: cargo build succeeded but reported no libinterfacial.a "
    "(no compiler-artifact message for the 'interfacial' staticlib in its JSON output; target "
    "directory ${TARGET_DIR}); nothing staged")
endif()
foreach(f IN ITEMS "${a_in}" "${so_in}")
  if(f STREQUAL "")
    continue()
  endif()
  string(FIND "${f}" "${TARGET_DIR}/" at)
  if(NOT at EQUAL 0)
    message(FATAL_ERROR "cargo_build.cmake: cargo reported ${f}, outside the target directory "
      "${TARGET_DIR}; nothing staged")
  endif()
  if(NOT EXISTS "${f}")
    message(FATAL_ERROR "cargo_build.cmake: cargo reported ${f}, which does not exist")
  endif()
endforeach()

file(MAKE_DIRECTORY "${TO}")
# Copies `in` to `out` unless the last copy (its stamp) was of the same content.
function(stage_needed in out result)
  file(SHA256 "${in}" hash)
  set(stamp "")
  if(EXISTS "${out}" AND EXISTS "${out}.source")
    file(READ "${out}.source" stamp)
  endif()
  # (The stamp's last word names this recipe: a change to what staging does restages.)
  if(stamp STREQUAL "${hash} ${in} stripped-1")
    set(${result} FALSE PARENT_SCOPE)
  else()
    set(${result} TRUE PARENT_SCOPE)
  endif()
  set(stage_stamp "${hash} ${in} stripped-1" PARENT_SCOPE)
endfunction()

function(run_objcopy)
  execute_process(COMMAND "${OBJCOPY}" ${ARGN} RESULT_VARIABLE orc)
  if(NOT orc EQUAL 0)
    message(FATAL_ERROR "cargo_build.cmake: ${OBJCOPY} ${ARGN} failed (${orc})")
  endif()
endfunction()

# The archive as installed: the WEAK entry points weak, no debug information (34 MB -> under
# 6 MB) and no LLVM bitcode. With lto = "fat" rustc embeds the crate's bitcode (.llvmbc) beside
# the machine code; no C or Fortran linker uses it, but binutils' nm and ar hand such a member
# to an LLVM plugin, which fails ("no symbols") when its LLVM is older than rustc's. The
# machine code is left as cargo built it (tests: the consumer suite compares fric_'s).
set(a_out "${TO}/${STEM}.a")
stage_needed("${a_in}" "${a_out}" copy)
if(copy)
  message(STATUS "interfacial: staging ${a_in} as ${a_out}")
  set(tmp "${a_out}.tmp")
  file(COPY_FILE "${a_in}" "${tmp}")
  if(OBJCOPY)
    # A host that defines one of the Abaqus entry points itself keeps its own: the archive's
    # definitions are weak, so the linker takes the host's strong one without a "multiple
    # definition" error, and still pulls the archive member for the entry points the host
    # does not define.
    set(objcopy_args --strip-debug --remove-section=.llvmbc --remove-section=.llvmcmd)
    string(REPLACE "," ";" WEAK "${WEAK}")
    foreach(sym IN LISTS WEAK)
      list(APPEND objcopy_args "--weaken-symbol=${sym}")
    endforeach()
    run_objcopy(${objcopy_args} "${tmp}")
  endif()
  file(RENAME "${tmp}" "${a_out}")
  file(WRITE "${a_out}.source" "${stage_stamp}")
endif()

# The shared library stripped, its debug information in STEM.so.VERSION.debug beside it (found
# by gdb through the .gnu_debuglink section; installed apart, docs/install.md).
if(NOT so_in STREQUAL "")
  set(so_out "${TO}/${STEM}.so.${VERSION}")
  stage_needed("${so_in}" "${so_out}" copy)
  if(copy OR NOT EXISTS "${so_out}.debug")
    message(STATUS "interfacial: staging ${so_in} as ${so_out}")
    if(OBJCOPY)
      run_objcopy(--only-keep-debug "${so_in}" "${so_out}.debug")
      run_objcopy(--strip-unneeded "--add-gnu-debuglink=${so_out}.debug" "${so_in}"
        "${so_out}.tmp")
      file(RENAME "${so_out}.tmp" "${so_out}")
    else()
      file(COPY_FILE "${so_in}" "${so_out}")
      file(COPY_FILE "${so_in}" "${so_out}.debug")
    endif()
    file(WRITE "${so_out}.source" "${stage_stamp}")
  endif()
  file(CREATE_LINK "${STEM}.so.${VERSION}" "${TO}/${STEM}.so.${SOVERSION}" SYMBOLIC)
  file(CREATE_LINK "${STEM}.so.${SOVERSION}" "${TO}/${STEM}.so" SYMBOLIC)
endif()
