#!/usr/bin/env bash
# The CalculiX host's checks: builds ccx with build.sh (cached), then runs the decks of
# hosts/calculix/decks/ with Debian's stock ccx (/usr/bin/ccx, package calculix-ccx) and with
# ours. One pass/fail line per check with its numbers; exit status 1 on any failure.
#   hosts/calculix/test.sh [WORKDIR]
set -euo pipefail
t_start=$(date +%s)
here=$(cd "$(dirname "$0")" && pwd)
keep=${1:+yes}
work=${1:-$(mktemp -d)}
mkdir -p "$work"
work=$(cd "$work" && pwd)

"$here/build.sh" "$work/bin" | sed 's/^/  /'
ours=$work/bin/ccx
if [ ! -x /usr/bin/ccx ]; then
  if [ "$(id -u)" -eq 0 ]; then
    apt-get install -y --no-install-recommends calculix-ccx >/dev/null 2>&1 || {
      apt-get update >/dev/null
      apt-get install -y --no-install-recommends calculix-ccx >/dev/null
    }
  else
    echo "test.sh: Debian's stock ccx is missing: apt-get install calculix-ccx" >&2
    exit 1
  fi
fi
stock=/usr/bin/ccx

# shellcheck source=hosts/calculix/lib.sh
. "$here/lib.sh"

# run EXE DECK [ENV...]: runs DECK.inp in its own directory under $work/runs; prints the wall
# time in seconds on stdout; the log is DIR/log, the exit status DIR/status.
run() {
  local exe=$1 deck=$2 d=$work/runs/$3
  shift 3
  fresh_decks "$d"
  ccx_run "$d" "$exe" "$deck" "$@"
}

# cmp_totals A B: the totals files A and B equal per increment within CalculiX's printed
# precision: 7 significant digits (E13.6), i.e. each component's difference at most 2e-6 of the
# increment's largest |component| (1e-6 for the last digit and 2 x 0.5e-6 for the rounding of
# the two prints); same times, same number of increments. Sets cmp_status (PASS/FAIL) and
# cmp_what (the numbers).
cmp_totals() {
  local res
  res=$(paste "$1" "$2" | awk '
    function abs(x) { return x < 0 ? -x : x }
    NF != 8 { bad = bad " (increments differ in number)"; next }
    { n++
      if ($1 != $5) { bad = bad " time " $1 "/" $5 }
      m = abs($2); if (abs($3) > m) m = abs($3); if (abs($4) > m) m = abs($4)
      for (i = 2; i <= 4; i++) { d = abs($i - $(i + 4)) / m; if (d > worst) { worst = d; at = $1 } }
      if (abs($2 - $6) > 2e-6 * m || abs($3 - $7) > 2e-6 * m || abs($4 - $8) > 2e-6 * m) nbad++
      last = sprintf("Fx %s/%s Fy %s/%s Fz %s/%s", $2, $6, $3, $7, $4, $8)
    }
    END { printf "%s %d/%d increments (worst relative difference %.2e at time %s, limit 2e-6; last: %s)%s\n",
      (n > 0 && nbad == 0 && bad == "" ? "PASS" : "FAIL"), n - nbad, n, worst, at, last, bad }')
  cmp_status=${res%% *}
  cmp_what=${res#* }
}

# --- deck 1: stock *FRICTION against *FRICTION, USER (law 1), drag along x and diagonally ------
for dir in x xy x_f2f xy_f2f; do
  ts=$(run "$stock" "block_${dir}_stock" "block_${dir}_stock")
  tu=$(run "$ours" "block_${dir}_user" "block_${dir}_user")
  ds=$work/runs/block_${dir}_stock
  du=$work/runs/block_${dir}_user
  if [ "$(cat "$ds/status")" != 0 ] || [ "$(cat "$du/status")" != 0 ]; then
    report FAIL "deck 1 ($dir): a run failed (stock status $(cat "$ds/status"), USER $(cat "$du/status"); logs in $ds, $du)"
    continue
  fi
  totals "$ds/block_${dir}_stock.dat" >"$ds/totals"
  totals "$du/block_${dir}_user.dat" >"$du/totals"
  cmp_totals "$ds/totals" "$du/totals"
  report "$cmp_status" "deck 1 ($dir drag): reaction totals stock vs USER equal in $cmp_what"
  mkdir -p "$work/charts"
  "$here/chart.sh" "$ds/totals" "$du/totals" 0.05 "$work/charts/calculix-deck1-$dir.svg" \
    "Deck 1 ($dir): friction force against drag, stock and USER"
  its=$(iterations "$ds/block_${dir}_stock.sta")
  itu=$(iterations "$du/block_${dir}_user.sta")
  echo "INFO deck 1 ($dir drag): Newton iterations stock $its, USER $itu; wall time stock ${ts} s, USER ${tu} s"
done

# --- deck 1 through CalculiX's own cut-backs: the state restored --------------------------------
# The drag step of deck 1 (x) with automatic incrementation, the whole drag tried as one
# increment and CalculiX's divergence check early (*CONTROLS TIME INCREMENTATION I_0 = 2,
# I_R = 3): CalculiX abandons and repeats increments at a quarter of their size, and USER must
# do what stock does through them. Checks: at least one repeated increment, the same attempts
# in both .sta files, the reaction totals equal per increment (as deck 1), and the full slide
# at the end at |Fx|/|Fz| = mu = 0.3 (within 1e-4). (Every repeat here ends in full slip, so
# a host that started a repeat from the abandoned attempt's stress would give the same totals:
# the restart from the converged state, xstateini, is by construction, not shown by this deck.)
d=$work/decks_cutbacks
rm -rf "$d" && mkdir -p "$d"
awk 'held != "" { if ($0 == "0.05, 1.") {
    print "*CONTROLS, PARAMETERS=TIME INCREMENTATION"; print "2, 3, 9, 50, 10, 4, , 5"
    print "*STATIC"; print "1., 1., 1.e-5, 1."; held = ""; next }
    print held; held = "" }
  $0 == "*STATIC, DIRECT" { held = $0; next } { print }' \
  "$here/decks/block_steps_x.inp" >"$d/block_steps_x.inp"
