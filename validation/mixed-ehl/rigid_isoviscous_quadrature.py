#!/usr/bin/python3
"""The rigid-isoviscous line contact's constants by 30-digit quadrature (mpmath), a third
derivation beside tests/reference/rigid_isoviscous.hpp's closed form and Odeint shooting.

Usage: validation/mixed-ehl/rigid_isoviscous_quadrature.py

dP/dxi = (xi^2 - xi_e^2)/(1 + xi^2)^3 from P(xi_in) = 0; the exit xi_e where P(xi_e) = 0 (findroot on
the quadrature); C = 24 int P dxi (quadrature of the quadrature: no antiderivative, no integration by
parts); the peak coefficient c_p = 12 sqrt(2) P(max(-xi_e, xi_in)). Prints inlet, xi_e, C, c_p, the
values tests/test_rigid_isoviscous.cpp stores.
"""
import mpmath as m

m.mp.dps = 30


def solution(xi_in):
    def residual(e):
        points = [xi_in] + ([-e] if -e > xi_in else []) + [0, e]
        return m.quad(lambda t: (t**2 - e**2) / (1 + t**2)**3, points)

    e = m.findroot(residual, 0.4)

    def p(x):
        return m.quad(lambda t: (t**2 - e**2) / (1 + t**2)**3, [xi_in, x])

    load = 24 * m.quad(p, [xi_in, max(xi_in, -e), 0, e])
    return e, load, 12 * m.sqrt(2) * p(max(-e, xi_in))


if __name__ == "__main__":
    print("inlet,exit,load_C,peak_c_p")
    for xi_in in (-m.inf, -10, -3, -1, -0.3):
        print(",".join([m.nstr(m.mpf(xi_in), 6)] + [m.nstr(v, 16) for v in solution(xi_in)]))
