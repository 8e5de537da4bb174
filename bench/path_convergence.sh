#!/usr/bin/env bash
# How the loading path converges as its increments are halved (docs/servo_bc.md,
# "Interior"): the 232-disc irregular frictional packing of Sect. 4.2 compressed
# by `strain 0.01` (mu 0.4, dt 7.5e-5 s), F12 from 0 to 0.004 in K = 1, 2, 4, 8,
# 16, 32 increments under (D) and (P), with interior newton and interior dynamic
# at one preset. For each K it prints P11, P12, P22 at the path's end, the
# difference from the same method at 2K (the path error of K, relative to the
# largest |P_ij|), the DEM steps, the Newton iterations and the solves the
# relaxation finished.
# Usage: bench/path_convergence.sh SERVO_BC [PRESET] [KS]
#   defaults: balanced, "1 2 4 8 16 32"
set -euo pipefail
bin=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
preset=${2:-balanced}
ks=${3:-1 2 4 8 16 32}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
contact='contact frictional kn 1e4 ks 2e3 mu 0.4
density 2e3
timestep 7.5e-5'
printf 'dimension 2\ngenerate periodic n0 200 rmin 0.67e-3 polydispersity 2 seed 1 strain 0.01\nwrite_packing text %s/p.txt\n' \
  "$tmp" > "$tmp/gen.sbc"
"$bin" "$tmp/gen.sbc" > "$tmp/gen.log" 2>&1 || { tail -3 "$tmp/gen.log"; exit 1; }
# end NAME: "P11 P12 P22 steps newton_iterations" of the last row, steps and iterations summed over the path
end() {
  awk -F, 'NR == 1 { for (c = 1; c <= NF; c++) col[$c] = c; next }
           { s += $col["relax_steps"]; k += $col["newton_iterations"]; a = $col["P11"]; b = $col["P12"]; d = $col["P22"] }
           END { printf "%.10g %.10g %.10g %d %d", a, b, d, s, k }' "$tmp/$1.csv"
}
printf '%-3s %-8s %4s %12s %12s %12s %11s %10s %8s %7s\n' BC interior K P11 P12 P22 "path error" steps Newton relaxed
for bc in D P; do
  for m in newton dynamic; do
    prev=
    for k in $ks; do
      name="${bc}_${m}_$k"
      printf 'dimension 2\nread_packing %s/p.txt\n%s\nservo_bc %s F 1 0.004 0 1 increments %s accuracy %s interior %s file %s/%s.csv\nrun\n' \
        "$tmp" "$contact" "$bc" "$k" "$preset" "$m" "$tmp" "$name" > "$tmp/$name.sbc"
      (cd "$tmp" && "$bin" "$name.sbc" > "$name.log" 2>&1) || { tail -3 "$tmp/$name.log"; exit 1; }
      read -r p11 p12 p22 s n <<< "$(end "$name")"
      echo "$k $p11 $p12 $p22 $s $n $(grep -c 'finished an unconverged' "$tmp/$name.log" || true)" >> "$tmp/${bc}_$m"
    done
    # the path error of K: |P(K) - P(2K)| / max |P(2K)|, the last K against none
    awk -v bc="$bc" -v m="$m" '{ k[NR] = $1; a[NR] = $2; b[NR] = $3; d[NR] = $4; s[NR] = $5; n[NR] = $6; r[NR] = $7 }
      END { for (i = 1; i <= NR; i++) {
              e = "-"
              if (i < NR) { m1 = a[i+1] < 0 ? -a[i+1] : a[i+1]; m2 = b[i+1] < 0 ? -b[i+1] : b[i+1]; m3 = d[i+1] < 0 ? -d[i+1] : d[i+1]
                            sc = m1; if (m2 > sc) sc = m2; if (m3 > sc) sc = m3
                            x = a[i] - a[i+1]; if (x < 0) x = -x; y = b[i] - b[i+1]; if (y < 0) y = -y; z = d[i] - d[i+1]; if (z < 0) z = -z
                            w = x; if (y > w) w = y; if (z > w) w = z; e = sprintf("%.2e", w / sc) }
              printf "%-3s %-8s %4d %12.6f %12.6f %12.6f %11s %10d %8d %7d\n", bc, m, k[i], a[i], b[i], d[i], e, s[i], n[i], r[i] } }' \
      "$tmp/${bc}_$m"
  done
done
