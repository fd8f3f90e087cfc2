#!/usr/bin/python3
"""Exact plane-stress solution of a curved bar (quarter ring) bent by a radial force at its end,
and a standalone check of the muParser expressions that the scene file uses for it.

Source
  S. P. Timoshenko & J. N. Goodier, Theory of Elasticity, 3rd ed. (McGraw-Hill 1970), sec. 31
  "Bending of a curved bar by a force at the end". Every formula below was derived again (the
  derivation is summarised here); none is taken on trust from the book.

Geometry and load (x = r cos(theta), y = r sin(theta), plane stress, Young E, Poisson nu)
  quarter ring a <= r <= b, 0 <= theta <= pi/2; r = a and r = b traction free;
  end theta = 0 (edge y = 0, a <= x <= b, outward normal (0,-1)) loaded by a radial shear;
  end theta = pi/2 (edge x = 0) fixed in T&G's sense (point conditions at r0 below).

Stress function  phi = (A r^3 + B/r + D r ln r) sin(theta)
  sigma_r  =  (2 A r - 2 B/r^3 + D/r) sin(theta)
  sigma_th =  (6 A r + 2 B/r^3 + D/r) sin(theta)
  tau_rth  = -(2 A r - 2 B/r^3 + D/r) cos(theta)
  N = a^2 - b^2 + (a^2 + b^2) ln(b/a),  A = P/(2N),  B = -P a^2 b^2/(2N),  D = -P (a^2 + b^2)/N
  r^2 * sigma_r / sin = 2 A r^2 - 2 B/r^2 + D = P (r^2 + a^2 b^2/r^2 - a^2 - b^2)/N, which is
  zero at r = a and r = b (traction-free curved edges; tau_rth has the same factor).
  Shear on theta = 0:  integral_a^b tau_rth(r, 0) dr = -[A r^2 + B/r^2 + D ln r]_a^b = +P.
  The traction on that end is t = sigma.(-e_theta) = (-tau_rth) e_r = -tau_rth e_x, so the
  applied end force is  F = (-P, 0):  for P > 0 it points in -x, radially towards the centre
  of the ring (line of action = the x axis, no moment about the origin).
  At the fixed end x = 0 the reaction is (+P, 0) with zero moment about the origin.

Displacements (integrating eps_r, eps_th, gamma_rth of plane-stress Hooke's law)
  u_r  = -(2D/E) theta cos(theta)
         + (sin(theta)/E) [D (1-nu) ln r + A (1-3nu) r^2 + B (1+nu)/r^2] + K sin(theta) + L cos(theta)
  u_th =  (2D/E) theta sin(theta)
         - (cos(theta)/E) [A (5+nu) r^2 + B (1+nu)/r^2 - D (1-nu) ln r]
         + (D (1+nu)/E) cos(theta) + K cos(theta) - L sin(theta) + H r
  (T&G's form, all signs confirmed.) K = u_y, L = u_x of a rigid translation, H a rigid rotation.
  T&G's supports: at r0 = (a+b)/2, theta = pi/2:  u_r = u_th = 0 and d u_th / d r = 0:
  H = 0,  L = pi D / E,  K = -[D (1-nu) ln r0 + A (1-3nu) r0^2 + B (1+nu)/r0^2] / E.
  Deflection of the loaded end: u_x(x, 0) = L = pi D/E = -pi P (a^2+b^2)/(E N) for all x.

Cartesian form (r^2 = x^2 + y^2, theta = atan2(y, x)); see the strings CONSTANTS, FIELDS, TRACTION.
  u_x = -(2D/E) theta + x y [(6-2nu) A + 2 (1+nu) B/r^4 - (1+nu) D/r^2]/E + L - H y
  u_y = [D (1-nu) ln r + A ((1-3nu) y^2 - (5+nu) x^2) + B (1+nu)(y^2-x^2)/r^4
         + D (1+nu) x^2/r^2]/E + K + H x
  sxx = y [6A + 2B (y^2 - 3x^2)/r^6 + D (3x^2 + y^2)/r^4]
  syy = y [2A + 2B (3x^2 - y^2)/r^6 + D (y^2 - x^2)/r^4]
  sxy = x [2B (x^2 - 3y^2)/r^6 + D (y^2 - x^2)/r^4 - 2A]
  end traction on y = 0:  t_x = -sxy(x, 0) = 2A x - 2B/x^3 + D/x,  t_y = -syy(x, 0) = 0

The expressions are kept below exactly as they go into the scene file (muParser syntax); this
script evaluates them by translating ^ -> **, ln -> log, atan2 -> numpy.arctan2, pi -> numpy.pi.

Checks (numpy; plus exact symbolic checks with sympy when it is importable):
  (i)   strains of u by central finite differences = plane-stress Hooke strains of sigma
        (200 random points), relative to max |eps|, tolerance 1e-7
  (ii)  equilibrium div sigma = 0 by finite differences, relative to max|sigma|/(b-a), tol 1e-7
  (iii) traction free at r = a and r = b, relative to max |sigma|
  (iv)  resultant of the end traction = (-P, 0), zero moment; T&G's integral of tau_rth = +P;
        traction strings = -(sxy, syy)(x, 0); global balance with the fixed-end reaction
  (v)   u_r = u_th = 0 and d u_th/d r = 0 at (x, y) = (0, r0)
  (vi)  Cartesian strings = polar T&G formulas above (stresses and displacements)
usage: exact_solution_check.py        (exit 1 if any check fails)
"""
import math
import re
import sys

