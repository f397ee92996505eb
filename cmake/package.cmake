# Binary packages from the install rules (cmake/install.cmake), for hosts without a Rust
# toolchain: `cpack --config build/CPackConfig.cmake` (scripts/test-packages.sh builds, checks
# and uses them; docs/install.md, "Packages").
#
#   DEB  libinterfacial0       Runtime: libinterfacial.so.0 and libinterfacial_calculix.so.0
#        libinterfacial-dev    Development: header, Fortran module, static libraries, the .so
#                              links, CMake and pkg-config files, documentation
#        libinterfacial0-dbg   Debug: the shared libraries' debug information (by build ID)
#   TGZ  interfacial-<v>-linux-<machine>.tar.gz        Runtime + Development, relocatable
#        interfacial-<v>-linux-<machine>-debug.tar.gz  Debug
set(CPACK_PACKAGE_NAME "interfacial")
set(CPACK_PACKAGE_VENDOR "interfacial")
set(INTERFACIAL_PACKAGE_CONTACT "interfacial maintainers <interfacial@example.org>" CACHE STRING
  "Maintainer of the binary packages (Debian's Maintainer field)")
set(CPACK_PACKAGE_CONTACT "${INTERFACIAL_PACKAGE_CONTACT}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
  "contact-interface laws behind Abaqus-compatible user-subroutine entry points")
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_RESOURCE_FILE_LICENSE "${PROJECT_SOURCE_DIR}/LICENSE-MIT")
set(CPACK_GENERATOR "DEB;TGZ")
set(CPACK_SOURCE_GENERATOR "")
set(CPACK_STRIP_FILES OFF) # stripped when staged; the debug information is its own component
set(CPACK_PACKAGE_DIRECTORY "${PROJECT_BINARY_DIR}/packages")
set(CPACK_COMPONENTS_ALL Runtime Development Debug)
set(CPACK_COMPONENT_RUNTIME_DESCRIPTION "shared libraries (SONAME libinterfacial.so.0)")
set(CPACK_COMPONENT_DEVELOPMENT_DESCRIPTION
  "header, Fortran module, static libraries, CMake and pkg-config files")
set(CPACK_COMPONENT_DEBUG_DESCRIPTION "debug information of the shared libraries")
set(CPACK_COMPONENT_DEVELOPMENT_DEPENDS Runtime)
set(CPACK_COMPONENT_DEBUG_DEPENDS Runtime)
set(CPACK_COMPONENT_RUNTIME_GROUP main)
set(CPACK_COMPONENT_DEVELOPMENT_GROUP main)
set(CPACK_COMPONENT_DEBUG_GROUP debug)

# Debian: one package per component, installed under /usr.
execute_process(COMMAND dpkg --print-architecture OUTPUT_VARIABLE _ifl_deb_arch
  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT _ifl_deb_arch)
  set(_ifl_deb_arch amd64)
endif()
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_DEBIAN_PACKAGE_ARCHITECTURE "${_ifl_deb_arch}")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${CPACK_PACKAGE_CONTACT}")
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME "libinterfacial${INTERFACIAL_SOVERSION}")
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SECTION libs)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SHLIBDEPS ON)
# shlibs and the ldconfig trigger written here: CPack's own (GENERATE_SHLIBS) calls ldconfig
# from postinst/postrm, which lintian refuses ("lacks-ldconfig-trigger").
file(WRITE "${PROJECT_BINARY_DIR}/debian/shlibs"
  "libinterfacial ${INTERFACIAL_SOVERSION} libinterfacial${INTERFACIAL_SOVERSION} (>= ${PROJECT_VERSION})\n"
  "libinterfacial_calculix ${INTERFACIAL_SOVERSION} libinterfacial${INTERFACIAL_SOVERSION} (>= ${PROJECT_VERSION})\n")
file(WRITE "${PROJECT_BINARY_DIR}/debian/triggers" "activate-noawait ldconfig\n")
set(CPACK_DEBIAN_RUNTIME_PACKAGE_CONTROL_EXTRA
  "${PROJECT_BINARY_DIR}/debian/shlibs;${PROJECT_BINARY_DIR}/debian/triggers")
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_NAME "libinterfacial-dev")
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_DEBUG_PACKAGE_NAME "libinterfacial${INTERFACIAL_SOVERSION}-dbg")
set(CPACK_DEBIAN_DEBUG_PACKAGE_SECTION debug)
set(CPACK_DEBIAN_ENABLE_COMPONENT_DEPENDS ON)

