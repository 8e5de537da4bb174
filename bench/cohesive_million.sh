#!/usr/bin/env bash
# A million cohesive discs: a SIDE x SIDE square lattice (spacing 2 mm,
# R 1.02 mm, every neighbour bonded by Table 6's cohesive law, eqs. 7-8;
# default SIDE 1000: 1 000 000 discs, 1 998 000 bonds) released from its 4 %
# overlap, STEPS steps of 1e-6 s, free edges: the embedded engine
# (build/bench_engine SIDE STEPS cohesive, one core) and fix servo_bc/bonds
# cohesive in LAMMPS and LIGGGHTS on 1 and 2 ranks, each contact kept with its
# discs. Prints per engine and rank count: wall time of the steps, ns per
# disc-step, the ratio to the embedded engine, the 2-rank efficiency
# t1 / (2 t2), the largest resident memory of a rank (MB, /usr/bin/time) and
# bytes per disc, and eq. 12's Ep after the steps (the same on every rank
# count).
#   bash bench/cohesive_million.sh [OUT]     SIDE=1000 STEPS=100 HOSTS="lammps liggghts"
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
. "$top/bench/rank_run.sh"
B=${B:-$top/build}
out=${1:-$top/out/bench-cohesive-million}
side=${SIDE:-1000} steps=${STEPS:-100}
hosts=${HOSTS:-lammps liggghts}
mkdir -p "$out"
discs=$((side * side))
echo "cohesive_million: $side x $side = $discs discs, $((2 * side * (side - 1))) cohesive bonds, $steps steps"
printf '| engine | ranks | wall (s) | ns per disc-step | against embedded | 2-rank efficiency | MB per rank (max) | bytes per disc | Ep after (J) |\n'
printf '| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n'
embedded=
if /usr/bin/time -f 'maxrss %M' "$B/bench_engine" "$side" "$steps" cohesive > "$out/embedded.log" 2>&1; then
  set -- $(awk '$1 == "engine+cohesive" { ns = $4; ep = $6 } $1 == "maxrss" { kb = $2 } END { print ns, kb, ep }' \
    "$out/embedded.log")
  embedded=$1
  awk -v ns="$1" -v kb="$2" -v ep="$3" -v n="$discs" -v st="$steps" 'BEGIN {
    printf "| embedded | 1 | %.2f | %.1f | 1 | | %.0f | %.0f | %s |\n", ns * n * st * 1e-9, ns, kb / 1024, kb * 1024 / n, ep }'
else
  echo "| embedded | 1 | failed: $(tail -1 "$out/embedded.log") |"
fi
deck() {  # HOST
  printf 'units si\ndimension 2\nboundary f f p\natom_style sphere\natom_modify map array%s\n' \
    "$([ "$1" = liggghts ] && echo ' sort 0 0.0')"
  printf 'lattice sq 2e-3\nregion box block -1 %s -1 %s -2 2 units lattice\ncreate_box 1 box\n' "$side" "$side"
  printf 'region solid block -0.01 %s -0.01 %s -0.5 0.5 units lattice\ncreate_atoms 1 region solid\n' \
    "$(awk -v n="$side" 'BEGIN { print n - 0.99 }')" "$(awk -v n="$side" 'BEGIN { print n - 0.99 }')"
  # M = rho pi R^2 with rho = 2e3 kg/m^2, as the embedded engine (a 2D density in neither host's set command)
  # LIGGGHTS 3.8 stops with "Cannot use neighbor bins - box size << cutoff" on the 10^6-disc box with bin;
  # no pair style asks for a list, so nsq
  printf 'set type 1 diameter 2.04e-3\nset type 1 mass %s\nneighbor 2.55e-4 %s\n' \
    "$(awk 'BEGIN { printf "%.15g", 2e3 * 3.14159265358979 * 1.02e-3 * 1.02e-3 }')" "$([ "$1" = liggghts ] && echo nsq || echo bin)"
  # the ghost cutoff: 2 R + the skin, with room to spare (fix servo_bc/bonds checks it)
  [ "$1" = liggghts ] && printf 'communicate single cutoff 0.0025 vel yes\n' ||
    printf 'comm_modify cutoff 0.0025 vel yes\n'
  printf 'fix bonds all servo_bc/bonds cohesive kn 1e8 ks 4e7 kr 20 fn 300 fs 60 mr 0.2 mu 0.6\n'
  printf 'fix integrate all nve/sphere%s\nfix plane all enforce2d\n' "$([ "$1" = lammps ] && echo ' disc')"
  printf 'timestep 1e-6\nthermo_style custom step f_bonds f_bonds[1]\nthermo 0\nrun 0\nrun %s\n' "$steps"
  printf 'variable ep equal f_bonds\nprint "Ep ${ep}"\n'
}
row() {  # HOST NP T T1 KB
  local ep
  ep=$(awk '$1 == "Ep" { print $2 }' "$out/${1}_np$2.log")
  awk -v h="$1" -v np="$2" -v t="$3" -v t1="$4" -v kb="$5" -v n="$discs" -v st="$steps" -v e="${embedded:-0}" \
    -v ep="${ep:-none}" 'BEGIN {
      eff = np == 2 && t > 0 ? sprintf("%.0f %%", 100 * t1 / (2 * t)) : ""
      ns = t / st / n * 1e9
      ratio = e > 0 ? sprintf("%.2f", ns / e) : ""
      printf "| %s | %d | %.2f | %.1f | %s | %s | %.0f | %.0f | %s |\n", h, np, t, ns, ratio, eff, kb / 1024,
        kb * 1024 * np / n, ep }'
}
hosts_ranks "$out" $hosts
