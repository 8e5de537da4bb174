#!/usr/bin/env bash
# replicas K (docs/runner.md, "Replicas") on a small irregular packing under
# (P): every sigma statistic of the summary finite, the mean within the
# replicas' range at every increment, the spread larger than zero (the
# perturbed histories part) and at most the stress scale; K = 1 and replica 0
# reproduce the plain run byte for byte; a replica that stops is named.
# Prints "N passed, N failed". Usage: replicas.sh BUILD
set -u
B=$(cd "${1:-build}" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "replicas $1"; }
no() { fail=$((fail + 1)); echo "FAIL replicas $1"; }
head='dimension 2
generate periodic n0 30 rmin 1e-3 polydispersity 1.5 seed 1 strain 0.01
contact frictional kn 1e4 ks 2e3 mu 0.4
density 2e3
timestep 1e-4'
words='servo_bc P F 1 0.02 0 1 increments 4'
printf '%s\n%s file plain.csv\nrun\n' "$head" "$words" > "$tmp/plain.sbc"
printf '%s\nreplicas 4 jobs 2\n%s file four.csv\nrun\n' "$head" "$words" > "$tmp/four.sbc"
printf '%s\nreplicas 1\n%s file one.csv\nrun\n' "$head" "$words" > "$tmp/one.sbc"
(cd "$tmp" && "$B/servo-bc" plain.sbc > plain.log 2>&1 && "$B/servo-bc" four.sbc > four.log 2>&1 &&
  "$B/servo-bc" one.sbc > one.log 2>&1) || { no "runs failed:"; tail -n 3 "$tmp"/*.log; }
res=$(awk -F, 'NR > 1 { n++; if ($6 != 4) bad++
        for (c = 7; c <= 22; c += 4) { m = $c; s = $(c + 1); lo = $(c + 2); hi = $(c + 3)
          if (!(m == m + 0 && s == s + 0 && s >= 0 && lo <= m && m <= hi)) bad++
          if (hi - lo > w) w = hi - lo; a = m < 0 ? -m : m; if (a > S) S = a } }
      END { printf "%d %d %.3g %.4g", n, bad, w, S }' "$tmp/four_replicas.csv" 2>/dev/null)
set -- ${res:-0 1 0 0}
if [ "$1" = 5 ] && [ "$2" = 0 ] && awk -v w="$3" -v S="$4" 'BEGIN { exit !(w > 0 && w <= S) }'; then
  ok "K = 4: 5 increments, every mean within the replicas' range, the largest spread $3 N/m of the stress scale $4 N/m"
else
  no "K = 4 summary: rows $1, $2 bad statistics, spread $3 of $4"
fi
if cmp -s "$tmp/plain.csv" "$tmp/four.csv" && cmp -s "$tmp/plain.csv" "$tmp/one.csv"; then
  ok "replica 0 of K = 4, and K = 1, write the plain run's results byte for byte"
else
  no "replica 0 or K = 1 differs from the plain run"
fi
if awk -F, 'NR > 1 { for (c = 8; c <= 20; c += 4) if ($c != 0) bad++ } END { exit !(NR == 6 && bad == 0) }' "$tmp/one_replicas.csv"; then
  ok "K = 1: the summary's spread is 0"
else
  no "K = 1 summary: $(head -3 "$tmp/one_replicas.csv")"
fi
# replicas that stop (max_iterations 3 is too few for increment 0) are named
printf '%s\nreplicas 3\n%s max_iterations 3 file stop.csv\nrun\n' "$head" "$words" > "$tmp/stop.sbc"
(cd "$tmp" && "$B/servo-bc" stop.sbc > stop.log 2>&1)
rc=$?
if [ $rc -ge 1 ] && [ $rc -le 125 ] && grep -q "^ERROR: replica [0-9]*: .*max_iterations" "$tmp/stop.log" &&
   grep -q "replicas stopped (replica [0-9]* first" "$tmp/stop.log" && [ "$(wc -l < "$tmp/stop_replicas.csv")" = 1 ]; then
  ok "a replica that stops is named (exit $rc): $(grep -m1 '^ERROR: .*replicas:' "$tmp/stop.log" | cut -c1-140)"
else
  no "a stopping replica (exit $rc):"; tail -n 3 "$tmp/stop.log"
fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
