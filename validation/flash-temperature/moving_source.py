"""Surface temperature of a half-space under a band heat source moving over it, integrated
numerically (not from Blok's closed form): the independent reference for geartrib's flash
temperature.

Two solutions of the same problem (a body moving at speed V under a fixed heat flux q(x) on the
band |x| < b, its surface otherwise insulated, steady state):
  - the high-Peclet limit (Jaeger 1942): heat flows only into the body, one-dimensionally, and a
    surface point that entered the band at -b is at x after (x + b)/V:
        T(x) = 1/(B sqrt(pi V)) int_{-b}^{x} q(xi) / sqrt(x - xi) dxi,       B = sqrt(k rho c);
  - any Peclet number (the moving line source, Carslaw & Jaeger, Conduction of Heat in Solids,
    2nd ed. 1959, sec. 10.7; Jaeger, Proc. R. Soc. NSW 76 (1942) 203-224):
        T(x) = 1/(pi k) int_{-b}^{b} q(xi) exp(P (x - xi)/b) K0(P |x - xi|/b) dxi,   P = V b/(2 kappa),
    P the Peclet number as geartrib states it (kappa = k/(rho c)), the body moving towards +x (the
    heated trail at x > xi).
The frictional heat mu p(x) |v1 - v2| with the Hertz pressure p = p0 sqrt(1 - x^2/b^2),
p0 = 2 w/(pi b), is shared between the two flanks so that their peak temperatures are equal
(Blok's postulate); the temperatures are linear in the flux, so the share is found directly.
"""
import math

from scipy import integrate, optimize, special

SQRT_PI = math.sqrt(math.pi)


def _unit_profile(u):
    """The semi-elliptic flux over its peak at u = x/b."""
    return math.sqrt(max(0.0, 1.0 - u * u))


def high_peclet_integral(u):
    """int_{-1}^{u} sqrt(1 - t^2)/sqrt(u - t) dt, with t = u - s^2 removing the singularity."""
    if u <= -1.0:
        return 0.0
    top = math.sqrt(u + 1.0)
    value, _ = integrate.quad(lambda s: 2.0 * _unit_profile(u - s * s), 0.0, top, epsabs=1e-14, epsrel=1e-12,
                              limit=200)
    return value


def high_peclet_peak():
    """(max over u of the integral above, where): the band's peak in the high-Peclet limit."""
    r = optimize.minimize_scalar(lambda u: -high_peclet_integral(u), bounds=(-1.0, 1.0), method="bounded",
                                 options={"xatol": 1e-10})
    return -r.fun, r.x


def line_source_integral(u, peclet):
    """int_{-1}^{1} sqrt(1 - t^2) exp(P (u - t)) K0(P |u - t|) dt (dimensionless, band units)."""
    def f(t):
        d = u - t
        if d == 0.0:
            return 0.0  # the logarithmic singularity is integrable; quad never lands on it exactly
        # exp(P d) K0(P |d|) = k0e(P|d|) exp(P d - P|d|): no overflow either side of the source.
        return _unit_profile(t) * special.k0e(peclet * abs(d)) * math.exp(peclet * (d - abs(d)))
    points = [u] if -1.0 < u < 1.0 else None
    value, _ = integrate.quad(f, -1.0, 1.0, points=points, epsabs=1e-13, epsrel=1e-11, limit=400)
    return value


def line_source_peak(peclet):
    """Peak of the finite-Peclet integral over the band (and just behind it), and where."""
    r = optimize.minimize_scalar(lambda u: -line_source_integral(u, peclet), bounds=(-1.0, 1.5), method="bounded",
                                 options={"xatol": 1e-9})
    return -r.fun, r.x


def peak_per_flux(material, speed, half_width, finite_peclet=True):
    """The peak temperature rise [K] per unit peak flux q0 [W/m^2] of the semi-elliptic source on a
    body of `material` (conductivity, density, specific heat; SI) moving at `speed` through it."""
    k, rho, c = material
    if speed <= 0.0:
        return math.inf
    if finite_peclet:
        kappa = k / (rho * c)
        peclet = speed * half_width / (2.0 * kappa)
        peak, _ = line_source_peak(peclet)
        return half_width * peak / (math.pi * k)
    b_m = math.sqrt(k * rho * c)
    peak, _ = high_peclet_peak()
    return math.sqrt(half_width) * peak / (b_m * SQRT_PI * math.sqrt(speed))


def flash_temperature(mu, line_load, half_width, v1, v2, material1, material2, finite_peclet=True):
    """Blok's flash temperature by integration: the flux mu p |v1 - v2| shared so that both flanks
    peak equally; returns (flash temperature [K], pinion's share of the heat)."""
    if mu == 0.0 or v1 == v2 or line_load <= 0.0:
        return 0.0, 0.5
    q0 = mu * 2.0 * line_load / (math.pi * half_width) * abs(v1 - v2)
    m1 = peak_per_flux(material1, v1, half_width, finite_peclet)
    m2 = peak_per_flux(material2, v2, half_width, finite_peclet)
    if math.isinf(m1):
        return q0 * m2, 0.0
    if math.isinf(m2):
        return q0 * m1, 1.0
    share = m2 / (m1 + m2)  # phi m1 = (1 - phi) m2
    return q0 * m1 * m2 / (m1 + m2), share