import numpy as np

# ------------------------------------------------------------------------------------------------
# The muParser expressions (named constants are defined in this order, each from earlier ones)
# ------------------------------------------------------------------------------------------------
CONSTANTS = [
    ("N", "a^2 - b^2 + (a^2 + b^2)*ln(b/a)"),
    ("A", "P/(2*N)"),
    ("B", "-(P*a^2*b^2)/(2*N)"),
    ("D", "-(P*(a^2 + b^2))/N"),
    ("r0", "(a + b)/2"),
    ("H", "0"),
    ("K", "-(D*(1 - nu)*ln(r0) + A*(1 - 3*nu)*r0^2 + B*(1 + nu)/r0^2)/E"),
    ("L", "pi*D/E + H*r0"),
]

FIELDS = {
    "u_x": "-2*D/E*atan2(y, x) + x*y*((6 - 2*nu)*A + 2*(1 + nu)*B/(x^2 + y^2)^2"
           " - (1 + nu)*D/(x^2 + y^2))/E + L - H*y",
    "u_y": "(D*(1 - nu)*ln(sqrt(x^2 + y^2)) + A*((1 - 3*nu)*y^2 - (5 + nu)*x^2)"
           " + B*(1 + nu)*(y^2 - x^2)/(x^2 + y^2)^2 + D*(1 + nu)*x^2/(x^2 + y^2))/E + K + H*x",
    "sxx": "y*(6*A + 2*B*(y^2 - 3*x^2)/(x^2 + y^2)^3 + D*(3*x^2 + y^2)/(x^2 + y^2)^2)",
    "syy": "y*(2*A + 2*B*(3*x^2 - y^2)/(x^2 + y^2)^3 + D*(y^2 - x^2)/(x^2 + y^2)^2)",
    "sxy": "x*(2*B*(x^2 - 3*y^2)/(x^2 + y^2)^3 + D*(y^2 - x^2)/(x^2 + y^2)^2 - 2*A)",
}

# traction applied on the loaded end y = 0, a <= x <= b (outward normal (0, -1)), functions of x
TRACTION = {
    "t_x": "2*A*x - 2*B/x^3 + D/x",
    "t_y": "0",
}

PARAMETER_SETS = [
    dict(a=5.0, b=10.0, P=1.0, E=1000.0, nu=0.3),        # the reported case
    dict(a=1.0, b=3.0, P=-2.5, E=210000.0, nu=0.25),     # a second, unrelated case
]

REPORT_POINTS = [(7.5, 0.0), (5.0, 0.0), (10.0, 0.0), (0.0, 7.5)]


# ------------------------------------------------------------------------------------------------
# muParser -> numpy
# ------------------------------------------------------------------------------------------------
def lint(expr):
    """Refuse constructs whose meaning differs between muParser and Python: a unary minus right
    in front of a power operand (muParser versions differ on -x^2), chained powers."""
    if re.search(r"(^|[(,*/^+\-])\s*-\s*[\w.]+\s*\^", expr):
        raise ValueError("unary minus before a power in: " + expr)
    if re.search(r"\^\s*[\w.]+\s*\^", expr) or re.search(r"\^\s*\([^()]*\)\s*\^", expr):
        raise ValueError("chained power in: " + expr)
    if "**" in expr:
        raise ValueError("'**' is not muParser syntax: " + expr)


