#!/usr/bin/env bash
# Cost of the bond models inside LAMMPS (fix servo_bc/bonds) against the
# embedded 3D engine, on the thesis' HCP specimen at r_p = 5 mm (0.25 x 0.1 x
# 0.1 m, Timoshenko beams, E_b = 4 GPa): STEPS steps of free motion after a
# small initial stretch velocity, on one core (embedded, LAMMPS 1 rank) and
# LAMMPS on 2 ranks. Prints spheres, bonds, wall time of the steps and ns per
# bond-step, and LAMMPS' ns per bond-step over the embedded engine's.
# LAMMPS builds its HCP with `lattice hcp 0.01` in the same box (the embedded
# engine's own generator: a packing of the same spacing, not the same file).
#   bash bench/bpm_hosts.sh [OUT]      STEPS=2000 (default)
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
B=${B:-$top/build}
out=${1:-$top/out/bench-bpm-hosts}
steps=${STEPS:-2000}
mkdir -p "$out"
cat > "$out/embedded.sbc" <<CASE
dimension 3
packing hcp radius 5e-3
bond beam E 4e9 nu 0.3
density 925 scaled
timestep critical 0.6
test uniaxial velocity -1e-5 steps $steps
run
CASE
"$B/servo-bc" "$out/embedded.sbc" > "$out/embedded.log" 2>&1 || { echo "bpm_hosts: the embedded run failed"; exit 1; }
emb=$(awk '/ ns per bond-step/ { split($0, d, ", "); split(d[2], e, " "); print e[1] }' "$out/embedded.log")
emb_n=$(awk '/packing,/ { for (i = 1; i <= NF; ++i) { if ($i == "spheres") n = $(i - 1); if ($i == "bonds") b = $(i - 1) } } END { print n, b }' "$out/embedded.log")
cat > "$out/lammps.in" <<LMP
units si
dimension 3
boundary f f f
atom_style sphere
lattice hcp 0.01
region box block -0.01 0.26 -0.01 0.11 -0.01 0.11 units box
create_box 1 box
region solid block 0 0.25 0 0.1 0 0.1 units box
create_atoms 1 region solid
set type 1 diameter 0.01
set type 1 density 925
velocity all ramp vx 0 1e-5 x 0 0.25 units box
comm_modify cutoff 0.015
fix bonds all servo_bc/bonds beam 4e9 0.3 1.0
fix integrate all nve/sphere
thermo_style custom step f_bonds f_bonds[1]
run 0
variable dt equal 0.6*f_bonds[2]
timestep \${dt}
thermo 0
run $steps
LMP
printf '| engine | ranks | spheres | bonds | wall (s) | ns per bond-step | against embedded |\n| --- | ---: | ---: | ---: | ---: | ---: | ---: |\n'
set -- $emb_n
printf '| embedded | 1 | %s | %s | | %s | 1 |\n' "$1" "$2" "$emb"
[ -x "$B/lmp_servo" ] || { echo "bpm_hosts: no build/lmp_servo (make lammps)"; exit 0; }
for np in 1 2; do
  if [ "$np" = 1 ]; then (cd "$out" && "$B/lmp_servo" -in lammps.in -log lammps_np1.log -screen none)
  else (cd "$out" && mpirun --allow-run-as-root --oversubscribe -np 2 "$B/lmp_servo" -in lammps.in -log lammps_np2.log -screen none); fi
  awk -v np="$np" -v steps="$steps" -v emb="$emb" '
    /servo_bc\/bonds:/ { nb = $3; n = $7 }
    /^Loop time of/ { t = $4 }
    END { ns = t / steps / nb * 1e9; printf "| LAMMPS | %d | %s | %s | %.2f | %.1f | %.2f |\n", np, n, nb, t, ns, ns / emb }' "$out/lammps_np$np.log"
done
