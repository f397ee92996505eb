#!/usr/bin/env python3
"""Charts of the CalculiX host (issue 24): runs the decks of hosts/calculix/test.sh with stock ccx
and with ours and draws what they give, as SVG files (Python's standard library only).

    python3 hosts/calculix/charts.py CCX_OURS CCX_STOCK [OUTDIR]   (OUTDIR: docs/charts)

C1-friction-force.svg  deck 1, drag along x: the top's |Fx| against the drag displacement,
                       stock *FRICTION 0.3, 5000 and *FRICTION, USER (law 1, PROPS(7) = 4),
                       with mu*N of the last increment for reference.
C3-decay-newton.svg    the decay deck (mu = mu_k + (mu_s - mu_k) exp(-d_c v), v = 0.1) dragged
                       in 10, 100 and 1000 increments: Newton iterations per increment of the
                       drag step against the increments per drag.
C3-decay-force.svg     the same runs: |Fx|/|Fz| against the drag displacement, with mu(v).

Every number drawn is read from the runs' .dat (reaction totals) and .sta (iterations) files;
the script stops naming the run when a run fails or prints nothing it can read.
"""

import math
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
DECKS = os.path.join(HERE, "decks")
ROOT = os.path.dirname(os.path.dirname(HERE))

FONT = 'font-family="sans-serif"'
COLORS = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd"]


def fail(msg):
    sys.stderr.write("charts.py: " + msg + "\n")
    sys.exit(1)


def run(exe, deck, where, extra=None):
    """Runs DECK.inp with EXE in a fresh copy of the decks under WHERE/DECK-tag; returns that
    directory. EXTRA: {file name: text} written over the copies (deck variants)."""
    d = os.path.join(where, deck + "-" + os.path.basename(os.path.dirname(exe)) + "-" + str(len(os.listdir(where))))
    os.makedirs(d)
    for f in os.listdir(DECKS):
        if f.endswith(".inp"):
            shutil.copy(os.path.join(DECKS, f), d)
    for name, text in (extra or {}).items():
        with open(os.path.join(d, name), "w") as fh:
            fh.write(text)
    env = dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_RESULTS="1", CCX_NPROC_STIFFNESS="1")
    with open(os.path.join(d, "log"), "w") as log:
        st = subprocess.call([exe, deck], cwd=d, stdout=log, stderr=subprocess.STDOUT, env=env)
    if st != 0:
        fail("%s on %s.inp stopped with status %d (log %s/log)" % (exe, deck, st, d))
    return d


def totals(path):
    """The reaction totals of a .dat file: [(total time, fx, fy, fz)]."""
    out = []
    with open(path) as fh:
        lines = fh.read().splitlines()
    for i, line in enumerate(lines):
        if "total force (fx,fy,fz)" in line:
            t = float(line.split()[-1])
            f = [float(v) for v in lines[i + 2].split()]
            out.append((t, f[0], f[1], f[2]))
    if not out:
        fail("%s: no reaction totals" % path)
    return out


def increments(path, step):
    """(increments, Newton iterations) of STEP in a .sta file."""
    n = its = 0
    with open(path) as fh:
        for line in fh.read().splitlines()[2:]:
            p = line.split()
            if len(p) >= 7 and p[0] == str(step):
                n += 1
                its += int(p[3])
    if n == 0:
        fail("%s: no increment of step %d" % (path, step))
    return n, its


def nice_ticks(lo, hi, want=6):
    span = hi - lo
    raw = span / want
    mag = 10 ** math.floor(math.log10(raw))
    step = min((s * mag for s in (1, 2, 2.5, 5, 10) if s * mag >= raw), default=10 * mag)
    first = math.ceil(lo / step - 1e-9) * step
    ticks = []
    v = first
    while v <= hi + 1e-9 * span:
        ticks.append(round(v, 12))
        v += step
    return ticks


def fmt(v):
    if v == 0:
        return "0"
    s = "%g" % v
    return s


