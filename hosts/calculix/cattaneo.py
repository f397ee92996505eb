#!/usr/bin/env python3
"""Deck 2 of the CalculiX host: Cattaneo-Mindlin partial slip of a cylinder on a flat.

    cattaneo.py gen DIR          writes the decks into DIR
    cattaneo.py check DIR        reads DIR/cylinder_{user,stock}.dat, prints one
                                 PASS/FAIL line per check, exit 1 on a failure
    cattaneo.py chart DIR SVG    c/a against Q/(mu P), USER and stock, with the closed form

Python 3 standard library only. The geometry, the loads and the closed forms live here once;
hosts/calculix/cattaneo.sh runs the decks and calls this script.

The model (plane strain, a slice one element thick with every node's z fixed):
  - the flat: a block |x| <= L, -L <= y <= 0;
  - the cylinder: the part |x| <= L of a cylinder of radius R whose lowest line touches the
    flat at x = 0, cut flat at y = L (bottom y = R - sqrt(R^2 - x^2), top y = L): near the
    contact, where the closed forms look, it is a cylinder of radius R; L = 12 a keeps both
    bodies large against the contact (the half-space assumption of Hertz and Cattaneo);
  - the same material both sides (E, nu), so the normal and tangential problems decouple
    (Dundurs' beta = 0), which is what Cattaneo-Mindlin's closed form assumes;
  - the top of the cylinder is tied to one node (*EQUATION in x and y): it translates as a
    rigid face without turning, and the loads on that node are the totals P and Q exactly.
  - mesh: a structured grid of C3D8, squares of side h = a/H_PER_A in |x| <= 1.25 a next to the
    contact (both bodies share the same x columns there), growing by a factor GROW per
    element outwards and away from the contact line.
  - node-to-face penalty contact (slave: the cylinder, master: the flat), linear
    pressure-overclosure, *FRICTION mu, lambda (stock) or *FRICTION, USER law 1 with
    PROPS(7) = 4, PROPS(5) = lambda (ours).
Steps: (1) top pushed down by a small displacement (contact found under displacement control;
x held), (2) the top's y load ramped to P (load control, x held, automatic increments of at
most 0.05 P), (3, 4, ...) x freed and the tangential load raised to Q/(mu P) = Q_FRACTIONS in
turn, 4 increments each, monotonically (Cattaneo's solution for a monotonic Q depends only on
the current Q). Residual and correction tolerances tightened to 1e-9 (*CONTROLS), as in deck 1,
so that stock and USER agree to the printed digits.

What check measures, from *CONTACT PRINT's CSTR (per slave node: pressure p, shears; the front
and back nodes of each x averaged) at the end of each step:
  - a: on each side the zero of p^2 extrapolated linearly from the two outermost nodes with
    p > 0 (p^2 is linear in x at Hertz's edge);
  - c: the stick nodes are those with |q| < mu p (1 - MARGIN); on each side the edge half-way
    between the outermost stick node and its slipping neighbour (to within h/2 = a/64);
  - the shear in |x| < c against the closed form, as the RMS of the error over mu p0: of the
    shear's change since the end of the normal load (the closed form has no shear under the
    normal load alone; the mesh leaves some, printed as INFO), and of the shear itself;
  - the flat's support reactions (*NODE PRINT RF totals) against the applied -Q and P;
  - USER against stock: the same c/a and contact stresses within TOL_SAME p0.
"""

import math
import os
import sys

# --- the problem --------------------------------------------------------------------------------
E = 1000.0  # Young's modulus, both bodies
NU = 0.3  # Poisson's ratio, both bodies
R = 1.0  # cylinder radius
P = 1.0  # normal load per unit length
MU = 0.3  # friction coefficient
Q_FRACTIONS = (0.2, 0.35, 0.5, 0.65, 0.8, 0.9)  # Q/(mu P) of steps 3, 4, ...

# Closed forms (plane strain, two equal elastic bodies):
#   E* = E / (2 (1 - nu^2))                the contact modulus of the pair
#   a  = sqrt(4 P R / (pi E*)) = sqrt(8 P R (1 - nu^2) / (pi E))     Hertz half-width
#   p0 = 2 P / (pi a)                       peak pressure, p(x) = p0 sqrt(1 - x^2/a^2)
#   c  = a sqrt(1 - Q/(mu P))               Cattaneo-Mindlin stick half-width
#   q(x) = mu p0 [sqrt(1 - x^2/a^2) - (c/a) sqrt(1 - x^2/c^2)]   shear in the stick zone |x| < c
E_STAR = E / (2.0 * (1.0 - NU * NU))
A_HERTZ = math.sqrt(4.0 * P * R / (math.pi * E_STAR))
P0 = 2.0 * P / (math.pi * A_HERTZ)