def to_python(expr):
    lint(expr)
    s = expr.replace("^", "**")
    s = re.sub(r"\bln\b", "log", s)
    s = re.sub(r"\batan2\b", "arctan2", s)
    return s


NUMPY_NAMES = {"sqrt": np.sqrt, "log": np.log, "sin": np.sin, "cos": np.cos,
               "arctan2": np.arctan2, "pi": np.pi}


def constants_for(params):
    env = dict(params)
    for name, expr in CONSTANTS:
        env[name] = float(eval(to_python(expr), {"__builtins__": {}}, {**NUMPY_NAMES, **env}))
    return env


def compile_field(expr, env):
    code = compile(to_python(expr), expr, "eval")
    glob = {"__builtins__": {}, **NUMPY_NAMES, **env}

    def f(x, y=0.0):
        x = np.asarray(x, dtype=float)
        y = np.asarray(y, dtype=float)
        val = eval(code, glob, {"x": x, "y": y})
        return np.broadcast_to(np.asarray(val, dtype=float), np.broadcast(x, y).shape).copy()

    return f


# ------------------------------------------------------------------------------------------------
# Independent polar formulas (the T&G form stated in the header)
# ------------------------------------------------------------------------------------------------
def polar_stress(c, r, th):
    A, B, D = c["A"], c["B"], c["D"]
    srr = (2 * A * r - 2 * B / r**3 + D / r) * np.sin(th)
    stt = (6 * A * r + 2 * B / r**3 + D / r) * np.sin(th)
    trt = -(2 * A * r - 2 * B / r**3 + D / r) * np.cos(th)
    return srr, stt, trt


def polar_displacement(c, r, th):
    A, B, D, E, nu = c["A"], c["B"], c["D"], c["E"], c["nu"]
    K, L, H = c["K"], c["L"], c["H"]
    ur = (-(2 * D / E) * th * np.cos(th)
          + np.sin(th) / E * (D * (1 - nu) * np.log(r) + A * (1 - 3 * nu) * r**2
                              + B * (1 + nu) / r**2)
          + K * np.sin(th) + L * np.cos(th))
    ut = ((2 * D / E) * th * np.sin(th)
          - np.cos(th) / E * (A * (5 + nu) * r**2 + B * (1 + nu) / r**2 - D * (1 - nu) * np.log(r))
          + D * (1 + nu) / E * np.cos(th) + K * np.cos(th) - L * np.sin(th) + H * r)
    return ur, ut


# ------------------------------------------------------------------------------------------------
def d_dx(f, x, y, h):
    """4th-order central difference."""
    return (-f(x + 2 * h, y) + 8 * f(x + h, y) - 8 * f(x - h, y) + f(x - 2 * h, y)) / (12 * h)


def d_dy(f, x, y, h):
    return (-f(x, y + 2 * h) + 8 * f(x, y + h) - 8 * f(x, y - h) + f(x, y - 2 * h)) / (12 * h)


class Checker:
    def __init__(self):
        self.failed = []

    def check(self, label, value, tol):
        ok = bool(np.isfinite(value)) and abs(value) <= tol
        print(f"  {'ok  ' if ok else 'FAIL'} {label:<62s} {value: .3e}  (tol {tol:.0e})")
        if not ok:
            self.failed.append(label)


