"""spd_cli_peers.py - what `luxcalc spd --format csv FILE -o OUT` does, as a user of numpy or of
colour-science would write it, for `luxcalc bench spd` (src/cli/cmd_bench.c) to time as whole
processes beside the CLI in the same run.

usage: python3 spd_cli_peers.py numpy|colour CSV OUT WEIGHTS
  CSV      rows layout: a header "id,360,...,830", then "name,v1,...,v471" per spectrum
  WEIGHTS  471 x 4 float64 (x_bar, y_bar, z_bar, V'), 360-830 nm at 1 nm, written by the bench from
           luxcalc's own CIE tables (so numpy needs no other data)
numpy:  np.loadtxt, one matmul for X, Y, Z and scotopic Y, the derived columns (x, y, u', v', LER,
        S/P, the radiant integral), np.savetxt with %.17g: every default column but CCT and Duv
colour: colour-science 0.4.x: colour.msds_to_XYZ (method Integration, vectorised over the spectra),
        xy, u'v', CIE 1960 uv and colour.temperature.uv_to_CCT_Ohno2013 (CCT, Duv) on all of them,
        scotopic Y with colour's CIE 1951 scotopic efficiency, np.savetxt as above
Prints one JSON line: import_s, read_s, compute_s, write_s, total_s (in-process; the bench also
times the whole process).
"""
import json
import sys
import time

t0 = time.perf_counter()
mode, csv, out, weights = sys.argv[1:5]
import numpy as np  # noqa: E402

if mode == "colour":
    import warnings

    warnings.filterwarnings("ignore")
    import colour  # noqa: E402
KM, KM_SCOT = 683.002, 1700.06
t1 = time.perf_counter()
S = np.loadtxt(csv, delimiter=",", skiprows=1, usecols=range(1, 472), ndmin=2)
t2 = time.perf_counter()
radiant = np.trapezoid(S, dx=1.0, axis=1) if hasattr(np, "trapezoid") else np.trapz(S, dx=1.0, axis=1)
if mode == "numpy":
    W = np.fromfile(weights, dtype=np.float64).reshape(471, 4)
    I = S @ W
    X, Y, Z, V = KM * I[:, 0], KM * I[:, 1], KM * I[:, 2], KM_SCOT * I[:, 3]
    s, d = X + Y + Z, X + 15 * Y + 3 * Z
    cols = [X, Y, Z, X / s, Y / s, 4 * X / d, 9 * Y / d, Y / radiant, V, V / Y, radiant]
else:
    shape = colour.SpectralShape(360, 830, 1)
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"].copy().align(shape)
    ones = colour.sd_ones(shape)
    # colour's reference scale returns XYZ / 100 for an explicit k (as ../shared/peers scale back)
    XYZ = 100 * colour.msds_to_XYZ(S, cmfs, ones, k=KM, method="Integration", shape=shape)
    xy = colour.XYZ_to_xy(XYZ)
    upvp = colour.xy_to_Luv_uv(xy)
    uv = colour.UCS_to_uv(colour.XYZ_to_UCS(XYZ))
    cct_duv = colour.temperature.uv_to_CCT_Ohno2013(uv)
    scot = colour.colorimetry.SDS_LEFS_SCOTOPIC["CIE 1951 Scotopic Standard Observer"].copy().align(shape)
    V = KM_SCOT * (S @ scot.values)
    X, Y, Z = XYZ[:, 0], XYZ[:, 1], XYZ[:, 2]
    cols = [X, Y, Z, xy[:, 0], xy[:, 1], upvp[:, 0], upvp[:, 1], cct_duv[:, 0], cct_duv[:, 1], Y / radiant, V,
            V / Y, radiant]
t3 = time.perf_counter()
np.savetxt(out, np.column_stack(cols), fmt="%.17g", delimiter=",")
t4 = time.perf_counter()
print(json.dumps({"mode": mode, "spectra": int(S.shape[0]), "import_s": t1 - t0, "read_s": t2 - t1,
                  "compute_s": t3 - t2, "write_s": t4 - t3, "total_s": t4 - t0}))