# --- the mesh -----------------------------------------------------------------------------------
H_PER_A = 32  # elements per contact half-width in the refined zone
H = A_HERTZ / H_PER_A  # element size in the contact zone (and the slice's thickness)
X_FINE = 1.25 * A_HERTZ  # half-width of the refined zone
L = 12.0 * A_HERTZ  # half-width of both bodies, depth of the flat, height of the cylinder
GROW = 1.2  # size ratio of neighbouring elements outside the refined zone

# --- contact ------------------------------------------------------------------------------------
# Penalty slope (stress per length): the penetration at p0, P0/K_PEN = 1.3e-5, is 1.1 % of the
# gap a^2/(2R) at the contact's edge; about 1.5 E/h (stiffer slopes, 1e7, made the normal
# load's Newton iterations chatter between contact states and fail).
K_PEN = 1.0e6
# CalculiX's tension at large clearances: its linear law is smoothed over a clearance
# pi SIGMA_INF / K_PEN = 4e-8, 0.3 % of the penetration at p0.
SIGMA_INF = 1.0e-3 * P0
# Stick slope (stress per length; stock's second *FRICTION value, PROPS(5) of ours): the elastic
# slip it allows at mu p0, 4e-6, is a few % of Cattaneo's slip scale mu p0 a / E* = 3.5e-4.
LAMBDA = 1.0e6
DELTA0_NODES = 3  # step 1 pushes the top until about this many nodes each side touch

# --- checks: tolerances -------------------------------------------------------------------------
TOL_A = 0.03  # |a_measured - a_Hertz| / a
TOL_C = 0.03  # |c_measured - c_closed| / a
# RMS over the stick zone |x| < c of (q - q_closed) / (mu p0): q the shear's change since the end
# of the normal load (TOL_Q_NORM), and the shear itself (TOL_Q_RAW). The closed form has no shear
# under the normal load alone (equal materials); the mesh leaves some, locked in at the nodes as
# they come into contact (printed: RMS about 0.045 mu p0, up to 0.13 at single nodes near the edge).
TOL_Q_NORM = 0.05
TOL_Q_RAW = 0.08
MARGIN = 1.0e-3  # stick: |q| < mu p (1 - MARGIN)
# USER against stock, largest contact-stress difference / p0 at the end of each step. The two
# take the same Newton path (same increments and iterations) but differ by 3.4e-5 p0 after the
# normal load (the shear locked in at one node, 100045, as it comes into contact in increment 9
# of step 2: cause not found) and by up to 2.2e-4 p0 at Q = 0.9 mu P, unlike deck 1's flat blocks
# (4e-8). That growth is stock's: its stick force is the stick slope times the accumulated
# relative displacement as a 3-D vector, whose earlier parts leave the tangent plane as the
# surface under the cylinder turns, so stock's friction force gets a normal part (and the
# pressures follow); FRIC's TAU lies in today's tangent plane. A build of ours that adds stock's
# normal part (an experiment, not kept) brought the end-of-step differences down to 3.4e-5 to
# 6.5e-5 p0 (1.3e-5 at Q = 0.9 mu P). The limit is about twice the measured 2.2e-4.
TOL_SAME = 5.0e-4


def graded(first, total, grow):
    """Lengths starting at `first`, each `grow` times the last, the last one stretched or
    merged so that they add up to `total` exactly."""
    out = []
    size = first
    s = 0.0
    while s + size < total - 1e-12 * total:
        out.append(size)
        s += size
        size *= grow
    rest = total - s
    if out and rest < 0.5 * out[-1]:
        out[-1] += rest
    else:
        out.append(rest)
    return out


def columns(shift):
    """The x positions of the node columns, symmetric about x = 0: in the refined zone every
    h from x = shift (0 or h/2), then growing to L."""
    n_fine = int(round(X_FINE / H))
    fine = [shift + i * H for i in range(n_fine + 1)]
    outer = []
    x = fine[-1]
    for d in graded(H * GROW, L - fine[-1], GROW):
        x += d
        outer.append(x)
    outer[-1] = L
    half = fine + outer
    if shift == 0.0:
        return [-v for v in reversed(half[1:])] + half
    return [-v for v in reversed(half)] + half


