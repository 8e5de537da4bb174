#!/bin/bash
# make fe2-demo3d at its smallest (tests/, in make fe2-patch): fe2/triaxial.py with one hexahedron of eight (D)
# and eight (P) points of n0 15 spheres and a DNS of n0 120, two steps of u. The CSV has the columns of the curves
# run, the forces are compressive and grow with u, the DNS holds the lateral stresses P11 = P22 = -p at every row
# (tight: 1e-6), and the (D) rows are the same bits on 1 and 2 threads.
# Prints "N passed, N failed". Usage: fe2_demo3d.sh LIBSERVO_BC RUNNER PLOT [PYTHON]
lib=${1:?usage: fe2_demo3d.sh LIBSERVO_BC RUNNER PLOT [PYTHON]}
runner=${2:?}; plot=${3:?}; py=${4:-python3}
here=$(cd "$(dirname "$0")" && pwd)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
passed=0 failed=0
check() { if [ "$1" = 0 ]; then passed=$((passed + 1)); echo "fe2 demo3d: $2"; else failed=$((failed + 1)); echo "FAIL fe2 demo3d: $2"; fi; }
triaxial() { SERVO_BC_LIB=$lib timeout 600 "$py" "$here/../fe2/triaxial.py" --n0 15 --steps 2 --pressure 2e4 \
  --runner "$runner" --plot "$plot" "$@"; }
triaxial --only D,P,DNS --out "$out" > "$out/log" 2>&1
check $? "fe2/triaxial.py at its smallest runs ($(tail -1 "$out/log"))"
[ "$(head -1 "$out/triaxial.csv" 2>/dev/null)" = "u,force_D,force_P,force_DNS" ] && [ "$(wc -l < "$out/triaxial.csv")" = 4 ]
check $? "triaxial.csv: u,force_D,force_P,force_DNS and 3 rows"
awk -F, 'NR == 2 { for (i = 2; i <= 4; ++i) f[i] = $i; ok = f[2] > 0 && f[3] > 0 && f[4] > 0; next }
         NR > 2 { for (i = 2; i <= 4; ++i) { ok = ok && $i > f[i]; f[i] = $i } } END { exit !(NR == 4 && ok) }' \
  "$out/triaxial.csv" 2>/dev/null
check $? "FE2 (D), (P) and the DNS compressive and growing with u: $(tail -3 "$out/triaxial.csv" 2>/dev/null | tr '\n' ' ')"
awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) { if ($i == "P11") a = i; if ($i == "P22") b = i }; next }
         { n++; for (k = 0; k < 2; ++k) { d = ((k ? $b : $a) + 2e4) / 2e4; if (d < 0) d = -d; if (d > worst) worst = d } }
         END { printf "%.2e\n", worst; exit !(a && b && n == 3 && worst <= 1e-6) }' "$out/triaxial_dns_rows.csv" \
  > "$out/p" 2>/dev/null
check $? "the DNS holds P11 = P22 = -2e4 N/m^2 at its 3 rows (largest relative difference $(cat "$out/p"))"
[ -s "$out/triaxial.svg" ]
check $? "the figure triaxial.svg"
mkdir -p "$out/one" && cp "$out"/packing3d_n15_seed*.txt "$out/one/"
triaxial --only D --threads 1 --out "$out/one" > "$out/one/log" 2>&1 && \
  cmp -s <(cut -d, -f1,2 "$out/triaxial.csv") "$out/one/triaxial.csv"
check $? "the (D) rows on 1 thread and on 2 the same bits"
echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
