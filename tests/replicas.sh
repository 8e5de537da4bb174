#!/usr/bin/env bash
# replicas K (docs/runner.md, "Replicas") on a small irregular packing under
# (P): every sigma statistic of the summary finite, the mean within the
# replicas' range at every increment, the spread larger than zero (the
# perturbed histories part) and at most the stress scale; K = 1 and replica 0
# reproduce the plain run byte for byte; a replica that stops is named. In 3D
# (71 spheres, (P), K = 4): the summary's 9 F and 9 sigma columns, replica 0
# the plain run byte for byte, and the spread with interior newton at most a
# tenth of that with interior dynamic.
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
# 3D: 71 spheres under (P), K = 4 with interior newton and with interior dynamic
head3='dimension 3
generate periodic n0 30 rmin 1e-3 polydispersity 1.5 seed 1 strain 0.002
contact frictional kn 1e4 ks 5e3 mu 0.5
density 2650
timestep 9e-6'
words3='servo_bc P F 1 0 0.003 0 1 0 0 0 1 increments 2 accuracy tight'
for m in newton dynamic; do
  printf '%s\n%s interior %s file plain3%s.csv\nrun\n' "$head3" "$words3" "$m" "$m" > "$tmp/plain3$m.sbc"
  printf '%s\nreplicas 4 jobs 2\n%s interior %s file four3%s.csv\nrun\n' "$head3" "$words3" "$m" "$m" > "$tmp/four3$m.sbc"
  (cd "$tmp" && "$B/servo-bc" "plain3$m.sbc" > "plain3$m.log" 2>&1 && "$B/servo-bc" "four3$m.sbc" > "four3$m.log" 2>&1) ||
    { no "3D $m runs failed:"; tail -n 3 "$tmp/four3$m.log"; }
done
spread3() { # rows, bad statistics, the largest spread over the stress scale
  awk -F, 'NR == 1 { if (NF != 47 || $11 != "replicas" || $44 != "sigma33_mean") bad++ }
    NR > 1 { n++; if ($11 != 4) bad++
      for (c = 12; c <= 44; c += 4) { m = $c; s = $(c + 1); lo = $(c + 2); hi = $(c + 3)
        if (!(m == m + 0 && s == s + 0 && s >= 0 && lo <= m && m <= hi)) bad++
        if (hi - lo > w) w = hi - lo; a = m < 0 ? -m : m; if (a > S) S = a } }
    END { printf "%d %d %.3g", n, bad, (S > 0 ? w / S : -1) }' "$1" 2>/dev/null
}
read -r n_new bad_new w_new <<< "$(spread3 "$tmp/four3newton_replicas.csv")"
read -r n_dyn bad_dyn w_dyn <<< "$(spread3 "$tmp/four3dynamic_replicas.csv")"
if [ "${n_new:-0}" = 3 ] && [ "${bad_new:-1}" = 0 ] && [ "${n_dyn:-0}" = 3 ] && [ "${bad_dyn:-1}" = 0 ] &&
   cmp -s "$tmp/plain3newton.csv" "$tmp/four3newton.csv" && cmp -s "$tmp/plain3dynamic.csv" "$tmp/four3dynamic.csv"; then
  ok "3D, K = 4: 3 increments of 9 F and 9 sigma columns, every mean within the replicas' range, replica 0 the plain run byte for byte"
else
  no "3D K = 4 summaries: newton rows ${n_new:-?} bad ${bad_new:-?}, dynamic rows ${n_dyn:-?} bad ${bad_dyn:-?}"
fi
# a static increment is a function of its loading: its spread a tenth of the relaxation's at most
if awk -v a="${w_new:--1}" -v b="${w_dyn:--1}" 'BEGIN { exit !(a >= 0 && b > 0 && a <= 0.1 * b) }'; then
  ok "3D: the spread of 4 replicas (centres moved by up to 1e-6 R) is $w_new of the stress scale with interior newton, $w_dyn with interior dynamic"
else
  no "3D spreads: newton ${w_new:-?}, dynamic ${w_dyn:-?}"
fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
