#!/usr/bin/env python3
"""Reference solutions of the thick-walled tube under internal pressure p, plane strain
(eps_z = 0), inner radius a, outer radius b, elastic (E, nu) - perfectly plastic von Mises
(yield stress sigma_y). Stress in any unit, lengths in any unit, consistently.

Sources
  [L]  Lame: Timoshenko & Goodier, Theory of Elasticity, 3rd ed. 1970, sec. 28 (thick-walled
       cylinder), specialised to plane strain (sigma_z = nu (sigma_r + sigma_t)).
  [H]  R. Hill, The Mathematical Theory of Plasticity, Oxford 1950, ch. V, sec. 3 "Expansion of
       a cylindrical tube", the plane-strain (zero axial extension) case. Hill's simplified
       theory takes the axial stress in the plastic zone as the mean
       sigma_z = (sigma_r + sigma_t) / 2; von Mises then reads sigma_t - sigma_r = 2 k with
       k = sigma_y / sqrt(3), formally Tresca with the shear yield stress k.
       (Equation numbers are not quoted: they were not checked against the book here; every
       formula below is re-derived in its comment.)
  [HLT] Hill, Lee & Tupper, Proc. R. Soc. A 191 (1947) 278-303: the same tube with elastic
       compressibility and the exact Prandtl-Reuss/von Mises law, solved numerically. The
       function j2_radial_reference below re-does that numerically (1D radial finite elements)
       to measure how far Hill's simplification is from the exact J2 answer at nu = 0.3.

Assumptions of [H]'s closed form and which results depend on them
  * Elastic zone c <= r <= b: exact plane-strain Lame solution (compressible, any nu), driven by
    the radial pressure p_c = -sigma_r(c) at the elastic-plastic radius c. u(b) therefore
    depends on the plastic zone only through p_c(c) and the yield condition at r = c.
  * Yield at r = c and everywhere in the plastic zone: sigma_t - sigma_r = 2k. This is exact
    von Mises when sigma_z is the mean of sigma_r and sigma_t, i.e. for an elastically
    incompressible material (nu = 1/2), and at collapse (fully plastic flow with eps_z = 0
    forces s_z = 0). For nu = 0.3 it is an approximation (the exact elastic-limit pressure is
    given by elastic_limit_pressure_mises for comparison: 0.17 % lower at b/a = 2, nu = 0.3).
  * Plastic zone a <= r <= c: the stresses follow from equilibrium and the yield condition
    alone (statically determinate); the plastic strain is incompressible, the elastic strain
    keeps nu (Hill's displacements in the plastic zone; not used here).

usage: hill_solution.py [--self-test]   prints the reference curve for the default tube and runs
                                        the unit checks of the elastic branch (exit 1 on failure)
"""
import math
import sys

import numpy as np


def shear_yield(sigma_y):
    """von Mises: k = sigma_y / sqrt(3) (yield in pure shear)."""
    return sigma_y / math.sqrt(3.0)


# --------------------------------------------------------------------------------------------
# Elastic: Lame [L], plane strain
# --------------------------------------------------------------------------------------------
def lame(p, a, b, E, nu, r):
    """Stresses and radial displacement of a tube a <= r <= b under internal pressure p (outer
    surface free), plane strain.

    Airy: sigma_r = A - B'/r^2, sigma_t = A + B'/r^2 (equilibrium d sigma_r/dr + (sigma_r -
    sigma_t)/r = 0 holds for any A, B'). sigma_r(a) = -p, sigma_r(b) = 0 give
        A = p a^2 / (b^2 - a^2),  B' = A b^2:
        sigma_r = p a^2/(b^2 - a^2) (1 - b^2/r^2),  sigma_t = p a^2/(b^2 - a^2) (1 + b^2/r^2),
        sigma_z = nu (sigma_r + sigma_t) = 2 nu p a^2/(b^2 - a^2)           (eps_z = 0).
    Hooke in plane strain: eps_t = u/r = [(1 - nu^2) sigma_t - nu (1 + nu) sigma_r] / E, so
        u(r) = (1 + nu)/E * p a^2/(b^2 - a^2) * [(1 - 2 nu) r + b^2 / r].
    Units: A [stress], u = stress/E * length = length.
    """
    r = np.asarray(r, dtype=float)
    A = p * a * a / (b * b - a * a)
    s_r = A * (1.0 - b * b / r ** 2)
    s_t = A * (1.0 + b * b / r ** 2)
    s_z = nu * (s_r + s_t)
    u = (1.0 + nu) / E * A * ((1.0 - 2.0 * nu) * r + b * b / r)
    return s_r, s_t, s_z, u


