#!/usr/bin/env bash
# A million bonded spheres: the thesis' uniform (simple cubic) specimen
# enlarged to NX x NY x NZ spheres (r = 0.1 m, 925 kg/m^3, Timoshenko beams,
# E_b = 4 GPa; default 250 x 64 x 64 = 1 024 000 spheres, 3 0xx xxx bonds),
# STEPS steps of the uniaxial test's free stretch (velocity ramp along x), in
# the embedded 3D engine (one core) and through fix servo_bc/bonds in LAMMPS
# and LIGGGHTS on 1 and 2 ranks, each bond kept with its atoms. Prints per
# engine and rank count: wall time of the steps, ns per bond-step, the 2-rank
# efficiency t1 / (2 t2), the largest resident memory of a rank (MB, from
# /usr/bin/time) and bytes per sphere, and the midspan stretch after the steps
# (the same on every rank count).
#   bash bench/bonds_million.sh [OUT]     NX=250 NY=64 NZ=64 STEPS=100 HOSTS="lammps liggghts"
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
. "$top/bench/rank_run.sh"
B=${B:-$top/build}
out=${1:-$top/out/bench-bonds-million}
nx=${NX:-250} ny=${NY:-64} nz=${NZ:-64} steps=${STEPS:-100}
hosts=${HOSTS:-lammps liggghts}
mkdir -p "$out"
spheres=$((nx * ny * nz))
bonds=$(((nx - 1) * ny * nz + nx * (ny - 1) * nz + nx * ny * (nz - 1)))
lx=$(awk -v n="$nx" 'BEGIN { printf "%.6g", 0.2 * n }') ly=$(awk -v n="$ny" 'BEGIN { printf "%.6g", 0.2 * n }')
lz=$(awk -v n="$nz" 'BEGIN { printf "%.6g", 0.2 * n }')
echo "bonds_million: $nx x $ny x $nz = $spheres spheres, $bonds beams, $steps steps"
printf '| engine | ranks | wall (s) | ns per bond-step | 2-rank efficiency | MB per rank (max) | bytes per sphere | stretch (m) |\n'
printf '| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n'
cat > "$out/embedded.sbc" <<CASE
dimension 3
packing cubic radius 0.1 box $lx $ly $lz
bond beam E 4e9 nu 0.3
density 925
timestep critical 0.6
test uniaxial velocity -1e-5 steps $steps
run
CASE
if /usr/bin/time -f 'maxrss %M' "$B/servo-bc" "$out/embedded.sbc" > "$out/embedded.log" 2>&1; then
  awk -v n="$spheres" '/ ns per bond-step/ { split($0, d, ", "); split(d[2], e, " "); ns = e[1] }
    $1 == "maxrss" { kb = $2 }
    END { printf "| embedded | 1 | | %s | | %.0f | %.0f | |\n", ns, kb / 1024, kb * 1024 / n }' "$out/embedded.log"
else
  echo "| embedded | 1 | failed: $(tail -1 "$out/embedded.log") |"
fi
deck() {  # HOST
  printf 'units si\ndimension 3\nboundary f f f\natom_style sphere\natom_modify map array%s\n' \
    "$([ "$1" = liggghts ] && echo ' sort 0 0.0')"
  printf 'lattice sc 0.2\nregion box block -1 %s -1 %s -1 %s units lattice\ncreate_box 1 box\n' "$nx" "$ny" "$nz"
  printf 'region solid block -0.01 %s -0.01 %s -0.01 %s units lattice\ncreate_atoms 1 region solid\n' \
    "$(awk -v n="$nx" 'BEGIN { print n - 0.99 }')" "$(awk -v n="$ny" 'BEGIN { print n - 0.99 }')" \
    "$(awk -v n="$nz" 'BEGIN { print n - 0.99 }')"
  printf 'set type 1 diameter 0.2\nset type 1 density 925\n'
  printf 'velocity all ramp vx 0 1e-5 x 0 %s units box\n' "$(awk -v n="$nx" 'BEGIN { print 0.2 * (n - 1) }')"
  [ "$1" = liggghts ] && printf 'communicate single cutoff 0.5\n' || printf 'comm_modify cutoff 0.5\n'
  printf 'fix bonds all servo_bc/bonds beam 4e9 0.3 1.0\nfix integrate all nve/sphere\n'
  printf 'region lface block -0.01 0.01 INF INF INF INF units lattice\nregion rface block %s %s INF INF INF INF units lattice\n' \
    "$(awk -v n="$nx" 'BEGIN { print n - 1.01 }')" "$(awk -v n="$nx" 'BEGIN { print n - 0.99 }')"
  printf 'group left region lface\ngroup right region rface\n'
  printf 'thermo_style custom step f_bonds[1]\nrun 0\nvariable dtc equal 0.6*f_bonds[2]\nvariable dt equal ${dtc}\ntimestep ${dt}\n'
  printf 'thermo 0\nrun %s\nvariable s equal xcm(right,x)-xcm(left,x)\nprint "stretch ${s}"\n' "$steps"
}
row() {  # HOST NP T T1 KB
  local stretch
  stretch=$(awk '$1 == "stretch" { print $2 }' "$out/${1}_np$2.log")
  awk -v h="$1" -v np="$2" -v t="$3" -v t1="$4" -v kb="$5" -v nb="$bonds" -v n="$spheres" -v st="$steps" \
    -v s="${stretch:-none}" 'BEGIN {
      eff = np == 2 && t > 0 ? sprintf("%.0f %%", 100 * t1 / (2 * t)) : ""
      printf "| %s | %d | %.2f | %.1f | %s | %.0f | %.0f | %s |\n", h, np, t, t / st / nb * 1e9, eff, kb / 1024, kb * 1024 * np / n, s }'
}
hosts_ranks "$out" $hosts