def rows():
    """Fractions 0 .. 1 of the height from the contact line outwards (first layer h)."""
    fr = [0.0]
    s = 0.0
    for d in graded(H, L, GROW):
        s += d
        fr.append(s / L)
    fr[-1] = 1.0
    return fr


def y_arc(x):
    return R - math.sqrt(R * R - x * x)


class Mesh:
    def __init__(self):
        # the flat's columns are shifted by h/2 against the cylinder's in the refined zone, so
        # that no slave node projects onto a master node or face edge
        self.xs = [columns(0.5 * H), columns(0.0)]
        self.fr = rows()
        self.nxs = [len(c) - 1 for c in self.xs]
        self.ny = len(self.fr) - 1
        self.ix0 = self.nxs[1] // 2  # the cylinder's column at x = 0

    # node numbers: body 0 the flat, 1 the cylinder; j counted from the contact line outwards
    def node(self, body, i, j, k):
        return 1 + body * 100000 + i + (self.nxs[body] + 1) * (j + (self.ny + 1) * k)

    def coords(self, body, i, j, k):
        x = self.xs[body][i]
        if body == 0:
            y = -L * self.fr[j]
        else:
            yb = y_arc(x)
            y = yb + self.fr[j] * (L - yb)
        return x, y, k * H

    def element(self, body, i, j):
        return 1 + body * 100000 + i + self.nxs[body] * j

    def element_nodes(self, body, i, j):
        # C3D8: 1-4 on z = 0 counter-clockwise seen from +z, 5-8 the same on z = h.
        # lo/hi: the row below/above in y.
        lo, hi = (j + 1, j) if body == 0 else (j, j + 1)
        n = []
        for k in (0, 1):
            n += [
                self.node(body, i, lo, k),
                self.node(body, i + 1, lo, k),
                self.node(body, i + 1, hi, k),
                self.node(body, i, hi, k),
            ]
        return n

    def in_contact_zone(self, body, i):
        # an element between columns i and i+1 whose both ends are in the refined zone
        xs = self.xs[body]
        lim = X_FINE + 0.5 * H + 1e-12
        return abs(xs[i]) <= lim and abs(xs[i + 1]) <= lim

    def ref_node(self):
        return self.node(1, self.ix0, self.ny, 0)

    def slave_nodes(self):
        """(x, node) of the cylinder's contact-line nodes on z = 0 in the slave surface."""
        out = []
        for i, x in enumerate(self.xs[1]):
            if abs(x) <= X_FINE + 1e-12:
                out.append((x, self.node(1, i, 0, 0)))
                out.append((x, self.node(1, i, 0, 1)))
        return out


def lines8(values):
    vals = [str(v) for v in values]
    return "\n".join(", ".join(vals[i : i + 8]) for i in range(0, len(vals), 8))


