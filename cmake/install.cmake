# cmake --install: the GNUInstallDirs layout (docs/install.md lists every file).
#   include/interfacial.h, include/interfacial.mod
#   lib/libinterfacial.a, lib/libinterfacial.so.<version> + .so.<ABI> + .so links
#   lib/libinterfacial_calculix.{a,so...}, lib/libinterfacial_fortran.a
#   lib/cmake/Interfacial/InterfacialConfig.cmake, InterfacialConfigVersion.cmake
#   lib/pkgconfig/interfacial.pc, interfacial-fortran.pc, interfacial_calculix.pc
#   share/interfacial/fortran/interfacial.f90
#   share/doc/interfacial/: README.md, CHANGELOG.md, the licences and docs/ (the pages the
#   library's messages name, e.g. docs/config.md, are share/doc/interfacial/docs/config.md)
set(_ifl_lib "${INTERFACIAL_LIB_DIR}")
set(_ifl_v "${PROJECT_VERSION}")
set(_ifl_so "${INTERFACIAL_SOVERSION}")

# Three components, which the packages follow (cmake/package.cmake): Runtime (the SONAME'd
# shared libraries), Development (everything a host builds with) and Debug (the shared
# libraries' debug information, by build ID). The staged libraries are already stripped
# (cmake/cargo_build.cmake).
install(FILES "${PROJECT_SOURCE_DIR}/include/interfacial.h"
  DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}" COMPONENT Development)
install(FILES "${_ifl_lib}/libinterfacial.a" "${_ifl_lib}/libinterfacial_calculix.a"
  DESTINATION "${CMAKE_INSTALL_LIBDIR}" COMPONENT Development)
install(FILES "${_ifl_lib}/libinterfacial.so.${_ifl_v}" "${_ifl_lib}/libinterfacial_calculix.so.${_ifl_v}"
  DESTINATION "${CMAKE_INSTALL_LIBDIR}" COMPONENT Runtime
  PERMISSIONS OWNER_READ OWNER_WRITE GROUP_READ WORLD_READ)
# The links (file(INSTALL) keeps a symbolic link a link): the SONAME's with the library, the
# unversioned one for linking with the development files.
install(FILES "${_ifl_lib}/libinterfacial.so.${_ifl_so}"
              "${_ifl_lib}/libinterfacial_calculix.so.${_ifl_so}"
  DESTINATION "${CMAKE_INSTALL_LIBDIR}" COMPONENT Runtime)
install(FILES "${_ifl_lib}/libinterfacial.so" "${_ifl_lib}/libinterfacial_calculix.so"
  DESTINATION "${CMAKE_INSTALL_LIBDIR}" COMPONENT Development)

# Debug information: lib/debug/.build-id/xx/yyyy.debug, where gdb looks for it by the library's
# build ID (under /usr/lib/debug for a /usr install; elsewhere `set debug-file-directory
# <prefix>/lib/debug`). The ID is read when installing, from the staged .debug file.
find_program(INTERFACIAL_READELF NAMES readelf "${CMAKE_READELF}")
if(NOT INTERFACIAL_READELF)
  message(WARNING "interfacial: no readelf (binutils); the debug information is not installed")
  set(_ifl_debug_stems "")
else()
  set(_ifl_debug_stems libinterfacial libinterfacial_calculix)