for v in stock user; do
  if [ $v = stock ]; then exe=$stock; else exe=$ours; fi
  RUN_EXTRA=$d run "$exe" "block_x_$v" "cutbacks_$v" >/dev/null
done
cs=$work/runs/cutbacks_stock
cu=$work/runs/cutbacks_user
if ! grep -q 'TIME INCREMENTATION' "$d/block_steps_x.inp"; then
  report FAIL "deck 1 with cut-backs: the drag step's increment line was not found"
elif [ "$(cat "$cs/status")" != 0 ] || [ "$(cat "$cu/status")" != 0 ]; then
  report FAIL "deck 1 with cut-backs: a run failed (stock status $(cat "$cs/status"), USER $(cat "$cu/status"); logs in $cs, $cu)"
else
  attempts() { awk 'NR > 2 && NF >= 7 { print $1, $2, $3, $5 }' "$1"; }
  repeats=$(awk 'NR > 2 && $3 ~ /U$/ { c++ } END { print c + 0 }' "$cu/block_x_user.sta")
  same=no
  [ "$(attempts "$cs/block_x_stock.sta")" = "$(attempts "$cu/block_x_user.sta")" ] && same=yes
  totals "$cs/block_x_stock.dat" >"$cs/totals"
  totals "$cu/block_x_user.dat" >"$cu/totals"
  cmp_totals "$cs/totals" "$cu/totals"
  ratio=$(tail -1 "$cu/totals" | awk '{ r = $2 / $4; if (r < 0) r = -r; printf "%.6f", r }')
  st=$(awk -v r="$ratio" -v n="$repeats" -v s="$same" -v c="$cmp_status" 'BEGIN {
    e = r - 0.3; if (e < 0) e = -e
    print (n >= 1 && s == "yes" && c == "PASS" && e <= 1e-4 ? "PASS" : "FAIL") }')
  report "$st" "deck 1 with CalculiX's own cut-backs (x drag, automatic incrementation): $repeats increment(s) repeated, the same attempts as stock: $same; reaction totals stock vs USER equal in $cmp_what; last |Fx|/|Fz| = $ratio (mu = 0.3, limit 1e-4)"
