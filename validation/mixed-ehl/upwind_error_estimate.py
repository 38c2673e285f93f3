#!/usr/bin/python3
"""How far a first-order upwind finite-volume Reynolds solution of the rigid-isoviscous case lies
from the exact one: the size of the discretisation error the solver's rigid-limit tolerance must
allow (validation/mixed-ehl/README.md, "Rigid-isoviscous"). Not the solver: rigid, isoviscous,
incompressible, steady, a fixed film; the same discretisation as the solver's header states (the
Poiseuille flux centred, the Couette flux from the upstream node, Reynolds' exit by the
complementarity p >= 0, residual >= 0, by a primal-dual active set).

Usage: validation/mixed-ehl/upwind_error_estimate.py     (about 5 s)

Prints, for 256..4096 nodes over xi in [-5, 0.6] (xi = x/sqrt(2 R h0)), the load's relative error
at the given film (against the closed form at the same inlet) and the last wet node against the
exact exit. Observed: first order, the load error 1.02 dx/sqrt(2 R h0) (2.8e-3 at 2048 nodes), the
exit within one node.
"""
import math

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spl
from scipy.optimize import brentq

R, ETA, UM, H0 = 0.01, 0.01, 1.0, 10e-6
LENGTH = math.sqrt(2 * R * H0)


def exact(xi_in):
    """(xi_e, C) in closed form (tests/reference/rigid_isoviscous.hpp's first derivation)."""
    def a(g, e2):
        return g / 8 - math.sin(4 * g) / 32 - e2 * (3 * g / 8 + math.sin(2 * g) / 4 + math.sin(4 * g) / 32)

    g_in = math.atan(xi_in)
    e = brentq(lambda e: a(math.atan(e), e * e) - a(g_in, e * e), 1e-12, 1.0, xtol=1e-15)

    def f(g):
        return (math.sin(g)**4 + e * e * math.cos(g)**4) / 4

    return e, 24 * (f(g_in) - f(math.atan(e)))


def upwind(n, xi_in, xi_out):
    x = np.linspace(xi_in * LENGTH, xi_out * LENGTH, n)
    dx = x[1] - x[0]
    h = H0 + x**2 / (2 * R)
    hm = 0.5 * (h[1:] + h[:-1])
    west, east = hm[:-1]**3 / (12 * ETA * dx), hm[1:]**3 / (12 * ETA * dx)
    # Interior node i: Poiseuille out of its faces minus the upwinded Couette flux difference.
    a = sp.diags([-west[1:], west + east, -east[:-1]], [-1, 0, 1], format="csr")
    rhs = -UM * (h[1:-1] - h[:-2])
    cavitated = np.zeros(n - 2, bool)
    for _ in range(500):
        free = ~cavitated
        p = np.zeros(n - 2)
        p[free] = spl.spsolve(a[free][:, free].tocsc(), rhs[free])
        residual = a @ p - rhs
        residual[free] = 0.0
        new = residual - p > 0.0
        if (new == cavitated).all():
            break
        cavitated = new
    full = np.zeros(n)
    full[1:-1] = p
    return x, full


def main():
    xi_in, xi_out = -5.0, 0.6
    e, c = exact(xi_in)
    w_exact = c * ETA * UM * R / H0
    print(f"exact at xi_in = {xi_in}: xi_e = {e:.6f}, C = {c:.6f}")
    print("nodes  dx/length   load error   last wet xi  (exact)")
    for n in (256, 512, 1024, 2048, 4096):
        x, p = upwind(n, xi_in, xi_out)
        w = float(np.sum(0.5 * (p[1:] + p[:-1]) * np.diff(x)))
        wet = x[np.nonzero(p > 0)[0][-1]] / LENGTH
        print(f"{n:5d}  {(xi_out - xi_in) / (n - 1):.3e}   {w / w_exact - 1:+.3e}   {wet:.5f}  ({e:.5f})")


if __name__ == "__main__":
    main()