def write_mesh(m, path):
    out = ["** Deck 2's mesh, written by hosts/calculix/cattaneo.py (do not edit)"]
    out.append("*NODE, NSET=NALL")
    for body in (0, 1):
        for k in (0, 1):
            for j in range(m.ny + 1):
                for i in range(m.nxs[body] + 1):
                    x, y, z = m.coords(body, i, j, k)
                    out.append("%d, %.12g, %.12g, %.12g" % (m.node(body, i, j, k), x, y, z))
    for body, name in ((0, "EFLAT"), (1, "ECYL")):
        out.append("*ELEMENT, TYPE=C3D8, ELSET=%s" % name)
        for j in range(m.ny):
            for i in range(m.nxs[body]):
                n = m.element_nodes(body, i, j)
                out.append("%d, %s" % (m.element(body, i, j), ", ".join(map(str, n))))
    out.append("*NSET, NSET=NBOTTOM")
    out.append(lines8([m.node(0, i, m.ny, k) for k in (0, 1) for i in range(m.nxs[0] + 1)]))
    ref = m.ref_node()
    out.append("*NSET, NSET=NREF")
    out.append(str(ref))
    # the top of the cylinder tied to the reference node in x and y
    out.append("*EQUATION")
    for k in (0, 1):
        for i in range(m.nxs[1] + 1):
            n = m.node(1, i, m.ny, k)
            if n == ref:
                continue
            for dof in (1, 2):
                out.append("2")
                out.append("%d, %d, 1., %d, %d, -1." % (n, dof, ref, dof))
    # master: the flat's top faces (S5: nodes 3-7-8-4, the row above) in the refined zone;
    # slave: the cylinder's bottom faces (S3: nodes 1-2-6-5, the row below) there.
    out.append("*SURFACE, NAME=SMASTER")
    for i in range(m.nxs[0]):
        if m.in_contact_zone(0, i):
            out.append("%d, S5" % m.element(0, i, 0))
    out.append("*SURFACE, NAME=SSLAVE")
    for i in range(m.nxs[1]):
        if m.in_contact_zone(1, i):
            out.append("%d, S3" % m.element(1, i, 0))
    out.append("*NSET, NSET=NSLAVE")
    out.append(lines8([n for _, n in m.slave_nodes()]))
    out.append("*MATERIAL, NAME=STEEL")
    out.append("*ELASTIC")
    out.append("%r, %r" % (E, NU))
    out.append("*SOLID SECTION, ELSET=EFLAT, MATERIAL=STEEL")
    out.append("*SOLID SECTION, ELSET=ECYL, MATERIAL=STEEL")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def write_steps(m, path):
    t = H  # slice thickness: the loads per unit length times t
    delta0 = (DELTA0_NODES * H) ** 2 / (2 * R)
    fix = ["*BOUNDARY", "NBOTTOM, 1, 2", "NALL, 3, 3"]
    ctrl = ["*CONTROLS, PARAMETERS=FIELD, FIELD=DISPLACEMENT", "1.e-9, 1.e-9"]
    out = [
        "** Deck 2's steps, written by hosts/calculix/cattaneo.py (do not edit).",
        "** Loads per unit length P = %r, Q = (%s) mu P, mu = %r; slice thickness %.12g"
        % (P, ", ".join("%r" % q for q in Q_FRACTIONS), MU, t),
        "** Step 1: contact found under displacement control (top down %.6g, x held)." % delta0,
        "*STEP, INC=1000",
        "*STATIC, DIRECT",
        "0.5, 1.",
    ]
    out += fix
    out += ["NREF, 1, 1", "NREF, 2, 2, %.12g" % -delta0]
    out += ["*END STEP"]

    def loaded(comment, static, held, loads):
        """A step loading the reference node: the field controls, the procedure (its line and
        increments), the bottom and the slice held (and `held`, the reference node's), the
        *CLOAD lines, the bottom's reaction totals and the contact stresses printed."""
        return (
            [comment, "*STEP, INC=1000"] + ctrl + static + ["*BOUNDARY, OP=NEW"] + fix[1:] + held
            + ["*CLOAD"] + loads
            + ["*NODE PRINT, NSET=NBOTTOM, TOTALS=ONLY", "RF", "*CONTACT PRINT", "CSTR", "*END STEP"]
        )

    out += loaded(
        "** Step 2: the normal load P on the reference node (the top's total), x still held.",
        ["*STATIC", "0.02, 1., 1e-4, 0.05"],
        ["NREF, 1, 1"],
        ["NREF, 2, %.12g" % (-P * t)],
    )
    for q in Q_FRACTIONS:
        out += loaded(
            "** The tangential load Q = %r mu P on the reference node, x free." % q,
            ["*STATIC, DIRECT", "0.25, 1."],
            [],
            ["NREF, 1, %.12g" % (q * MU * P * t), "NREF, 2, %.12g" % (-P * t)],
        )
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def write_decks(d):
    os.makedirs(d, exist_ok=True)
    m = Mesh()
    write_mesh(m, os.path.join(d, "cylinder_mesh.inp"))
    write_steps(m, os.path.join(d, "cylinder_steps.inp"))
    head = "*SURFACE INTERACTION, NAME=SI\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n"
    head += "%.12g, %.12g\n" % (K_PEN, SIGMA_INF)
    pair = "*CONTACT PAIR, INTERACTION=SI, TYPE=NODE TO SURFACE\nSSLAVE, SMASTER\n"
    with open(os.path.join(d, "cylinder_stock.inp"), "w") as f:
        f.write("*HEADING\nDeck 2 (Cattaneo-Mindlin), stock *FRICTION mu, lambda\n")
        f.write("*INCLUDE, INPUT=cylinder_mesh.inp\n" + head)
        f.write("*FRICTION\n%r, %.12g\n" % (MU, LAMBDA))
        f.write(pair + "*INCLUDE, INPUT=cylinder_steps.inp\n")
    with open(os.path.join(d, "cylinder_user.inp"), "w") as f:
        f.write("*HEADING\nDeck 2 (Cattaneo-Mindlin), *FRICTION, USER: law 1, ")
        f.write("constant stick stiffness (PROPS(7) = 4, PROPS(5) = lambda)\n")
        f.write("*INCLUDE, INPUT=cylinder_mesh.inp\n" + head)
        f.write("*FRICTION, USER, PROPERTIES=7, DEPVAR=3\n")
        f.write("1., %r, 0., 0., %.12g, 0., 4.\n" % (MU, LAMBDA))
        f.write(pair + "*INCLUDE, INPUT=cylinder_steps.inp\n")
    print(
        "gen: a = %.6g, p0 = %.6g, h = %.6g (a/h = %d), %d x %d elements per body, %d nodes"
        % (A_HERTZ, P0, H, H_PER_A, m.nxs[1], m.ny, 2 * (sum(m.nxs) + 2) * (m.ny + 1))
    )


