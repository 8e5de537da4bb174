#!/usr/bin/env bash
# Keyword remap x through the runner, the cases too long for the C suite's
# sanitizer and valgrind runs (tests/test_remap.c has the lattices, a material
# point and the words; docs/servo_bc.md, "Remap"):
# - (T) on the touching frictionless 5 x 5 lattice, F = diag(0.99, 1) in 3
#   increments, tight (test_accuracy.c): P11 = -kn eps (N - 1)/(N - 3/2) to
#   1e-5, with and without remap;
# - a 60-disc frictionless irregular packing (unique equilibrium), one
#   increment of F = [[0.9995, 0.0005], [0, 0.9998]]: the rows with and
#   without remap within twice the preset's accuracy of each other, relative
#   to the largest |P| ((D) tight 1e-6, (P) balanced 1e-4).
# Prints "N passed, N failed". Usage: remap.sh [BUILD-DIR]
set -u
CHECKS_LABEL=remap
. "$(dirname "$0")/shell_checks.sh"
run() {  # NAME PACKING_LINES WORDS
  printf 'dimension 2\n%s\ncontact frictional kn 1e4 ks 0 mu 0\ndensity 2e3\ntimestep 1e-5\nservo_bc %s file %s/%s.csv\nrun\n' \
    "$2" "$3" "$tmp" "$1" > "$tmp/$1.sbc"
  (cd "$tmp" && "$B/servo-bc" "$1.sbc" > "$1.log" 2>&1) || { echo "  $1: $(tail -n 1 "$tmp/$1.log")"; return 1; }
}
for rm in none x; do
  if run "T_$rm" "lattice square 5 5 spacing 2e-3 radius 1e-3" "T F 0.99 0 0 1 increments 3 accuracy tight remap $rm"; then
    got=$(awk -F, "$COLUMNS_AWK"'NR > 1 && $col("increment") > 0 { n++; eps = 1 - $col("F11"); want = -1e4 * eps * 4 / 3.5
        d = ($col("P11") - want) / want; if (d < 0) d = -d; if (d > m) m = d } END { printf "%d %.3g", n, m }' "$tmp/T_$rm.csv")
    set -- $got
    if [ "$1" = 3 ] && awk -v m="$2" 'BEGIN { exit !(m <= 1e-5) }'; then
      ok "(T) touching frictionless 5 x 5 lattice, remap $rm: P11 = -kn eps (N-1)/(N-3/2) to $2"
    else
      no "(T) lattice, remap $rm: ${1:-0} rows of 3, P11 off by ${2:-?}"
    fi
  else
    no "(T) lattice, remap $rm: the run stopped"
  fi
done
packing="generate periodic n0 60 rmin 1e-3 polydispersity 2 seed 3 strain 0.01
write_packing text $tmp/irregular.txt"
for bc in D P; do
  preset=$([ $bc = D ] && echo tight || echo balanced)
  accuracy=$([ $bc = D ] && echo 1e-6 || echo 1e-4)
  for rm in none x; do
    run "${bc}_$rm" "$packing" "$bc F 0.9995 0.0005 0 0.9998 increments 1 accuracy $preset remap $rm" || true
    packing="read_packing $tmp/irregular.txt"
  done
  got=$(paste -d, "$tmp/${bc}_none.csv" "$tmp/${bc}_x.csv" 2>/dev/null | awk -F, "$COLUMNS_AWK"'NR > 1 { w = NF / 2; n++
      for (c = col("P11"); c <= col("P22"); c++) { d = $c - $(c + w); if (d < 0) d = -d; if (d > m) m = d; a = $c < 0 ? -$c : $c; if (a > S) S = a }
      if ($col("increment") > 0) { s0 += $col("relax_steps"); s1 += $(col("relax_steps") + w) } }
    END { printf "%d %.3g %d %d", n, (S > 0 ? m / S : 1), s1, s0 }')
  set -- $got
  if [ "${1:-0}" = 2 ] && awk -v m="$2" -v a="$accuracy" 'BEGIN { exit !(m <= 2 * a) }'; then
    ok "frictionless irregular packing ($bc), $preset: rows with and without remap $2 of max |P| apart; DEM steps of the increment $3 and $4"
  else
    no "frictionless irregular packing ($bc), $preset: ${1:-0} rows of 2, ${2:-?} of max |P| apart (limit 2 x $accuracy)"
  fi
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