def numeric_checks(params, chk, report):
    c = constants_for(params)
    a, b, P, E, nu = (c[k] for k in ("a", "b", "P", "E", "nu"))
    f = {k: compile_field(v, c) for k, v in FIELDS.items()}
    t = {k: compile_field(v, c) for k, v in TRACTION.items()}

    print(f"parameters: {params}")
    print("derived constants: " + ", ".join(f"{n} = {c[n]:.12g}" for n, _ in CONSTANTS))
    print(f"end load resultant (applied on y = 0): F = ({-P:g}, 0) "
          f"-> {'-x, towards the centre' if P > 0 else '+x, away from the centre'}")

    rng = np.random.default_rng(20240531)
    n = 200
    r = a + (b - a) * rng.random(n)
    th = 0.5 * np.pi * rng.random(n)
    x, y = r * np.cos(th), r * np.sin(th)
    h = 1e-3 * b

    # (i) strains
    exx = d_dx(f["u_x"], x, y, h)
    eyy = d_dy(f["u_y"], x, y, h)
    gxy = d_dy(f["u_x"], x, y, h) + d_dx(f["u_y"], x, y, h)
    sxx, syy, sxy = f["sxx"](x, y), f["syy"](x, y), f["sxy"](x, y)
    hxx = (sxx - nu * syy) / E
    hyy = (syy - nu * sxx) / E
    hxy = 2 * (1 + nu) * sxy / E
    eps_scale = max(np.abs(hxx).max(), np.abs(hyy).max(), np.abs(hxy).max())
    chk.check("(i) eps_xx: FD of u_x vs Hooke, max rel.", np.abs(exx - hxx).max() / eps_scale, 1e-7)
    chk.check("(i) eps_yy: FD of u_y vs Hooke, max rel.", np.abs(eyy - hyy).max() / eps_scale, 1e-7)
    chk.check("(i) gamma_xy: FD of u vs Hooke, max rel.", np.abs(gxy - hxy).max() / eps_scale, 1e-7)

    # (ii) equilibrium
    sig_scale = max(np.abs(sxx).max(), np.abs(syy).max(), np.abs(sxy).max())
    div_x = d_dx(f["sxx"], x, y, h) + d_dy(f["sxy"], x, y, h)
    div_y = d_dx(f["sxy"], x, y, h) + d_dy(f["syy"], x, y, h)
    chk.check("(ii) div sigma, x: max |.| (b-a)/max|sigma|",
              np.abs(div_x).max() * (b - a) / sig_scale, 1e-7)
    chk.check("(ii) div sigma, y: max |.| (b-a)/max|sigma|",
              np.abs(div_y).max() * (b - a) / sig_scale, 1e-7)

    # (iii) traction-free curved edges
    ths = np.linspace(0.0, 0.5 * np.pi, 201)
    for rad, name in ((a, "r = a"), (b, "r = b")):
        xe, ye = rad * np.cos(ths), rad * np.sin(ths)
        nx, ny = np.cos(ths), np.sin(ths)
        tx = f["sxx"](xe, ye) * nx + f["sxy"](xe, ye) * ny
        ty = f["sxy"](xe, ye) * nx + f["syy"](xe, ye) * ny
        chk.check(f"(iii) traction on {name}: max |t|/max|sigma|",
                  max(np.abs(tx).max(), np.abs(ty).max()) / sig_scale, 1e-12)

    # (iv) loaded end y = 0 and global balance
    gx, gw = np.polynomial.legendre.leggauss(40)
    xs = 0.5 * (a + b) + 0.5 * (b - a) * gx
    ws = 0.5 * (b - a) * gw
    chk.check("(iv) t_x string - (-sxy(x,0)), max rel.",
              np.abs(t["t_x"](xs) + f["sxy"](xs, 0.0)).max() / sig_scale, 1e-13)
    chk.check("(iv) t_y string - (-syy(x,0)), max rel.",
              np.abs(t["t_y"](xs) + f["syy"](xs, 0.0)).max() / sig_scale, 1e-13)
    Fx = np.sum(ws * t["t_x"](xs))
    Fy = np.sum(ws * t["t_y"](xs))
    Mz = np.sum(ws * (xs * t["t_y"](xs)))          # moment about the origin (y = 0 on this edge)
    print(f"  loaded end: integral t_x = {Fx:.15g}, integral t_y = {Fy:.3g}, moment = {Mz:.3g}")
    chk.check("(iv) (integral t_x - (-P))/|P|", (Fx + P) / abs(P), 1e-12)
    chk.check("(iv) integral t_y / |P|", Fy / abs(P), 1e-12)
    chk.check("(iv) moment about origin / (|P| b)", Mz / (abs(P) * b), 1e-12)
    srr0, stt0, trt0 = polar_stress(c, xs, 0.0 * xs)
    chk.check("(iv) T&G: (integral tau_rth(r,0) dr - P)/|P|", (np.sum(ws * trt0) - P) / abs(P), 1e-12)
    # fixed end x = 0, a <= y <= b, outward normal (-1, 0): t = (-sxx, -sxy)
    ys = xs
    Rx = np.sum(ws * -f["sxx"](0.0, ys))
    Ry = np.sum(ws * -f["sxy"](0.0, ys))
    Rm = np.sum(ws * (0.0 * -f["sxy"](0.0, ys) - ys * -f["sxx"](0.0, ys)))
    print(f"  fixed end reaction: ({Rx:.15g}, {Ry:.3g}), moment about origin {Rm:.3g}")
    chk.check("(iv) global balance: (Fx + Rx)/|P|", (Fx + Rx) / abs(P), 1e-12)
    chk.check("(iv) global balance: (Fy + Ry)/|P|", (Fy + Ry) / abs(P), 1e-12)
    chk.check("(iv) global balance: (M_end + M_fixed)/(|P| b)", (Mz + Rm) / (abs(P) * b), 1e-12)

    # (v) T&G supports at (0, r0): u_r = u_y, u_th = -u_x, d u_th/dr = -d u_x/dy
    r0 = c["r0"]
    u_scale = max(np.abs(f["u_x"](x, y)).max(), np.abs(f["u_y"](x, y)).max())
    chk.check("(v) u_r(r0, pi/2) / max|u|", f["u_y"](0.0, r0) / u_scale, 1e-13)
    chk.check("(v) u_th(r0, pi/2) / max|u|", -f["u_x"](0.0, r0) / u_scale, 1e-13)
    chk.check("(v) d u_th/dr (r0, pi/2) / max|eps| (FD)",
              -d_dy(f["u_x"], 0.0, r0, h) / eps_scale, 1e-9)

    # (vi) Cartesian strings vs the polar T&G formulas
    srr, stt, trt = polar_stress(c, r, th)
    cs, sn = np.cos(th), np.sin(th)
    pxx = srr * cs**2 + stt * sn**2 - 2 * trt * sn * cs
    pyy = srr * sn**2 + stt * cs**2 + 2 * trt * sn * cs
    pxy = (srr - stt) * sn * cs + trt * (cs**2 - sn**2)
    chk.check("(vi) Cartesian stress strings vs polar formulas, max rel.",
              max(np.abs(pxx - sxx).max(), np.abs(pyy - syy).max(), np.abs(pxy - sxy).max())
              / sig_scale, 1e-13)
    ur, ut = polar_displacement(c, r, th)
    chk.check("(vi) Cartesian u strings vs polar T&G u_r, u_th, max rel.",
              max(np.abs(ur * cs - ut * sn - f["u_x"](x, y)).max(),
                  np.abs(ur * sn + ut * cs - f["u_y"](x, y)).max()) / u_scale, 1e-13)

    if report:
        print("  displacements:")
        for px, py in REPORT_POINTS:
            print(f"    (x, y) = ({px:g}, {py:g}):  u_x = {float(f['u_x'](px, py)): .12e}   "
                  f"u_y = {float(f['u_y'](px, py)): .12e}")
        print(f"    pi D / E = {math.pi * c['D'] / E:.12e} (= u_x all along y = 0)")