def elastic_limit_pressure(a, b, sigma_y):
    """[H]: first yield at r = a when sigma_t - sigma_r = 2k; from [L] sigma_t - sigma_r =
    2 p a^2 b^2 / ((b^2 - a^2) r^2), largest at r = a:  p_e = k (1 - a^2/b^2)."""
    return shear_yield(sigma_y) * (1.0 - a * a / (b * b))


def elastic_limit_pressure_mises(a, b, sigma_y, nu):
    """Exact von Mises first yield with sigma_z = nu (sigma_r + sigma_t) (for comparison only).
    With q = p/(b^2 - a^2): sigma_r(a) = -q (b^2 - a^2), sigma_t(a) = q (b^2 + a^2),
    sigma_z = 2 nu q a^2, so sigma_vm^2 = q^2 [3 b^4 + (1 - 2 nu)^2 a^4] and
        p_e = (b^2 - a^2) sigma_y / sqrt(3 b^4 + (1 - 2 nu)^2 a^4)  (= [H] at nu = 1/2)."""
    return (b * b - a * a) * sigma_y / math.sqrt(3 * b ** 4 + (1 - 2 * nu) ** 2 * a ** 4)


# --------------------------------------------------------------------------------------------
# Elastic-plastic: Hill [H]
# --------------------------------------------------------------------------------------------
def pressure_at_radius(c, a, b, sigma_y):
    """Bore pressure p(c) with the elastic-plastic boundary at r = c, a <= c <= b.

    Elastic zone (c <= r <= b) is the Lame tube under p_c; yield at r = c:
        sigma_t - sigma_r = 2 p_c b^2 / (b^2 - c^2) = 2k  ->  p_c = k (1 - c^2/b^2).
    Plastic zone: equilibrium d sigma_r/dr = (sigma_t - sigma_r)/r = 2k/r, with sigma_r(a) = -p:
        sigma_r = -p + 2k ln(r/a),  sigma_t = sigma_r + 2k              (a <= r <= c).
    Continuity of sigma_r at r = c (sigma_r(c) = -p_c):
        p(c) = k [1 - c^2/b^2 + 2 ln(c/a)].
    c = a gives p_e; c = b gives the collapse pressure 2k ln(b/a). dp/dc = 2k (1/c - c/b^2) > 0.
    """
    k = shear_yield(sigma_y)
    return k * (1.0 - c * c / (b * b) + 2.0 * math.log(c / a))


def collapse_pressure(a, b, sigma_y):
    """[H]: the whole wall plastic, p_L = 2k ln(b/a) = (2/sqrt(3)) sigma_y ln(b/a)."""
    return 2.0 * shear_yield(sigma_y) * math.log(b / a)