# --- reading CalculiX's .dat ---------------------------------------------------------------------
def read_dat(path):
    """{time: (fx, fy, fz)} of the NBOTTOM totals and {time: {node: (p, t1, t2)}} of the
    contact stresses, one entry per printed increment."""
    totals = {}
    cstr = {}
    with open(path) as f:
        lines = f.read().splitlines()
    i = 0
    while i < len(lines):
        line = lines[i]
        if "total force (fx,fy,fz) for set NBOTTOM" in line:
            t = float(line.split()[-1])
            i += 1
            while i < len(lines) and not lines[i].strip():
                i += 1
            totals[t] = tuple(float(v) for v in lines[i].split()[:3])
        elif line.strip().startswith("contact stress (slave node"):
            t = float(line.split()[-1])
            block = {}
            i += 1
            while i < len(lines) and not lines[i].strip():
                i += 1
            while i < len(lines) and lines[i].strip():
                v = lines[i].split()
                if len(v) != 4:
                    break
                block[int(v[0])] = (float(v[1]), float(v[2]), float(v[3]))
                i += 1
            cstr[t] = block
            continue
        i += 1
    return totals, cstr


def at_time(table, t):
    for k, v in table.items():
        if abs(k - t) < 1e-6:
            return v
    return None


def profile(m, block):
    """[(x, p, q)] along the contact line, the front (z = 0) and back (z = h) nodes of each x
    averaged; q the shear along t1 (CalculiX's first tangent, global x on the flat)."""
    front = {}
    for i, x in enumerate(m.xs[1]):
        if abs(x) <= X_FINE + 1e-12:
            front[x] = (m.node(1, i, 0, 0), m.node(1, i, 0, 1))
    out = []
    for x in sorted(front):
        a, b = front[x]
        if a in block and b in block:
            p = 0.5 * (block[a][0] + block[b][0])
            q = 0.5 * (block[a][1] + block[b][1])
            out.append((x, p, q))
    return out


def edge(x1, f1, x2, f2):
    """The zero of the line through (x1, f1), (x2, f2) (f2 != f1)."""
    return x1 - f1 * (x2 - x1) / (f2 - f1)


def half_width(prof, inside, value=None):
    """Half-width of the zone of the nodes for which inside(x, p, q) holds, from its outermost
    nodes on each side: with value, the zero of value(x, p, q) extrapolated linearly from the
    zone's two outermost nodes (value vanishing linearly at the edge, e.g. p^2 at Hertz's
    square-root edge); without, half-way between the outermost node inside and its neighbour
    outside (within h/2). Returns (half-width, centre, nodes in the zone) or None."""
    idx = [k for k, r in enumerate(prof) if inside(*r)]
    if len(idx) < 4 or (value is None and (idx[0] == 0 or idx[-1] == len(prof) - 1)):
        return None
    z = [prof[k] for k in idx]
    if value is not None:
        lo = edge(z[0][0], value(*z[0]), z[1][0], value(*z[1]))
        hi = edge(z[-1][0], value(*z[-1]), z[-2][0], value(*z[-2]))
    else:
        lo = 0.5 * (prof[idx[0]][0] + prof[idx[0] - 1][0])
        hi = 0.5 * (prof[idx[-1]][0] + prof[idx[-1] + 1][0])
    return 0.5 * (hi - lo), 0.5 * (hi + lo), len(idx), idx[-1] - idx[0] + 1


