#!/usr/bin/env bash
# Keyword update newton through the runner, on a packing with one
# equilibrium (docs/servo_bc.md, "Newton"; tests/test_newton.c has the
# lattices' closed forms): the 232-disc frictionless irregular packing of
# bench/newton_servo.sh (`generate periodic n0 200 ... strain 0.01`, seal yes)
# under (P) at `balanced`, F12 to 0.002 in 2 increments (before its first
# rearrangement): the rows of update newton and update secant within twice
# the preset's accuracy (1e-4) of each other at every increment, relative to
# the largest |P|; the servo iterations of both reported. (Frictionless (T)
# on an irregular packing is not a case: neither rule certifies it.)
# Prints "N passed, N failed". Usage: newton.sh [BUILD-DIR]
set -u
CHECKS_LABEL=newton
. "$(dirname "$0")/shell_checks.sh"
run() {  # NAME PACKING_LINES WORDS
  printf 'dimension 2\n%s\ncontact frictional kn 1e4 ks 0 mu 0\ndensity 2e3\ntimestep 7.5e-5\nservo_bc %s file %s/%s.csv\nrun\n' \
    "$2" "$3" "$tmp" "$1" > "$tmp/$1.sbc"
  (cd "$tmp" && "$B/servo-bc" "$1.sbc" > "$1.log" 2>&1) || { echo "  $1: $(tail -n 1 "$tmp/$1.log")"; return 1; }
}
packing="generate periodic n0 200 rmin 0.67e-3 polydispersity 2 seed 1 strain 0.01
write_packing text $tmp/irregular.txt"
for bc in P; do
  preset=balanced
  accuracy=1e-4
  for rule in secant newton; do
    run "${bc}_$rule" "$packing" "$bc F 1 0.002 0 1 increments 2 accuracy $preset seal yes update $rule" || true
    packing="read_packing $tmp/irregular.txt"
  done
  got=$(paste -d, "$tmp/${bc}_secant.csv" "$tmp/${bc}_newton.csv" 2>/dev/null | awk -F, "$COLUMNS_AWK"'NR > 1 { w = NF / 2; n++
      for (c = col("P11"); c <= col("P22"); c++) { d = $c - $(c + w); if (d < 0) d = -d; if (d > m) m = d; a = $c < 0 ? -$c : $c; if (a > S) S = a }
      if ($col("increment") > 0) { i0 += $col("iterations"); i1 += $(col("iterations") + w) } }
    END { printf "%d %.3g %d %d", n, (S > 0 ? m / S : 1), i0, i1 }')
  set -- $got
  if [ "${1:-0}" = 3 ] && awk -v m="$2" -v a="$accuracy" 'BEGIN { exit !(m <= 2 * a) }'; then
    ok "frictionless irregular packing ($bc), $preset: rows of secant and newton $2 of max |P| apart; servo iterations of the 2 increments $3 and $4"
  else
    no "frictionless irregular packing ($bc), $preset: ${1:-0} rows of 3, ${2:-?} of max |P| apart (limit 2 x $accuracy)"
  fi
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
