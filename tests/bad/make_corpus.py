#!/usr/bin/env python3
# make_corpus.py - writes the committed bad-input corpus (tests/bad/{ies,ldt,spd,scene,exr}/) that
# tests/cli/bad_inputs.sh runs; expectations are in tests/bad/expected.tsv. Run from tests/bad.
# The big cases (1e6 columns, 10 MB lines) and the special files (directory, unreadable file,
# FIFO) are made at test time by the driver instead.
import os

def w(path, data):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    if isinstance(data, str):
        data = data.encode('utf-8')
    open(path, 'wb').write(data)

# ---------- IES: a complete LM-63-2002 file with TILT=INCLUDE, cut after every section ----------
ies_lines = [
    "IESNA:LM-63-2002",           # 1 version
    "[TEST] robustness corpus",   # 2 keyword
    "[MANUFAC] luxcalc",          # 3 keyword
    "TILT=INCLUDE",               # 4 tilt line
    "1",                          # 5 lamp-to-luminaire geometry
    "3",                          # 6 number of tilt angles
    "0 45 90",                    # 7 tilt angles
    "1 0.9 0.8",                  # 8 tilt factors
    "1 1000 1 3 2 1 2 0 0 0",     # 9 lamps lumens mult nv nh type units w l h
    "1 1 10",                     # 10 ballast, ballast-lamp, watts
    "0 45 90",                    # 11 vertical angles
    "0 90",                       # 12 horizontal angles (quadrant)
    "100 80 50",                  # 13 candela, plane C0
    "100 70 40",                  # 14 candela, plane C90
]
w("good/reference.ies", "\n".join(ies_lines) + "\n")
def cut(n, extra=""):
    return "\n".join(ies_lines[:n]) + "\n" + extra
cuts = {
    "ies_trunc_01_version_only.ies": cut(1),
    "ies_trunc_02_keywords.ies": cut(3),
    "ies_trunc_03_after_tilt.ies": cut(4),
    "ies_trunc_04_tilt_geometry.ies": cut(5),
    "ies_trunc_05_tilt_count.ies": cut(6),
    "ies_trunc_06_mid_tilt_angles.ies": cut(6, "0 45\n"),
    "ies_trunc_07_tilt_angles.ies": cut(7),
    "ies_trunc_08_mid_tilt_factors.ies": cut(7, "1 0.9\n"),
    "ies_trunc_09_tilt_factors.ies": cut(8),
    "ies_trunc_10_mid_header.ies": cut(8, "1 1000 1 3 2\n"),
    "ies_trunc_11_header.ies": cut(9),
    "ies_trunc_12_mid_ballast.ies": cut(9, "1 1\n"),
    "ies_trunc_13_ballast.ies": cut(10),
    "ies_trunc_14_mid_vertical.ies": cut(10, "0 45\n"),
    "ies_trunc_15_vertical.ies": cut(11),
    "ies_trunc_16_horizontal.ies": cut(12),
    "ies_trunc_17_mid_first_plane.ies": cut(12, "100 80\n"),
    "ies_trunc_18_first_plane.ies": cut(13),
    "ies_trunc_19_mid_last_plane.ies": cut(13, "100 70\n"),
    "ies_trunc_20_no_final_newline.ies": cut(13, "100 70"),
}
for k, v in cuts.items():
    w("ies/" + k, v)
def ies_with(i, line):
    lines = list(ies_lines)
    lines[i - 1] = line
    return "\n".join(lines) + "\n"
w("ies/ies_counts_lie_huge.ies", ies_with(9, "1 1000 1 100000 100000 1 2 0 0 0"))
w("ies/ies_counts_lie_extra.ies", ies_with(9, "1 1000 1 2 2 1 2 0 0 0"))
w("ies/ies_tilt_count_lies.ies", ies_with(6, "100000"))
w("ies/ies_num_1e999.ies", ies_with(13, "100 1e999 50"))
w("ies/ies_num_nan.ies", ies_with(13, "100 nan 50"))
w("ies/ies_num_hexfloat.ies", ies_with(13, "100 0x1p3 50"))
w("ies/ies_num_arabic_digits.ies", ies_with(13, "100 \u0661\u0662\u0663 50"))
w("ies/ies_num_inf.ies", ies_with(13, "100 inf 50"))
w("ies/ies_negative_candela.ies", ies_with(14, "100 -70 40"))
w("ies/ies_angles_backwards.ies", ies_with(11, "0 90 45"))
w("ies/ies_tilt_file_missing.ies", ies_with(4, "TILT=no_such_tilt_file.dat"))
w("ies/ies_tilt_file_is_dir.ies", ies_with(4, "TILT=."))
w("ies/ies_empty.ies", "")
w("ies/ies_garbage.ies", bytes((i * 197 + 13) % 256 for i in range(3000)))
w("ies/ies_only_tilt.ies", "TILT=NONE\n")
w("ies/ies_type_a.ies", ies_with(9, "1 1000 1 3 2 3 2 0 0 0"))