# The tarball: relocatable (the CMake package and the .pc files find their files relative to
# themselves), one for Runtime + Development and one for Debug.
set(CPACK_ARCHIVE_COMPONENT_INSTALL ON)
execute_process(COMMAND uname -m OUTPUT_VARIABLE _ifl_machine OUTPUT_STRIP_TRAILING_WHITESPACE)
# (Also the tarballs' top directory: the debug one unpacks into the same.)
set(CPACK_PACKAGE_FILE_NAME "interfacial-${PROJECT_VERSION}-linux-${_ifl_machine}")
set(CPACK_ARCHIVE_MAIN_FILE_NAME "${CPACK_PACKAGE_FILE_NAME}")
set(CPACK_ARCHIVE_DEBUG_FILE_NAME "interfacial-${PROJECT_VERSION}-linux-${_ifl_machine}-debug")

# Per generator (read by cpack): groups for the tarballs, one package per component for Debian,
# and /usr as the Debian prefix.
set(CPACK_PROJECT_CONFIG_FILE "${PROJECT_BINARY_DIR}/CPackProjectConfig.cmake")
file(WRITE "${CPACK_PROJECT_CONFIG_FILE}" "
if(CPACK_GENERATOR STREQUAL \"DEB\")
  set(CPACK_COMPONENTS_GROUPING IGNORE)
  set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
  set(ENV{INTERFACIAL_DEBIAN_DOCS} 1)
else()
  set(CPACK_COMPONENTS_GROUPING ONE_PER_GROUP)
  set(CPACK_PACKAGING_INSTALL_PREFIX /)
  set(CPACK_INCLUDE_TOPLEVEL_DIRECTORY ON)
  set(CPACK_COMPONENT_INCLUDE_TOPLEVEL_DIRECTORY ON)
  set(ENV{INTERFACIAL_DEBIAN_DOCS} 0)
endif()
")

# What Debian asks of every package: /usr/share/doc/<package>/copyright and changelog.gz
# (written only when cpack builds the Debian packages).
set(_ifl_copyright "${PROJECT_BINARY_DIR}/debian/copyright")
file(READ "${PROJECT_SOURCE_DIR}/LICENSE-MIT" _ifl_mit)
file(WRITE "${_ifl_copyright}" "Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/
Upstream-Name: interfacial
Source: the interfacial source tree

Files: *
Copyright: the interfacial authors
License: MIT or Apache-2.0
 The Apache-2.0 text is at /usr/share/common-licenses/Apache-2.0; the MIT text follows.

License: MIT
")
string(REGEX REPLACE "\n\n" "\n.\n" _ifl_mit "${_ifl_mit}")
string(REGEX REPLACE "\n([^\n])" "\n \\1" _ifl_mit " ${_ifl_mit}")
file(APPEND "${_ifl_copyright}" "${_ifl_mit}")
find_program(INTERFACIAL_GZIP gzip)
string(TIMESTAMP _ifl_date "%a, %d %b %Y %H:%M:%S +0000" UTC)
foreach(_ifl_comp Runtime Development Debug)
  string(TOUPPER "${_ifl_comp}" _ifl_up)
  set(_ifl_pkg "${CPACK_DEBIAN_${_ifl_up}_PACKAGE_NAME}")
  install(CODE "
    if(\"\$ENV{INTERFACIAL_DEBIAN_DOCS}\" STREQUAL \"1\")
      set(dir \"${PROJECT_BINARY_DIR}/debian/${_ifl_pkg}\")
      file(MAKE_DIRECTORY \"\${dir}\")
      file(WRITE \"\${dir}/changelog\" \"${_ifl_pkg} (${PROJECT_VERSION}) unstable; urgency=medium

  * Binary package of interfacial ${PROJECT_VERSION} (CHANGELOG.md in libinterfacial-dev).

 -- ${CPACK_PACKAGE_CONTACT}  ${_ifl_date}
\")
      execute_process(COMMAND \"${INTERFACIAL_GZIP}\" -9nf \"\${dir}/changelog\"
        COMMAND_ERROR_IS_FATAL ANY)
      file(INSTALL \"${_ifl_copyright}\" \"\${dir}/changelog.gz\"
        DESTINATION \"\${CMAKE_INSTALL_PREFIX}/share/doc/${_ifl_pkg}\"
        PERMISSIONS OWNER_READ OWNER_WRITE GROUP_READ WORLD_READ)
    endif()
    " COMPONENT ${_ifl_comp})
endforeach()

include(CPack)
