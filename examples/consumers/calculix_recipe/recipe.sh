#!/usr/bin/env bash
# docs/install.md's CalculiX steps, run literally on a stand-in for a stock CalculiX source tree
# (the same archive name, ccx_2.22.a built with `ar vr`, the same link line shape), with the
# library installed in prefix $1. Usage: recipe.sh PREFIX WORKDIR
set -euo pipefail
P=$1
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$2" && cd "$2"
# The stock build: every object in ccx_2.22.a, then the executable.
gfortran -std=legacy -O2 -c "$here/ccx_2.22.f" "$here/heat.f" "$here/gapcon.f"
ar vr ccx_2.22.a heat.o gapcon.o >/dev/null 2>&1
gfortran -O2 -o ccx_2.22 ccx_2.22.o ccx_2.22.a -lpthread -lm -lc
./ccx_2.22 | grep -q 'AK(1) = -99.000' || { echo "stand-in build broken"; exit 1; }

# --- docs/install.md, "CalculiX", steps 2-4 ---------------------------------------------------
ar d ccx_2.22.a gapcon.o
if ar t ccx_2.22.a | grep -qx gapcon.o; then echo "gapcon.o still in ccx_2.22.a"; exit 1; fi
gfortran -O2 -o ccx_2.22 ccx_2.22.o ccx_2.22.a "$P/lib/libinterfacial_calculix.a" \
  -lpthread -lm -lc -lgcc_s -lutil -lrt -ldl -Wl,-y,gapcon_ >link.log 2>&1
grep -q 'libinterfacial_calculix\.a(.*): definition of gapcon_' link.log ||
  { cat link.log; echo "gapcon_ does not come from libinterfacial_calculix.a"; exit 1; }
# ------------------------------------------------------------------------------------------------
out=$(./ccx_2.22)
echo "$out"
if [ "$out" = "AK(1) =   2.000" ]; then echo "1 passed, 0 failed"; else echo "0 passed, 1 failed"; exit 1; fi
