#!/bin/bash
# FE^2 on irregular frictional points (in make fe2-patch; docs/fe2.md, "Irregular points"): fe2/irregular_shear.py,
# a 2 x 2 mesh of 55-disc frictional points sheared by u_x = 0.002 H in 3 steps, (D) and (P) points with the
# condensed tangent. (D): every step within 6 macro iterations to 1e-6 of the reaction, the last contraction
# quadratic (below a tenth of the one before). (P): the path completes, every committed step at 1e-6; the steps
# within 6 iterations and quadratic at the end are counted (docs/fe2.md gives which are not). A line per macro
# iteration is printed. Prints "N passed, N failed". Usage: fe2_irregular.sh LIBSERVO_BC RUNNER [PYTHON]
lib=${1:?usage: fe2_irregular.sh LIBSERVO_BC RUNNER [PYTHON]}
runner=${2:?}; py=${3:-python3}
here=$(cd "$(dirname "$0")" && pwd)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
passed=0 failed=0
check() { if [ "$1" = 0 ]; then passed=$((passed + 1)); echo "fe2 irregular: $2"; else failed=$((failed + 1)); echo "FAIL fe2 irregular: $2"; fi; }
SERVO_BC_LIB=$lib timeout 900 "$py" "$here/../fe2/irregular_shear.py" --runner "$runner" --bc D,P --out "$out" \
  > "$out/log" 2>&1
check $? "fe2/irregular_shear.py runs ($(grep -c 'iteration' "$out/log") progress lines; $(grep 'steps committed' "$out/log" | tr '\n' ' '))"
csv=$out/irregular_shear.csv
[ "$(head -1 "$csv" 2>/dev/null)" = "bc,step,t,iterations,residuals,force_x,force_y,seconds" ]
check $? "irregular_shear.csv has its columns"
# per condition: steps, steps within 6 iterations, steps whose last contraction is below a tenth of the one
# before, the largest final residual, the last t
summary() {
  awk -F, -v bc="$1" 'NR > 1 && $1 == bc {
      n++; m = split($5, h, ";"); last = h[m] + 0; if (last > worst) worst = last
      if ($4 <= 6) few++
      if (m >= 3 && h[m - 1] > 0 && h[m - 2] > 0 && h[m] / h[m - 1] < 0.1 * h[m - 1] / h[m - 2]) quad++
      else if (m == 2 && h[2] < 1e-3 * h[1]) quad++
      t = $3 }
    END { printf "%d %d %d %.3e %s", n, few, quad, worst, t }' "$csv" 2>/dev/null
}
read -r n few quad worst t <<< "$(summary D)"
[ "$n" = 3 ] && [ "$few" = 3 ] && [ "$quad" = 3 ] && awk -v w="$worst" 'BEGIN { exit !(w <= 1e-6) }'
check $? "(D) points: $n steps, $few within 6 macro iterations, $quad quadratic at the end, largest final residual $worst"
read -r n few quad worst t <<< "$(summary P)"
[ "${t:-0}" = 1 ] && awk -v w="$worst" 'BEGIN { exit !(w <= 1e-6) }'
check $? "(P) points: the path completes (t = ${t:-?}) in $n steps, every one to $worst of the reaction; $few within 6 macro iterations, $quad quadratic at the end"
echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