def measure(m, block, qfrac, base):
    """{a, c: (half-width, centre, nodes) or None; rms, max: the error of the shear change
    since the end of the normal loading in the stick zone |x| < c (closed-form c) against the
    closed form, / (mu p0); raw_rms: the same for the shear itself} of one contact print.
    base: {x: q} at the end of the normal loading."""
    prof = profile(m, block)
    sign = 1.0 if sum(r[2] for r in prof) >= 0 else -1.0
    prof = [(x, p, sign * q) for x, p, q in prof]
    a = half_width(prof, lambda x, p, q: p > 0, lambda x, p, q: p * p)
    res = {"a": a, "c": None, "rms": None, "max": None, "raw_rms": None, "n": 0}
    if qfrac is None:
        return res
    mu_p = lambda p: MU * max(p, 0.0)
    stick = lambda x, p, q: p > 0 and abs(q) < mu_p(p) * (1 - MARGIN)
    # the stick zone's edge half-way between its outermost stick node and the first slip node
    # (1 - |q|/(mu p) vanishes like sqrt(c - |x|) there, but the nodes' scatter makes an
    # extrapolation from two stick nodes less sure than the bracket)
    res["c"] = half_width(prof, stick)
    c = A_HERTZ * math.sqrt(1 - qfrac)
    errs = []
    raw = []
    for x, p, q in prof:
        if abs(x) < c and x in base:
            qth = MU * P0 * (math.sqrt(1 - x * x / A_HERTZ**2) - (c / A_HERTZ) * math.sqrt(1 - x * x / (c * c)))
            errs.append((q - sign * base[x] - qth) / (MU * P0))
            raw.append((q - qth) / (MU * P0))
    if errs:
        res["rms"] = math.sqrt(sum(e * e for e in errs) / len(errs))
        res["max"] = max(abs(e) for e in errs)
        res["raw_rms"] = math.sqrt(sum(e * e for e in raw) / len(raw))
        res["n"] = len(errs)
    return res