fi

# --- cost: stock against USER on deck 1 (x) with 200 increments per drag, CPU time -------------
d=$work/decks_timing
rm -rf "$d" && mkdir -p "$d"
awk '/^0\.05, 1\.$/ { print "0.005, 1."; next } { print }' "$here/decks/block_steps_x.inp" \
  >"$d/block_steps_x.inp"
cpu() { # DIR EXE DECK: user+system seconds of one run (bash's time keyword)
  local out TIMEFORMAT='%U %S'
  out=$({ time (cd "$1" && OMP_NUM_THREADS=1 CCX_NPROC_RESULTS=1 CCX_NPROC_STIFFNESS=1 \
    "$2" "$3" >/dev/null 2>&1); } 2>&1)
  echo "$out" | awk '{ printf "%.2f", $1 + $2 }'
}
for v in stock user; do
  RUN_EXTRA=$d run /bin/true "block_x_$v" "timing_$v" >/dev/null
done
ts=() tu=()
for i in 1 2 3; do
  ts+=("$(cpu "$work/runs/timing_stock" "$stock" block_x_stock)")
  tu+=("$(cpu "$work/runs/timing_user" "$ours" block_x_user)")
done
med() { printf '%s\n' "$@" | sort -g | sed -n 2p; }
its=$(iterations "$work/runs/timing_stock/block_x_stock.sta")
itu=$(iterations "$work/runs/timing_user/block_x_user.sta")
echo "INFO cost, deck 1 (x) with 200 increments per drag: CPU time (median of 3) stock $(med "${ts[@]}") s, USER $(med "${tu[@]}") s; Newton iterations stock $its, USER $itu"

# --- what stock cannot do: the decay law, steady force μ(v)·N at 10, 100, 1000 increments ------
# μ = μ_k + (μ_s − μ_k)·exp(−d_c·v) with μ_s = 0.5, μ_k = 0.2, d_c = 10 at v = 0.1 (drag 0.1 in
# a step of time 1): the last increment's |Fx|/|Fz| of the top against μ(v), within 1 %.
mu_v=$(awk 'BEGIN { printf "%.7f", 0.2 + 0.3 * exp(-10 * 0.1) }')
for n in 10 100 1000; do
  inc=$(awk -v n="$n" 'BEGIN { printf "%g", 1 / n }')
  d=$work/decks_decay$n
  rm -rf "$d" && mkdir -p "$d"
  # The drag step's increment line (the second "0.01, 1.", the first being 0.1) set to 1/n.
  awk -v inc="$inc" '/^0\.01, 1\.$/ { print inc ", 1."; next } { print }' \
    "$here/decks/block_decay_steps.inp" >"$d/block_decay_steps.inp"
  grep -qx "$inc, 1." "$d/block_decay_steps.inp" || { report FAIL "decay deck: no drag increment line"; continue; }
  t=$(RUN_EXTRA=$d run "$ours" block_decay_user "decay$n")
  r=$work/runs/decay$n
  if [ "$(cat "$r/status")" != 0 ]; then
    report FAIL "decay law, $n increments per drag: the run failed (log in $r)"
    continue
  fi
  incs=$(awk 'NR > 2 && $1 == 2 { c++ } END { print c + 0 }' "$r/block_decay_user.sta")
  its=$(awk 'NR > 2 && $1 == 2 { s += $4 } END { print s + 0 }' "$r/block_decay_user.sta")
  line=$(totals "$r/block_decay_user.dat" | tail -1)
  res=$(echo "$line" | awk -v m="$mu_v" '{ r = -$2 / $4; if (r < 0) r = -r; e = (r - m) / m; if (e < 0) e = -e
    printf "%s %.7f %.2e", (e <= 0.01 ? "PASS" : "FAIL"), r, e }')
  st=${res%% *}
  rest=${res#* }
  report "$st" "decay law, $n increments per drag ($incs run): |Fx|/|Fz| = ${rest% *} against mu(v) = $mu_v (relative difference ${rest#* }, limit 1e-2); Newton iterations per increment $(awk -v a="$its" -v b="$incs" 'BEGIN { printf "%.2f", a / b }'), wall time ${t} s"
done

# --- what stock cannot do, more: anisotropy and mu(theta) (more.sh, its own lines) -----------
more_st=0
more_out=$("$here/more.sh" "$ours" "$stock" "$work/more") || more_st=$?
while read -r st line; do
  case "$st" in PASS | FAIL) report "$st" "$line" ;; INFO) echo "INFO $line" ;; esac
