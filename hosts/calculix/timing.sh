#!/usr/bin/env bash
# Stock *FRICTION against *FRICTION, USER: wall and CPU time, interleaved, on deck 1 (drag along
# x with 200 increments per drag, as test.sh's cost line) and deck 2 (the Cattaneo cylinder).
# Not run by the tests (deck 2 alone takes minutes per round); docs/calculix.md quotes its output.
#   hosts/calculix/timing.sh CCX_OURS CCX_STOCK WORKDIR [ROUNDS]
# Each round runs stock then USER on each deck, one thread each, one run at a time. Prints per
# deck and code the minimum and the spread (max - min) of wall and CPU (user + system) time over
# the rounds, the ratio USER/stock of the minima, and the Newton iterations (the .sta's ITRS sum).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
[ $# -ge 3 ] || { echo "usage: $0 CCX_OURS CCX_STOCK WORKDIR [ROUNDS]" >&2; exit 2; }
ours=$(realpath "$1")
stock=$(realpath "$2")
mkdir -p "$3"
work=$(cd "$3" && pwd)
rounds=${4:-7}
command -v python3 >/dev/null || { echo "timing.sh: python3 is missing" >&2; exit 2; }

# deck 1 (x), 200 increments per drag; deck 2 written by cattaneo.py
d1=$work/deck1
rm -rf "$d1" && mkdir -p "$d1"
cp "$here"/decks/*.inp "$d1/"
awk '/^0\.05, 1\.$/ { print "0.005, 1."; next } { print }' "$here/decks/block_steps_x.inp" \
  >"$d1/block_steps_x.inp"
grep -qx '0.005, 1.' "$d1/block_steps_x.inp" || { echo "timing.sh: no drag increment line" >&2; exit 1; }
d2=$work/deck2
rm -rf "$d2" && mkdir -p "$d2"
python3 "$here/cattaneo.py" gen "$d2" >/dev/null

# one DIR EXE DECK: "wall cpu" of one run (GNU time's format when present, else bash's)
one() {
  local out TIMEFORMAT='%R %U %S'
  out=$({ time (cd "$1" && OMP_NUM_THREADS=1 CCX_NPROC_RESULTS=1 CCX_NPROC_STIFFNESS=1 \
    "$2" "$3" >log_"$3" 2>&1); } 2>&1) || { echo "timing.sh: $2 $3 failed (log $1/log_$3)" >&2; exit 1; }
  echo "$out" | awk '{ printf "%.3f %.3f\n", $1, $2 + $3 }'
}
: >"$work/times"
for r in $(seq 1 "$rounds"); do
  for c in "deck1|$d1|block_x" "deck2|$d2|cylinder"; do
    IFS='|' read -r name dir deck <<<"$c"
    echo "$name stock $(one "$dir" "$stock" "${deck}_stock")" >>"$work/times"
    echo "$name user $(one "$dir" "$ours" "${deck}_user")" >>"$work/times"
  done
  echo "round $r of $rounds done" >&2
done
its() { awk 'NR > 2 && NF >= 7 { s += $4 } END { print s + 0 }' "$1"; }
for c in "deck1|$d1|block_x" "deck2|$d2|cylinder"; do
  IFS='|' read -r name dir deck <<<"$c"
  awk -v n="$name" -v is="$(its "$dir/${deck}_stock.sta")" -v iu="$(its "$dir/${deck}_user.sta")" '
    $1 == n { k = $2; c[k]++
      if (c[k] == 1 || $3 < wmin[k]) wmin[k] = $3; if (c[k] == 1 || $3 > wmax[k]) wmax[k] = $3
      if (c[k] == 1 || $4 < cmin[k]) cmin[k] = $4; if (c[k] == 1 || $4 > cmax[k]) cmax[k] = $4 }
    END {
      printf "%s, %d rounds: wall min stock %.2f s (spread %.2f), USER %.2f s (spread %.2f), USER/stock %.3f; CPU min stock %.2f s (spread %.2f), USER %.2f s (spread %.2f), USER/stock %.3f; Newton iterations stock %d, USER %d\n",
        n, c["stock"], wmin["stock"], wmax["stock"] - wmin["stock"], wmin["user"], wmax["user"] - wmin["user"],
        wmin["user"] / wmin["stock"], cmin["stock"], cmax["stock"] - cmin["stock"], cmin["user"],
        cmax["user"] - cmin["user"], cmin["user"] / cmin["stock"], is, iu }' "$work/times"
done
