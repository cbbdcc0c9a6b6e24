#!/usr/bin/env python3
"""daylight_ref.py - reference numbers for tests/test_openings.c: the sky and ground illuminance
through a rectangular opening at a point, computed from the definition, independently of luxcalc:
E = integral over the opening of L(w) tau(m . w) max(0, n . w) (m . w) / r^2 dA (w the unit direction
from the point to the opening's point, m the opening's outward normal), with scipy's adaptive
dblquad on pieces split where the horizon crosses the opening.

Skies: uniform (L = 1), the traditional CIE overcast sky L = Lz (1 + 2 cos Z) / 3 (Moon & Spencer
1942), CIE standard general sky type 1 (ISO 15469 / CIE S 011: gradation a = 4, b = -0.7,
indicatrix c = 0, d = -1, e = 0: L / Lz = (1 + 4 exp(-0.7 / cos Z)) / (1 + 4 exp(-0.7))). Ground:
uniform, L = rho_g E_h / pi below the horizon. Glazing: CIE 171:2006's 6 mm clear glass (test cases
5.10, 5.12; Tregenza & Sharples 1993, algorithm 2.34), tau = P(cos theta), clamped at 0.
The room is the 4 x 4 x 3 m one of CIE 171:2006 test cases 5.9 - 5.12: a 1 x 1 m roof opening at
the ceiling's centre (R) and a 2 x 1 m facade opening (W), unglazed and glazed.
Run: python3 tests/ref/daylight_ref.py  (numpy 2.4.6, scipy 1.17.1 produced the numbers in the test)."""
import math
from scipy import integrate

P = [-0.028378, 3.156075, -3.058376, -1.428919, 4.014235, -1.775827]


def tau_clear(c):
    return max(sum(P[j] * c ** j for j in range(6)), 0.0)


def sky_L(sky, wz):
    if sky == 'uniform':
        return 1.0
    if sky == 'overcast':
        return (1 + 2 * wz) / 3
    if sky == 'cie1':
        return (1 + 4 * math.exp(-0.7 / wz)) / (1 + 4 * math.exp(-0.7)) if wz > 0 else 0.0
    raise ValueError(sky)


def E_h(sky):
    """The sky's horizontal illuminance (Lz = 1)."""
    v, _ = integrate.quad(lambda z: sky_L(sky, math.cos(z)) * math.cos(z) * math.sin(z), 0, math.pi / 2,
                          epsabs=1e-15, epsrel=1e-14)
    return 2 * math.pi * v


def E(x, n, o, u, v, m, sky, glazing, Lg, splits_t=()):
    def f(t, s):
        y = [o[k] + s * u[k] + t * v[k] - x[k] for k in range(3)]
        r = math.sqrt(sum(a * a for a in y))
        w = [a / r for a in y]
        nw = sum(n[k] * w[k] for k in range(3))
        if nw <= 0:
            return 0.0
        c = sum(m[k] * w[k] for k in range(3))
        L = sky_L(sky, w[2]) if w[2] >= 0 else Lg
        return L * (tau_clear(c) if glazing else 1.0) * nw * c / (r * r)
    cr = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    A = math.sqrt(sum(a * a for a in cr))
    ts = [0] + sorted(splits_t) + [1]
    tot = 0
    for j in range(len(ts) - 1):
        val, _ = integrate.dblquad(f, 0, 1, ts[j], ts[j + 1], epsabs=1e-14, epsrel=1e-13)
        tot += val
    return tot * A


R = dict(o=(1.5, 1.5, 3), u=(1, 0, 0), v=(0, 1, 0), m=(0, 0, 1))
W = dict(o=(1, 0, 1), u=(2, 0, 0), v=(0, 0, 1), m=(0, -1, 0))
# opening, point, normal, where the horizon crosses the opening (t)
POINTS = [(R, (2, 2, 0), (0, 0, 1), ()), (R, (0.5, 1, 0), (0, 0, 1), ()), (R, (3.7, 0.4, 0.85), (0, 0, 1), ()),
          (R, (2, 0.2, 1.5), (0, 1, 0), ()), (W, (2, 1, 0.85), (0, 0, 1), ()), (W, (1, 2.5, 0), (0, 0, 1), ()),
          (W, (2, 0.8, 1.5), (0, 0, 1), (0.5,)), (W, (2, 1.0, 1.5), (0, -1, 0), (0.5,)), (W, (3.5, 2, 0.85), (-1, 0, 0), ())]

if __name__ == '__main__':
    for sky in ('uniform', 'overcast', 'cie1'):
        Lg = 0.2 * E_h(sky) / math.pi  # ground reflectance 0.2
        print('%s: E_h = %.17g' % (sky, E_h(sky)))
        for g in (0, 1):
            vals = [E(x, n, o['o'], o['u'], o['v'], o['m'], sky, g, Lg, splits_t=ts) for o, x, n, ts in POINTS]
            print('  %s: {%s}' % ('clear' if g else 'none', ', '.join('%.16g' % v for v in vals)))
