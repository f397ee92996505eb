#!/usr/bin/env bash
# What stock *FRICTION cannot do, run through *FRICTION, USER in CalculiX: anisotropic friction
# (law 1, PROPS(3)) and a temperature-dependent coefficient (law 1, PROPS(12..13)) in a coupled
# temperature-displacement step. Every check against a closed form; one PASS/FAIL line per check
# with its numbers; exit status 1 on any failure.
#   hosts/calculix/more.sh CCX_OURS CCX_STOCK WORKDIR
# CCX_OURS: the ccx that hosts/calculix/build.sh leaves; CCX_STOCK: Debian's /usr/bin/ccx (run
# on one anisotropic deck only, to print what it makes of *FRICTION, USER).
set -euo pipefail
t_start=$(date +%s)
here=$(cd "$(dirname "$0")" && pwd)
if [ $# -ne 3 ]; then
  echo "usage: $0 CCX_OURS CCX_STOCK WORKDIR" >&2
  exit 2
fi
ours=$1
stock=$2
for e in "$ours" "$stock"; do
  [ -x "$e" ] || { echo "more.sh: $e is not an executable" >&2; exit 2; }
done
mkdir -p "$3"
work=$(cd "$3" && pwd)

# shellcheck source=hosts/calculix/lib.sh
. "$here/lib.sh"

# run EXE DECK TAG [f2f]: runs DECK.inp in $work/runs/TAG (a fresh copy of the decks); the log
# is TAG/log, the exit status TAG/status. With f2f the deck's node-to-face contact pair is made
# face-to-face (TYPE=SURFACE TO SURFACE) in the copy.
run() {
  local exe=$1 deck=$2 d=$work/runs/$3 kind=${4:-n2f}
  fresh_decks "$d"
  if [ "$kind" = f2f ]; then
    sed -i 's/TYPE=NODE TO SURFACE/TYPE=SURFACE TO SURFACE/' "$d/$deck.inp"
    grep -q 'TYPE=SURFACE TO SURFACE' "$d/$deck.inp" || { echo 99 >"$d/status"; return; }
  fi
  ccx_run "$d" "$exe" "$deck" >/dev/null
}

# ran TAG WHAT: true when run TAG ended with status 0; otherwise a FAIL line for WHAT with the
# status and the log, and false.
ran() {
  local r=$work/runs/$1
  [ "$(cat "$r/status")" = 0 ] && return 0
  report FAIL "$2: the run failed (status $(cat "$r/status"), log $r/log)"
  return 1
}

# --- anisotropic friction: mu1 = 0.4 along t1 = x, mu2 = 0.2 along t2 = +-y -------------------
# Law 1 with PROPS(3): the isotropic algorithm on scaled stresses (mu_bar/mu_i) tau_i, so in
# full slip along the unit direction d the stress is on the ellipse (tau1/mu1)^2 + (tau2/mu2)^2
# = p^2 with tau_i proportional to mu_i^2 d_i: tau_i = p mu_i^2 d_i / sqrt(sum_j mu_j^2 d_j^2).
# In steady sliding the whole contact slips along the drag direction, so the top's reaction
# totals obey the same with N = |Fz|: along x |Fx| = mu1 N, along y |Fy| = mu2 N, along the
# diagonal |Fx| = mu1^2 N / sqrt(mu1^2 + mu2^2) and |Fy| = mu2^2 N / sqrt(mu1^2 + mu2^2).
# Checked at the last increment, each component within 1 % of its closed form.
# Both contact kinds: node-to-face as written, face-to-face (f2f) by the copy's contact pair.
for c in "x|1|0|n2f" "y|0|1|n2f" "xy|0.7071068|0.7071068|n2f" \
  "x|1|0|f2f" "y|0|1|f2f" "xy|0.7071068|0.7071068|f2f"; do
  IFS='|' read -r dir dx dy kind <<<"$c"
  run "$ours" "aniso_$dir" "aniso_${dir}_$kind" "$kind"
  ran "aniso_${dir}_$kind" "anisotropy ($kind), drag along $dir" || continue
  r=$work/runs/aniso_${dir}_$kind
  totals "$r/aniso_$dir.dat" >"$r/totals"
  res=$(tail -1 "$r/totals" | awk -v m1=0.4 -v m2=0.2 -v dx="$dx" -v dy="$dy" '
    function abs(x) { return x < 0 ? -x : x }
    { n = abs($4); s = sqrt(m1 * m1 * dx * dx + m2 * m2 * dy * dy)
      ex = m1 * m1 * dx / s; ey = m2 * m2 * dy / s
      gx = abs($2) / n; gy = abs($3) / n
      # a zero closed form (the cross component of an axis drag): |F|/N at most 1e-6, scaled
      # so that the 1e-2 limit below says that
      rx = ex > 0 ? abs(gx - ex) / ex : gx / 1e-4
      ry = ey > 0 ? abs(gy - ey) / ey : gy / 1e-4
      ok = rx <= 0.01 && ry <= 0.01
      # the same on the ellipse: (Fx/mu1)^2 + (Fy/mu2)^2 = N^2
      e = sqrt((gx / m1) ^ 2 + (gy / m2) ^ 2)
      printf "%s |Fx|/N = %.6f (closed form %.6f), |Fy|/N = %.6f (closed form %.6f), N = %.4f, sqrt((Fx/mu1)^2 + (Fy/mu2)^2)/N = %.6f (ellipse: 1); worst relative difference %.2e, limit 1e-2 (a zero closed form: |F|/N <= 1e-6)",
        (ok && abs(e - 1) <= 0.01 ? "PASS" : "FAIL"), gx, ex, gy, ey, n, e, (rx > ry ? rx : ry) }')
  report "${res%% *}" "anisotropy ($kind; mu1 = 0.4, mu2 = 0.2), steady drag along $dir: ${res#* }"
done
# Stock ccx has no anisotropic friction, and it does not refuse the deck: it ignores USER and
# reads the first two values as its mu = 1 and stick slope 0.4 (INFO, not a check of ours).
run "$stock" aniso_x aniso_x_stock
r=$work/runs/aniso_x_stock
if [ "$(cat "$r/status")" = 0 ]; then
  echo "INFO anisotropy: stock ccx runs aniso_x.inp as *FRICTION 1., 0.4 (USER ignored): $(totals "$r/aniso_x.dat" | tail -1 |
    awk '{ r = $2 / $4; printf "|Fx|/N = %.6f at the end of the drag, not 0.4", r < 0 ? -r : r }')"
else
  echo "INFO anisotropy: stock ccx stops on aniso_x.inp (status $(cat "$r/status"))"
fi

# --- temperature-dependent mu: mu(theta) = 0.3 exp(-5e-3 (theta - 20)) -------------------------
# thermal_user.inp: coupled temperature-displacement steps with every node's temperature
# prescribed, so theta_bar = theta. The drag at 60 (step 2), then on at a temperature ramped
# from 60 to 100 over step 3 (theta = 60 + 40 (t - 2) at total time t). Checks: the last
# increment of step 2 against mu(60), that of step 3 against mu(100), and every increment of
# step 3 against mu(theta(t)) (the coefficient follows the temperature as it changes), each
# |Fx|/|Fz| within 1 %.
for kind in n2f f2f; do
  run "$ours" thermal_user "thermal_user_$kind" "$kind"
  ran "thermal_user_$kind" "temperature-dependent mu ($kind)" || continue
  r=$work/runs/thermal_user_$kind
  totals "$r/thermal_user.dat" >"$r/totals"
  for c in "60|2" "100|3"; do
    theta=${c%|*}
    tend=${c#*|}
    res=$(awk -v th="$theta" -v te="$tend" '
      function abs(x) { return x < 0 ? -x : x }
      abs($1 - te) < 1e-9 { line = $0; r = abs($2) / abs($4); n = abs($4) }
      END { if (line == "") { print "FAIL no increment at total time " te; exit }
        m = 0.3 * exp(-5e-3 * (th - 20)); e = abs(r - m) / m
        printf "%s |Fx|/|Fz| = %.7f against mu(%s) = %.7f (relative difference %.2e, limit 1e-2; N = %.4f)",
          (e <= 0.01 ? "PASS" : "FAIL"), r, th, m, e, n }' "$r/totals")
    report "${res%% *}" "temperature-dependent mu ($kind), steady drag at theta = $theta: ${res#* }"
  done
  res=$(awk '
    function abs(x) { return x < 0 ? -x : x }
    $1 > 2 + 1e-9 && $1 <= 3 + 1e-9 { n++; th = 60 + 40 * ($1 - 2); m = 0.3 * exp(-5e-3 * (th - 20))
      e = abs(abs($2) / abs($4) - m) / m; if (e > worst) { worst = e; at = th } }
    END { printf "%s %d increments, worst relative difference %.2e at theta = %.1f, limit 1e-2",
      (n >= 10 && worst <= 0.01 ? "PASS" : "FAIL"), n, worst, at }' "$r/totals")
  report "${res%% *}" "temperature-dependent mu ($kind) along the ramp 60 -> 100 (step 3): |Fx|/|Fz| against mu(theta(t)) at ${res#* }"
done

# --- rate-and-state friction (law 3): steady sliding at mu_ss(v) -------------------------------
# rate_state_user.inp: deck 1's mesh pressed lightly (the decay deck's steps), dragged 0.1 at
# v = 0.1 (100 L of slip); law 3 with mu0 = 0.6, a = 0.015, b = 0.01, V0 = 0.01, L = 1e-3, aging
# law, regularised form. Steady state: mu_ss = mu0 + (a - b) ln(v/V0); the last increment's
# |Fx|/|Fz| within 1 %, both contact kinds.
for kind in n2f f2f; do
  run "$ours" rate_state_user "rate_state_$kind" "$kind"
  ran "rate_state_$kind" "rate-and-state ($kind)" || continue
  r=$work/runs/rate_state_$kind
  res=$(totals "$r/rate_state_user.dat" | tail -1 | awk '
    function abs(x) { return x < 0 ? -x : x }
    { r = abs($2) / abs($4); m = 0.6 + (0.015 - 0.01) * log(0.1 / 0.01); e = abs(r - m) / m
      printf "%s |Fx|/|Fz| = %.7f against mu_ss(v) = %.7f (relative difference %.2e, limit 1e-2)",
        (e <= 0.01 ? "PASS" : "FAIL"), r, m, e }')
  report "${res%% *}" "rate-and-state law 3 ($kind), steady drag at v = 0.1: ${res#* }"
done

echo "$passed passed, $failed failed (hosts/calculix/more.sh, $(($(date +%s) - t_start)) s)"
if [ "$failed" -ne 0 ]; then
  echo "runs kept in $work/runs"
  exit 1
fi
