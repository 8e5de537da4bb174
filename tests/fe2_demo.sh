#!/bin/bash
# make fe2-demo at its smallest (tests/, in make fe2-patch): fe2/biaxial.py with one element of four (D)
# points of n0 20 discs and a DNS of n0 80, one step of u. The DNS holds the lateral stress P11 = -p at every
# row (tight: 1e-6), both forces are compressive and grow with u, and the CSV has the issue's columns; then
# fe2/size_study.py at its smallest (one specimen of n0 25, (D) only).
# Prints "N passed, N failed". Usage: fe2_demo.sh LIBSERVO_BC RUNNER PLOT [PYTHON]
lib=${1:?usage: fe2_demo.sh LIBSERVO_BC RUNNER PLOT [PYTHON]}
runner=${2:?}; plot=${3:?}; py=${4:-python3}
here=$(cd "$(dirname "$0")" && pwd)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
passed=0 failed=0
check() { if [ "$1" = 0 ]; then passed=$((passed + 1)); echo "fe2 demo: $2"; else failed=$((failed + 1)); echo "FAIL fe2 demo: $2"; fi; }
SERVO_BC_LIB=$lib timeout 600 "$py" "$here/../fe2/biaxial.py" --n0 20 --steps 1 --only D,DNS --pressure 50 \
  --runner "$runner" --plot "$plot" --out "$out" > "$out/log" 2>&1
check $? "fe2/biaxial.py at its smallest runs ($(tail -1 "$out/log"))"
n_it=$(grep -c '^fe2 (D): u .* m, iteration [0-9]*, residual .* of the reaction, .* s$' "$out/log")
n_step=$(awk '/^fe2 \(D\): u .* Newton iterations/ { split($0, a, "Newton iterations "); split(a[2], b, ","); n = split(b[1], c, "+"); for (i = 1; i <= n; ++i) t += c[i] + 1 } END { print t + 0 }' "$out/log")
[ "$n_it" -gt 0 ] && [ "$n_it" = "$n_step" ]
check $? "a progress line per macro iteration, with its residual and elapsed time ($n_it lines, as many as the steps' iterations say)"
[ "$(head -1 "$out/biaxial.csv" 2>/dev/null)" = "u,force_D,force_DNS" ] && [ "$(wc -l < "$out/biaxial.csv")" = 3 ]
check $? "biaxial.csv: u,force_D,force_DNS and 2 rows"
awk -F, 'NR == 2 { d0 = $2; n0 = $3 } NR == 3 { ok = d0 > 0 && n0 > 0 && $2 > d0 && $3 > n0 } END { exit !ok }' \
  "$out/biaxial.csv" 2>/dev/null
check $? "FE2 (D) and DNS forces compressive and growing with u: $(tail -2 "$out/biaxial.csv" 2>/dev/null | tr '\n' ' ')"
awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "P11") c = i; next }
         { n++; d = ($c + 50) / 50; if (d < 0) d = -d; if (d > worst) worst = d }
         END { printf "%.2e\n", worst; exit !(c && n == 2 && worst <= 1e-6) }' "$out/biaxial_dns_rows.csv" > "$out/p11" 2>/dev/null
check $? "the DNS holds P11 = -50 N/m at both rows (largest relative difference $(cat "$out/p11"))"
[ -s "$out/biaxial.svg" ]
check $? "the figure biaxial.svg"
# a torn cache (round 4): the DNS packing without its last 5 rows is made again, and the curve is the same
cp "$out/biaxial.csv" "$out/first.csv"
dns=$(ls "$out"/packing_n80_seed*.txt | head -n 1)
head -n $(($(wc -l < "$dns") - 5)) "$dns" > "$dns.torn" && mv "$dns.torn" "$dns"
SERVO_BC_LIB=$lib timeout 600 "$py" "$here/../fe2/biaxial.py" --n0 20 --steps 1 --only D,DNS --pressure 50 \
  --runner "$runner" --plot "$plot" --out "$out" > "$out/log2" 2>&1
grep -q "announces .* discs and it holds .*; generating it again" "$out/log2" && cmp -s "$out/first.csv" "$out/biaxial.csv"
check $? "a torn cached packing is found by its count, made again, and gives the same rows ($(grep -o 'announces [0-9]* discs and it holds [0-9]*' "$out/log2"))"
# the size study at its smallest: one specimen of n0 25, (D) only; its gain error recomputed from the run's own CSV
SERVO_BC_LIB=$lib timeout 600 "$py" "$here/../fe2/size_study.py" --n0s 25 --specimens 1 --only D --steps 1 \
  --runner "$runner" --plot "$plot" --out "$out/size" > "$out/size.log" 2>&1
check $? "fe2/size_study.py at its smallest runs ($(tail -1 "$out/size.log"))"
awk -F, 'FNR == 1 { next } FILENAME ~ /biaxial/ { f[FNR] = $2; d[FNR] = $3; n = FNR; next }
         { want = (f[n] - f[2]) / (d[n] - d[2]) - 1; e = $6 - want; if (e < 0) e = -e; rows++; ok = e <= 1e-12 }
         END { exit !(rows == 1 && ok) }' "$out/size/n25_s0/biaxial.csv" "$out/size/size_study.csv" 2>/dev/null
check $? "size_study.csv: one (D) row whose gain error is its biaxial.csv's (F(u) - F(0)) / (F_DNS(u) - F_DNS(0)) - 1"
echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
