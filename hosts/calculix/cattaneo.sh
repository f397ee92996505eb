#!/usr/bin/env bash
# Deck 2 of the CalculiX host: Cattaneo-Mindlin partial slip of a cylinder on a flat (plane
# strain, same elastic material both sides, node-to-face penalty contact), normal load P, then a
# tangential load Q = 0.2, 0.5, 0.8 mu P. Runs the deck with stock *FRICTION mu, lambda (Debian's
# ccx) and with the same law as *FRICTION, USER (law 1, PROPS(7) = 4) in our ccx, side by side
# (one thread each), then prints one PASS/FAIL line per check with its numbers (Hertz half-width,
# stick half-width, the shear in the stick zone, the totals, USER against stock) and writes the
# chart WORKDIR/cattaneo-c-over-a.svg. Exit status 1 on any failure.
#
#   hosts/calculix/cattaneo.sh CCX_OURS CCX_STOCK WORKDIR
#
# The decks are written at run time by cattaneo.py (python3, standard library only), which
# holds the geometry, the loads, the closed forms and the tolerances.
set -euo pipefail
t_start=$(date +%s)
here=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=hosts/calculix/lib.sh
. "$here/lib.sh"
if [ $# -ne 3 ]; then
  echo "usage: $0 CCX_OURS CCX_STOCK WORKDIR" >&2
  exit 2
fi
ours=$(realpath "$1")
stock=$(realpath "$2")
for exe in "$ours" "$stock"; do
  [ -x "$exe" ] || { echo "cattaneo.sh: $exe is not an executable" >&2; exit 2; }
done
command -v python3 >/dev/null || { echo "cattaneo.sh: python3 is missing" >&2; exit 2; }
work=$3
mkdir -p "$work"
work=$(cd "$work" && pwd)
d=$work/cattaneo
rm -rf "$d" && mkdir -p "$d/user" "$d/stock"

python3 "$here/cattaneo.py" gen "$d/user" | sed 's/^/INFO deck 2: /'
cp "$d"/user/cylinder_*.inp "$d/stock/"

# run KIND EXE: the deck cylinder_KIND.inp in d/KIND, one thread; wall time in d/KIND/time
run() {
  ccx_run "$d/$1" "$2" "cylinder_$1" >"$d/$1/time"
}
# The two runs side by side (CI has 2 cores).
run user "$ours" &
pid_user=$!
run stock "$stock" &
pid_stock=$!
wait "$pid_user" "$pid_stock"

ok=yes
for kind in user stock; do
  if [ "$(cat "$d/$kind/status")" != 0 ]; then
    echo "FAIL deck 2 (Cattaneo-Mindlin): the $kind run failed with status $(cat "$d/$kind/status") (log $d/$kind/log)"
    tail -5 "$d/$kind/log" | sed 's/^/  /'
    ok=no
  fi
done
if [ "$ok" = no ]; then
  echo "runs kept in $d"
  exit 1
fi

# iterations STA: the sum of the ITRS column; increments: the converged increments
increments() { awk 'NR > 2 && NF >= 7 && $3 !~ /U$/ { c++ } END { print c + 0 }' "$1"; }
echo "INFO deck 2: Newton iterations (increments) stock $(iterations "$d/stock/cylinder_stock.sta") ($(increments "$d/stock/cylinder_stock.sta")), USER $(iterations "$d/user/cylinder_user.sta") ($(increments "$d/user/cylinder_user.sta")); wall time side by side stock $(cat "$d/stock/time") s, USER $(cat "$d/user/time") s"

cp "$d/stock/cylinder_stock.dat" "$d/user/"
st=0
python3 "$here/cattaneo.py" check "$d/user" || st=$?
python3 "$here/cattaneo.py" chart "$d/user" "$work/cattaneo-c-over-a.svg"
echo "INFO deck 2: chart $work/cattaneo-c-over-a.svg; cattaneo.sh took $(($(date +%s) - t_start)) s"
if [ "$st" -ne 0 ]; then
  echo "runs kept in $d"
  exit 1
fi