class Chart:
    """A single x-y chart: linear axes (or a log x axis), lines, markers, a legend."""

    def __init__(self, title, xlabel, ylabel, xlim, ylim, logx=False, w=860, h=520):
        self.title, self.xlabel, self.ylabel = title, xlabel, ylabel
        self.xlim, self.ylim, self.logx = xlim, ylim, logx
        self.w, self.h = w, h
        self.left, self.right, self.top, self.bottom = 90, 30, 50, 70
        self.items = []
        self.legend = []

    def px(self, x):
        a, b = self.xlim
        if self.logx:
            x, a, b = math.log10(x), math.log10(a), math.log10(b)
        return self.left + (x - a) / (b - a) * (self.w - self.left - self.right)

    def py(self, y):
        a, b = self.ylim
        return self.h - self.bottom - (y - a) / (b - a) * (self.h - self.top - self.bottom)

    def line(self, xs, ys, color, width=2.0, dash=None, label=None):
        pts = " ".join("%.2f,%.2f" % (self.px(x), self.py(y)) for x, y in zip(xs, ys))
        d = ' stroke-dasharray="%s"' % dash if dash else ""
        self.items.append('<polyline fill="none" stroke="%s" stroke-width="%.1f"%s points="%s"/>' % (color, width, d, pts))
        if label:
            self.legend.append(("line", color, width, dash, label))

    def markers(self, xs, ys, color, r=4.5, hollow=True, label=None):
        for x, y in zip(xs, ys):
            fill = "none" if hollow else color
            self.items.append('<circle cx="%.2f" cy="%.2f" r="%.1f" fill="%s" stroke="%s" stroke-width="1.6"/>' % (self.px(x), self.py(y), r, fill, color))
        if label:
            self.legend.append(("marker", color, r, hollow, label))

    def text(self, x, y, s, color="#000000", anchor="start", size=13):
        self.items.append('<text x="%.2f" y="%.2f" text-anchor="%s" %s font-size="%d" fill="%s">%s</text>' % (self.px(x), self.py(y), anchor, FONT, size, color, esc(s)))

    def svg(self, xticks, yticks, legend_at="lower right"):
        out = ['<svg width="%d" height="%d" viewBox="0 0 %d %d" xmlns="http://www.w3.org/2000/svg">' % (self.w, self.h, self.w, self.h),
               '<rect x="0" y="0" width="%d" height="%d" fill="#FFFFFF"/>' % (self.w, self.h)]
        x0, x1 = self.left, self.w - self.right
        y0, y1 = self.h - self.bottom, self.top
        for t in xticks:
            x = self.px(t)
            out.append('<line stroke="#EBEBEB" x1="%.2f" y1="%d" x2="%.2f" y2="%d"/>' % (x, y0, x, y1))
            out.append('<line stroke="#000000" x1="%.2f" y1="%d" x2="%.2f" y2="%d"/>' % (x, y0, x, y0 + 5))
            out.append('<text x="%.2f" y="%d" text-anchor="middle" %s font-size="13">%s</text>' % (x, y0 + 20, FONT, fmt(t)))
        for t in yticks:
            y = self.py(t)
            out.append('<line stroke="#EBEBEB" x1="%d" y1="%.2f" x2="%d" y2="%.2f"/>' % (x0, y, x1, y))
            out.append('<line stroke="#000000" x1="%d" y1="%.2f" x2="%d" y2="%.2f"/>' % (x0 - 5, y, x0, y))
            out.append('<text x="%d" y="%.2f" text-anchor="end" %s font-size="13">%s</text>' % (x0 - 8, y + 4.5, FONT, fmt(t)))
        out.append('<rect x="%d" y="%d" width="%d" height="%d" fill="none" stroke="#000000"/>' % (x0, y1, x1 - x0, y0 - y1))
        out.append('<text x="%d" y="28" %s font-size="16">%s</text>' % (x0, FONT, esc(self.title)))
        out.append('<text x="%.1f" y="%d" text-anchor="middle" %s font-size="14">%s</text>' % ((x0 + x1) / 2, self.h - 22, FONT, esc(self.xlabel)))
        out.append('<text transform="translate(24,%.1f) rotate(-90)" text-anchor="middle" %s font-size="14">%s</text>' % ((y0 + y1) / 2, FONT, esc(self.ylabel)))
        out.append('<g clip-path="none">')
        out.extend(self.items)
        out.append("</g>")
        # legend box
        if self.legend:
            rows = len(self.legend)
            lw = 30 + max(len(e[-1]) for e in self.legend) * 7.4 + 20
            lh = 24 * rows + 10
            if legend_at == "lower right":
                lx, ly = x1 - lw - 12, y0 - lh - 12
            elif legend_at == "upper right":
                lx, ly = x1 - lw - 12, y1 + 12
            else:
                lx, ly = x0 + 12, y1 + 12
            out.append('<rect x="%.1f" y="%.1f" width="%.1f" height="%d" fill="#FFFFFF" fill-opacity="0.9" stroke="#999999"/>' % (lx, ly, lw, lh))
            for i, e in enumerate(self.legend):
                cy = ly + 17 + 24 * i
                if e[0] == "line":
                    d = ' stroke-dasharray="%s"' % e[3] if e[3] else ""
                    out.append('<line stroke="%s" stroke-width="%.1f"%s x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f"/>' % (e[1], e[2], d, lx + 8, cy, lx + 34, cy))
                else:
                    fill = "none" if e[3] else e[1]
                    out.append('<circle cx="%.1f" cy="%.1f" r="%.1f" fill="%s" stroke="%s" stroke-width="1.6"/>' % (lx + 21, cy, e[2], fill, e[1]))
                out.append('<text x="%.1f" y="%.1f" %s font-size="13">%s</text>' % (lx + 42, cy + 4.5, FONT, esc(e[4])))
        out.append("</svg>")
        return "\n".join(out) + "\n"


