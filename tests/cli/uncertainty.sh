# uncertainty.sh - `luxcalc spd --uncertainty`: the columns (NAME_u, _lo, _hi after each quantity,
# the plain values unchanged), the table's ±, json's budget, the methods, reproducible trials, the
# per-wavelength uncertainties from a column, a second file or a covariance matrix (the same GUM
# result three ways), bad input (a matrix that is not positive semi-definite, a grid that does not
# match, an unknown term), and batches.
. tests/cli/lib.sh
L=samples/spd/lamp.csv
D=tests/data/uncertainty

run spd --format csv "$L"
plain=$out
run spd --uncertainty 1% --uncertainty-method gum --format csv "$L"
expect_rc 0 "gum exits 0"
hdr=$(printf '%s\n' "$out" | head -n 1)
case "$hdr" in
  file,spectrum,X,X_u,X_lo,X_hi,Y,Y_u,Y_lo,Y_hi,Z,Z_u,Z_lo,Z_hi,x,x_u,x_lo,x_hi,*,cct_K,cct_K_u,cct_K_lo,cct_K_hi,*,radiant,radiant_u,radiant_lo,radiant_hi,method)
    ok "columns: each quantity then NAME_u, NAME_lo, NAME_hi" ;;
  *) notok "columns: each quantity then NAME_u, NAME_lo, NAME_hi" "$hdr" ;;
esac
# the plain columns keep their values
p=$(printf '%s\n' "$plain" | sed -n 2p | cut -d, -f3,10)
q=$(printf '%s\n' "$out" | awk -F, 'NR==1{for(i=1;i<=NF;i++){if($i=="X")a=i; if($i=="cct_K")b=i}} NR==2{print $a","$b}')
[ "$p" = "$q" ] && ok "the values are the plain run's" || notok "the values are the plain run's" "$p vs $q"
# GUM: u(Y)/Y of 1 % uncorrelated noise is well below 1 % (the noise averages out over 81 samples)
v=$(printf '%s\n' "$out" | awk -F, 'NR==1{for(i=1;i<=NF;i++){if($i=="Y")a=i; if($i=="Y_u")b=i; if($i=="Y_lo")c=i}} NR==2{printf "%.6f %.12f", $b/$a, ($a-$c)/$b}')
set -- $v
awk -v r="$1" 'BEGIN{exit !(r > 0.0005 && r < 0.005)}' && ok "u(Y)/Y of 1 % noise" || notok "u(Y)/Y of 1 % noise" "$1"
awk -v k="$2" 'BEGIN{d=k-1.959963984540054; if(d<0)d=-d; exit !(d < 1e-9)}' && ok "GUM interval y - 1.96 u" || notok "GUM interval y - 1.96 u" "$2"

# Monte Carlo: the same seed the same bits, another seed other trials
run spd --uncertainty '1%+scale=2%+shift=0.2nm' --trials 3000 --format csv "$L"
a=$out
run spd --uncertainty '1%+scale=2%+shift=0.2nm' --trials 3000 --format csv "$L"
[ "$a" = "$out" ] && ok "Monte Carlo reproducible" || notok "Monte Carlo reproducible" "two runs differ"
run spd --uncertainty '1%+scale=2%+shift=0.2nm' --trials 3000 --seed 5 --format csv "$L"
[ "$a" != "$out" ] && ok "another seed, other trials" || notok "another seed, other trials" "same output"

# the table: value ± u [lo, hi], the u, lo, hi columns left out
run spd --uncertainty 1% --trials 2000 "$L"
expect_out_match '^cct_K +[0-9.]+ ± [0-9.]+ K  \[[0-9.]+, [0-9.]+\]$' "table: cct_K value ± u K [lo, hi]"
case "$out" in *cct_K_u*) notok "table: no _u rows" "$out" ;; *) ok "table: no _u rows" ;; esac

# json: the budget, the validation, the trials
run spd --uncertainty '1%+shift=0.2nm' --uncertainty-method both --trials 20000 --format json "$L"
expect_rc 0 "both exits 0"
expect_out_match '"uncertainty": \{"method": "both", "trials": 20000' "json: method and trials"
expect_out_match '"cct_K": \{"value": [0-9.]+, "u": [0-9.]+' "json: cct_K's u"
expect_out_match '"budget": \[\{"component": "(1%|shift=0.2nm)", "u": ' "json: the GUM budget names components"
expect_out_match '"gum_valid": (true|false|null), "d_low": ' "json: JCGM 101 8 validation"
run spd --uncertainty '1%+shift=0.2nm' --uncertainty-method both --trials 20000 --format csv "$L"
expect_out_match '^file,.*,cct_K,cct_K_u,cct_K_lo,cct_K_hi,cct_K_gum_u,cct_K_gum_valid,' "csv: _gum_u and _gum_valid with both"

# --explain: the trials and why
run spd --uncertainty 1% --digits 1 --explain --format csv "$L"
expect_rc 0 "adaptive exits 0"
expect_err_match 'adaptive \(JCGM 101 7.9\): sequences of 10000' "explain: the adaptive procedure"
expect_err_match '^  stable after [0-9]+ trials' "explain: stable after N trials"
expect_err_match 'largest 2 s / delta' "explain: trials against tolerance"

