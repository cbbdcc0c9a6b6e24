# metrics.sh - `luxcalc spd --metrics`: the CLI.md column names and order, values against the
# library's tested references (CIE published Ra, colour-science 0.4.7), refusals, units.
. tests/cli/lib.sh
S=samples/spd/cie_illuminants.csv   # A, D65, FL2, FL11 (CIE 015:2018 tables)

run spd --metrics all --format csv "$S"
expect_rc 0 "metrics all exits 0"
hdr=$(printf '%s\n' "$out" | head -n 1)
want='cri_ra,cri_r1,cri_r2,cri_r3,cri_r4,cri_r5,cri_r6,cri_r7,cri_r8,cri_r9,cri_r10,cri_r11,cri_r12,cri_r13,cri_r14,tm30_rf,tm30_rg,melanopic_edi_lx,melanopic_der,alphaopic_sc,alphaopic_mc,alphaopic_lc,alphaopic_rh,alphaopic_mel'
case "$hdr" in
  file,spectrum,X,Y,Z,x,y,u_prime,v_prime,cct_K,duv,ler_lm_per_W,scotopic_Y,sp_ratio,*",$want,"*) ok "CLI.md column order" ;;
  *) notok "CLI.md column order" "header: $hdr" ;;
esac
# CIE 13.3 Ra of FL2 is published as 64 (colour-science 0.4.7: 64.2337); FL11 83 (82.8591)
expect_field 3 cri_ra 64.23 0.3 "FL2 Ra"
expect_field 4 cri_ra 82.86 0.3 "FL11 Ra"
# R9 of FL2: -83.6 (colour-science 0.4.7 -83.5875)
expect_field 3 cri_r9 -83.6 1 "FL2 R9"
# TM-30 FL2: Rf 70.1, Rg 86.4 (colour-science 0.4.7: 70.1208, 86.4163)
expect_field 3 tm30_rf 70.12 0.2 "FL2 Rf"
expect_field 3 tm30_rg 86.42 0.2 "FL2 Rg"
# A and D65 are their own references: Ra 100 (this file starts at 380 nm: the spectrum is zero
# in 360-375 nm where the full D65 table and the D-series reference are not, which costs D65 0.02)
expect_field 1 cri_ra 100 0.01 "A Ra"
expect_field 2 cri_ra 100 0.03 "D65 Ra"
# melanopic DER of A 0.4957 +- 0.001 (CIE S 026 toolbox value quoted by the issue); D65: 1
expect_field 1 melanopic_der 0.4957 0.001 "A melanopic DER"
expect_field 2 melanopic_der 1 0.001 "D65 melanopic DER"
expect_field 1 cri_valid 1 0 "A CRI valid"

# groups and single columns
run spd --metrics tm30_rf,melanopic_edi_lx --format csv "$S"
hdr=$(printf '%s\n' "$out" | head -n 1)
case "$hdr" in *",method,tm30_rf,melanopic_edi_lx") ok "selected columns in contract order" ;; *) notok "selected columns in contract order" "$hdr" ;; esac
run spd --metrics alphaopic --format csv "$S"
expect_out_match 'alphaopic_mel' "alphaopic group"
run spd --metrics colour --format csv "$S"
expect_rc 1 "unknown metric is a usage error"
expect_err_match "^luxcalc: spd: --metrics: unknown group or column 'colour'" "unknown metric message"

# melanopic EDI of D65 irradiance: E_mel / 1.3262 mW/lm equals E_v for D65 (DER 1, CIE S 026), so
# melanopic_edi_lx ~ Y in lx with --unit W/m2/nm
run spd --unit W/m2/nm --metrics melanopic_edi_lx --format csv "$S"
y=$(printf '%s\n' "$out" | awk -F, 'NR==3{print $4}')
expect_field 2 melanopic_edi_lx "$y" "$(awk -v y="$y" 'BEGIN{print y*1e-3}')" "D65 EDI equals its illuminance"

# far off the locus: a green narrow band -> cri/tm30 empty, reason on stderr, exit 0
printf 'wavelength_nm,green\n' >"$T/g.csv"
awk 'BEGIN{for(l=380;l<=780;l+=5) printf "%d,%.6g\n", l, exp(-0.5*((l-530)/12)^2)}' >>"$T/g.csv"
run spd --metrics cri_ra,tm30_rf,melanopic_der --format csv "$T/g.csv"
expect_rc 0 "off-locus spectrum exits 0"
expect_err_match "Duv" "off-locus reason on stderr"
row=$(printf '%s\n' "$out" | sed -n 2p)
case "$row" in *,,,*) ok "off-locus cri/tm30 cells empty" ;; *) notok "off-locus cri/tm30 cells empty" "$row" ;; esac