done <<<"$more_out"
[ "$more_st" -le 1 ] || report FAIL "more.sh stopped with status $more_st (runs in $work/more)"

# --- bad input through the deck: a clear stop naming the cause, no crash -----------------------
for c in "bad_too_few_props|PROPERTIES=7 but 6 values given" \
  "bad_refused_props|PROPS(2): friction coefficient" \
  "bad_depvar|NSTATV = 2 but the Coulomb law needs 3" \
  "bad_no_properties|of interaction SI: PROPERTIES=n is required"; do
  deck=${c%%|*}
  want=${c#*|}
  run "$ours" "$deck" "$deck" >/dev/null
  r=$work/runs/$deck
  st=$(cat "$r/status")
  # CalculiX's own stop is exit(201); a signal would show as 129..192.
  if [ "$st" != 0 ] && { [ "$st" -le 128 ] || [ "$st" -gt 192 ]; } && grep -qF "$want" "$r/log" &&
    grep -q 'CalculiX stops' "$r/log"; then
    report PASS "bad input $deck: stopped with status $st, the message names the cause ('$want')"
  else
    report FAIL "bad input $deck: status $st (>= 128 is a crash), message '$want' $(grep -qF "$want" "$r/log" && echo found || echo missing) (log $r/log)"
  fi
done

# --- cut-back: a refusal at run time repeats the increment with its size times 0.25 ------------
# cutback_user.inp (law 1 with mu·exp(-b(theta - theta_ref)) out of f64's range at the deck's
# temperature): every attempt is refused. From the .sta file, the attempts of the first
# increment (ATT column "nU"): the first of the deck's initial size 0.1, each next one 0.25 x
# the one before (the library's PNEWDT; within the 7 printed digits), none converged; from the
# log, the library's message (routine, interaction, cause), CalculiX's "requested ... through
# pnewdt" once per attempt (so the cut-back is the library's, not CalculiX's own divergence
# rule, whose factor is also 0.25), and its own stop after its limit of cut-backs (status 201,
# not a signal). Node-to-face as written and face-to-face (the copy's contact pair changed).
d=$work/decks_cutback_f2f
rm -rf "$d" && mkdir -p "$d"
sed 's/TYPE=NODE TO SURFACE/TYPE=SURFACE TO SURFACE/' "$here/decks/cutback_user.inp" >"$d/cutback_user.inp"
for kind in n2f f2f; do
  if [ "$kind" = f2f ]; then
    RUN_EXTRA=$d run "$ours" cutback_user "cutback_$kind" >/dev/null
  else
    run "$ours" cutback_user "cutback_$kind" >/dev/null
  fi
  r=$work/runs/cutback_$kind
  st=$(cat "$r/status")
  grep -q 'TYPE=SURFACE TO SURFACE' "$r/cutback_user.inp" && is_f2f=f2f || is_f2f=n2f
  sta=$(awk 'NR > 2 && NF >= 7 { printf "%s %s\n", $3, $NF }' "$r/cutback_user.sta" 2>/dev/null || true)
  res=$(echo "$sta" | awk '
    function abs(x) { return x < 0 ? -x : x }
    NF == 2 && $1 ~ /U$/ { n++; dt[n] = $2 + 0; next }
    NF == 2 { conv++ }
    END {
      ok = n >= 2 && conv == 0 && abs(dt[1] - 0.1) <= 1e-7
      worst = 0; seq = dt[1]
      for (i = 2; i <= n; i++) {
        q = dt[i] / dt[i - 1]; e = abs(q - 0.25) / 0.25; if (e > worst) worst = e
        seq = seq ", " dt[i]
      }
      if (worst > 1e-5) ok = 0
      printf "%s %d %d %.1e %s\n", (ok ? "PASS" : "FAIL"), n, conv, worst, seq
    }')
  read -r ok n conv worst seq <<<"$res"
  asked=$(grep -c 'increment size decrease requested by a material user routine (through pnewdt)' "$r/log" || true)
  msg=$(grep -m1 "^interfacial: FRIC: interaction 'SI' .*overflowed" "$r/log" || true)
  if [ "$ok" = PASS ] && [ "$is_f2f" = "$kind" ] && [ "$asked" = "$n" ] && [ -n "$msg" ] &&
    [ "$st" != 0 ] && { [ "$st" -le 128 ] || [ "$st" -gt 192 ]; } &&
    grep -q 'too many cutbacks' "$r/log"; then
    report PASS "cut-back ($kind): a refused increment is repeated with its size times 0.25: attempts of increment 1 of size $seq (ratio 0.25 within $worst, limit 1e-5), none converged, each cut back through PNEWDT (CalculiX says so $asked times), then CalculiX's 'too many cutbacks' stop (status $st); the library's message: ${msg#interfacial: }"
  else
    report FAIL "cut-back ($kind): status $st, contact kind $is_f2f, attempts '$seq' ($n refused, $conv converged; ratio error $worst), $asked cut-backs through PNEWDT, message '${msg:-missing}', 'too many cutbacks' $(grep -q 'too many cutbacks' "$r/log" && echo found || echo missing) (log $r/log)"
  fi
done

# --- threads: the same answers with 1 and 2 threads ---------------------------------------------
for deck in block_xy_user block_xy_f2f_user; do
  run "$ours" "$deck" "${deck}_t2" OMP_NUM_THREADS=2 CCX_NPROC_RESULTS=2 CCX_NPROC_STIFFNESS=2 >/dev/null
  r2=$work/runs/${deck}_t2
  if [ "$(cat "$r2/status")" != 0 ] || ! grep -q 'Using up to 2 cpu(s) for the stress calculation' "$r2/log"; then
    report FAIL "threads: $deck with 2 threads failed or did not use 2 threads (log $r2/log)"
    continue
  fi
  totals "$r2/$deck.dat" >"$r2/totals"
  # The summation order of the threads changes the last bits (stock ccx's too): the printed
  # precision, as deck 1.
  cmp_totals "$work/runs/$deck/totals" "$r2/totals"
  report "$cmp_status" "threads: $deck with 1 and 2 threads equal in $cmp_what"
done

echo "charts (friction force against drag, deck 1): $work/charts/"
# --- deck 2: Cattaneo-Mindlin partial slip of a cylinder on a flat (cattaneo.sh) ---------------
cm_st=0
"$here/cattaneo.sh" "$ours" "$stock" "$work" >"$work/cattaneo.out" 2>&1 || cm_st=$?
cat "$work/cattaneo.out"
passed=$((passed + $(grep -c '^PASS' "$work/cattaneo.out" || true)))
failed=$((failed + $(grep -c '^FAIL' "$work/cattaneo.out" || true)))
if [ "$cm_st" -ne 0 ] && ! grep -q '^FAIL' "$work/cattaneo.out"; then
  report FAIL "deck 2: cattaneo.sh exited with status $cm_st (output $work/cattaneo.out)"
fi

# --- deck 4: frictional heat (hosts/calculix/heat.sh prints its own PASS/FAIL lines) --------
heat_status=0
"$here/heat.sh" "$ours" "$work/heat" >"$work/heat.log" 2>&1 || heat_status=$?
grep -v ' passed, .* failed (hosts/calculix/heat.sh' "$work/heat.log" || true
passed=$((passed + $(grep -c '^PASS' "$work/heat.log" || true)))
failed=$((failed + $(grep -c '^FAIL' "$work/heat.log" || true)))
if [ "$heat_status" -ne 0 ] && ! grep -q '^FAIL' "$work/heat.log"; then
  report FAIL "deck 4: heat.sh exited with status $heat_status (log $work/heat.log)"
fi

echo "$passed passed, $failed failed (hosts/calculix/test.sh, $(($(date +%s) - t_start)) s)"
if [ "$failed" -ne 0 ]; then
  echo "runs kept in $work/runs"
  exit 1
fi
[ -n "$keep" ] || rm -rf "$work"