# ---------- EULUMDAT: a complete file (Isym 1: one plane stored), cut at its sections ----------
ldt = ["luxcalc corpus", "1", "1", "4", "90", "3", "45", "report", "name", "number", "file", "date",
       "100", "100", "10", "100", "100", "10", "10", "10", "10", "100", "80", "1", "0", "1",
       "1", "LED", "1000", "3000", "80", "10",
       "0", "0", "0", "0", "0", "0", "0", "0", "0", "0",
       "0", "90", "180", "270",   # 43-46 C angles (Mc 4)
       "0", "45", "90",           # 47-49 gamma angles (Ng 3)
       "100", "50", "10"]         # 50-52 one plane (Isym 1)
# lines: 1 company, 2 Ityp, 3 Isym, 4 Mc, 5 Dc, 6 Ng, 7 Dg, 8-12 texts, 13-21 dimensions, 22 DFF,
# 23 LORL, 24 conversion factor, 25 tilt, 26 lamp sets, 27-32 set 1, 33-42 direct ratios
w("good/reference.ldt", "\r\n".join(ldt) + "\r\n")
for n, name in [(1, "company"), (4, "mc"), (12, "date"), (21, "dimensions"), (26, "lamp_sets"),
                (30, "mid_lamp_set"), (42, "direct_ratios"), (44, "mid_c_angles"), (46, "c_angles"),
                (49, "gamma_angles"), (51, "mid_intensities")]:
    w("ldt/ldt_trunc_%02d_%s.ldt" % (n, name), "\r\n".join(ldt[:n]) + "\r\n")
def ldt_with(i, v):
    lines = list(ldt)
    lines[i - 1] = v
    return lines
# Isym 0, Mc 3600, Ng 18001: every angle present, three intensities instead of 3600 x 18001
huge = list(ldt)
huge[2], huge[3], huge[4], huge[5], huge[6] = "0", "3600", "0.1", "18001", "0.01"
huge = huge[:42] + ["%g" % (0.1 * i) for i in range(3600)] + ["%g" % (0.01 * j) for j in range(18001)] + ["100", "50", "10"]
w("ldt/ldt_counts_lie_huge.ldt", "\r\n".join(huge) + "\r\n")
w("ldt/ldt_isym_out_of_range.ldt", "\r\n".join(ldt_with(3, "7")) + "\r\n")
w("ldt/ldt_num_1e999.ldt", "\r\n".join(ldt_with(50, "1e999")) + "\r\n")
w("ldt/ldt_num_nan.ldt", "\r\n".join(ldt_with(50, "nan")) + "\r\n")
w("ldt/ldt_num_hexfloat.ldt", "\r\n".join(ldt_with(51, "0x1p3")) + "\r\n")
w("ldt/ldt_num_arabic_digits.ldt", "\r\n".join(ldt_with(52, "\u0661\u0662\u0663")) + "\r\n")
w("ldt/ldt_data_after_table.ldt", "\r\n".join(ldt) + "\r\n7\r\n")

# ---------- spectra ----------
w("spd/spd_empty.csv", "")
w("spd/spd_garbage.bin", bytes((i * 151 + 7) % 256 for i in range(4096)))
w("spd/spd_garbage_no_nul.csv", bytes(128 + (i * 37) % 128 for i in range(2048)))
w("spd/spd_num_1e999.csv", "nm,v\n500,1\n510,1e999\n520,1\n")
w("spd/spd_num_nan.csv", "nm,v\n500,1\n510,nan\n520,1\n")
w("spd/spd_num_hexfloat.csv", "nm,v\n500,1\n510,0x1p3\n520,1\n")
w("spd/spd_num_arabic_digits.csv", "nm,v\n500,1\n510,\u0661\u0662\u0663\n520,1\n")
w("spd/spd_wavelength_underflow.csv", "nm,v\n1e-400,1\n510,1\n520,1\n")
w("spd/spd_bom_only.csv", b"\xef\xbb\xbf")
w("spd/spd_blank_lines.csv", "\r\n\r\n  \r\n")
cg = "CGATS.17\nNUMBER_OF_FIELDS %s\nBEGIN_DATA_FORMAT\nSAMPLE_ID SPEC_400 SPEC_500 SPEC_600\nEND_DATA_FORMAT\nNUMBER_OF_SETS %s\nBEGIN_DATA\n"
w("spd/spd_cgats_sets_lie.sp", cg % ("4", "1000000") + "1 0.1 0.2 0.3\nEND_DATA\n")
w("spd/spd_cgats_fields_lie.sp", cg % ("1000000", "1") + "1 0.1 0.2 0.3\nEND_DATA\n")
w("spd/spd_cgats_truncated.sp", cg % ("4", "2") + "1 0.1 0.2 0.3\n2 0.1\n")
w("spd/spd_rows_count_mismatch.csv", "id,400,500,600\nA,1,2,3\nB,1,2\n")