endif()
foreach(_ifl_stem IN LISTS _ifl_debug_stems)
  install(CODE "
    set(dbg \"${_ifl_lib}/${_ifl_stem}.so.${_ifl_v}.debug\")
    execute_process(COMMAND \"${INTERFACIAL_READELF}\" -n \"\${dbg}\" OUTPUT_VARIABLE notes
      RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0 OR NOT notes MATCHES \"Build ID: ([0-9a-f][0-9a-f])([0-9a-f]+)\")
      message(FATAL_ERROR \"interfacial: no build ID in \${dbg} (readelf: ${INTERFACIAL_READELF})\")
    endif()
    file(INSTALL \"\${dbg}\" DESTINATION
      \"\${CMAKE_INSTALL_PREFIX}/lib/debug/.build-id/\${CMAKE_MATCH_1}\"
      RENAME \"\${CMAKE_MATCH_2}.debug\" PERMISSIONS OWNER_READ OWNER_WRITE GROUP_READ WORLD_READ)
    " COMPONENT Debug)
endforeach()

set(INTERFACIAL_INSTALLS_FORTRAN OFF)
if(INTERFACIAL_FORTRAN_MODULE)
  set(INTERFACIAL_INSTALLS_FORTRAN ON)
  install(TARGETS interfacial_fortran ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}"
    COMPONENT Development)
  # The .mod of the compiler that built it, next to the C header (as netCDF-Fortran does), and
  # the source for any other compiler.
  install(FILES "${PROJECT_BINARY_DIR}/fortran/interfacial.mod"
    DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}" COMPONENT Development)
  install(FILES "${PROJECT_SOURCE_DIR}/fortran/interfacial.f90"
    DESTINATION "${CMAKE_INSTALL_DATADIR}/interfacial/fortran" COMPONENT Development)
endif()

# CMake package.
set(INTERFACIAL_CMAKE_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/Interfacial")
configure_package_config_file("${PROJECT_SOURCE_DIR}/cmake/InterfacialConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/InterfacialConfig.cmake"
  INSTALL_DESTINATION "${INTERFACIAL_CMAKE_DIR}"
  PATH_VARS CMAKE_INSTALL_INCLUDEDIR CMAKE_INSTALL_LIBDIR)
# 0.y.z: only the same 0.y is compatible (semver; CHANGELOG.md "C ABI").
write_basic_package_version_file("${PROJECT_BINARY_DIR}/InterfacialConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}" COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/InterfacialConfig.cmake"
              "${PROJECT_BINARY_DIR}/InterfacialConfigVersion.cmake"
  DESTINATION "${INTERFACIAL_CMAKE_DIR}" COMPONENT Development)

# pkg-config, relocatable: prefix is found from the .pc file's own place.
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  set(INTERFACIAL_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
else()
  file(RELATIVE_PATH _ifl_up "/p/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/p")
  string(REGEX REPLACE "/$" "" _ifl_up "${_ifl_up}")
  set(INTERFACIAL_PC_PREFIX "\${pcfiledir}/${_ifl_up}")
endif()
list(TRANSFORM INTERFACIAL_NATIVE_LIBS PREPEND "-l" OUTPUT_VARIABLE _ifl_private)
string(JOIN " " INTERFACIAL_PC_LIBS_PRIVATE ${_ifl_private})
foreach(pc interfacial interfacial_calculix)
  set(INTERFACIAL_PC_NAME "${pc}")
  if(pc STREQUAL "interfacial_calculix")
    set(INTERFACIAL_PC_CFLAGS "-DINTERFACIAL_CALCULIX")
    set(INTERFACIAL_PC_WHAT "CalculiX variant: gapcon with AREA after KINC")
  else()
    set(INTERFACIAL_PC_CFLAGS "")
    set(INTERFACIAL_PC_WHAT "Abaqus argument lists")
  endif()
  configure_file("${PROJECT_SOURCE_DIR}/cmake/interfacial.pc.in"
    "${PROJECT_BINARY_DIR}/pkgconfig/${pc}.pc" @ONLY)
  install(FILES "${PROJECT_BINARY_DIR}/pkgconfig/${pc}.pc"
    DESTINATION "${CMAKE_INSTALL_LIBDIR}/pkgconfig" COMPONENT Development)
endforeach()
if(INTERFACIAL_INSTALLS_FORTRAN)
  configure_file("${PROJECT_SOURCE_DIR}/cmake/interfacial-fortran.pc.in"
    "${PROJECT_BINARY_DIR}/pkgconfig/interfacial-fortran.pc" @ONLY)
  install(FILES "${PROJECT_BINARY_DIR}/pkgconfig/interfacial-fortran.pc"
    DESTINATION "${CMAKE_INSTALL_LIBDIR}/pkgconfig" COMPONENT Development)
endif()

# The documentation, laid out as in the source tree so README's links and the messages'
# "docs/config.md" hold below share/doc/interfacial.
install(FILES "${PROJECT_SOURCE_DIR}/README.md" "${PROJECT_SOURCE_DIR}/CHANGELOG.md"
              "${PROJECT_SOURCE_DIR}/LICENSE-MIT" "${PROJECT_SOURCE_DIR}/LICENSE-APACHE"
  DESTINATION "${CMAKE_INSTALL_DOCDIR}" COMPONENT Development)
install(DIRECTORY "${PROJECT_SOURCE_DIR}/docs/" DESTINATION "${CMAKE_INSTALL_DOCDIR}/docs"
  COMPONENT Development FILES_MATCHING PATTERN "*.md" PATTERN "*.svg")