def esc(s):
    return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def write(path, text):
    with open(path, "w") as fh:
        fh.write(text)
    print("charts.py: wrote " + os.path.relpath(path, ROOT))


def chart_c1(ours, stock, work, outdir):
    """Deck 1, drag along x: |Fx| against the drag displacement (0.05 over step 2, time 1 to 2)."""
    ds = run(stock, "block_x_stock", work)
    du = run(ours, "block_x_user", work)
    series = []
    for d, deck in ((ds, "block_x_stock"), (du, "block_x_user")):
        rows = [r for r in totals(os.path.join(d, deck + ".dat")) if r[0] >= 1 - 1e-9]
        series.append(([0.05 * (r[0] - 1) for r in rows], [abs(r[1]) for r in rows], abs(rows[-1][3])))
    (xs, ys, ns), (xu, yu, nu) = series
    top = max(max(ys), max(yu), 0.3 * nu) * 1.15
    c = Chart("Deck 1: a block pressed, then dragged along x (CalculiX 2.20, node-to-face)",
              "drag displacement of the top", "friction force |Fx| (reaction total of the top)",
              (0, 0.05), (0, top))
    c.line([0, 0.05], [0.3 * nu, 0.3 * nu], "#777777", 1.4, "6,4", "mu*N = 0.3 * |Fz| (last increment)")
    c.markers(xs, ys, COLORS[1], 6.5, True, "stock *FRICTION 0.3, 5000")
    c.line(xu, yu, COLORS[0], 2.0, None, "*FRICTION, USER (law 1, PROPS(7) = 4)")
    c.markers(xu, yu, COLORS[0], 2.2, False)
    c.text(0.0012, top * 0.93, "stick slope 5000, then partial and full slip; 20 increments", "#444444")
    write(os.path.join(outdir, "C1-friction-force.svg"), c.svg(nice_ticks(0, 0.05), nice_ticks(0, top)))
    worst = max(abs(a - b) for a, b in zip(ys, yu)) / max(ys)
    return "C1: %d increments, |Fx| stock and USER differ by at most %.1e of the largest; last |Fx|/|Fz| stock %.6f, USER %.6f" % (
        len(ys), worst, ys[-1] / ns, yu[-1] / nu)