# the same uncertainties three ways: a column in per cent, a second file, a diagonal covariance
run spd --uncertainty 'column=u_pct:%' --uncertainty-method gum --format csv "$D/lamp_u.csv"
expect_rc 0 "column= exits 0"
rows=$(printf '%s\n' "$out" | awk 'END{print NR - 1}')
[ "$rows" = 1 ] && ok "the uncertainty column is not a spectrum" || notok "the uncertainty column is not a spectrum" "$rows rows"
c1=$(printf '%s\n' "$out" | awk -F, 'NR==1{for(i=1;i<=NF;i++) if($i=="cct_K_u")c=i} NR==2{print $c}')
run spd --columns 1,2 --uncertainty "file=$D/lamp_u_abs.csv" --uncertainty-method gum --format csv "$D/lamp_u.csv"
c2=$(printf '%s\n' "$out" | awk -F, 'NR==1{for(i=1;i<=NF;i++) if($i=="cct_K_u")c=i} NR==2{print $c}')
run spd --columns 1,2 --uncertainty "covariance=$D/lamp_cov_diag.csv" --uncertainty-method gum --format csv "$D/lamp_u.csv"
c3=$(printf '%s\n' "$out" | awk -F, 'NR==1{for(i=1;i<=NF;i++) if($i=="cct_K_u")c=i} NR==2{print $c}')
awk -v a="$c1" -v b="$c2" -v c="$c3" 'BEGIN{exit !(a > 0 && (a-b)^2 < (1e-6*a)^2 && (a-c)^2 < (1e-6*a)^2)}' &&
  ok "column=, file= and covariance= agree" || notok "column=, file= and covariance= agree" "$c1 $c2 $c3"

# bad input
run spd --columns 1,2 --uncertainty "covariance=$D/cov_not_psd.csv:rel" --format csv "$D/lamp_u.csv"
expect_rc 2 "a covariance that is not positive semi-definite exits 2"
expect_err_match 'not positive semi-definite: 1 negative eigenvalue, the smallest -2e-05' "and says so, with its eigenvalue"
run spd --uncertainty "covariance=$D/lamp_cov_diag.csv" --format csv samples/spd/led_batch.csv
expect_rc 2 "a covariance on another grid exits 2"
expect_err_match "spectrum 'led_warm': no uncertainty: covariance=.*: its grid is not the spectrum's: 81 samples over 380-780 nm, the spectrum's 401 over 380-780 nm" "and says which grids"
run spd --uncertainty 'colour=1%' "$L"
expect_rc 1 "an unknown term is a usage error"
expect_err_match "^luxcalc: spd: uncertainty 'colour=1%': unknown key" "unknown term message"
run spd --uncertainty 'noise=-1' "$L"
expect_rc 1 "a negative uncertainty is refused"
run spd --trials 100 "$L"
expect_rc 1 "--trials without --uncertainty"
run spd --uncertainty 1% --trials 1 "$L"
expect_rc 1 "--trials 1 refused"
run spd --uncertainty 1% --trials 1e9 "$L"
expect_rc 2 "trials beyond 2 GB of values are refused"
expect_err_match "1000000000 trials of 13 quantities would hold 104.0 GB of values; at most [0-9]+ trials" "and say how many fit"
run spd --uncertainty 'column=nope' "$D/lamp_u.csv"
expect_rc 2 "column= naming no column exits 2"
expect_err_match "no column 'nope' \(the file's columns: 'lamp', 'u_pct'\)" "and lists the columns"

# a batch: every spectrum its row, the same columns
run spd --uncertainty 1% --uncertainty-method gum --metrics cri --format csv samples/spd/led_batch.csv
expect_rc 0 "batch exits 0"
n=$(printf '%s\n' "$out" | awk -F, 'NR==1{for(i=1;i<=NF;i++) if($i=="cri_ra_u")c=i} NR>1 && $c > 0 {k++} END{print k+0}')
[ "$n" = 4 ] && ok "every spectrum of the batch has u(Ra)" || notok "every spectrum of the batch has u(Ra)" "$n rows"
# a large rows-layout batch (1100 spectra) is streamed, each spectrum on the cores in turn: its rows
# are the rows the general reader gives the same spectra (the trials depend on the seed alone)
awk 'BEGIN{printf "id"; for(l=380;l<=780;l+=5) printf ",%d", l; print "";
  for(i=0;i<1100;i++){printf "s%d", i; for(l=380;l<=780;l+=5){a=(l-450-i%20)/12; p=(l-580)/50; printf ",%.6f", exp(-0.5*a*a)+0.8*exp(-0.5*p*p)} print ""}}' > "$T/big.csv"
(head -n 1 "$T/big.csv"; sed -n 3p "$T/big.csv") > "$T/one.csv"
for m in "--uncertainty-method gum" "--trials 1000"; do
  run spd --uncertainty '1%+shift=0.2nm' $m --format csv "$T/big.csv"
  rows=$(printf '%s\n' "$out" | awk 'END{print NR - 1}')
  a=$(printf '%s\n' "$out" | sed -n 3p | cut -d, -f2-)
  run spd --uncertainty '1%+shift=0.2nm' $m --format csv "$T/one.csv"
  b=$(printf '%s\n' "$out" | sed -n 2p | cut -d, -f2-)
  [ "$rows" = 1100 ] && [ -n "$a" ] && [ "$a" = "$b" ] && ok "streamed batch ($m): every row, the general reader's values" ||
    notok "streamed batch ($m): every row, the general reader's values" "$rows rows; $a vs $b"
done
exit 0
