#!/usr/bin/env bash
# (T) on the 232-disc irregular packing (Sect. 4.2, n0 = 200, jammed at
# `strain 0.01`), the short path in make check: simple shear F12 = 0.02 in 4
# increments at the default preset with the frame seal, 0.1 of the critical
# step. The whole path to F12 = 0.5 is in docs/servo_bc.md ("Seal") and
# docs/reproduction-irregular.md. Every row meets what `balanced` states:
# F exactly as prescribed (eq. 15 restored after each force correction),
# force balance <= 1e-5, frame residual <= 1e-4, Hill-Mandel <= 1e-4; the
# packing carries the load it was jammed with (sigma11, sigma22 < 0) and
# resists the shear (sigma12 > 0), with sigma12 = sigma21 to 1e-3 of the
# stress scale (moment balance). Prints "N passed, N failed".
# Usage: traction_irregular.sh [BUILD-DIR]
set -u
CHECKS_LABEL="(T) irregular"
. "$(dirname "$0")/shell_checks.sh"
cat > "$tmp/T.sbc" <<EOF
dimension 2
generate periodic n0 200 rmin 0.67e-3 polydispersity 2 seed 1 strain 0.01
contact frictional kn 1e4 ks 2e3 mu 0.4
density 2e3
timestep 7.5e-5
servo_bc T F 1 0.02 0 1 increments 4 seal yes file $tmp/T.csv
run
EOF
if (cd "$tmp" && "$B/servo-bc" T.sbc > T.log 2>&1); then
  pass=$((pass + 1)); echo "(T) irregular, 232 discs: $(grep finished "$tmp/T.log")"
else
  fail=$((fail + 1)); echo "FAIL (T) irregular: the run stopped: $(tail -n 1 "$tmp/T.log")"
fi
while read -r verdict line; do
  if [ "$verdict" = ok ]; then pass=$((pass + 1)); echo "(T) irregular: $line"; else fail=$((fail + 1)); echo "FAIL (T) irregular: $line"; fi
done < <(awk -F, "$COLUMNS_AWK"'function abs(a) { return a < 0 ? -a : a }
  NR > 1 { n++; k = $col("increment")
    F11 = $col("F11"); F12 = $col("F12"); F21 = $col("F21"); F22 = $col("F22"); s11 = $col("sigma11")
    s12 = $col("sigma12"); s21 = $col("sigma21"); s22 = $col("sigma22"); ub = $col("unbalanced")
    fr = $col("frame_residual"); hm = $col("hill_mandel")
    bad = ""
    if (abs(F11 - 1) > 1e-12 || abs(F22 - 1) > 1e-12 || abs(F12 - 0.005 * k) > 1e-12 || abs(F21) > 1e-12) bad = bad " F"
    if (ub > 1e-5) bad = bad " unbalanced " ub
    if (fr > 1e-4) bad = bad " frame_residual " fr
    if (abs(hm) > 1e-4) bad = bad " hill_mandel " hm
    s = abs(s11) > abs(s22) ? abs(s11) : abs(s22)
    if (!(s11 < 0 && s22 < 0)) bad = bad " sigma11, sigma22 not compressive"
    if (k > 0 && !(s12 > 0)) bad = bad " sigma12 " s12 " not positive"
    if (abs(s12 - s21) > 1e-3 * s) bad = bad " sigma12 - sigma21 = " (s12 - s21)
    if (bad == "") printf "ok increment %d: F12 = %.3f, sigma11 %.4g, sigma12 %.4g N/m, unbalanced %.2g, frame residual %.2g, HM %.2g\n", k, F12, s11, s12, ub, fr, hm
    else printf "bad increment %d:%s\n", k, bad }
  END { if (n != 5) printf "bad %d rows, expected 5 (increments 0-4)\n", n }' "$tmp/T.csv" 2>/dev/null || echo "bad no results file")
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
