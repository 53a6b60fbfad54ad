#!/usr/bin/env python3
"""Avitzur's upper bound for the compression of a flat ring (the ring test's theory).

A ring of inner radius Ri, outer Ro and height T between flat dies closing at U, the flow
homogeneous through the height (no barrelling):

    v_z = -U z / T,   v_r = U / (2T) (r - Rn^2 / r)        (incompressible for every Rn)

Rn is the neutral radius, where the metal does not slide on the dies. The plastic power of
the field and the friction power of a constant friction factor m (shear m k on both faces,
k = sigma0 / sqrt 3), per sigma0 U:

    W_p = 2 pi int_Ri^Ro sqrt(1 + Rn^4 / (3 r^4)) r dr           (the equivalent strain rate is
                                                               U / T sqrt(1 + Rn^4 / (3 r^4)))
    W_f = 2 pi m / sqrt(3) / T int_Ri^Ro |r^2 - Rn^2| dr         (two faces, slip |v_r|)

The upper bound takes the Rn in [0, Ro] that minimises W_p + W_f; the inner radius then moves
at v_r(Ri) = U / (2T) (Ri - Rn^2 / Ri). Rn = 0 is homogeneous flow (the inner radius grows
like the outer); Rn > Ri makes the hole shrink. Integrating dRi/dT = -(Ri - Rn^2/Ri) / (2T)
(and the outer radius likewise, so that the volume stays) from T0 to T0 (1 - R) gives the
calibration curve of m.

usage: ring_avitzur.py [m ...]   prints the inner-diameter change (%) at 10..50% reduction
"""
import math
import sys


def power(rn2, ri, ro, t, m):
    """W_p + W_f per (sigma0 U), in closed form. With u = r^2 and b = Rn^4 / 3 the plastic
    integrand is sqrt(u^2 + b) / (2u) du, whose integral is (S - sqrt(b) ln((sqrt(b) + S) / u)) / 2,
    S = sqrt(u^2 + b); the friction's is r^3 / 3 - Rn^2 r, split at r = Rn."""
    b = rn2 * rn2 / 3.0
    sb = math.sqrt(b)

    def plastic(r):
        u = r * r
        s = math.sqrt(u * u + b)
        return 0.5 * (s - (sb * math.log((sb + s) / u) if sb > 0 else 0.0))

    def g(r):
        return r ** 3 / 3.0 - rn2 * r

    wp = 2 * math.pi * (plastic(ro) - plastic(ri))
    rn = math.sqrt(rn2)
    if rn <= ri:
        f = g(ro) - g(ri)
    elif rn >= ro:
        f = g(ri) - g(ro)
    else:
        f = (g(ri) - g(rn)) + (g(ro) - g(rn))
    wf = 2 * math.pi * m / math.sqrt(3.0) / t * f
    return wp + wf


def neutral_radius_sq(ri, ro, t, m):
    """The Rn^2 in [0, Ro^2] that minimises the power (golden section; the power is convex)."""
    a, b = 0.0, ro * ro
    g = (math.sqrt(5) - 1) / 2
    c, d = b - g * (b - a), a + g * (b - a)
    fc, fd = power(c, ri, ro, t, m), power(d, ri, ro, t, m)
    for _ in range(80):
        if fc < fd:
            b, d, fd = d, c, fc
            c = b - g * (b - a)
            fc = power(c, ri, ro, t, m)
        else:
            a, c, fc = c, d, fd
            d = a + g * (b - a)
            fd = power(d, ri, ro, t, m)
    return 0.5 * (a + b)


def curve(m, ri0=7.5, ro0=15.0, t0=10.0, reductions=(10, 20, 30, 40, 50), steps=200):
    """Inner-diameter change in % at each height reduction (%), for friction factor m."""
    out = {}
    ri, ro, t = ri0, ro0, t0
    t_end = t0 * (1 - max(reductions) / 100)
    dt = (t0 - t_end) / steps
    targets = sorted(reductions)
    k = 0
    for s in range(steps + 1):
        red = (t0 - t) / t0 * 100
        while k < len(targets) and red >= targets[k] - 1e-9:
            out[targets[k]] = (ri / ri0 - 1) * 100
            k += 1
        if s == steps:
            break
        # midpoint rule in T (dT = -dt)
        def rates(ri, ro, t):
            rn2 = neutral_radius_sq(ri, ro, t, m)
            return (ri - rn2 / ri) / (2 * t), (ro - rn2 / ro) / (2 * t)
        a1, b1 = rates(ri, ro, t)
        a2, b2 = rates(ri + 0.5 * dt * a1, ro + 0.5 * dt * b1, t - 0.5 * dt)
        ri, ro, t = ri + dt * a2, ro + dt * b2, t - dt
    return out


if __name__ == "__main__":
    ms = [float(x) for x in sys.argv[1:]] or [0, 0.05, 0.1, 0.2, 0.3, 0.5, 1.0]
    red = (10, 20, 30, 40, 50)
    print("m      " + "  ".join("%5d%%" % r for r in red))
    for m in ms:
        c = curve(m, reductions=red)
        print("%-6.3f " % m + "  ".join("%+6.1f" % c[r] for r in red))
