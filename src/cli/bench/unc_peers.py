"""unc_peers.py - Monte Carlo trials of a spectrum's uncertainty as a user of luxpy would run them,
for `luxcalc bench uncertainty` (src/cli/bench/bench_uncertainty.c) to time beside luxcalc in the
same run, on the same input model: the same spectrum, the same distributions, other random numbers.

usage: python3 unc_peers.py SPD N WHAT
  SPD   two columns (wavelength nm, value), 380-780 nm at 1 nm, written by the bench
  N     trials
  WHAT  xyz: X, Y, Z, x, y, CCT and Duv of every trial; cri: also CIE 13.3 Ra and CIE 224 Rf
The model (luxcalc's SPEC "1%+scale=2%+shift=0.2nm"): every value times (1 + 0.01 z_j), the whole
spectrum times (1 + 0.02 z), the wavelength scale shifted by 0.2 z nm (linear interpolation, end
values held). numpy draws the trials (N x 401 spectra); luxpy 1.12.5 integrates them
(spd_to_xyz, vectorised over the trials), solves CCT and Duv (xyz_to_cct, its default method),
and computes Ra (cri.spd_to_ciera) and Rf (cri.spd_to_cierf) over all the trials at once.
Prints one JSON line: import_s, draw_s, compute_s, total_s, u_cct_K, u_Y_rel (and u_ra, u_rf).
"""
import json
import sys
import time

t0 = time.perf_counter()
path, n, what = sys.argv[1], int(sys.argv[2]), sys.argv[3]
import warnings  # noqa: E402

warnings.filterwarnings("ignore")
import numpy as np  # noqa: E402
import luxpy as lx  # noqa: E402

t1 = time.perf_counter()
d = np.loadtxt(path, delimiter=",", comments="#")
wl, s = d[:, 0], d[:, 1]
rng = np.random.default_rng(0)
sp = s[None, :] * (1 + 0.01 * rng.standard_normal((n, wl.size)))
sp *= 1 + 0.02 * rng.standard_normal((n, 1))
shift = 0.2 * rng.standard_normal(n)
h = wl[1] - wl[0]
x = (wl[None, :] - shift[:, None] - wl[0]) / h  # S(lambda - d) on the grid, by index
x = np.clip(x, 0, wl.size - 1)
i0 = np.minimum(np.floor(x).astype(int), wl.size - 2)
f = x - i0
rows = np.arange(n)[:, None]
sp = sp[rows, i0] * (1 - f) + sp[rows, i0 + 1] * f
t2 = time.perf_counter()
xyz = lx.spd_to_xyz(np.vstack((wl, sp)), relative=False, cieobs="1931_2")
Yxy = lx.xyz_to_Yxy(xyz)
cct, duv = lx.xyz_to_cct(xyz, cieobs="1931_2", out="cct,duv")
res = {"u_cct_K": float(np.std(cct, ddof=1)), "u_Y_rel": float(np.std(xyz[:, 1], ddof=1) / np.mean(xyz[:, 1])),
       "u_x": float(np.std(Yxy[:, 1], ddof=1))}
if what == "cri":
    spds = np.vstack((wl, sp))
    ra = lx.cri.spd_to_ciera(spds)
    rf = lx.cri.spd_to_cierf(spds)
    res["u_ra"] = float(np.std(ra, ddof=1))
    res["u_rf"] = float(np.std(rf, ddof=1))
t3 = time.perf_counter()
res.update({"import_s": t1 - t0, "draw_s": t2 - t1, "compute_s": t3 - t2, "total_s": t3 - t0})
print(json.dumps(res))
