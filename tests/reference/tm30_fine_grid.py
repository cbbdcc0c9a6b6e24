"""tm30_fine_grid.py - an independent CIE 224:2017 / ANSI/IES TM-30-20 Rf and Rg of the line spectrum
of cri_fine_grid.py on a 0.01 nm grid, the reference of tests/test_tm30.c (test_line_spectrum).
numpy 2.4.6, scipy 1.17.1 and colour-science 0.4.7 for CIECAM02 and CAM02-UCS only
(colour.XYZ_to_CIECAM02, colour.JMh_CIECAM02_to_CAM02UCS: L_A 100 cd/m2, Y_b 20, average surround,
complete adaptation); the 99 CES, the CIE 1964 10-degree and 1931 2-degree CMFs and the daylight
basis from luxcalc's src/data CSV files, interpolated linearly to the grid; CCT from 380-780 nm with
the 2-degree CMFs (as CIE 224; the Planckian locus summed at the CMFs' 1 nm nodes), the reference Planckian below 4000 K, CIE daylight above 5000 K, the
Y-normalised mix between.

usage: python3 tm30_fine_grid.py [SHIFT_NM]   (prints CCT, Rf, Rg)
"""
import sys
import warnings
import numpy as np
from scipy.optimize import minimize_scalar
warnings.filterwarnings('ignore')
import colour


DATA = __file__.rsplit('/', 2)[0] + '/../src/data/'

def table(name):
    rows = [l.strip().split(',') for l in open(DATA + name) if l.strip() and not l.startswith('#')]
    return rows[0], np.array([[float(v) for v in r] for r in rows[1:]])

LINES = [(404.66, 0.25), (435.83, 0.55), (546.07, 0.60), (576.96, 0.08), (579.07, 0.09)]
HALF, CONT = 0.1, 5e-3

def spd(lam, shift=0.0):
    s = np.where((lam >= 380) & (lam <= 780), CONT, 0.0)
    for c, p in LINES:
        s = s + p / HALF * np.clip(1 - np.abs(lam - (c + shift)) / HALF, 0, None)
    return s

def main():
    shift = float(sys.argv[1]) if len(sys.argv) > 1 else 0.0
    lam = np.round(np.arange(38000, 78001) * 0.01, 2)
    w = np.full(lam.size, 0.01); w[0] = w[-1] = 0.005
    _, c2 = table('cie1931_2deg_xyz_1nm.csv')
    _, c10 = table('cie1964_10deg_xyz_1nm.csv')
    x2, y2, z2 = (np.interp(lam, c2[:, 0], c2[:, k]) for k in (1, 2, 3))
    x10, y10, z10 = (np.interp(lam, c10[:, 0], c10[:, k]) for k in (1, 2, 3))
    _, ces = table('ies_tm30_ces_1nm.csv')
    CES = [np.interp(lam, ces[:, 0], ces[:, k]) for k in range(1, 100)]
    _, dl = table('cie_daylight_basis.csv')
    S0, S1, S2 = (np.interp(lam, dl[:, 0], dl[:, k]) for k in (1, 2, 3))
    S = spd(lam, shift)
    def uv(E):
        X, Y, Z = (np.sum(w * E * c) for c in (x2, y2, z2))
        d = X + 15 * Y + 3 * Z
        return 4 * X / d, 6 * Y / d
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
    ut, vt = uv(S)
    l1 = c2[:, 0] * 1e-9  # the Planckian locus as CIE 015 computes it: sums at the 1 nm CMF nodes
    def loc(T):
        b = 1 / (l1 ** 5 * np.expm1(1.4388e-2 / (l1 * T)))
        X, Y, Z = (np.sum(b * c2[:, k]) for k in (1, 2, 3))
        d = X + 15 * Y + 3 * Z
        return 4 * X / d, 6 * Y / d
    res = minimize_scalar(lambda s: np.hypot(*(np.array(loc(np.exp(s))) - (ut, vt))),
                          bounds=(np.log(1000), np.log(1e6)), method='bounded', options={'xatol': 1e-12})
    T = float(np.exp(res.x))
    if T < 4000:
        ref = planck(T)
    elif T >= 5000:
        ref = daylight(T)
    else:
        p, d = planck(T), daylight(T)
        m = (T - 4000) / 1000
        ref = (1 - m) * p / np.sum(w * p * y2) + m * d / np.sum(w * d * y2)
    def jab(E):
        XYZw = np.array([np.sum(w * E * c) for c in (x10, y10, z10)])
        k = 100 / XYZw[1]
        XYZw *= k
        out = []
        for r in CES:
            XYZ = np.array([np.sum(w * E * r * c) for c in (x10, y10, z10)]) * k
            sp = colour.XYZ_to_CIECAM02(XYZ, XYZw, 100, 20, colour.VIEWING_CONDITIONS_CIECAM02['Average'],
                                        discount_illuminant=True)
            out.append(colour.JMh_CIECAM02_to_CAM02UCS(np.array([sp.J, sp.M, sp.h])))
        return np.array(out)
    jt, jr = jab(S), jab(ref)
    dE = np.linalg.norm(jt - jr, axis=1)
    rf = lambda e: 10 * np.log1p(np.exp((100 - 6.73 * e) / 10))
    hue = np.degrees(np.arctan2(jr[:, 2], jr[:, 1])) % 360
    b = np.minimum((hue // 22.5).astype(int), 15)
    at = np.array([jt[b == k, 1:].mean(axis=0) for k in range(16)])
    ar = np.array([jr[b == k, 1:].mean(axis=0) for k in range(16)])
    area = lambda a: 0.5 * np.sum(a[:, 0] * np.roll(a[:, 1], -1) - a[:, 1] * np.roll(a[:, 0], -1))
    print('CCT %.6f Rf %.6f Rg %.6f' % (T, rf(dE.mean()), 100 * area(at) / area(ar)))

main()