def radius_at_pressure(p, a, b, sigma_y):
    """Inverse of pressure_at_radius (bisection; p(c) is increasing). None below the elastic
    limit (no plastic zone); b at or above collapse."""
    if p <= elastic_limit_pressure(a, b, sigma_y):
        return None
    if p >= collapse_pressure(a, b, sigma_y):
        return b
    lo, hi = a, b
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if pressure_at_radius(mid, a, b, sigma_y) < p:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def outer_displacement_at_radius(c, a, b, E, nu, sigma_y):
    """u(b) with the plastic zone reaching c: [L] with a -> c and p -> p_c = k (1 - c^2/b^2):
        u(r) = (1 + nu)/E * p_c c^2/(b^2 - c^2) * [(1 - 2 nu) r + b^2/r]
             = k c^2/(2 G r) * [(1 - 2 nu) r^2/b^2 + 1]          (G = E / (2 (1 + nu)))
        u(b) = 2 (1 - nu^2) k c^2 / (E b).
    Units: k/E dimensionless, c^2/b length."""
    return 2.0 * (1.0 - nu * nu) * shear_yield(sigma_y) * c * c / (E * b)


def outer_displacement_at_pressure(p, a, b, E, nu, sigma_y):
    """u(b) at bore pressure p: the elastic Lame value up to p_e, Hill's above (to collapse)."""
    c = radius_at_pressure(p, a, b, sigma_y)
    if c is None:
        return float(lame(p, a, b, E, nu, b)[3])
    return outer_displacement_at_radius(c, a, b, E, nu, sigma_y)


# --------------------------------------------------------------------------------------------
# Exact J2 (Prandtl-Reuss, nu kept) by 1D radial finite elements, after [HLT]
# --------------------------------------------------------------------------------------------
def j2_radial_reference(pressures, a, b, E, nu, sigma_y, elements=200, substeps=10):
    """Plane-strain axisymmetric tube, quadratic 3-node elements in r (3-point Gauss), strain
    (eps_r, eps_t, eps_z = 0), von Mises radial return with its consistent tangent, Newton per
    increment; each interval between consecutive requested pressures is split into `substeps`.
    Returns [(p, c, u_b)] with c the radius where the plastic strain, extrapolated linearly
    from the outermost two plastic Gauss points, falls to 0 (None while elastic).
    Only meant to measure Hill's sigma_z = mean approximation at nu < 1/2 (checked: at nu = 0.49,
    where sigma_z is nearly the mean, it reproduces Hill's c and u_b to 3e-5 up to 0.95 of
    collapse)."""
    G, K = E / (2 * (1 + nu)), E / (3 * (1 - 2 * nu))
    one = np.ones(3)
    Idev = np.eye(3) - np.outer(one, one) / 3
    Ce = K * np.outer(one, one) + 2 * G * Idev
    nodes = np.linspace(a, b, 2 * elements + 1)
    xi, w = np.polynomial.legendre.leggauss(3)
    e = np.repeat(np.arange(elements), 3)
    xi, w = np.tile(xi, elements), np.tile(w, elements)
    idx = np.stack([2 * e, 2 * e + 1, 2 * e + 2], axis=1)  # (nq, 3)
    h = nodes[idx[:, 2]] - nodes[idx[:, 0]]
    N = np.stack([xi * (xi - 1) / 2, 1 - xi * xi, xi * (xi + 1) / 2], axis=1)
    dN = np.stack([xi - 0.5, -2 * xi, xi + 0.5], axis=1) * (2 / h)[:, None]
    rq = np.sum(N * nodes[idx], axis=1)
    wr = w * h / 2 * rq
    B = np.stack([dN, N / rq[:, None], np.zeros_like(N)], axis=1)  # (nq, 3 strains, 3 nodes)
    nq, n_dof = len(rq), len(nodes)
    sig, eps, ep, u = np.zeros((nq, 3)), np.zeros((nq, 3)), np.zeros(nq), np.zeros(n_dof)
    rows = np.repeat(idx, 3, axis=1).ravel()
    cols = np.tile(idx, (1, 3)).ravel()

    def material(deps):
        tr = sig + deps @ Ce
        s = tr @ Idev
        ns = np.linalg.norm(s, axis=1)
        f = ns - np.sqrt(2.0 / 3.0) * sigma_y
        yl = f > 0
        D = np.broadcast_to(Ce, (nq, 3, 3)).copy()
        dl = np.where(yl, f / (2 * G), 0.0)
        n = s / np.maximum(ns, 1e-300)[:, None]
        theta = 1 - 2 * G * dl / np.maximum(ns, 1e-300)
        Dp = (K * np.outer(one, one)[None] + 2 * G * theta[:, None, None] * Idev[None]
              - 2 * G * theta[:, None, None] * n[:, :, None] * n[:, None, :])
        D[yl] = Dp[yl]
        return tr - 2 * G * dl[:, None] * n, D, np.sqrt(2.0 / 3.0) * dl

    out, p_prev = [], 0.0
    for p_target in pressures:
        for p in np.linspace(p_prev, p_target, substeps + 1)[1:]:
            du = np.zeros(n_dof)
            for _ in range(60):
                ue = (u + du)[idx]
                s, D, dep = material(np.einsum("qij,qj->qi", B, ue) - eps)
                R = np.zeros(n_dof)
                np.add.at(R, idx, wr[:, None] * np.einsum("qij,qi->qj", B, s))
                R[0] -= p * a  # the bore pressure's force (per radian and unit length)
                if np.linalg.norm(R) <= 1e-9 * p * a:
                    break
                Kq = wr[:, None, None] * np.einsum("qia,qij,qjb->qab", B, D, B)
                Kt = np.zeros((n_dof, n_dof))
                np.add.at(Kt, (rows, cols), Kq.ravel())
                du -= np.linalg.solve(Kt, R)
            else:
                raise RuntimeError("radial J2 reference: Newton did not converge at p = %g" % p)
            u += du
            eps = np.einsum("qij,qj->qi", B, u[idx])
            sig, ep = s, ep + dep
        p_prev = p_target
        plastic = np.nonzero(ep > 0)[0]
        if len(plastic) == 0:
            c = None
        elif plastic[-1] == nq - 1:
            c = b
        else:
            j = plastic[-1]
            c = rq[j]
            if j > 0 and ep[j - 1] > ep[j]:
                c = rq[j] + ep[j] * (rq[j] - rq[j - 1]) / (ep[j - 1] - ep[j])
            c = min(max(c, rq[j]), rq[j + 1])
        out.append((p_target, c, u[-1]))
    return out


