# The native libraries the static archive needs, as rustc reports them, against the list that
# CMakeLists.txt gives the Interfacial:: targets and interfacial.pc's Libs.private (EXPECTED).
# A debug build in its own target directory: the release build in target/ is not disturbed.
# rustc prints the note only when it compiles the crate: forget the crate's fingerprint so it
# does (its dependencies stay built).
file(GLOB fingerprints "${TARGET_DIR}/debug/.fingerprint/interfacial-*")
if(fingerprints)
  file(REMOVE_RECURSE ${fingerprints})
endif()
execute_process(
  COMMAND "${CARGO}" rustc --locked --lib --crate-type staticlib --target-dir "${TARGET_DIR}"
          -- --print native-static-libs
  WORKING_DIRECTORY "${SOURCE_DIR}"
  OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cargo rustc failed (${rc}):\n${err}")
endif()
# "note: native-static-libs: -lgcc_s -lutil -lrt -lpthread -lm -ldl -lc"
if(NOT "${out}${err}" MATCHES "native-static-libs: ([^\n]*)")
  message(FATAL_ERROR "no native-static-libs note in cargo's output:\n${err}")
endif()
string(STRIP "${CMAKE_MATCH_1}" flags)
separate_arguments(flags UNIX_COMMAND "${flags}")
set(reported "")
foreach(f IN LISTS flags)
  string(REGEX REPLACE "^-l" "" f "${f}")
  list(APPEND reported "${f}")
endforeach()
if(NOT reported STREQUAL EXPECTED)
  message(FATAL_ERROR "rustc reports the native libraries '${reported}', CMakeLists.txt's "
    "INTERFACIAL_NATIVE_LIBS (and interfacial.pc's Libs.private) say '${EXPECTED}': update "
    "INTERFACIAL_NATIVE_LIBS")
endif()
message(STATUS "native-static-libs: ${reported} (as CMakeLists.txt says)")