# ---------- scenes ----------
S = ("[scene]\ntitle = corpus\n\n[luminaire lamp]\ntype = point\nposition = 0 m, 0 m, 3 m\nflux = 1000 lm\n\n"
     "[receiver p]\ntype = point\nposition = 0 m, 0 m, 0 m\n")
w("good/reference.scene", S)
w("scene/scene_empty.scene", "")
w("scene/scene_garbage.scene", bytes((i * 89 + 3) % 256 for i in range(2048)))
w("scene/scene_num_1e999.scene", S.replace("flux = 1000 lm", "flux = 1e999 lm"))
w("scene/scene_num_nan.scene", S.replace("flux = 1000 lm", "flux = nan lm"))
w("scene/scene_num_hexfloat.scene", S.replace("flux = 1000 lm", "flux = 0x1p3 lm"))
w("scene/scene_num_arabic_digits.scene", S.replace("flux = 1000 lm", "flux = \u0661\u0662\u0663 lm"))
w("scene/scene_unknown_section.scene", S + "\n[teapot]\nspout = 1 m\n")
w("scene/scene_missing_include.scene", "include = no_such_file.scene\n" + S)
w("scene/scene_missing_ies.scene", S.replace("type = point\nposition = 0 m, 0 m, 3 m\nflux = 1000 lm",
                                             "type = file\nfile = no_such_file.ies\nposition = 0 m, 0 m, 3 m", 1))
w("scene/scene_bad_ies.scene", S.replace("type = point\nposition = 0 m, 0 m, 3 m\nflux = 1000 lm",
                                         "type = file\nfile = ../ies/ies_num_nan.ies\nposition = 0 m, 0 m, 3 m", 1))
w("scene/scene_include_dir.scene", "include = .\n" + S)
w("scene/scene_truncated_section.scene", S + "\n[luminaire")
# a point source closer to the receiver than double arithmetic resolves (d^2 underflows below 1.5e-154 m:
# it gave 0 lx), and one on the receiver point (undefined)
w("scene/scene_lamp_1e-162m.scene", S.replace("position = 0 m, 0 m, 3 m", "position = 0 m, 0 m, 1e-162 m"))
w("scene/scene_lamp_on_receiver.scene", S.replace("position = 0 m, 0 m, 3 m", "position = 0 m, 0 m, 0 m"))

# ---------- EXR ----------
w("exr/exr_empty.exr", "")
w("exr/exr_garbage.exr", bytes((i * 61 + 11) % 256 for i in range(4096)))
w("exr/exr_text.exr", "this is not an OpenEXR file\n")
w("exr/exr_magic_only.exr", b"\x76\x2f\x31\x01")
furnace = open("../../samples/envmaps/furnace.exr", "rb").read()
w("exr/exr_truncated_header.exr", furnace[:60])
w("exr/exr_truncated_data.exr", furnace[:len(furnace) - 40])
reg = "../fuzz/regressions/exr"
# the fuzzer's 414-byte file declaring a 16777280 x 32 display window (named: the folder grows)
w("exr/exr_windows_lie.exr", open(os.path.join(reg, "oom-2d81a3b639d5c85ea7d89213e45fd9c69ce1ef73"), "rb").read())
# windows of 100000 x 100000 pixels (1e10, 40 GB of RGB float) in a file of a few hundred bytes:
# refused before anything is allocated (the 1e9-pixel bound of src/core/limits.h)
def set_box(data, name, xmax, ymax):
    key = name.encode() + b"\0box2i\0"
    at = data.index(key) + len(key) + 4
    return data[:at] + (0).to_bytes(4, "little") * 2 + xmax.to_bytes(4, "little") + ymax.to_bytes(4, "little") + data[at + 16:]
w("exr/exr_window_1e10.exr", set_box(set_box(furnace, "dataWindow", 99999, 99999), "displayWindow", 99999, 99999))