# ------------------------------------------------------------------------------------------------
def symbolic_checks(chk):
    try:
        import sympy as sp
    except ImportError:
        print("sympy not importable: symbolic checks skipped")
        return
    print(f"symbolic checks (sympy {sp.__version__}), exact, any a < b, P, E, nu:")
    x, y = sp.symbols("x y", real=True)
    th = sp.symbols("theta", positive=True)
    a, b, P, E, nu = sp.symbols("a b P E nu", positive=True)
    loc = {"x": x, "y": y, "a": a, "b": b, "P": P, "E": E, "nu": nu,
           "log": sp.log, "sqrt": sp.sqrt, "sin": sp.sin, "cos": sp.cos,
           "arctan2": sp.atan2, "pi": sp.pi}
    # the derived constants as plain symbols (sympy's integrate stalls on the full expressions),
    # and their definitions, substituted last to first to reach a, b, P, E, nu
    definitions = []
    for name, expr in CONSTANTS:
        definitions.append((sp.Symbol(name), sp.sympify(to_python(expr), locals=loc)))
        loc[name] = definitions[-1][0]

    def full(e):
        for sym, value in reversed(definitions):
            e = e.subs(sym, value)
        return e

    Fs = {k: sp.sympify(to_python(v), locals=loc) for k, v in FIELDS.items()}
    Ts = {k: sp.sympify(to_python(v), locals=loc) for k, v in TRACTION.items()}
    F = {k: full(v) for k, v in Fs.items()}
    T = {k: full(v) for k, v in Ts.items()}

    def is_zero(e):
        # logs split into ln of symbols, then numerator of the rational function must expand to 0
        e = sp.expand_log(sp.expand(e), force=True)
        if sp.expand(sp.numer(sp.together(e))) == 0:
            return True
        return sp.simplify(e) == 0

    def zero(label, e):
        ok = is_zero(e)
        print(f"  {'ok  ' if ok else 'FAIL'} {label:<62s} {'0' if ok else 'nonzero'}")
        if not ok:
            chk.failed.append("symbolic: " + label)

    def definite(integrand, var):
        """integrand with the constants as symbols; result with them substituted"""
        G = sp.integrate(integrand, var)  # antiderivative, checked, then evaluated at a and b
        zero(f"     d/d{var} antiderivative - ({str(integrand)[:36]})", sp.diff(G, var) - integrand)
        return full(G.subs(var, b) - G.subs(var, a))

    hxx = (F["sxx"] - nu * F["syy"]) / E
    hyy = (F["syy"] - nu * F["sxx"]) / E
    hxy = 2 * (1 + nu) * F["sxy"] / E
    zero("(i) d u_x/dx - Hooke eps_xx", sp.diff(F["u_x"], x) - hxx)
    zero("(i) d u_y/dy - Hooke eps_yy", sp.diff(F["u_y"], y) - hyy)
    zero("(i) d u_x/dy + d u_y/dx - Hooke gamma_xy",
         sp.diff(F["u_x"], y) + sp.diff(F["u_y"], x) - hxy)
    zero("(ii) d sxx/dx + d sxy/dy", sp.diff(F["sxx"], x) + sp.diff(F["sxy"], y))
    zero("(ii) d sxy/dx + d syy/dy", sp.diff(F["sxy"], x) + sp.diff(F["syy"], y))
    for R, name in ((a, "a"), (b, "b")):
        cs, sn = sp.cos(th), sp.sin(th)
        sub = {x: R * cs, y: R * sn}
        zero(f"(iii) t_x on r = {name}", (F["sxx"] * cs + F["sxy"] * sn).subs(sub))
        zero(f"(iii) t_y on r = {name}", (F["sxy"] * cs + F["syy"] * sn).subs(sub))
    zero("(iv) t_x + sxy(x, 0)", T["t_x"] + F["sxy"].subs(y, 0))
    zero("(iv) t_y + syy(x, 0)", T["t_y"] + F["syy"].subs(y, 0))
    zero("(iv) integral_a^b t_x dx + P", definite(Ts["t_x"], x) + P)
    zero("(iv) fixed end: integral_a^b -sxx(0, y) dy - P", definite(-Fs["sxx"].subs(x, 0), y) - P)
    zero("(iv) fixed end: integral_a^b y sxx(0, y) dy (moment)",
         definite(y * Fs["sxx"].subs(x, 0), y))
    r0 = (a + b) / 2
    u_th = -F["u_x"]  # at theta = pi/2: e_theta = -e_x
    zero("(v) u_r = u_y at (0, r0)", F["u_y"].subs({x: 0, y: r0}))
    zero("(v) u_th = -u_x at (0, r0)", u_th.subs({x: 0, y: r0}))
    zero("(v) d u_th/dr = -d u_x/dy at (0, r0)", sp.diff(u_th, y).subs({x: 0, y: r0}))


def main():
    for name, expr in CONSTANTS:
        print(f"{name} = {expr}")
    for name, expr in {**FIELDS, **TRACTION}.items():
        print(f"{name} = {expr}")
    print()
    chk = Checker()
    for i, params in enumerate(PARAMETER_SETS):
        numeric_checks(params, chk, report=(i == 0))
        print()
    symbolic_checks(chk)
    print()
    if chk.failed:
        print(f"FAILED: {len(chk.failed)} check(s): " + "; ".join(chk.failed))
        return 1
    print("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
