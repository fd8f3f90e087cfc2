#!/usr/bin/env python3
"""The reference values of the clamped square Kirchhoff plate under uniform load q (a = 1,
nu = 0.3), computed independently of efg: finite differences of D lap^2 w = q (13-point stencil,
the clamped edge by ghost-node reflection w(-h) = w(h)) on 40, 80 and 160 intervals,
Richardson-extrapolated (O(h^2)). Prints w_c D / (q a^4) = 0.0012653 (Taylor & Govindjee 2004:
0.00126532; Timoshenko & Woinowsky-Krieger table 35: 0.00126) and the centre moment
M = -D (w_xx + nu w_yy) = 0.022905 q a^2 (the table's 0.0231 is a three-digit approximation).
Used by Shell.ClampedPlateUnderPressureDoesNotLock (docs/shells.md). Run: python3 this_file
"""
import numpy as np, scipy.sparse as sp, scipy.sparse.linalg as sla
nu = 0.3
def solve(n):
    h = 1.0 / n
    m = n - 1                       # interior nodes per direction
    idx = lambda i, j: (i - 1) * m + (j - 1)
    rows, cols, vals = [], [], []
    st = {(0,0):20, (1,0):-8, (-1,0):-8, (0,1):-8, (0,-1):-8, (1,1):2, (1,-1):2, (-1,1):2, (-1,-1):2,
          (2,0):1, (-2,0):1, (0,2):1, (0,-2):1}
    for i in range(1, n):
        for j in range(1, n):
            for (di, dj), c in st.items():
                a, b = i + di, j + dj
                if a in (0, n) or b in (0, n):
                    continue            # w = 0 on the edge
                if a == -1: a = 1       # clamped: w(-h) = w(h)
                if a == n + 1: a = n - 1
                if b == -1: b = 1
                if b == n + 1: b = n - 1
                rows.append(idx(i, j)); cols.append(idx(a, b)); vals.append(c / h**4)
    A = sp.csr_matrix((vals, (rows, cols)), shape=(m*m, m*m))
    w = sla.spsolve(A.tocsc(), np.ones(m*m))          # q / D = 1
    W = np.zeros((n+1, n+1)); W[1:n, 1:n] = w.reshape(m, m)
    c = n // 2
    wxx = (W[c+1, c] - 2*W[c, c] + W[c-1, c]) / h**2
    wyy = (W[c, c+1] - 2*W[c, c] + W[c, c-1]) / h**2
    return W[c, c], -(wxx + nu * wyy)
r = [solve(n) for n in (40, 80, 160)]
for n, (w, M) in zip((40, 80, 160), r):
    print(n, w, M)
# O(h^2): Richardson
w_ex = (4 * r[2][0] - r[1][0]) / 3; M_ex = (4 * r[2][1] - r[1][1]) / 3
print("extrapolated w %.7f  M %.6f" % (w_ex, M_ex))
