#!/usr/bin/env bash
# The packing generator's wall time and memory against the particle count
# (docs/benchmarks.md, "The packing generator"): `generate periodic n0 N rmin
# 1e-3 polydispersity 2 seed 1 strain 0.01 protocol P` in 2D and 3D, timed by
# /usr/bin/time (wall seconds, peak resident memory); prints the particles
# after the periodic reconstruction, the volume fraction, coordination and
# largest net force (over the mean contact force) the runner reports, and the
# growth exponent of the time (least squares of log time on log n0).
# Usage: bench/generate_scaling.sh SERVO_BC [N0S_2D] [N0S_3D] [PROTOCOL]
#   defaults: "400 1600 6400", "120 480 1920", shrink.
set -euo pipefail
bin=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
n0s_2d=${2:-400 1600 6400}
n0s_3d=${3:-120 480 1920}
protocol=${4:-shrink}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "protocol $protocol"
printf '%-3s %7s %10s %9s %11s %9s %12s %10s\n' dim n0 particles seconds "memory MB" fraction coordination "net force"
for dim in 2 3; do
  if [ "$dim" = 2 ]; then n0s=$n0s_2d; else n0s=$n0s_3d; fi
  points=
  for n0 in $n0s; do
    printf 'dimension %s\ncontact frictional kn 1e4 ks 2e3 mu 0.4\ndensity 2e3\ntimestep 1e-6\n' "$dim" > "$tmp/g.sbc"
    printf 'generate periodic n0 %s rmin 1e-3 polydispersity 2 seed 1 strain 0.01 protocol %s\nwrite_packing text %s\n' \
      "$n0" "$protocol" "$tmp/p.txt" >> "$tmp/g.sbc"
    /usr/bin/time -f '%e %M' -o "$tmp/time" "$bin" "$tmp/g.sbc" > "$tmp/log"
    read -r seconds kb < "$tmp/time"
    line=$(grep 'generate: n0' "$tmp/log")
    particles=$(sed 's/.*-> \([0-9]*\) .*/\1/' <<< "$line")
    fraction=$(sed 's/.*volume fraction \([0-9.]*\).*/\1/' <<< "$line")
    coordination=$(sed 's/.*coordination \([0-9.]*\).*/\1/' <<< "$line")
    net=$(sed 's/.*largest net force \([0-9.e+-]*\) .*/\1/' <<< "$line")
    printf '%-3s %7s %10s %9s %11.1f %9s %12s %10s\n' "$dim" "$n0" "$particles" "$seconds" \
      "$(awk -v k="$kb" 'BEGIN { print k / 1024 }')" "$fraction" "$coordination" "$net"
    points="$points $n0 $seconds"
  done
  echo "$points" | awk -v d="$dim" '{ n = 0; sx = sy = sxx = sxy = 0
    for (k = 1; k < NF; k += 2) { x = log($k); y = log($(k + 1) > 0 ? $(k + 1) : 0.01); n++; sx += x; sy += y; sxx += x * x; sxy += x * y }
    if (n > 1) printf "%dD: time grows as n0^%.2f\n", d, (n * sxy - sx * sy) / (n * sxx - sx * sx) }'
done
