# Sourced by the CalculiX host's check scripts (test.sh, more.sh, heat.sh, cattaneo.sh): the
# PASS/FAIL reporter, the one way a deck is run, and CalculiX's printed totals. Expects $here
# (this folder) set by the script that sources it.

passed=0
failed=0
# report STATUS LINE: prints "STATUS LINE" and counts it (PASS, or anything else as a failure).
report() {
  if [ "$1" = PASS ]; then passed=$((passed + 1)); else failed=$((failed + 1)); fi
  echo "$1 $2"
}

# fresh_decks DIR: DIR emptied, then the decks of hosts/calculix/decks copied into it, then those
# of $RUN_EXTRA (a directory whose decks replace those of the same name: variants) when set.
fresh_decks() {
  rm -rf "$1" && mkdir -p "$1"
  cp "$here"/decks/*.inp "$1/"
  if [ -n "${RUN_EXTRA:-}" ]; then cp "$RUN_EXTRA"/*.inp "$1/"; fi
}

# ccx_run DIR EXE DECK [ENV...]: EXE runs DECK.inp in DIR with one thread (and the ENV
# assignments); the log is DIR/log, the exit status DIR/status; prints the wall time in seconds.
ccx_run() {
  local d=$1 exe=$2 deck=$3 t0 t1 st=0
  shift 3
  t0=$(date +%s.%N)
  (cd "$d" && env OMP_NUM_THREADS=1 CCX_NPROC_RESULTS=1 CCX_NPROC_STIFFNESS=1 "$@" \
    "$exe" "$deck" >log 2>&1) || st=$?
  t1=$(date +%s.%N)
  echo "$st" >"$d/status"
  awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.3f", b - a }'
}

# totals DAT: one line per printed total force: time fx fy fz
totals() { awk '/total force \(fx,fy,fz\)/ { t = $NF; getline; getline; print t, $1, $2, $3 }' "$1"; }
# iterations STA: the sum of the ITRS column (Newton iterations of the run)
iterations() { awk 'NR > 2 && NF >= 7 { s += $4 } END { print s + 0 }' "$1"; }