def check(d):
    m = Mesh()
    t = H
    runs = {}
    for kind in ("user", "stock"):
        path = os.path.join(d, "cylinder_%s.dat" % kind)
        if not os.path.exists(path):
            print("FAIL deck 2: %s is missing (the run failed?)" % path)
            return 1
        runs[kind] = read_dat(path)
    failed = 0

    def report(ok, text):
        nonlocal failed
        if not ok:
            failed += 1
        print("%s deck 2 (Cattaneo-Mindlin): %s" % ("PASS" if ok else "FAIL", text))

    print(
        "INFO deck 2: plane strain, E = %g, nu = %g both bodies, R = %g, P = %g per length, mu = %g;"
        " E* = E/(2(1-nu^2)) = %.6g, a = sqrt(4PR/(pi E*)) = %.6g, p0 = 2P/(pi a) = %.6g;"
        " element size in the contact zone h = a/%d = %.4g"
        % (E, NU, R, P, MU, E_STAR, A_HERTZ, P0, H_PER_A, H)
    )
    cas = {"user": [], "stock": []}
    base = {}
    # step 2 ends at total time 2 (normal load only), step 2 + k at 2 + k (Q_FRACTIONS[k-1])
    for step, qfrac in [(2, None)] + [(3 + k, q) for k, q in enumerate(Q_FRACTIONS)]:
        got = {}
        for kind in ("user", "stock"):
            totals, cstr = runs[kind]
            tot = at_time(totals, float(step))
            block = at_time(cstr, float(step))
            if tot is None or block is None:
                report(False, "%s: no output at the end of step %d" % (kind, step))
                got[kind] = None
                continue
            if qfrac is None:
                base[kind] = {x: q for x, _, q in profile(m, block)}
            got[kind] = (tot, block, measure(m, block, qfrac, base.get(kind, {})))
        if got["user"] is None or got["stock"] is None:
            continue
        tot, block, r = got["user"]
        qf = 0.0 if qfrac is None else qfrac
        what = "Q = 0" if qfrac is None else "Q/(mu P) = %g" % qfrac
        # totals: the flat's support reactions against the applied loads, printed precision
        qa, pa = qf * MU * P * t, P * t
        for kind in ("user", "stock"):
            fx, fy, _ = got[kind][0]
            # E13.6 prints 7 significant digits: the rounding is at most 5e-7 of the value
            # (x held in step 2: Fx is then the small reaction of that hold, not checked)
            ok = abs(fy - pa) <= 5e-7 * pa
            if qa:
                ok = ok and abs(-fx - qa) <= 5e-7 * qa
            report(
                ok,
                "%s, %s: support reactions (Fx, Fy) = (%.6e, %.6e) against the applied (-Q, P)"
                " = (%.6e, %.6e) per slice (printed precision: within 5e-7 relative)"
                % (what, kind, fx, fy, -qa, pa),
            )
        if r["a"] is None:
            report(False, "%s: fewer than 4 nodes in contact" % what)
            continue
        am, centre, n, _ = r["a"]
        if qfrac is None:
            err = abs(am - A_HERTZ) / A_HERTZ
            report(
                err <= TOL_A,
                "Hertz half-width, USER: a = %.6g against sqrt(8PR(1-nu^2)/(pi E)) = %.6g"
                " (%+.2f %%, limit %g %%; %d nodes in contact, h = a/%d; centre %+.3f h)"
                % (am, A_HERTZ, 100 * (am - A_HERTZ) / A_HERTZ, 100 * TOL_A, n, H_PER_A, centre / H),
            )
            res0 = [q / (MU * P0) for x, p, q in profile(m, block) if abs(x) < A_HERTZ]
            rms0 = math.sqrt(sum(v * v for v in res0) / len(res0))
            print(
                "INFO deck 2: shear left by the normal load (closed form: 0), USER: RMS / (mu p0)"
                " = %.4f, max %.4f over %d nodes |x| < a" % (rms0, max(map(abs, res0)), len(res0))
            )
            sa = got["stock"][2]["a"]
            if sa is not None:
                print("INFO deck 2: Hertz half-width, stock: a = %.6g (%+.2f %%)" % (sa[0], 100 * (sa[0] - A_HERTZ) / A_HERTZ))
            continue
        cth = A_HERTZ * math.sqrt(1 - qfrac)
        for kind in ("user", "stock"):
            rr = got[kind][2]
            if rr["c"] is None:
                report(False, "%s, %s: fewer than 4 nodes in stick" % (what, kind))
                cas[kind].append((qfrac, None))
                continue
            cm, cc, nn, span = rr["c"]
            cas[kind].append((qfrac, cm / A_HERTZ))
            err = abs(cm - cth) / A_HERTZ
            report(
                err <= TOL_C,
                "%s, %s: stick half-width c/a = %.4f against sqrt(1 - Q/(mu P)) = %.4f"
                " (difference %.2f %% of a, limit %g %%; %d stick nodes of %d between the outermost,"
                " centre %+.2f h)" % (what, kind, cm / A_HERTZ, cth / A_HERTZ, 100 * err, 100 * TOL_C, nn, span, cc / H),
            )
            report(
                rr["rms"] is not None and rr["rms"] <= TOL_Q_NORM and rr["raw_rms"] <= TOL_Q_RAW,
                "%s, %s: shear in the stick zone (its change since the end of the normal load)"
                " against mu p0 [sqrt(1 - x^2/a^2) - (c/a) sqrt(1 - x^2/c^2)]: RMS error / (mu p0)"
                " = %.4f (limit %g), max %.4f, over %d nodes |x| < c; the shear itself: RMS %.4f (limit %g)"
                % (what, kind, rr["rms"] or float("nan"), TOL_Q_NORM, rr["max"] or float("nan"),
                   rr["n"], rr["raw_rms"] or float("nan"), TOL_Q_RAW),
            )
        # USER against stock: the same law, so the same stick zone to the 4 printed digits of
        # c/a, and the same contact stresses within TOL_SAME p0 (a wrong mu or stick slope
        # moves them by a good fraction of mu p0)
        bu, bs = got["user"][1], got["stock"][1]
        diff = max((abs(bu[k][i] - bs[k][i]) for k in bu if k in bs for i in range(3)), default=None)
        same = set(bu) == set(bs)
        cu, cs = cas["user"][-1][1], cas["stock"][-1][1]
        ok = same and diff is not None and diff <= TOL_SAME * P0 and cu is not None and cs is not None
        ok = ok and "%.4f" % cu == "%.4f" % cs
        report(
            ok,
            "%s: USER c/a = %s beside stock c/a = %s (equal to 4 digits required); contact stresses"
            " USER vs stock: largest difference %.2e = %.1e p0 (limit %g p0), same contact nodes: %s"
            % (what, "%.4f" % cu if cu is not None else "-", "%.4f" % cs if cs is not None else "-",
               diff if diff is not None else float("nan"), (diff or 0.0) / P0, TOL_SAME,
               "yes" if same else "no"),
        )
    with open(os.path.join(d, "c_over_a.tsv"), "w") as f:
        f.write("q_over_mu_p\tuser\tstock\tclosed_form\n")
        for (q, cu), (_, cs) in zip(cas["user"], cas["stock"]):
            fmt = lambda v: "None" if v is None else "%.6f" % v
            f.write("%g\t%s\t%s\t%.6f\n" % (q, fmt(cu), fmt(cs), math.sqrt(1 - q)))
    return 1 if failed else 0


