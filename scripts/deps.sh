#!/usr/bin/env bash
# Installs what the tests need beyond Rust and gcc (Debian packages): gfortran and cmake for the
# harnesses, valgrind for the memory checks, OpenMPI for the MPI harness, make, pkg-config and
# binutils for the consumer suite, lintian, dpkg-dev and file for the packages. Run as root, or
# install them yourself: apt-get install gfortran cmake valgrind openmpi-bin libopenmpi-dev
# INTERFACIAL_MPI=OFF leaves MPI out (then configure with cmake -DINTERFACIAL_MPI=OFF too).
set -euo pipefail
missing=()
command -v gfortran >/dev/null 2>&1 || missing+=(gfortran)
command -v cmake >/dev/null 2>&1 || missing+=(cmake)
command -v valgrind >/dev/null 2>&1 || missing+=(valgrind)
# The consumer suite (scripts/test-consumers.sh): make and pkg-config for the Makefile host,
# objcopy, readelf and strings (binutils) for the weak entry points, the SONAME checks and the
# pages messages name.
command -v make >/dev/null 2>&1 || missing+=(make)
command -v pkg-config >/dev/null 2>&1 || missing+=(pkg-config)
{ command -v objcopy && command -v readelf && command -v strings; } >/dev/null 2>&1 || missing+=(binutils)
# The binary packages (scripts/test-packages.sh): lintian checks them, dpkg-shlibdeps (dpkg-dev)
# and file give the runtime package's Depends.
command -v lintian >/dev/null 2>&1 || missing+=(lintian)
command -v dpkg-shlibdeps >/dev/null 2>&1 || missing+=(dpkg-dev)
command -v file >/dev/null 2>&1 || missing+=(file)
# The CalculiX host's deck 2 (hosts/calculix/cattaneo.py): python3, standard library only.
command -v python3 >/dev/null 2>&1 || missing+=(python3)
[ "${INTERFACIAL_MPI:-ON}" = OFF ] || { command -v mpif90 && command -v mpirun; } >/dev/null 2>&1 ||
  missing+=(openmpi-bin libopenmpi-dev)
# The MPI harness needs MPI's Fortran module: `use mpi` must compile with mpif90.
check_mpi_fortran() {
  [ "${INTERFACIAL_MPI:-ON}" = OFF ] && return 0
  local d
  d=$(mktemp -d)
  printf '%s\n' 'program p' '  use mpi' '  implicit none' '  integer :: ierr' \
    '  call mpi_init(ierr)' '  call mpi_finalize(ierr)' 'end program p' >"$d/p.f90"
  if ! (cd "$d" && mpif90 p.f90 -o p) >"$d/log" 2>&1; then
    echo "interfacial: mpif90 cannot compile 'use mpi' (is libopenmpi-dev installed?):" >&2
    cat "$d/log" >&2
    rm -rf "$d"
    exit 1
  fi
  rm -rf "$d"
}
[ ${#missing[@]} -eq 0 ] && { check_mpi_fortran; exit 0; }
echo "interfacial: installing ${missing[*]} (Debian packages)"
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO=sudo; else
    echo "interfacial: need ${missing[*]}; run as root or: apt-get install ${missing[*]}" >&2
    exit 1
  fi
else SUDO=; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
check_mpi_fortran