# mesopic only with radiance input: 0.1 W/(sr m2 nm) flat is photopic (>5 cd/m2) -> m = 1
awk 'BEGIN{print "wavelength_nm,flat"; for(l=380;l<=780;l+=5) print l ",0.1"}' >"$T/f.csv"
run spd --unit W/sr/m2/nm --metrics mesopic --format csv "$T/f.csv"
expect_field 1 mesopic_m 1 0 "mesopic m = 1 in photopic range"

run spd --help
expect_out_match -- '--metrics LIST\|all' "help mentions --metrics"
# equivalent-daylight columns are named by what they hold (CIE S 026): with radiance input they are
# luminances; the EDI names still select them
run spd --unit W/sr/m2/nm --metrics melanopic_edi_lx,cyanopic_edi --format csv "$S"
hdr=$(printf '%s\n' "$out" | head -n 1)
case "$hdr" in *",method,melanopic_edl_cd_m2,cyanopic_edl") ok "W/sr/m2/nm: melanopic_edl_cd_m2, cyanopic_edl" ;; *) notok "W/sr/m2/nm: edl names" "$hdr" ;; esac
run spd --unit W/nm --metrics melanopic_edl_cd_m2 --format csv "$S"
case "$(printf '%s\n' "$out" | head -n 1)" in *",method,melanopic_ed_flux_lm") ok "W/nm: melanopic_ed_flux_lm" ;; *) notok "W/nm: ed_flux name" "$out" ;; esac
run spd --unit W/m2/nm --metrics melanopic_ed_intensity_cd --format csv "$S"
case "$(printf '%s\n' "$out" | head -n 1)" in *",method,melanopic_edi_lx") ok "W/m2/nm: melanopic_edi_lx" ;; *) notok "W/m2/nm: edi name" "$out" ;; esac
# a 1000 K blackbody summed at 5 nm solves to 999.99935 K (its sampling, not the solver): the range
# end holds it (the ends as a blackbody at 1000 K shows them through the same sampling); Planck's
# law in W/(sr m2 nm) at 5 nm from luxcalc blackbody, whose values test_colorimetry.c checks
run blackbody --temperature 1000K --range 360:830:5
printf '%s\n' "$out" > "$T/bb1000.csv"
run spd --metrics cri_ra,tm30_rg --format csv "$T/bb1000.csv"
expect_field 1 cct_K 1000 1e-3 "1000 K blackbody at 5 nm: cct_K 999.99935, not empty"
expect_field 1 cri_ra 100 1e-4 "its Ra 100"
# every empty metric says why: TM-30 Rg at 1000 K (empty hue bins), mesopic without luminance, CCT
expect_err_match "tm30_rg .*empty: hue bins [0-9, ]+ hold none of the 99 colour evaluation samples" "an empty Rg says why"
run spd --metrics mesopic --format csv "$S"
expect_err_match "mesopic columns empty: they need luminance \(--unit W/sr/m2/nm" "empty mesopic columns say why"
printf 'nm,green\n500,0\n520,1\n540,0\n' > "$T/green.csv"
run spd --format csv "$T/green.csv"
expect_err_match "cct_K and duv empty: Duv [0-9.]+ is beyond 0.05" "an empty CCT says why"
run spd -q --format csv "$T/green.csv"
if [ -z "$err" ]; then ok "-q silences the notes"; else notok "-q silences the notes" "$err"; fi
# empty ANSI bins say why: a 10000 K blackbody (Planck's law, Duv 0) is beyond the warmest-to-coolest
# range of ANSI C78.377-2017 (nominal 2200-6500 K: 6530 +- 510 K at most); a 4000 K one (Duv 0,
# within 0.006 of the 3985 K category's target 0.001) is binned, with nothing said
run blackbody --temperature 10000K --range 380:780:5
printf '%s\n' "$out" > "$T/bb10000.csv"
run spd --metrics binning --format csv "$T/bb10000.csv"
expect_err_match "binning_ansi_\* and binning_flex_\* empty: CCT 99[0-9.]+ K, Duv [-0-9.]+ lies in no quadrangle" "empty ANSI bins say why"
run blackbody --temperature 4000K --range 380:780:5
printf '%s\n' "$out" > "$T/bb4000.csv"
run spd --metrics binning --format csv "$T/bb4000.csv"
expect_out_match ',4000,' "4000 K blackbody: binned in the 4000 K category"
if printf '%s\n' "$err" | grep -q 'binning'; then notok "a binned light: nothing said" "$err"; else ok "a binned light: nothing said"; fi