def chart(d, svg):
    """c/a against Q/(mu P): USER and stock from DIR/c_over_a.tsv (written by check), the
    closed form sqrt(1 - Q/(mu P)) as a line. Hand-written SVG."""
    rows_ = []
    with open(os.path.join(d, "c_over_a.tsv")) as f:
        next(f)
        for line in f:
            q, cu, cs, _ = line.rstrip("\n").split("\t")
            rows_.append((float(q), None if cu == "None" else float(cu), None if cs == "None" else float(cs)))
    w, h_, ml, mr, mt, mb = 600, 450, 70, 25, 58, 60
    pw, ph = w - ml - mr, h_ - mt - mb
    X = lambda v: ml + v * pw
    Y = lambda v: mt + (1 - v) * ph
    o = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" viewBox="0 0 %d %d"'
         ' font-family="sans-serif" font-size="13">' % (w, h_, w, h_)]
    o.append('<rect width="100%" height="100%" fill="white"/>')
    o.append('<text x="%d" y="22" text-anchor="middle" font-size="15">Cattaneo\u2013Mindlin stick zone:'
             ' cylinder on a flat in CalculiX</text>' % (w / 2))
    o.append('<text x="%d" y="42" text-anchor="middle" font-size="12">plane strain, same material both'
             ' sides, node-to-face penalty contact, \u03bc = %g, element size a/%d</text>' % (w / 2, MU, H_PER_A))
    for k in range(6):
        v = k / 5
        o.append('<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="#ddd"/>' % (X(v), Y(0), X(v), Y(1)))
        o.append('<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="#ddd"/>' % (X(0), Y(v), X(1), Y(v)))
        o.append('<text x="%.1f" y="%.1f" text-anchor="middle">%.1f</text>' % (X(v), Y(0) + 18, v))
        o.append('<text x="%.1f" y="%.1f" text-anchor="end">%.1f</text>' % (X(0) - 6, Y(v) + 4, v))
    o.append('<rect x="%d" y="%d" width="%d" height="%d" fill="none" stroke="black"/>' % (ml, mt, pw, ph))
    o.append('<text x="%.1f" y="%d" text-anchor="middle">Q / (\u03bc P)</text>' % (X(0.5), h_ - 15))
    o.append('<text transform="translate(20 %.1f) rotate(-90)" text-anchor="middle">c / a</text>' % Y(0.5))
    pts = " ".join("%.1f,%.1f" % (X(i / 200), Y(math.sqrt(1 - i / 200))) for i in range(201))
    o.append('<polyline points="%s" fill="none" stroke="black" stroke-width="1.5"/>' % pts)
    for q, cu, cs in rows_:
        if cs is not None:
            x, y = X(q), Y(cs)
            o.append('<path d="M%.1f %.1fl12 12m0 -12l-12 12" stroke="#d62728" stroke-width="2"/>' % (x - 6, y - 6))
        if cu is not None:
            o.append('<circle cx="%.1f" cy="%.1f" r="5" fill="none" stroke="#1f77b4" stroke-width="2"/>' % (X(q), Y(cu)))
    lx, ly = X(0.05), Y(0.25)
    o.append('<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="black" stroke-width="1.5"/>' % (lx, ly, lx + 24, ly))
    o.append('<text x="%.1f" y="%.1f">closed form \u221a(1 \u2212 Q/(\u03bc P))</text>' % (lx + 32, ly + 4))
    o.append('<circle cx="%.1f" cy="%.1f" r="5" fill="none" stroke="#1f77b4" stroke-width="2"/>' % (lx + 12, ly + 22))
    o.append('<text x="%.1f" y="%.1f">*FRICTION, USER (law 1, this library)</text>' % (lx + 32, ly + 26))
    o.append('<path d="M%.1f %.1fl12 12m0 -12l-12 12" stroke="#d62728" stroke-width="2"/>' % (lx + 6, ly + 38))
    o.append('<text x="%.1f" y="%.1f">stock *FRICTION \u03bc, \u03bb</text>' % (lx + 32, ly + 48))
    o.append("</svg>")
    with open(svg, "w", encoding="utf-8") as f:
        f.write("\n".join(o) + "\n")


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "gen":
        write_decks(sys.argv[2])
    elif len(sys.argv) == 3 and sys.argv[1] == "check":
        sys.exit(check(sys.argv[2]))
    elif len(sys.argv) == 4 and sys.argv[1] == "chart":
        chart(sys.argv[2], sys.argv[3])
    else:
        sys.stderr.write(__doc__)
        sys.exit(2)
