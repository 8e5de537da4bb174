#!/usr/bin/env bash
# (T) on an irregular sphere packing (docs/frame3d.md, "(T) and the frame's
# rotations"): the packing of inputs/frame3d/irregular_P_shear.sbc (100
# spheres jammed and compressed by 0.2 %, 178 after the reconstruction, a
# frame of 132; tests/packings/irregular100_strain.txt), frictional contacts
# (kn 1e4 N/m, ks 5e3 N/m, mu 0.5), F = diag(1, 1, 0.99) in 2 increments.
# - (D) and (P) at `balanced`; (T) at `fast` with the paper's free rotation
#   and with `rotation zero`.
# - Every run finishes, F33 as prescribed on every row, Hill-Mandel within
#   each run's preset (1e-4, 1e-2).
# - The paper's (T) carries nothing here: |P33| below 1 N/m^2 on every row
#   (measured about 3e-4; frame spheres with fewer than three contacts roll).
# - With `rotation zero` it carries load: (D) >= (P) >= (T) in the step's
#   stiffness (the rise of -P33 from increment 0 to 2), and (T) at least a
#   fifth of (P)'s.
# Prints "N passed, N failed". Not under valgrind: its (T) runs take about
# 10 s natively. Usage: traction_irregular_3d.sh [BUILD-DIR]
set -u
CHECKS_LABEL="(T) irregular 3D:"
. "$(dirname "$0")/shell_checks.sh"
# run NAME WORDS: the case under WORDS into $tmp/NAME.csv
run() {
  cat > "$tmp/$1.sbc" <<EOS
dimension 3
read_packing $top/tests/packings/irregular100_strain.txt
contact frictional kn 1e4 ks 5e3 mu 0.5
density 2650
timestep 9e-6
servo_bc $2 F 1 0 0 0 1 0 0 0 0.99 increments 2 file $tmp/$1.csv
run
EOS
  if (cd "$tmp" && "$B/servo-bc" "$1.sbc" > "$1.log" 2>&1); then ok "$1: $(grep finished "$tmp/$1.log")"
  else no "$1: the run stopped: $(tail -n 1 "$tmp/$1.log")"; fi
}
run D "D accuracy balanced"
run P "P accuracy balanced"
run T_free "T accuracy fast"
run T_zero "T accuracy fast rotation zero"
# rows NAME HM-LIMIT: per row, "ok"/"bad" and the row's check; then "rise VALUE" and "max_P33 VALUE"
rows() {
  awk -F, -v hm_limit="$2" "$COLUMNS_AWK"'function abs(a) { return a < 0 ? -a : a }
    NR > 1 { n++; k = $col("increment"); p = $col("P33"); hm = $col("hill_mandel"); b = ""
      if (abs($col("F33") - (1 - 0.005 * k)) > 1e-12 || abs($col("F11") - 1) > 1e-12 || abs($col("F22") - 1) > 1e-12) b = b " F"
      if (abs(hm) > hm_limit) b = b " hill_mandel " hm
      if (k == 0) p0 = p; if (k == 2) p2 = p; if (abs(p) > big) big = abs(p)
      if (b == "") printf "ok increment %d: P33 %.6g N/m^2, HM %.2g\n", k, p, hm; else printf "bad increment %d:%s\n", k, b }
    END { if (n != 3) printf "bad %d rows, expected 3\n", n; printf "rise %.17g\nmax_P33 %.17g\n", p0 - p2, big }' "$tmp/$1.csv" 2>/dev/null ||
    echo "bad no results file"
}
declare -A rise max
for name in D P T_free T_zero; do
  case $name in D | P) limit=1e-4 ;; *) limit=1e-2 ;; esac
  while read -r verdict line; do
    case $verdict in
      ok) ok "$name $line" ;;
      rise) rise[$name]=$line ;;
      max_P33) max[$name]=$line ;;
      *) no "$name $line" ;;
    esac
  done < <(rows $name $limit)
done
verdict=$(awk -v d="${rise[D]:-nan}" -v p="${rise[P]:-nan}" -v t="${rise[T_zero]:-nan}" -v f="${max[T_free]:-nan}" \
  'BEGIN { ok = (f + 0 == f && f < 1) ? "ok" : "bad"
           printf "%s the paper'"'"'s free rotation: max |P33| %.3g N/m^2 (below 1)\n", ok, f
           ok = (d + 0 == d && p + 0 == p && t + 0 == t && d >= p && p >= t && t >= 0.2 * p) ? "ok" : "bad"
           printf "%s rotation zero: -dP33 (D) %.6g >= (P) %.6g >= (T) %.6g N/m^2, (T)/(P) %.3f (at least 0.2)\n", ok, d, p, t, (p > 0 ? t / p : 0) }')
while read -r v line; do if [ "$v" = ok ]; then ok "$line"; else no "$line"; fi; done <<< "$verdict"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
