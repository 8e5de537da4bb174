#!/usr/bin/env bash
# scripts/path_error.awk (the error measure of bench/speed_accuracy.sh)
# against closed forms on synthetic servo_bc CSVs. Prints "N passed, N failed".
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
# check NAME GOT WANT TOL: |GOT - WANT| <= TOL
check() {
  if awk -v g="$2" -v w="$3" -v t="$4" 'BEGIN { d = g - w; exit !((d < 0 ? -d : d) <= t) }'; then
    pass=$((pass + 1))
  else
    fail=$((fail + 1)); echo "FAIL $1: got $2, expected $3 within $4"
  fi
}
err() { awk -F, -f "$top/scripts/columns.awk" -f "$top/scripts/first_peak.awk" -f "$top/scripts/path_error.awk" "$1" "$2"; }
# csv FILE AWK-BODY: rows k = 0..K of a servo_bc CSV with F12 = -0.01 k; the
# body sets s11 s12 s22 from k (s21 = s12)
csv() {
  awk -v K="${3:-29}" 'BEGIN {
    print "increment,F11,F12,F21,F22,P11,P12,P21,P22,sigma11,sigma12,sigma21,sigma22,overlap_mean,rotation_mean,iterations,relax_steps,r_force,r_moment,r_deformation"
    for (k = 0; k <= K; k++) { f = -0.01 * k; '"$2"'
      printf "%d,1,%.17g,%.17g,1,0,0,0,0,%.17g,%.17g,%.17g,%.17g,0,0,0,0,0,0,0\n", k, f, f, s11, s12, s12, s22 } }' > "$1"
}
# 1. identical paths
csv "$tmp/ref.csv" 's11 = -100; s12 = 0; s22 = -100'
read -r e m n last < <(err "$tmp/ref.csv" "$tmp/ref.csv")
check "identical: path error" "$e" 0 1e-15
check "identical: max" "$m" 0 1e-12
check "identical: points" "$n" 30 0
# 2. constant offset d on sigma11 at every other reference point:
#    ||d|| / ||sigma_ref|| = d / sqrt(2 * 100^2); max = 100 d / 100 %
awk -F, 'NR == 1 || (NR % 2 == 0 && NR > 1) { if (NR > 1) $10 = $10 + 1.5; print }' OFS=, "$tmp/ref.csv" > "$tmp/run.csv"
read -r e m n last < <(err "$tmp/ref.csv" "$tmp/run.csv")
check "offset: path error" "$e" "$(awk 'BEGIN { print 1.5 / sqrt(20000) }')" 1e-12
check "offset: max, % of scale" "$m" 1.5 1e-9
check "offset: points" "$n" 15 0
check "offset: last F12" "$last" 0.28 1e-12
# 3. linear sigma12 = 1e3 |F12| sampled at midpoints: the interpolation is exact
csv "$tmp/lin.csv" 's11 = -100; s12 = -1e3 * f; s22 = -100'
csv "$tmp/mid.csv" 'f = -0.01 * (k + 0.5); s11 = -100; s12 = -1e3 * f; s22 = -100' 27
read -r e m n last < <(err "$tmp/lin.csv" "$tmp/mid.csv")
check "midpoints of a linear path: path error" "$e" 0 1e-13
check "midpoints of a linear path: max" "$m" 0 1e-11
# 4. the first peak: sigma12 rises to k = 10 and falls; an offset after the
#    peak counts in the path error only, one before it in both
csv "$tmp/peak.csv" 's11 = -100; s12 = (k <= 10 ? 10 * k : 200 - 10 * k); s22 = -100'
awk -F, 'BEGIN { OFS = "," } NR > 1 && $1 >= 15 { $13 = $13 + 2 } { print }' "$tmp/peak.csv" > "$tmp/after.csv"
read -r e m n last < <(err "$tmp/peak.csv" "$tmp/after.csv")
check "offset after the peak: max before it" "$m" 0 1e-12
awk -F, 'BEGIN { OFS = "," } NR > 1 && $1 == 10 { $13 = $13 + 2 } { print }' "$tmp/peak.csv" > "$tmp/at.csv"
read -r e m n last < <(err "$tmp/peak.csv" "$tmp/at.csv")
check "offset at the peak: max, % of scale" "$m" 2 1e-9
csv "$tmp/peakmid.csv" 'f = -0.01 * (k + 0.5); x = k + 0.5; s11 = -100; s12 = (x <= 10 ? 10 * x : 200 - 10 * x); s22 = -100' 27
read -r e m n last < <(err "$tmp/peak.csv" "$tmp/peakmid.csv")
check "midpoints of a peaked path: path error" "$e" 0 1e-13
# 5. a mixed stress stage (F12 = 0 for increments 0..3) counts as its last row
#    (F12 measured by eq. 15: zero to round-off there)
{ head -1 "$tmp/ref.csv"; for k in 0 1 2; do echo "$k,1,$k.5e-17,0,1,0,0,0,0,-7,0,0,-7,0,0,0,0,0,0,0"; done
  tail -n +2 "$tmp/ref.csv" | awk -F, 'BEGIN { OFS = "," } { $1 += 3; print }'; } > "$tmp/stage.csv"
read -r e m n last < <(err "$tmp/ref.csv" "$tmp/stage.csv")
check "stress stage: path error" "$e" 0 1e-15
check "stress stage: points" "$n" 30 0
# ... and in the reference: its last row, not its first, meets the run's
read -r e m n last < <(err "$tmp/stage.csv" "$tmp/ref.csv")
check "stress stage in the reference: path error" "$e" 0 1e-15
check "stress stage in the reference: max" "$m" 0 1e-12
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
