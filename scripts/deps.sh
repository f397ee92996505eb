#!/usr/bin/env bash
# Installs what the tests need beyond Rust and gcc (Debian packages): gfortran and cmake for the
# harnesses, valgrind for the memory checks, OpenMPI for the MPI harness. Run as root, or
# install them yourself: apt-get install gfortran cmake valgrind openmpi-bin libopenmpi-dev
set -euo pipefail
missing=()
command -v gfortran >/dev/null 2>&1 || missing+=(gfortran)
command -v cmake >/dev/null 2>&1 || missing+=(cmake)
command -v valgrind >/dev/null 2>&1 || missing+=(valgrind)
command -v mpif90 >/dev/null 2>&1 || missing+=(openmpi-bin libopenmpi-dev)
[ ${#missing[@]} -eq 0 ] && exit 0
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