# --------------------------------------------------------------------------------------------
def self_test(a=100.0, b=200.0, E=210000.0, nu=0.3, sigma_y=240.0):
    """Unit checks of the elastic branch against [L] and of the branches' continuity."""
    fails = []

    def check(what, got, want, tol):
        ok = abs(got - want) <= tol * max(abs(want), 1e-300)
        print("  %-62s %.10g vs %.10g %s" % (what, got, want, "ok" if ok else "FAIL"))
        if not ok:
            fails.append(what)

    p = 50.0
    r = np.linspace(a, b, 2001)
    s_r, s_t, s_z, u = lame(p, a, b, E, nu, r)
    check("sigma_r(a) = -p", s_r[0], -p, 1e-12)
    check("sigma_r(b) = 0", s_r[-1] + 1.0, 1.0, 1e-12)
    # equilibrium d sigma_r/dr + (sigma_r - sigma_t)/r = 0 (central differences)
    h = r[1] - r[0]
    res = np.gradient(s_r, h)[1:-1] + ((s_r - s_t) / r)[1:-1]
    check("equilibrium residual / (p/a)", np.max(np.abs(res)) / (p / a) + 1.0, 1.0, 1e-5)
    # Hooke, plane strain: eps_r = du/dr, eps_t = u/r, eps_z = 0
    e_r, e_t = np.gradient(u, h)[1:-1], (u / r)[1:-1]
    lam, mu = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
    check("Hooke sigma_r = lam tr + 2 mu eps_r", np.max(np.abs(lam * (e_r + e_t) + 2 * mu * e_r
                                                             - s_r[1:-1])) / p + 1, 1.0, 1e-5)
    check("Hooke sigma_t = lam tr + 2 mu eps_t", np.max(np.abs(lam * (e_r + e_t) + 2 * mu * e_t
                                                             - s_t[1:-1])) / p + 1, 1.0, 1e-5)
    check("sigma_z = lam (eps_r + eps_t)", np.max(np.abs(lam * (e_r + e_t) - s_z[1:-1])) / p + 1,
          1.0, 1e-5)
    # textbook closed form of u(b) for plane strain: 2 (1 - nu^2) p a^2 b / (E (b^2 - a^2))
    check("u(b) = 2 (1 - nu^2) p a^2 b / (E (b^2 - a^2))", u[-1],
          2 * (1 - nu * nu) * p * a * a * b / (E * (b * b - a * a)), 1e-12)
    # scaling (units): u is linear in p/E and in length
    check("u scales as p/E * length", lame(2 * p, 2 * a, 2 * b, 2 * E, nu, 2 * b)[3],
          2 * lame(p, a, b, E, nu, b)[3], 1e-12)
    pe = elastic_limit_pressure(a, b, sigma_y)
    s_r, s_t, _, _ = lame(pe, a, b, E, nu, a)
    check("Tresca-k yield at r = a for p_e: sigma_t - sigma_r = 2k", s_t - s_r,
          2 * shear_yield(sigma_y), 1e-12)
    check("p(c = a) = p_e", pressure_at_radius(a, a, b, sigma_y), pe, 1e-12)
    check("p(c = b) = collapse", pressure_at_radius(b, a, b, sigma_y),
          collapse_pressure(a, b, sigma_y), 1e-12)
    check("u(b) continuous at p_e (Lame vs Hill c = a)", float(lame(pe, a, b, E, nu, b)[3]),
          outer_displacement_at_radius(a, a, b, E, nu, sigma_y), 1e-12)
    check("Mises p_e at nu = 1/2 equals Hill's", elastic_limit_pressure_mises(a, b, sigma_y, 0.5),
          pe, 1e-12)
    c = 150.0
    check("radius_at_pressure inverts pressure_at_radius",
          radius_at_pressure(pressure_at_radius(c, a, b, sigma_y), a, b, sigma_y), c, 1e-10)
    return fails


