#!/usr/bin/env bash
# An SVG chart of deck 1's drag step: the friction force |(Fx, Fy)| of the top against the
# drag distance, stock *FRICTION (line) and *FRICTION, USER (markers), with μ·|Fz| dashed.
#   hosts/calculix/chart.sh STOCK_TOTALS USER_TOTALS DRAG OUT.svg TITLE
# The totals files are test.sh's: "time fx fy fz" per increment; the drag step runs from
# time 1 to 2 and moves the top by DRAG.
set -euo pipefail
[ $# -eq 5 ] || { echo "usage: $0 STOCK_TOTALS USER_TOTALS DRAG OUT.svg TITLE" >&2; exit 2; }
awk -v drag="$3" -v title="$5" '
  function abs(x) { return x < 0 ? -x : x }
  FNR == 1 { file++ }
  $1 + 0 > 1 {
    n[file]++
    x[file, n[file]] = ($1 - 1) * drag
    y[file, n[file]] = sqrt($2 * $2 + $3 * $3)
    if (file == 1) m[n[file]] = 0.3 * abs($4)
    if (y[file, n[file]] > ymax) ymax = y[file, n[file]]
    if (m[n[file]] > ymax) ymax = m[n[file]]
  }
  END {
    W = 640; H = 400; L = 70; R = 20; T = 40; B = 50
    ymax *= 1.1
    sx = (W - L - R) / drag; sy = (H - T - B) / ymax
    printf "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" font-family=\"sans-serif\" font-size=\"12\">\n", W, H
    printf "<rect width=\"%d\" height=\"%d\" fill=\"white\"/>\n", W, H
    printf "<text x=\"%d\" y=\"22\" font-size=\"14\">%s</text>\n", L, title
    printf "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"black\"/>\n", L, H - B, W - R, H - B
    printf "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"black\"/>\n", L, T, L, H - B
    for (k = 0; k <= 5; k++) {
      xv = drag * k / 5; px = L + xv * sx
      printf "<line x1=\"%.1f\" y1=\"%d\" x2=\"%.1f\" y2=\"%d\" stroke=\"black\"/>\n", px, H - B, px, H - B + 5
      printf "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">%.3g</text>\n", px, H - B + 18, xv
      yv = ymax * k / 5; py = H - B - yv * sy
      printf "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"#ccc\"/>\n", L, py, W - R, py
      printf "<text x=\"%d\" y=\"%.1f\" text-anchor=\"end\">%.3g</text>\n", L - 6, py + 4, yv
    }
    printf "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\">drag of the top</text>\n", (L + W - R) / 2, H - 12
    printf "<text x=\"16\" y=\"%d\" transform=\"rotate(-90 16 %d)\" text-anchor=\"middle\">friction force |(Fx, Fy)|</text>\n", (T + H - B) / 2, (T + H - B) / 2
    printf "<polyline fill=\"none\" stroke=\"#888\" stroke-dasharray=\"5,4\" points=\""
    for (i = 1; i <= n[1]; i++) printf "%.1f,%.1f ", L + x[1, i] * sx, H - B - m[i] * sy
    printf "\"/>\n"
    printf "<polyline fill=\"none\" stroke=\"#1f77b4\" stroke-width=\"2\" points=\"%.1f,%.1f ", L, H - B
    for (i = 1; i <= n[1]; i++) printf "%.1f,%.1f ", L + x[1, i] * sx, H - B - y[1, i] * sy
    printf "\"/>\n"
    for (i = 1; i <= n[2]; i++)
      printf "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"4\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"1.5\"/>\n", L + x[2, i] * sx, H - B - y[2, i] * sy
    lx = W - R - 300; ly = H - B - 70
    printf "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"#1f77b4\" stroke-width=\"2\"/><text x=\"%d\" y=\"%d\">stock *FRICTION 0.3, 5000</text>\n", lx, ly, lx + 25, ly, lx + 32, ly + 4
    ly += 20
    printf "<circle cx=\"%d\" cy=\"%d\" r=\"4\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"1.5\"/><text x=\"%d\" y=\"%d\">*FRICTION, USER (law 1, PROPS(7) = 4)</text>\n", lx + 12, ly, lx + 32, ly + 4
    ly += 20
    printf "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"#888\" stroke-dasharray=\"5,4\"/><text x=\"%d\" y=\"%d\">0.3 |Fz| (stock)</text>\n", lx, ly, lx + 25, ly, lx + 32, ly + 4
    printf "</svg>\n"
  }' "$1" "$2" >"$4"
