"""settling_ode.py -- a sphere released from rest in a fluid at rest, with the Di Felice drag at
alpha = 1 (Zhang et al. 2023, eqs. A4-A7) and Archimedes' buoyancy, no added mass:

    m dv/dt = -(rho_p - rho_f) V g - K(|v|) v,   K = pi/8 rho_f d^2 (0.63 sqrt|v| + 4.8 sqrt(nu/d))^2

The reference of tutorials/settlingTest (compare.py) and of the stability suite's settling scenes.
"""
import math

G = 9.81


def drag_K(d, rho_f, nu, speed):
    """Di Felice drag coefficient K (F = K u_r) of one sphere at alpha = 1."""
    return math.pi / 8 * rho_f * d * d * (0.63 * math.sqrt(speed) + 4.8 * math.sqrt(nu / d)) ** 2


def settling(d, rho_p, rho_f, nu, times):
    """Velocities (m/s, negative downwards) at the given increasing times (s) by RK4, the terminal
    velocity (negative) and the particle response time m / K(v_t)."""
    V = math.pi / 6 * d ** 3
    m = rho_p * V
    weight = (rho_p - rho_f) * V * G
    K = lambda u: drag_K(d, rho_f, nu, abs(u))
    acc = lambda v: (-weight - K(v) * v) / m
    lo, hi = 0.0, 100.0                       # terminal speed: K(u) u = weight, by bisection
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if K(mid) * mid > weight:
            hi = mid
        else:
            lo = mid
    vt = -0.5 * (lo + hi)
    tau = m / K(vt)
    h = min(1e-5, tau / 50)
    out, v, t = [], 0.0, 0.0
    for T in times:
        while t < T - 1e-15:                  # RK4 steps that end exactly on T
            hh = min(h, T - t)
            k1 = acc(v); k2 = acc(v + hh / 2 * k1); k3 = acc(v + hh / 2 * k2); k4 = acc(v + hh * k3)
            v += hh / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
            t += hh
        out.append(v)
    return out, vt, tau