def chart_c3(ours, work, outdir):
    """The decay deck dragged in 10, 100, 1000 increments."""
    with open(os.path.join(DECKS, "block_decay_steps.inp")) as fh:
        steps = fh.read().splitlines()
    # The drag step's increment line: the second "0.01, 1." line, the first one being "0.1, 1."
    # (hosts/calculix/test.sh changes the same line).
    at = [i for i, l in enumerate(steps) if l == "0.01, 1."]
    if len(at) != 1:
        fail("block_decay_steps.inp: expected one drag increment line '0.01, 1.', found %d" % len(at))
    mu_v = 0.2 + 0.3 * math.exp(-10 * 0.1)
    per = []
    press = []
    curves = []
    for n in (10, 100, 1000):
        s = list(steps)
        s[at[0]] = "%g, 1." % (1.0 / n)
        d = run(ours, "block_decay_user", work, {"block_decay_steps.inp": "\n".join(s) + "\n"})
        incs, its = increments(os.path.join(d, "block_decay_user.sta"), 2)
        rows = [r for r in totals(os.path.join(d, "block_decay_user.dat")) if r[0] >= 1 - 1e-9]
        per.append((n, incs, its))
        press.append(abs(rows[-1][3]))
        curves.append((n, [0.1 * (r[0] - 1) for r in rows], [abs(r[1]) / abs(r[3]) for r in rows]))
    ns = [p[0] for p in per]
    ipi = [p[2] / p[1] for p in per]
    top = max(3.0, math.ceil(max(ipi) + 0.5))
    c = Chart("Decay law in CalculiX (*FRICTION, USER): Newton iterations per increment",
              "increments per drag (drag 0.1 in a step of time 1, log scale)",
              "Newton iterations per increment (drag step)", (5, 2000), (0, top), logx=True)
    c.line(ns, ipi, COLORS[0], 2.0, None, "mu = 0.2 + 0.3 exp(-10 v), N = |Fz| = %.4f" % press[-1])
    c.markers(ns, ipi, COLORS[0], 5, False)
    for (n, incs, its), v in zip(per, ipi):
        c.text(n, v + top * 0.04, "%.2f = %d / %d" % (v, its, incs), "#333333", "middle")
    write(os.path.join(outdir, "C3-decay-newton.svg"), c.svg([10, 100, 1000], nice_ticks(0, top, 6), "lower right"))

    # Log drag axis: the step from stick to sliding is in the first 1 % of the drag.
    lo = 0.0
    hi = max(max(y) for _, _, y in curves) * 1.1
    c = Chart("Decay law in CalculiX (*FRICTION, USER): friction ratio during the drag",
              "drag displacement of the top (log scale; drag 0.1 in a step of time 1)",
              "|Fx| / |Fz| of the top", (1e-4, 0.1), (lo, hi), logx=True)
    c.line([1e-4, 0.1], [mu_v, mu_v], "#777777", 1.4, "6,4", "mu(v = 0.1) = %.7f" % mu_v)
    for i, (n, xs, ys) in reversed(list(enumerate(curves))):
        pts = [(x, y) for x, y in zip(xs, ys) if x >= 1e-4 - 1e-12]
        px, py = [p[0] for p in pts], [p[1] for p in pts]
        c.line(px, py, COLORS[i], 2.0)
        if n == 10:
            c.markers(px, py, COLORS[i], 5, True)
    for i, (n, _, _) in enumerate(curves):  # the legend in increasing n
        c.legend.append(("line", COLORS[i], 2.0, None, "%d increments per drag" % n))
    write(os.path.join(outdir, "C3-decay-force.svg"), c.svg([1e-4, 1e-3, 1e-2, 1e-1], nice_ticks(lo, hi), "lower right"))
    return "C3: Newton iterations per increment " + ", ".join(
        "%d increments: %.2f" % (n, v) for n, v in zip(ns, ipi)) + "; last |Fx|/|Fz| " + ", ".join(
        "%.7f" % ys[-1] for _, _, ys in curves) + " against mu(v) = %.7f" % mu_v


def main(argv):
    if len(argv) not in (3, 4):
        sys.stderr.write(__doc__)
        return 2
    ours, stock = os.path.abspath(argv[1]), os.path.abspath(argv[2])
    for e in (ours, stock):
        if not os.access(e, os.X_OK):
            fail("%s is not an executable" % e)
    outdir = os.path.abspath(argv[3]) if len(argv) == 4 else os.path.join(ROOT, "docs", "charts")
    os.makedirs(outdir, exist_ok=True)
    work = tempfile.mkdtemp(prefix="ccx-charts-")
    print(chart_c1(ours, stock, work, outdir))
    print(chart_c3(ours, work, outdir))
    shutil.rmtree(work)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
