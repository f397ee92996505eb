#!/usr/bin/env bash
# Deck 4 of the CalculiX host: frictional heat with *FRICTION, USER and *GAP HEAT GENERATION,
# USER (the library's fricheat_). One PASS/FAIL line per check with its numbers; exit status 1
# on any failure.
#   hosts/calculix/heat.sh CCX_OURS WORKDIR
# CCX_OURS is the ccx that build.sh leaves; Debian's /usr/bin/ccx (package calculix-ccx), when
# present, runs the same model with CalculiX's own friction and heat beside it.
#
# The deck (decks/heat_block.inp): a block pressed on a base (step 1), then dragged d = 0.01
# along x in 100 increments (step 2, step time 1), coupled temperature-displacement, steady
# state, the block's top and the base's bottom held at temperature 0. Per increment n the .dat
# gives the drag reaction Fx_n of the top and the heat leaving through the top (the slave's
# share) and the bottom (the master's), -RFL. With the configuration's η, f and speed v = d/T:
#   friction work    W = Σ |Fx_n|·Δd_n,  Δd_n = d·Δt_n/T  (the drag of the increment)
#   heat             Q = Σ (Q_top,n + Q_bottom,n)·Δt_n
#   checks           Q = η·W within 1e-3; Q_top/Q = f within 1e-3; no heat in step 1, where
#                    nothing slides (|τ| = 0; CalculiX's own heat there is μ·p·v).
# Runs: f given and f from two effusivities (law 1, μ = 0.3); the decay law μ(v), whose heat
# rate is checked against η·μ(v)·|Fz|·v as well (heat_block_decay.inp); the same with 2 threads;
# stock CalculiX on heat_block_stock.inp; a configuration without `speed` (VNORM = -1: CalculiX's
# own sliding velocity), against stock's own velocity path; a configuration without the
# interaction's heat table.
set -euo pipefail
t_start=$(date +%s)
here=$(cd "$(dirname "$0")" && pwd)
[ $# -eq 2 ] || { echo "usage: $0 CCX_OURS WORKDIR" >&2; exit 2; }
ours=$(realpath "$1")
work=$2
mkdir -p "$work"
work=$(cd "$work" && pwd)
[ -x "$ours" ] || { echo "heat.sh: $ours is not an executable" >&2; exit 2; }

# The deck's numbers (heat_block.inp and heat_block_stock.inp say the same).
drag=0.01 # d, the drag of step 2
period=1  # T, step 2's time
eta=0.8
share=0.25
speed=$(awk -v d="$drag" -v t="$period" 'BEGIN { printf "%.17g", d / t }')

# shellcheck source=hosts/calculix/lib.sh
. "$here/lib.sh"

# run EXE DECK TAG [ENV...]: DECK.inp in its own directory; the log is DIR/log, the exit status
# DIR/status.
run() {
  local exe=$1 deck=$2 d=$work/$3
  shift 3
  fresh_decks "$d"
  ccx_run "$d" "$exe" "$deck" "$@" >/dev/null
}

# heat_config NAME INTERACTION LINE...: the configuration $work/NAME.toml, one heat table
# [interactions.INTERACTION.heat] with fraction = eta and the given lines.
heat_config() {
  local f=$work/$1.toml
  printf '[interactions.%s.heat]\nfraction = %s\n' "$2" "$eta" >"$f"
  shift 2
  printf '%s\n' "$@" >>"$f"
}

# rows DAT: one line per increment: time Fx Q_top Q_bottom (the heat leaving, -RFL).
rows() {
  awk '/total force \(fx,fy,fz\) for set NTOP/ { t = $NF; getline; getline; fx = $1 }
    /total heat generation for set NTOP/ { getline; getline; qt = -$1 }
    /total heat generation for set NBOTTOM/ { getline; getline; print t, fx, qt, -$1 }' "$1"
}

# sums ROWS: "Q_press W Q Q_top increments" with the sums defined above (step 1: time <= 1).
sums() {
  awk -v d="$drag" -v T="$period" '
    function abs(x) { return x < 0 ? -x : x }
    { dt = $1 - prev; prev = $1
      if ($1 <= 1 + 1e-9) { qp += ($3 + $4) * dt; next }
      n++; w += abs($2) * d * dt / T; q += ($3 + $4) * dt; qt += $3 * dt }
    END { printf "%.9e %.9e %.9e %.9e %d\n", qp, w, q, qt, n }' "$1"
}

# same_rows ROWS_A ROWS_B FROM MIN: two `rows` files side by side, the increments after total
# time FROM: Fx and both heats per increment within the printed precision (7 digits: 2e-6 of the
# larger of the two; below 1e-9 on both sides counts as 0, such as a press's round-off shear force
# of 1e-12 and heat of 1e-17). Prints "PASS|FAIL AGREE/N increments, worst relative difference
# D": PASS when more than MIN increments were compared and every one agrees.
same_rows() {
  paste "$1" "$2" | awk -v from="$3" -v min="$4" '
    function abs(x) { return x < 0 ? -x : x }
    $1 <= from + 1e-9 { next }
    NF != 8 { n++; bad++; next }
    { n++; off = 0
      for (i = 2; i <= 4; i++) { m = abs($i) > abs($(i + 4)) ? abs($i) : abs($(i + 4))
        if (m < 1e-9) continue
        d = abs($i - $(i + 4)) / m; if (d > worst) worst = d; if (d > 2e-6) off = 1 }
      bad += off }
    END { printf "%s %d/%d increments, worst relative difference %.2e", (n > min && bad == 0 ? "PASS" : "FAIL"), n - bad, n, worst }'
}

# check_heat TAG DECK F_EXPECTED WHAT: the three checks on run TAG of DECK.
check_heat() {
  local tag=$1 deck=$2 f=$3 what=$4 r=$work/$1
  if [ "$(cat "$r/status")" != 0 ]; then
    report FAIL "deck 4 ($what): the run failed with status $(cat "$r/status") (log $r/log)"
    return
  fi
  rows "$r/$deck.dat" >"$r/rows"
  read -r qp w q qt n < <(sums "$r/rows")
  if [ "$n" -lt 100 ]; then
    report FAIL "deck 4 ($what): $n drag increments in the .dat, expected 100 (log $r/log)"
    return
  fi
  local res
  res=$(awk -v q="$q" -v w="$w" -v e="$eta" 'BEGIN { r = q / (e * w); d = r - 1; if (d < 0) d = -d
    printf "%s Q = %.7e, eta*W = %.7e (W = %.7e), relative difference %.2e", (d <= 1e-3 ? "PASS" : "FAIL"), q, e * w, w, d }')
  report "${res%% *}" "deck 4 ($what): heat equals eta x friction work over the drag ($n increments): ${res#* } (limit 1e-3)"
  res=$(awk -v q="$q" -v qt="$qt" -v f="$f" 'BEGIN { s = qt / q; d = (s - f) / f; if (d < 0) d = -d
    printf "%s Q_slave/Q = %.7f against f = %.7f, relative difference %.2e", (d <= 1e-3 ? "PASS" : "FAIL"), s, f, d }')
  report "${res%% *}" "deck 4 ($what): slave share of the heat: ${res#* } (limit 1e-3)"
  res=$(awk -v qp="$qp" -v q="$q" 'BEGIN { a = qp < 0 ? -qp : qp
    printf "%s %.3e", (a <= 1e-9 * q ? "PASS" : "FAIL"), a }')
  report "${res%% *}" "deck 4 ($what): no heat while pressed without sliding (step 1): |Q| = ${res#* } (limit 1e-9 x the drag's Q = $(awk -v q="$q" 'BEGIN { printf "%.3e", 1e-9 * q }'))"
}

# --- the library's law: a given share, then Charron's share from two effusivities ----------------
heat_config heat_share SI "slave_share = $share" "speed = $speed"
# e_s = 2, e_m = 3: f = 2/(2 + 3) = 0.4
heat_config heat_effusivity SI "slave_effusivity = 2.0" "master_effusivity = 3.0" "speed = $speed"
t0=$(date +%s.%N)
run "$ours" heat_block share INTERFACIAL_CONFIG="$work/heat_share.toml"
t1=$(date +%s.%N)
check_heat share heat_block "$share" "slave_share = $share"
run "$ours" heat_block effusivity INTERFACIAL_CONFIG="$work/heat_effusivity.toml"
check_heat effusivity heat_block 0.4 "effusivities 2 and 3, f = 0.4"

# --- what stock cannot do: the decay law's |τ| = μ(v)·p heats ------------------------------------
# μ(v) = μ_k + (μ_s − μ_k)·exp(−d_c·v), μ_s = 0.5, μ_k = 0.2, d_c = 10 at v = d/T: the last
# increment's heat rate against η·μ(v)·|Fz|·v (Fz the top's normal reaction), within 1e-3.
run "$ours" heat_block_decay decay INTERFACIAL_CONFIG="$work/heat_share.toml"
check_heat decay heat_block_decay "$share" "decay law"
if [ "$(cat "$work/decay/status")" = 0 ]; then
  fz=$(awk '/total force \(fx,fy,fz\) for set NTOP/ { getline; getline; z = $3 } END { print z }' \
    "$work/decay/heat_block_decay.dat")
  res=$(tail -1 "$work/decay/rows" | awk -v e="$eta" -v v="$speed" -v fz="$fz" '{
    mu = 0.2 + 0.3 * exp(-10 * v); n = fz < 0 ? -fz : fz; want = e * mu * n * v; got = $3 + $4
    d = (got - want) / want; if (d < 0) d = -d
    printf "%s heat rate %.7e against eta*mu(v)*|Fz|*v = %.7e (mu(v) = %.7f, |Fz| = %.7e), relative difference %.2e",
      (d <= 1e-3 ? "PASS" : "FAIL"), got, want, mu, n, d }')
  report "${res%% *}" "deck 4 (decay law): the last increment's ${res#* } (limit 1e-3)"
fi
echo "INFO deck 4: one run $(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }') s, Newton iterations of the drag $(awk 'NR > 2 && $1 == 2 { s += $4 } END { print s + 0 }' "$work/share/heat_block.sta")"

# --- VNORM = -1: no speed in the configuration, CalculiX takes the sliding velocity itself ------
# fricheat_ answers VNORM = -1 when [interactions.SI.heat] has no speed; CalculiX then forms the
# relative velocity of slave and master at each contact point from its nodal velocities. In a
# static (steady-state) step those are the mean velocities of the last converged increment,
# (u - u_start)/Δt, set after each increment and zero at the start of a step: so increment 1 of
# the drag heats nothing, increment 2 heats with the slave's motion in increment 1 (less than
# the drag by the block's elastic shear), and from increment 3 on, in steady sliding, the slave
# moves with the top. Checks: over increments 3..100 the heat equals eta x sum |Fx|·Δd within
# 1e-3 (the same closed form as above, the speed now CalculiX's); the slave's share f within
# 1e-3; no heat in increment 1 (the velocity path taken); every increment (press and drag) equal to stock CalculiX's own velocity path
# (*GAP HEAT GENERATION 0.8, 0.25, -1 on heat_block_stock.inp) within the printed precision.
heat_config heat_nospeed SI "slave_share = $share"
run "$ours" heat_block vnorm INTERFACIAL_CONFIG="$work/heat_nospeed.toml"
r=$work/vnorm
if [ "$(cat "$r/status")" != 0 ]; then
  report FAIL "deck 4 (VNORM = -1): the run failed with status $(cat "$r/status") (log $r/log)"
else
  rows "$r/heat_block.dat" >"$r/rows"
  res=$(awk -v d="$drag" -v T="$period" -v e="$eta" -v f="$share" '
    function abs(x) { return x < 0 ? -x : x }
    { dt = $1 - prev; prev = $1 }
    $1 > 1 + 1e-9 { n++
      if (n == 1) q1 = $3 + $4
      if (n == 2) q2 = ($3 + $4) / (e * abs($2) * d / T)
      if (n == 3) rate = e * abs($2) * d / T
      if (n >= 3) { m++; w += abs($2) * d * dt / T; q += ($3 + $4) * dt; qt += $3 * dt } }
    END { r = w > 0 ? q / (e * w) : 0; dq = abs(r - 1); s = q > 0 ? qt / q : 0; ds = abs(s - f) / f
      ok = m >= 90 && dq <= 1e-3 && ds <= 1e-3 && abs(q1) <= 1e-9 * rate
      printf "%s %d %.7e %.7e %.2e %.7f %.2e %.3e %.4f\n", (ok ? "PASS" : "FAIL"),
        m, q, e * w, dq, s, ds, q1, q2 }' "$r/rows")
  read -r st m q ew dq s ds q1 q2 <<<"$res"
  report "$st" "deck 4 (VNORM = -1, CalculiX's own sliding velocity): heat over the drag's increments 3..100 ($m, steady sliding) Q = $q against eta x sum |Fx|·Δd = $ew (relative difference $dq, limit 1e-3); slave share $s against f = $share (relative difference $ds, limit 1e-3); increment 1 heat $q1 (limit 1e-9 x the steady rate: CalculiX's velocity is zero at a step's start, which a given speed would not be), increment 2 at $q2 of the steady rate (the slave's motion in increment 1)"
  if [ -x /usr/bin/ccx ]; then
    dv=$work/decks_vnorm
    rm -rf "$dv" && mkdir -p "$dv"
    sed 's/^0\.8, 0\.25, 0\.01$/0.8, 0.25, -1./' "$here/decks/heat_block_stock.inp" >"$dv/heat_block_stock.inp"
    if ! grep -qx '0.8, 0.25, -1.' "$dv/heat_block_stock.inp"; then
      report FAIL "deck 4 (VNORM = -1) against stock: no '0.8, 0.25, 0.01' line in heat_block_stock.inp to make VNORM = -1"
    else
      RUN_EXTRA=$dv run /usr/bin/ccx heat_block_stock stock_vnorm
      s=$work/stock_vnorm
      if [ "$(cat "$s/status")" != 0 ]; then
        report FAIL "deck 4 (VNORM = -1) stock: the run failed with status $(cat "$s/status") (log $s/log)"
      else
        rows "$s/heat_block_stock.dat" >"$s/rows"
        # Every increment of both steps (the press's round-off, which stock's slip test (0.95 mu
        # p) leaves out, against forces of 6 and heat rates of 0.01 in the drag).
        res=$(same_rows "$r/rows" "$s/rows" -1 100)
        report "${res%% *}" "deck 4 (VNORM = -1) against stock's own velocity path (*GAP HEAT GENERATION 0.8, 0.25, -1): Fx and both heats per increment of both steps equal in ${res#* } (limit 2e-6)"
      fi
    fi
  fi
fi

# --- threads: the same heat with 1 and 2 threads (the printed precision, as test.sh) -------------
run "$ours" heat_block threads INTERFACIAL_CONFIG="$work/heat_share.toml" OMP_NUM_THREADS=2 \
  CCX_NPROC_RESULTS=2 CCX_NPROC_STIFFNESS=2
r=$work/threads
if [ "$(cat "$r/status")" = 0 ] && grep -q 'Using up to 2 cpu(s) for the stress calculation' "$r/log"; then
  rows "$r/heat_block.dat" >"$r/rows"
  res=$(same_rows "$work/share/rows" "$r/rows" -1 0)
  report "${res%% *}" "deck 4 threads: Fx and both heats with 1 and 2 threads equal in ${res#* } (limit 2e-6)"
else
  report FAIL "deck 4 threads: the run with 2 threads failed or did not use 2 threads (log $r/log)"
fi

# --- stock CalculiX on the same model: the same heat where it slides, heat where it does not -----
if [ -x /usr/bin/ccx ]; then
  run /usr/bin/ccx heat_block_stock stock
  s=$work/stock
  if [ "$(cat "$s/status")" != 0 ]; then
    report FAIL "deck 4 stock: the run failed with status $(cat "$s/status") (log $s/log)"
  else
    rows "$s/heat_block_stock.dat" >"$s/rows"
    # Drag increments (after total time 1): stock's μ·p = |τ| of law 1 when sliding.
    res=$(same_rows "$work/share/rows" "$s/rows" 1 0)
    report "${res%% *}" "deck 4 against stock (drag): Fx and both heats per increment equal to stock *FRICTION/*GAP HEAT GENERATION: ${res#* } (limit 2e-6)"
    read -r sqp sw sq sqt sn < <(sums "$s/rows")
    echo "INFO deck 4 stock: heat in step 1 (pressed, nothing slides) $sqp from mu*p*v, the library's |tau| gives none; drag's heat $sq"
  fi
else
  echo "INFO deck 4: no /usr/bin/ccx (apt-get install calculix-ccx): the stock comparison is skipped"
fi

# --- bad input: the interaction has no heat table: no heat, the cause named, the run goes on ------
heat_config heat_other OTHER "slave_share = $share"
run "$ours" heat_block noheat INTERFACIAL_CONFIG="$work/heat_other.toml"
r=$work/noheat
want="FRICHEAT: interaction 'SI'"
cause="has no [interactions.SI.heat]"
if [ "$(cat "$r/status")" = 0 ] && grep -qF "$want" "$r/log" && grep -qF "$cause" "$r/log"; then
  rows "$r/heat_block.dat" >"$r/rows"
  read -r qp w q qt n < <(sums "$r/rows")
  if awk -v q="$q" -v qp="$qp" 'BEGIN { exit !(q == 0 && qp == 0) }'; then
    report PASS "bad input (no [interactions.SI.heat]): the message names FRICHEAT, SI and the cause ('$cause'), $(grep -cF "$want" "$r/log") line(s); no heat (Q = $q), the run finished"
  else
    report FAIL "bad input (no [interactions.SI.heat]): heat $q after the refusal, expected 0 (log $r/log)"
  fi
else
  report FAIL "bad input (no [interactions.SI.heat]): status $(cat "$r/status"), message '$want ... $cause' $(grep -qF "$cause" "$r/log" && echo found || echo missing) (log $r/log)"
fi

echo "$passed passed, $failed failed (hosts/calculix/heat.sh, $(($(date +%s) - t_start)) s)"
[ "$failed" -eq 0 ]