def main():
    a, b, E, nu, sy = 100.0, 200.0, 210000.0, 0.3, 240.0
    print("tube a = %g, b = %g, E = %g, nu = %g, sigma_y = %g" % (a, b, E, nu, sy))
    print("  elastic limit (Hill, sigma_t - sigma_r = 2k): %.4f" % elastic_limit_pressure(a, b, sy))
    print("  elastic limit (exact Mises, nu = %g):           %.4f"
          % (nu, elastic_limit_pressure_mises(a, b, sy, nu)))
    print("  collapse 2k ln(b/a):                          %.4f" % collapse_pressure(a, b, sy))
    fails = self_test(a, b, E, nu, sy)
    if "--self-test" not in sys.argv[1:]:
        pL = collapse_pressure(a, b, sy)
        ps = [f * pL for f in (0.5, 0.6, 0.7, 0.8, 0.9, 0.95, 0.98)]
        print("| p | c Hill | c J2 radial FE | u_b Hill | u_b J2 radial FE |")
        print("|---|---|---|---|---|")
        for p, c, ub in j2_radial_reference(ps, a, b, E, nu, sy):
            ch = radius_at_pressure(p, a, b, sy)
            print("| %.2f | %s | %s | %.6f | %.6f |" % (
                p, "-" if ch is None else "%.2f" % ch, "-" if c is None else "%.2f" % c,
                outer_displacement_at_pressure(p, a, b, E, nu, sy), ub))
    if fails:
        print("FAILED: " + ", ".join(fails))
        sys.exit(1)


if __name__ == "__main__":
    main()
