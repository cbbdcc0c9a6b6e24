"""cri_fine_grid.py - an independent CIE 13.3 colour rendering index of a line spectrum on a 0.01 nm
grid, the reference of tests/test_cri.c (test_line_spectrum). Written for luxcalc with numpy and
scipy (numpy 2.4.6, scipy 1.17.1); it shares only the published tables with luxcalc: the CIE 1931
2-degree CMFs (1 nm), the CIE 13.3 test colour samples (5 nm) and the CIE daylight basis (5 nm),
read from luxcalc's src/data CSV files (CIE values as distributed in colour-science 0.4.7), each
interpolated linearly to the fine grid. Planck's law with c2 = 1.4388e-2 m K (CIE 015:2018), CIE
daylight as CIE 015:2018 4.1.2 (M1, M2 rounded to three decimals), CCT by minimising the uv distance
to the Planckian locus (summed at the CMF table's 1 nm nodes, as CIE 015 computes it), von Kries in
CIE 1960 UCS, CIE 1964 U*V*W*.

usage: python3 cri_fine_grid.py [SHIFT_NM]   (prints CCT, Duv, Ra, R1..R14)
"""
import sys
import numpy as np
from scipy.optimize import minimize_scalar

DATA = __file__.rsplit('/', 2)[0] + '/../src/data/'

def table(name):
    rows = [l.strip().split(',') for l in open(DATA + name) if l.strip() and not l.startswith('#')]
    head = rows[0]
    vals = np.array([[float(v) for v in r] for r in rows[1:]])
    return head, vals

# the Hg-line spectrum of the test: triangles of 0.2 nm base on a flat continuum from 380 to 780 nm
# (W/nm); the continuum steps up within 0.01 nm at 380 and down at 780 (piecewise linear)
LINES = [(404.66, 0.25), (435.83, 0.55), (546.07, 0.60), (576.96, 0.08), (579.07, 0.09)]  # on the 0.01 nm grid
HALF = 0.1      # half base of each triangle, nm (peak = power / HALF)
CONT = 5e-3     # continuum, W/nm, from 380 to 780 nm

def spd(lam, shift=0.0):
    s = np.where((lam >= 380) & (lam <= 780), CONT, 0.0)
    for c, p in LINES:
        s = s + p / HALF * np.clip(1 - np.abs(lam - (c + shift)) / HALF, 0, None)
    return s

def main():
    shift = float(sys.argv[1]) if len(sys.argv) > 1 else 0.0
    lam = np.round(np.arange(36000, 83001) * 0.01, 2)
    w = np.full(lam.size, 0.01); w[0] = w[-1] = 0.005  # trapezoid on the fine grid
    h, cmf = table('cie1931_2deg_xyz_1nm.csv')
    xb, yb, zb = (np.interp(lam, cmf[:, 0], cmf[:, k]) for k in (1, 2, 3))
    h, tcs = table('cie13_3_tcs.csv')
    R = [np.interp(lam, tcs[:, 0], tcs[:, k]) for k in range(1, 15)]
    h, dl = table('cie_daylight_basis.csv')
    S0, S1, S2 = (np.interp(lam, dl[:, 0], dl[:, k]) for k in (1, 2, 3))
    S = spd(lam, shift)

    def uvY(E, refl=None):
        p = E if refl is None else E * refl
        X, Y, Z = (np.sum(w * p * c) for c in (xb, yb, zb))
        d = X + 15 * Y + 3 * Z
        return 4 * X / d, 6 * Y / d, Y

    def planck(T):
        l = lam * 1e-9
        return 1 / (l ** 5 * np.expm1(1.4388e-2 / (l * T)))

    def daylight(T):
        t = 1 / T
        xd = (-4.6070e9 * t**3 + 2.9678e6 * t**2 + 0.09911e3 * t + 0.244063) if T <= 7000 else \
             (-2.0064e9 * t**3 + 1.9018e6 * t**2 + 0.24748e3 * t + 0.237040)
        yd = -3.000 * xd * xd + 2.870 * xd - 0.275
        m = 0.0241 + 0.2562 * xd - 0.7341 * yd
        m1 = round((-1.3515 - 1.7703 * xd + 5.9114 * yd) / m * 1000) / 1000
        m2 = round((0.0300 - 31.4424 * xd + 30.0717 * yd) / m * 1000) / 1000
        return S0 + m1 * S1 + m2 * S2

    ut, vt, _ = uvY(S)
    # the Planckian locus as CIE 015 computes it: sums at the 1 nm nodes of the CMF table
    l1 = cmf[:, 0] * 1e-9
    def loc(T):
        b = 1 / (l1 ** 5 * np.expm1(1.4388e-2 / (l1 * T)))
        X, Y, Z = (np.sum(b * cmf[:, k]) for k in (1, 2, 3))
        d = X + 15 * Y + 3 * Z
        return 4 * X / d, 6 * Y / d
    res = minimize_scalar(lambda s: np.hypot(*(np.array(loc(np.exp(s))) - (ut, vt))),
                          bounds=(np.log(1000), np.log(1e6)), method='bounded', options={'xatol': 1e-12})
    T = float(np.exp(res.x))
    up, vp = loc(T)
    duv = float(np.hypot(ut - up, vt - vp))
    ref = planck(T) if T < 5000 else daylight(T)
    ur, vr, _ = uvY(ref)
    c = lambda u, v: (4 - u - 10 * v) / v
    d = lambda u, v: (1.708 * v + 0.404 - 1.481 * u) / v
    def uvw(E, u0, v0, adapt):
        _, _, Yw = uvY(E)
        out = []
        for r in R:
            u, v, Y = uvY(E, r)
            Y *= 100 / Yw
            if adapt:
                ci, di = c(u, v), d(u, v)
                cr, dr, ct, dt = c(ur, vr), d(ur, vr), c(u0, v0), d(u0, v0)
                den = 16.518 + 1.481 * (cr / ct) * ci - (dr / dt) * di
                u = (10.872 + 0.404 * (cr / ct) * ci - 4 * (dr / dt) * di) / den
                v = 5.520 / den
            W = 25 * np.cbrt(Y) - 17
            out.append((13 * W * (u - ur), 13 * W * (v - vr), W))
        return np.array(out)
    dE = np.linalg.norm(uvw(S, ut, vt, True) - uvw(ref, ur, vr, False), axis=1)
    Ri = 100 - 4.6 * dE
    print('CCT %.6f Duv %.6e Ra %.6f' % (T, duv, Ri[:8].mean()))
    print('R ' + ' '.join('%.6f' % r for r in Ri))

main()
