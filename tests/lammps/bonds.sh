#!/usr/bin/env bash
# fix servo_bc/bonds (the thesis' 3D bond models through the core) in LAMMPS
# or LIGGGHTS: the Appendix B beam (inputs/HOST/bpm_beam.in) of 3, 5, 7 and 11
# spheres against eq. B1 (1e-4) and the thesis' Table B1 (5 digits); the
# 11-sphere beam on 1, 2 and 4 ranks to 1e-10, and split by a restart; in LAMMPS the three-sphere
# beam's free vibration (723.29 Hz); the uniform packing's modulus pi E_b / 4;
# bad input named by keyword.
# Prints "N passed, N failed". Usage: bonds.sh BINARY [lammps|liggghts]
set -u
bin=$(cd "$(dirname "${1:?usage: bonds.sh BINARY [lammps|liggghts]}")" && pwd)/$(basename "$1")
host=${2:-lammps}
here=$(cd "$(dirname "$0")" && pwd)
deck=$here/../../inputs/$host/bpm_beam.in
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "$host bonds: $1"; }
bad() { fail=$((fail + 1)); echo "FAIL $host bonds: $1"; }
beam() {  # NP N FILE
  (cd "$tmp" && if [ "$1" = 1 ]; then timeout 300 "$bin" -in "$deck" -var n "$2" -var out "$3" -log none -screen none
   else timeout 300 mpirun --allow-run-as-root --oversubscribe -np "$1" "$bin" -in "$deck" -var n "$2" -var out "$3" \
     -log none -screen none; fi) > "$tmp/beam.log" 2>&1
  awk '$1 == "deflection" { print $2 }' "$tmp/$3" 2>/dev/null
}
for pair in 3:0.0065436 5:0.038551 7:0.12148 11:0.54201; do
  n=${pair%%:*} thesis=${pair#*:}
  got=$(beam 1 "$n" "beam_$n.txt")
  set -- $(awk -v n="$n" -v d="${got:-none}" -v t="$thesis" 'BEGIN {
      R = 0.1; E = 4e9; nu = 0.3; G = E / (2 * (1 + nu)); pi = atan2(0, -1); I = pi * R^4 / 4; A = pi * R * R
      Le = 2 * R * (n - 1); b1 = 1e3 * Le^3 / (48 * E * I) + 1e3 * Le * (10 / 9) / (4 * G * A)
      e1 = (d - b1) / b1; e2 = (1e3 * d - t) / t; if (e1 < 0) e1 = -e1; if (e2 < 0) e2 = -e2
      printf "%s %.3g %.3g %.9g", (d == d + 0 && e1 <= 1e-4 && e2 <= 1.5e-4) ? "ok" : "bad", e1, e2, b1 }')
  if [ "$1" = ok ]; then ok "beam of $n spheres: deflection $got m, eq. B1 $4 m (relative $2), Table B1 $thesis mm (relative $3)"
  else bad "beam of $n spheres: deflection ${got:-none} m against eq. B1 $4 m: $(tail -2 "$tmp/beam.log")"; fi
done
# eqs. 49-53 on the settled 11-sphere beam: the bonds' strain energy is F d / 2
# (Clapeyron: a linear elastic body under one load) to 1e-6, and eq. 53's
# balance of kinetic, strain and external work (load, supports, fix viscous,
# trapezoidal) within 1e-4 (measured 8.8e-6)
set -- $(awk '$1 == "deflection" { d = $2 } $1 == "energy" { u = $3; k = $5; w = $9; b = $11 }
  END { e = (u - 500 * d) / (500 * d); if (e < 0) e = -e
        printf "%s %.3g %s %s %s", (d > 0 && e <= 1e-6 && b <= 1e-4 && w > u) ? "ok" : "bad", e, u, w, b }' "$tmp/beam_11.txt" 2>/dev/null)
if [ "${1:-bad}" = ok ]; then ok "energies of the settled beam: strain $3 J = F d / 2 (relative $2), external work $4 J, eq. 53 balance $5"
else bad "energies of the settled beam: $(grep energy "$tmp/beam_11.txt" 2>/dev/null || echo none)"; fi
one=$(beam 1 11 ranks1.txt)
for np in 2 4; do
  got=$(beam "$np" 11 "ranks$np.txt")
  if awk -v a="${one:-none}" -v b="${got:-none}" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(a == a + 0 && b == b + 0 && d <= 1e-10 * a) }'; then
    ok "11 spheres on $np ranks: $got m, against 1 rank $one m (to 1e-10)"
  else
    bad "11 spheres on $np ranks: ${got:-none} m against 1 rank ${one:-none} m: $(tail -2 "$tmp/beam.log")"
  fi
done
# eqs. B2-B3: the three-sphere beam (central mass 7.4 kg, light ends 7.4 g,
# L_e = 0.4 m) held at 1 mm by a static load with damping, then let go: its
# frequency over 5 periods against 723.29 Hz (0.05 %), and below it (the
# ends' remaining inertia can only slow it)
[ "$host" = lammps ] && {
kbeam=$(awk 'BEGIN { R = 0.1; E = 4e9; nu = 0.3; G = E / (2 * (1 + nu)); pi = atan2(0, -1); I = pi * R^4 / 4; A = pi * R * R
  Le = 0.4; printf "%.17g", 192 * E * I * G * A / (4 * Le^3 * G * A + 48 * (10 / 9) * E * I * Le) }')
cat > "$tmp/vib.in" <<LMP
units si
dimension 3
boundary f f f
atom_style sphere
atom_modify map array
region box block -0.2 0.6 -0.5 0.5 -0.5 0.5
create_box 1 box
create_atoms 1 single 0 0 0
create_atoms 1 single 0.2 0 0
create_atoms 1 single 0.4 0 0
set type 1 diameter 0.2
set atom 2 mass 7.4
set atom 1 mass 7.4e-3
set atom 3 mass 7.4e-3
group left id 1
group right id 3
group middle id 2
fix bonds all servo_bc/bonds beam 4e9 0.3 1.0
fix integrate all nve/sphere
fix pin left setforce 0 0 0
fix roll right setforce NULL 0 0
fix load middle addforce 0 0 $(awk -v k="$kbeam" 'BEGIN { printf "%.17g", -k * 1e-3 }')
fix damp middle viscous 60000
run 0
variable dt equal 0.5*f_bonds[2]
timestep \${dt}
run 40000
print "held \$(-z[2]:%.17g)"
unfix load
unfix damp
variable z equal z[2]
variable t equal time
fix trace all print 1 "\${t} \${z}" file trace.txt screen no
run \$(round(5.5/723.29/v_dt))
LMP
(cd "$tmp" && timeout 300 "$bin" -in vib.in -log none) > "$tmp/vib.log" 2>&1
held=$(awk '$1 == "held" { print $2 }' "$tmp/vib.log")
set -- $(awk -v k="$kbeam" 'NR > 1 && $1 !~ /#/ { t = $1; z = $2
    if (n++ && zp < 0 && z >= 0) { tc = tp + (t - tp) * (-zp) / (z - zp); if (t0 == "") t0 = tc; else { p++; tl = tc } }
    zp = z; tp = t }
  END { pi = atan2(0, -1); fn = sqrt(k / 7.4) / (2 * pi); f = p > 0 ? p / (tl - t0) : 0
    printf "%d %.6f %.6f %.3g", p, f, fn, (f - fn) / fn }' "$tmp/trace.txt" 2>/dev/null)
if [ "${1:-0}" = 5 ] && awk -v f="$2" -v fn="$3" -v h="${held:-0}" 'BEGIN { d = (f - fn) / fn; if (d < 0) d = -d
    e = (h - 1e-3) / 1e-3; if (e < 0) e = -e; exit !(d <= 5e-4 && f < fn && e <= 1e-6 && fn > 723.285 && fn < 723.295) }'; then
  ok "three-sphere beam held at $held m, free vibration $2 Hz over 5 periods, eqs. B2-B3 $3 Hz (relative $4)"
else
  bad "three-sphere beam: held at ${held:-?} m, ${1:-0} periods, ${2:-?} Hz against ${3:-?} Hz: $(tail -2 "$tmp/vib.log")"
fi
}
# the uniform (simple cubic) packing's modulus under uniaxial tension: pi E_b / 4
# (inputs/HOST/bpm_uniaxial.in)
{
(cd "$tmp" && timeout 300 "$bin" -in "$here/../../inputs/$host/bpm_uniaxial.in" -var nx 5 -var ny 3 -var nz 3 \
  -var out uni.txt -log none -screen none) > "$tmp/uni.log" 2>&1
got=$(awk '$1 == "modulus" { print $2 }' "$tmp/uni.txt" 2>/dev/null)
if awk -v e="${got:-none}" 'BEGIN { t = atan2(0, -1) * 4e9 / 4; d = (e - t) / t; if (d < 0) d = -d; exit !(e == e + 0 && d <= 1e-6) }'; then
  ok "uniform packing 5 x 3 x 3 under uniaxial tension: E = $got Pa, pi E_b / 4 = 3141592653.6 Pa"
else
  bad "uniform packing: E = ${got:-none} Pa against pi E_b / 4: $(tail -2 "$tmp/uni.log")"
fi
}
# restart: the 11-sphere beam run 1500 + 1500 steps straight through, and
# split by write_restart / read_restart, ends at the same midspan position
# (the bond states travel in the restart file)
fixes="fix bonds all servo_bc/bonds beam 4e9 0.3 1.0
fix integrate all nve/sphere
fix pin left setforce 0 0 0
fix roll right setforce NULL 0 0
fix load middle addforce 0 0 -1000
fix damp all viscous 5000"
{
  printf 'units si\ndimension 3\nboundary f f f\natom_style sphere\natom_modify map array%s\n' \
    "$([ "$host" = liggghts ] && echo ' sort 0 0.0')"
  printf 'region box block -0.2 2.2 -0.5 0.5 -0.5 0.5\ncreate_box 1 box\n'
  for i in 0 1 2 3 4 5 6 7 8 9 10; do echo "create_atoms 1 single $(awk -v i=$i 'BEGIN { print 0.2 * i }') 0 0"; done
  printf 'set type 1 diameter 0.2\nset type 1 density 925\ngroup left id 1\ngroup right id 11\ngroup middle id 6\n'
  echo "$fixes"
  printf 'timestep 8e-6\nrun 1500\nwrite_restart split.restart\nrun 1500\nvariable z equal xcm(middle,z)\nprint "z ${z}" file straight.txt\n'
} > "$tmp/straight.in"
{
  printf 'read_restart split.restart\n'
  [ "$host" = liggghts ] && printf 'atom_modify sort 0 0.0\ntimestep 8e-6\n'
  echo "$fixes"
  printf 'run 1500\nvariable z equal xcm(middle,z)\nprint "z ${z}" file split.txt\n'
} > "$tmp/split.in"
(cd "$tmp" && timeout 120 "$bin" -in straight.in -log none -screen none && timeout 120 "$bin" -in split.in -log none -screen none) \
  > "$tmp/restart.log" 2>&1
a=$(awk '$1 == "z" { print $2 }' "$tmp/straight.txt" 2>/dev/null) b=$(awk '$1 == "z" { print $2 }' "$tmp/split.txt" 2>/dev/null)
if [ -n "$a" ] && [ -n "$b" ] && awk -v a="$a" -v b="$b" 'BEGIN { d = a - b; if (d < 0) d = -d; s = a < 0 ? -a : a
    exit !(a == a + 0 && b == b + 0 && s > 1e-6 && d <= 1e-10 * s) }'; then
  ok "restart mid-run: midspan at $b m after the split, $a m straight through (to 1e-10)"
else
  bad "restart mid-run: ${b:-none} m after the split, ${a:-none} m straight through: $(tail -3 "$tmp/restart.log")"
fi
# bonds that travel with their atoms: a bar of 11 x 2 x 2 spheres flies 2.4 m
# along x through the rank boundaries (a 4 x 1 x 1 grid at 1.25 and 3 m; for
# its second half LAMMPS moves them to balance the atoms), stretched at its
# ends and kicked at its middle, with a strength: on 1, 2
# and 4 ranks the middle's deflection to 1e-10, the intact bonds alike and the
# rows of keyword breaks byte for byte (atoms created one by one: their IDs,
# and so each bond's end A, do not depend on the rank count)
{
  printf 'units si\ndimension 3\nboundary f f f\natom_style sphere\natom_modify map array%s\n' \
    "$([ "$host" = liggghts ] && echo ' sort 0 0.0')"
  printf 'region box block -0.5 6.5 -1 1 -1 1\ncreate_box 1 box\n'
  for k in 0 1; do for j in 0 1; do for i in 0 1 2 3 4 5 6 7 8 9 10; do
    echo "create_atoms 1 single $(awk -v i=$i 'BEGIN { print 0.2 * i }') 0.$((2 * j)) 0.$((2 * k)) units box"
  done; done; done
  printf 'set type 1 diameter 0.2\nset type 1 density 925\n%s\n' \
    "$([ "$host" = liggghts ] && echo 'communicate single cutoff 0.5' || echo 'comm_modify cutoff 0.5')"
  printf 'fix bonds all servo_bc/bonds beam 4e9 0.3 1.0 strength 2e4 0 0 0 friction 0.5 breaks breaks.csv\n'
  printf 'fix integrate all nve/sphere\n'
  printf 'region left block INF 0.05 INF INF INF INF units box\nregion right block 1.95 INF INF INF INF INF units box\n'
  printf 'region middle block 0.95 1.05 INF INF INF INF units box\n'
  printf 'group left region left\ngroup right region right\ngroup middle region middle\n'
  printf 'velocity all set 25 0 0 units box\nvelocity left set 23 0 0 units box\n'
  printf 'velocity right set 27 0 0 units box\nvelocity middle set 25 0 2 units box\n'
  # the second half after load balancing: the subdomains move to where the bar is
  printf 'timestep 8e-6\nrun 6000\n%s\nrun 6000\n' \
    "$([ "$host" = liggghts ] && echo '# balance: LIGGGHTS 3.8 has no balance command' || echo 'balance 1.0 shift x 10 1.0')"
  printf 'variable zm equal xcm(middle,z)-0.5*(xcm(left,z)+xcm(right,z))\nvariable xm equal xcm(all,x)\n'
  printf 'variable intact equal f_bonds[1]\nprint "flight ${zm} ${intact} ${xm}" file flight.txt\n'
} > "$tmp/flight.in"
for np in 1 2 4; do
  (cd "$tmp" && rm -f flight.txt breaks.csv && if [ $np = 1 ]; then timeout 300 "$bin" -in flight.in -log none -screen none
   else timeout 300 mpirun --allow-run-as-root --oversubscribe -np $np "$bin" -in flight.in -log none -screen none; fi
   cp breaks.csv "breaks$np.csv" 2> /dev/null) > "$tmp/flight.log" 2>&1
  set -- $(awk '$1 == "flight" { print $2, $3, $4 }' "$tmp/flight.txt" 2>/dev/null)
  rows=$(($(wc -l < "$tmp/breaks$np.csv" 2>/dev/null || echo 1) - 1))
  if [ $np = 1 ]; then
    z1=${1:-none} n1=${2:-none}
    if [ -n "${3:-}" ] && awk -v x="$3" -v n="$n1" -v r="$rows" 'BEGIN { exit !(x > 3.3 && n > 0 && n < 84 && r == 84 - n) }'; then
      ok "bonded bar in flight on 1 rank: moved to x = $3 m, $rows of 84 bonds broke (rows of keyword breaks), $n1 intact"
    else
      bad "bonded bar in flight on 1 rank: x ${3:-none} m, intact ${n1}, $rows break rows: $(grep -m1 ERROR "$tmp/flight.log")"
    fi
  elif [ "${2:-x}" = "$n1" ] && cmp -s "$tmp/breaks1.csv" "$tmp/breaks$np.csv" &&
       awk -v a="$z1" -v b="${1:-none}" 'BEGIN { d = a - b; if (d < 0) d = -d; s = a < 0 ? -a : a
         exit !(a == a + 0 && b == b + 0 && s > 1e-4 && d <= 1e-10 * s) }'; then
    ok "bonded bar in flight on $np ranks: deflection $1 m (1 rank $z1), $2 intact, the $rows break rows byte for byte"
  else
    bad "bonded bar in flight on $np ranks: deflection ${1:-none} against $z1 m, intact ${2:-none} against $n1, break rows $(cmp "$tmp/breaks1.csv" "$tmp/breaks$np.csv" 2>&1 | head -1): $(grep -m1 ERROR "$tmp/flight.log")"
  fi
done
# the flight split by write_restart on 2 ranks and read_restart on 4: the bonds'
# per-atom states travel in the file to other ranks; the same deflection, intact
# bonds and break rows (the second part appends to them) as straight through
sed '/^balance\|^# balance/,$d' "$tmp/flight.in" > "$tmp/flight1.in"
echo 'write_restart flight.restart' >> "$tmp/flight1.in"
{
  printf 'read_restart flight.restart\n'
  [ "$host" = liggghts ] && printf 'atom_modify sort 0 0.0\n'
  sed -n '/^comm_modify\|^communicate/p; /^fix /p' "$tmp/flight.in"
  printf 'timestep 8e-6\n'
  sed -n '/^balance\|^# balance/,$p' "$tmp/flight.in"
} > "$tmp/flight2.in"
(cd "$tmp" && rm -f flight.txt breaks.csv &&
  timeout 300 mpirun --allow-run-as-root --oversubscribe -np 2 "$bin" -in flight1.in -log none -screen none &&
  timeout 300 mpirun --allow-run-as-root --oversubscribe -np 4 "$bin" -in flight2.in -log none -screen none) \
  > "$tmp/flight.log" 2>&1
set -- $(awk '$1 == "flight" { print $2, $3 }' "$tmp/flight.txt" 2>/dev/null)
if [ "${2:-x}" = "$n1" ] && cmp -s "$tmp/breaks1.csv" "$tmp/breaks.csv" &&
   awk -v a="$z1" -v b="${1:-none}" 'BEGIN { d = a - b; if (d < 0) d = -d; s = a < 0 ? -a : a
     exit !(a == a + 0 && b == b + 0 && s > 1e-4 && d <= 1e-10 * s) }'; then
  ok "the flight split by a restart, written on 2 ranks, read on 4: deflection $1 m, $2 intact, the break rows byte for byte"
else
  bad "the flight split by a restart (2 -> 4 ranks): ${1:-none} against $z1 m, intact ${2:-none} against $n1, $(cmp "$tmp/breaks1.csv" "$tmp/breaks.csv" 2>&1 | head -1): $(grep -m1 ERROR "$tmp/flight.log")"
fi
# cohesive contacts that travel with their discs: a 2D bar of 11 x 2 discs
# (eqs. 6-8, every neighbour bonded) flies 2.4 m along x through the rank
# boundaries (LAMMPS balances the ranks for its second half), stretched at its
# ends and kicked at its middle so that some of its 31 bonds break (25 intact in
# LAMMPS, 27 in LIGGGHTS: each host is compared with itself): on 1, 2 and 4
# ranks the middle's deflection and the intact bonds alike (each disc sums its
# pairs' loads in its partners' ID order, whichever rank computes them); then
# split by a restart written on 2 ranks and read on 4
{
  printf 'units si\ndimension 2\nboundary f f p\natom_style sphere\natom_modify map array%s\n' \
    "$([ "$host" = liggghts ] && echo ' sort 0 0.0')"
  printf 'region box block -0.5 6.5 -1 1 -0.5 0.5\ncreate_box 1 box\n'
  for j in 0 1; do for i in 0 1 2 3 4 5 6 7 8 9 10; do
    echo "create_atoms 1 single $(awk -v i=$i 'BEGIN { print 0.2 * i }') 0.$((2 * j)) 0 units box"
  done; done
  printf 'set type 1 diameter 0.2\nset type 1 density 925\n%s\nneighbor 0.02 bin\n' \
    "$([ "$host" = liggghts ] && echo 'communicate single cutoff 0.5 vel yes' || echo 'comm_modify cutoff 0.5 vel yes')"
  printf 'fix bonds all servo_bc/bonds cohesive kn 1e7 ks 4e6 kr 2e3 fn 2e3 fs 1e3 mr 50 mu 0.5\n'
  printf 'fix integrate all nve/sphere%s\nfix plane all enforce2d\n' "$([ "$host" = lammps ] && echo ' disc')"
  printf 'region left block INF 0.05 INF INF INF INF units box\nregion right block 1.95 INF INF INF INF INF units box\n'
  printf 'region middle block 0.95 1.05 INF INF INF INF units box\n'
  printf 'group left region left\ngroup right region right\ngroup middle region middle\n'
  printf 'velocity all set 2 0 0 units box\nvelocity left set 1.95 0 0 units box\n'
  printf 'velocity right set 2.05 0 0 units box\nvelocity middle set 2 0.5 0 units box\n'
  printf 'timestep 1e-4\nrun 6000\n%s\nrun 6000\n' \
    "$([ "$host" = liggghts ] && echo '# balance: LIGGGHTS 3.8 has no balance command' || echo 'balance 1.0 shift x 10 1.0')"
  printf 'variable ym equal xcm(middle,y)-0.5*(xcm(left,y)+xcm(right,y))\nvariable xm equal xcm(all,x)\n'
  printf 'variable intact equal f_bonds[1]\nprint "flight ${ym} ${intact} ${xm}" file cflight.txt\n'
} > "$tmp/cflight.in"
# same_flight LABEL LOG: cflight.txt's deflection against the first run's ($y1, to 1e-10) and its intact bonds ($c1)
same_flight() {
  set -- "$1" "$2" $(awk '$1 == "flight" { print $2, $3 }' "$tmp/cflight.txt" 2>/dev/null)
  if [ "${4:-x}" = "$c1" ] && awk -v a="$y1" -v b="${3:-none}" 'BEGIN { d = a - b; if (d < 0) d = -d; s = a < 0 ? -a : a
       exit !(a == a + 0 && b == b + 0 && s > 1e-3 && d <= 1e-10 * s) }'; then
    ok "$1: deflection $3 m (the first run's $y1), $4 intact"
  else
    bad "$1: deflection ${3:-none} against $y1 m, intact ${4:-none} against $c1: $(grep -m1 ERROR "$2")"
  fi
}
for np in 1 2 4; do
  (cd "$tmp" && rm -f cflight.txt && if [ $np = 1 ]; then timeout 300 "$bin" -in cflight.in -log none -screen none
   else timeout 300 mpirun --allow-run-as-root --oversubscribe -np $np "$bin" -in cflight.in -log none -screen none; fi) \
    > "$tmp/cflight.log" 2>&1
  set -- $(awk '$1 == "flight" { print $2, $3, $4 }' "$tmp/cflight.txt" 2>/dev/null)
  if [ $np = 1 ]; then
    y1=${1:-none} c1=${2:-none}
    if [ -n "${3:-}" ] && awk -v x="$3" -v n="$c1" 'BEGIN { exit !(x > 3.3 && n > 0 && n < 31) }'; then
      ok "cohesive bar in flight on 1 rank: moved to x = $3 m, $c1 of 31 bonds intact, deflection $1 m"
    else
      bad "cohesive bar in flight on 1 rank: x ${3:-none} m, intact ${c1}: $(grep -m1 ERROR "$tmp/cflight.log")"
    fi
  else
    same_flight "cohesive bar in flight on $np ranks" "$tmp/cflight.log"
  fi
done
sed '/^balance\|^# balance/,$d' "$tmp/cflight.in" > "$tmp/cflight1.in"
echo 'write_restart cflight.restart' >> "$tmp/cflight1.in"
{
  printf 'read_restart cflight.restart\n'
  [ "$host" = liggghts ] && printf 'atom_modify sort 0 0.0\n'
  sed -n '/^comm_modify\|^communicate\|^neighbor/p; /^fix /p' "$tmp/cflight.in"
  printf 'timestep 1e-4\n'
  sed -n '/^balance\|^# balance/,$p' "$tmp/cflight.in"
} > "$tmp/cflight2.in"
(cd "$tmp" && rm -f cflight.txt &&
  timeout 300 mpirun --allow-run-as-root --oversubscribe -np 2 "$bin" -in cflight1.in -log none -screen none &&
  timeout 300 mpirun --allow-run-as-root --oversubscribe -np 4 "$bin" -in cflight2.in -log none -screen none) \
  > "$tmp/cflight.log" 2>&1
same_flight "the cohesive flight split by a restart, written on 2 ranks, read on 4" "$tmp/cflight.log"
# the same bar in a box periodic in x, short enough (3.5 m) that it crosses the
# boundary: its pairs across it join an owned disc and a ghost image; on 1 and
# 2 ranks the deflection of the open box to 1e-10 (wrapped centres round off
# otherwise) and the same intact bonds
sed 's/^boundary f f p$/boundary p f p/; s/^region box block -0.5 6.5 -1 1 -0.5 0.5$/region box block -0.5 3.0 -1 1 -0.5 0.5/;
  /^balance\|^# balance/d' "$tmp/cflight.in" > "$tmp/cperiodic.in"
for np in 1 2; do
  (cd "$tmp" && rm -f cflight.txt && timeout 300 mpirun --allow-run-as-root --oversubscribe -np $np "$bin" \
    -in cperiodic.in -log none -screen none) > "$tmp/cperiodic.log" 2>&1
  same_flight "cohesive bar across a periodic boundary on $np rank(s)" "$tmp/cperiodic.log"
done
# a ghost cutoff shorter than a cohesive pair's reach, on 2 ranks: refused naming both
sed 's/cutoff 0.5 vel yes/cutoff 0.1 vel yes/' "$tmp/cflight.in" > "$tmp/ccut.in"
(cd "$tmp" && timeout 120 mpirun --allow-run-as-root --oversubscribe -np 2 "$bin" -in ccut.in -log none) > "$tmp/ccut.log" 2>&1
status=$?
if [ $status -ne 0 ] && grep -qF "the ghost cutoff 0.100000 m is shorter than a pair's reach 0.220000 m" "$tmp/ccut.log"; then
  ok "cohesive on 2 ranks, refuses a ghost cutoff shorter than a pair's reach (exit $status)"
else
  bad "cohesive on 2 ranks, a ghost cutoff of 0.1 m (exit $status): $(grep -m1 -E 'ERROR|signal' "$tmp/ccut.log")"
fi
# the ghost cutoff against the bonds, on 2 ranks: shorter than a bond at
# creation is refused naming both lengths; a bond pulled (setforce, velocity
# set) past the cutoff stops the run naming its atoms
cutoff_case() {  # LABEL CUTOFF EXPECTED
  {
    printf 'units si\ndimension 3\nboundary f f f\natom_style sphere\natom_modify map array%s\n' \
      "$([ "$host" = liggghts ] && echo ' sort 0 0.0')"
    printf 'region box block -1 1 -0.5 0.5 -0.5 0.5\ncreate_box 1 box\n'
    printf 'create_atoms 1 single -0.1 0 0\ncreate_atoms 1 single 0.1 0 0\nset type 1 diameter 0.2\nset type 1 density 925\n'
    [ "$host" = liggghts ] && printf 'communicate single cutoff %s\n' "$2" || printf 'comm_modify cutoff %s\n' "$2"
    printf 'fix bonds all servo_bc/bonds beam 4e9 0.3 1.0\nfix integrate all nve/sphere\nfix hold all setforce 0 0 0\n'
    printf 'group a id 1\ngroup b id 2\nvelocity a set -1 0 0 units box\nvelocity b set 1 0 0 units box\n'
    printf 'timestep 1e-4\nrun 2000\n'
  } > "$tmp/cutoff.in"
  (cd "$tmp" && timeout 120 mpirun --allow-run-as-root --oversubscribe -np 2 "$bin" -in cutoff.in -log none) \
    > "$tmp/cutoff.log" 2>&1
  local status=$?
  if [ $status -ne 0 ] && grep -qF "$3" "$tmp/cutoff.log"; then
    ok "on 2 ranks, refuses $1 (exit $status): $(grep -m1 -o 'ERROR.*' "$tmp/cutoff.log" | cut -c1-150)"
  else
    bad "on 2 ranks, $1 (exit $status): $(grep -m1 -E 'ERROR|signal' "$tmp/cutoff.log")"
  fi
}
cutoff_case "a ghost cutoff shorter than a bond" 0.1 "the ghost cutoff 0.100000 m is shorter than a bond at creation (2 r_max = 0.200000 m)"
cutoff_case "a bond stretched past the ghost cutoff" 0.25 "nor one of its ghosts (ghost cutoff 0.250000 m; the longest bond at creation 0.200000 m)"
# the bonds fix's restart block and its per-atom data checked value by value
# the bonds fix's restart block and its per-atom data checked value by value
# (sbc/saved.h): corrupted counts, sizes and values are refused by name, never
# a crash or a NaN output. The block is sealed (its length's seal, a checksum
# of its values): a changed value is refused by the checksum, and, sealed again
# after the change (as a writer that computed a wrong value would), by its own
# check. corrupt_bonds FILE OFFSET VALUE [unsealed] overwrites one double of
# the block (found by its marker, BONDS_MAGIC of fix_servo_bc_bonds.cpp:
# marker, length, seal, checksum, then the fields) and seals it again unless
# "unsealed" (tests/restart_edit.py). corrupt_atom FILE OFFSET VALUE overwrites one double of atom 1's
# per-atom data (size 33, work, fracture, 1 bond, partner 2, its 28 beam
# values: fix_servo_bc_bonds_slots.cpp)
corrupt_bonds() { python3 "$here/../restart_edit.py" "$1" 8.020007e7 "$2" "$3" ${4:-}; }
corrupt_atom() {
  perl -e '
    my ($file, $k, $value) = @ARGV;
    open(my $f, "+<", $file) or exit 1; binmode $f; local $/; my $d = <$f>;
    my ($at, $from) = (-1, 0);
    while (($at = index($d, pack("d", 33), $from)) >= 0) {
      last if substr($d, $at + 24, 16) eq pack("d", 1) . pack("d", 2);
      $from = $at + 1;
    }
    exit 1 if $at < 0;
    substr($d, $at + 8 * $k, 8) = pack("d", $value eq "nan" ? 9**9**9 / 9**9**9 : $value);
    seek($f, 0, 0); print $f $d; close $f;' "$1" "$2" "$3"
}
corrupt_unsealed() { corrupt_bonds "$@" unsealed; }
refused_restart() {  # LABEL OFFSET VALUE EXPECTED [corrupt_atom | corrupt_unsealed]
  cp "$tmp/split.restart" "$tmp/bad.restart"
  ${5:-corrupt_bonds} "$tmp/bad.restart" "$2" "$3" || { bad "restart: no fix servo_bc/bonds data in the file"; return; }
  sed 's/read_restart split.restart/read_restart bad.restart/' "$tmp/split.in" > "$tmp/bad.in"
  (cd "$tmp" && timeout 60 "$bin" -in bad.in -log none > bad.log 2>&1)
  local status=$?
  if [ $status -ge 1 ] && [ $status -le 125 ] && grep -qF "$4" "$tmp/bad.log"; then
    ok "refuses a restart file with $1 (exit $status): $(grep -m1 -o 'ERROR.*' "$tmp/bad.log" | cut -c1-120)"
  else
    bad "restart file with $1 (exit $status): $(grep -m1 -E 'ERROR|terminate|signal' "$tmp/bad.log")"
  fi
}
refused_restart "a length of 1e12" 1 1e12 "its length 1000000000000 does not match its seal"
refused_restart "1e10 spheres, unsealed" 19 1e10 "do not match their checksum" corrupt_unsealed
refused_restart "1e10 spheres" 19 1e10 "'sphere count'"
refused_restart "1e6 doubles per bond" 16 1e6 "'doubles per bond'"
refused_restart "29 doubles per beam bond" 16 29 "29 doubles per bond state; this version's beam bonds have 28"
refused_restart "1e4 bonds per sphere" 15 1e4 "'slots per atom'"
refused_restart "a smallest radius 0" 14 0 "'smallest radius'"
refused_restart "a NaN critical time step" 17 nan "'critical time step'"
refused_restart "another E" 5 5e9 "the file's bonds are beam 5000000000"
refused_restart "an atom with 7 bonds" 3 7 "'bond count'" corrupt_atom
refused_restart "an atom whose size does not fit its bonds" 0 34 "34 values for 1 bonds" corrupt_atom
refused_restart "a partner ID 0" 4 0 "'partner ID'" corrupt_atom
refused_restart "a NaN bond state" 9 nan "'bond state value'" corrupt_atom
refused_restart "a NaN fracture energy" 2 nan "'fracture energy'" corrupt_atom
refused_restart "a negative fracture energy" 2 -1 "fracture energy -1" corrupt_atom
# a second bonds fix on the same atoms, and a keyword twice
refused_fix_line() {  # LABEL WHAT-TO-APPEND-TO-THE-FIX-LINE EXPECTED
  sed "s/^fix bonds all servo_bc\/bonds beam 4e9 0.3 1.0\$/&$2/" "$tmp/split.in" > "$tmp/twice.in"
  (cd "$tmp" && timeout 60 "$bin" -in twice.in -log none > twice.log 2>&1)
  local status=$?
  if [ $status -ne 0 ] && grep -qF "$3" "$tmp/twice.log"; then
    ok "refuses $1 (exit $status)"
  else
    bad "$1 (exit $status): $(grep -m1 ERROR "$tmp/twice.log")"
  fi
}
refused_fix_line "a second fix servo_bc/bonds on the same atoms" '\nfix bonds2 all servo_bc\/bonds beam 4e9 0.3 1.0' \
  "which would bond them twice"
refused_fix_line "strength given twice" ' strength 1e5 0 0 0 strength 2e5 0 0 0' "keyword strength given twice"
# failure (strength FT 0 0 0, friction): two spheres (r = 0.1 m, parallel bond,
# axial stiffness K = k^n pi r^2 = E pi r / 2) pulled apart at 1e-6 m per
# step: 100 steps carry K 1e-4 exactly; the bond breaks at the first step
# where K d >= FT = 1e5 N (d = 1.6e-4 m, step 160), holding K d^2 / 2, which
# eq. 51 counts as dissipated; apart, no force; pushed back to an overlap of
# 5e-5 m, the broken bond is a contact of stiffness K (repulsion K 5e-5)
sort=
[ "$host" = liggghts ] && sort="atom_modify     sort 0 0.0"
cat > "$tmp/break.in" <<DECK
units           si
dimension       3
boundary        f f f
atom_style      sphere
atom_modify     map array
$sort
region          box block -1 1 -1 1 -1 1
create_box      1 box
create_atoms    1 single 0 0 0
create_atoms    1 single 0.2 0 0
set             type 1 diameter 0.2
set             type 1 density 925
group           a id 1
group           b id 2
fix             bonds all servo_bc/bonds parallel 4e9 0.3 1 strength 1e5 0 0 0 friction 0.5
fix             integrate all nve/sphere
fix             hold_a a setforce 0 0 0
fix             hold_b b setforce 0 0 0
timestep        1e-4
variable        f equal f_hold_b[1]
variable        intact equal f_bonds[1]
variable        dis equal f_bonds[4]
velocity        b set 0.01 0 0
run             100
print           "stretched \${f} \${intact} \${dis}" file $tmp/break.txt
run             100
print           "broken \${f} \${intact} \${dis}" append $tmp/break.txt
velocity        b set -0.01 0 0
run             250
print           "pressed \${f} \${intact} \${dis}" append $tmp/break.txt
DECK
(cd "$tmp" && timeout 60 "$bin" -in break.in -log none > break.log 2>&1)
verdict=$(awk 'BEGIN { K = 4e9 * atan2(0, -1) * 0.1 / 2 }
  $1 == "stretched" { e1 = ($2 + K * 1e-4) / (K * 1e-4); i1 = $3; d1 = $4 }
  $1 == "broken" { f2 = $2; i2 = $3; e2 = ($4 - K * 1.6e-4^2 / 2) / (K * 1.6e-4^2 / 2) }
  $1 == "pressed" { e3 = ($2 - K * 5e-5) / (K * 5e-5); i3 = $3; e4 = ($4 - K * 1.6e-4^2 / 2) / (K * 1.6e-4^2 / 2) }
  END { a = e1 < 0 ? -e1 : e1; b = e2 < 0 ? -e2 : e2; c = e3 < 0 ? -e3 : e3; g = e4 < 0 ? -e4 : e4
        ok = NR == 3 && a <= 1e-9 && i1 == 1 && d1 == 0 && f2 == 0 && i2 == 0 && b <= 1e-9 && c <= 1e-9 && i3 == 0 && g <= 1e-6
        printf "%s %.2g %.2g %.2g %.2g", ok ? "ok" : "bad", a, b, c, g }' "$tmp/break.txt" 2>/dev/null)
set -- $verdict
if [ "${1:-bad}" = ok ]; then
  ok "a bond that fails: K d to $2 before, broken at 1.6e-4 m holding K d^2/2 (eq. 51, to $3), a contact of stiffness K after (to $4)"
else
  bad "a bond that fails: $(cat "$tmp/break.txt" 2>/dev/null | tr '\n' ';') $(grep -m1 ERROR "$tmp/break.log")"
fi
refused() {  # LABEL FIX-LINE EXPECTED [DIMENSION [UNITS]]
  # 2d: periodic in z, the discs at z = 0
  local z=0.5 zb="0 1" bz=f
  [ "${4:-3}" = 2 ] && z=0 zb="-0.5 0.5" bz=p
  # LIGGGHTS 3.8 cannot sort atoms without a pair style (bin size 0)
  printf 'units %s\ndimension %s\nboundary f f %s\natom_style sphere\n%s\nregion b block 0 1 0 1 %s\ncreate_box 1 b\ncreate_atoms 1 single 0.1 0.5 %s\ncreate_atoms 1 single 0.3 0.5 %s\nset type 1 diameter 0.2\n%s\nrun 1\n' \
    "${5:-si}" "${4:-3}" "$bz" "$([ "$host" = liggghts ] && echo 'atom_modify sort 0 0.0')" "$zb" "$z" "$z" "$2" > "$tmp/bad.in"
  (cd "$tmp" && timeout 60 "$bin" -in bad.in -log none) > "$tmp/bad.log" 2>&1
  local status=$?
  if [ $status -ne 0 ] && grep -qF "$3" "$tmp/bad.log"; then ok "refuses $1 (exit $status): $3"
  else bad "$1 (exit $status), expected '$3': $(tail -2 "$tmp/bad.log")"; fi
}
refused "a missing alpha" "fix b all servo_bc/bonds beam 4e9 0.3" "expected at least 4 arguments after the style (MODEL E nu alpha), got 3"
refused "a strength with 3 values" "fix b all servo_bc/bonds beam 4e9 0.3 1 strength 1e5 0 0" "keyword strength needs 4 values (FT FS MB MT"
refused "a zero tensile strength" "fix b all servo_bc/bonds parallel 4e9 0.3 1 strength 0 1 1 1" "keyword strength: 0 1 1 1 (expected a tension > 0"
refused "an unknown keyword" "fix b all servo_bc/bonds beam 4e9 0.3 1 strenght 1e5 0 0 0" "unknown keyword 'strenght' (expected strength, friction or breaks)"
refused "an unknown model" "fix b all servo_bc/bonds rope 4e9 0.3 1" "model 'rope' is not valid (expected beam, parallel or cohesive)"
refused "a word for E" "fix b all servo_bc/bonds beam stiff 0.3 1" "keyword E: 'stiff' is not a number"
refused "nu = 0.5" "fix b all servo_bc/bonds beam 4e9 0.5 1" "expected E > 0 Pa, -1 < nu < 0.5, alpha > 0"
refused "spheres that do not touch" "set atom 2 x 0.6
fix b all servo_bc/bonds beam 4e9 0.3 1" "no two spheres touch"
refused "units metal" "fix b all servo_bc/bonds beam 4e9 0.3 1" "requires units si (the laws' quantities are SI; this script has units metal)" 3 metal
coh="kn 1e8 ks 4e7 kr 20 fn 300 fs 60 mr 0.2 mu 0.6"
refused "cohesive bonds in a 3d box" "fix b all servo_bc/bonds cohesive $coh" "cohesive requires a 2d box"
refused "a cohesive law without mu" "fix b all servo_bc/bonds cohesive kn 1e8 ks 4e7 kr 20 fn 300 fs 60 mr 0.2" \
  "cohesive: missing values (expected 'kn KN ks KS kr KR fn FN fs FS mr MR mu MU')" 2
refused "a word for a strength" "fix b all servo_bc/bonds cohesive kn 1e8 ks 4e7 kr 20 fn strong fs 60 mr 0.2 mu 0.6" \
  "cohesive: fn 'strong' is not a number (expected a real > 0)" 2
refused "a misspelt keyword" "fix b all servo_bc/bonds cohesive kn 1e8 ks 4e7 kb 20 fn 300 fs 60 mr 0.2 mu 0.6" \
  "cohesive: expected keyword 'kr' but found 'kb'" 2
refused "discs that do not touch" "set atom 2 x 0.6
fix b all servo_bc/bonds cohesive $coh" "cohesive: no two of the 2 discs touch, so no bond formed" 2
printf 'units si\ndimension 3\nboundary f f f\natom_style atomic\nregion b block 0 1 0 1 0 1\ncreate_box 1 b\ncreate_atoms 1 single 0.1 0.5 0.5\nmass 1 1\nfix b all servo_bc/bonds beam 4e9 0.3 1\n' > "$tmp/atomic.in"
(cd "$tmp" && timeout 60 "$bin" -in atomic.in -log none) > "$tmp/atomic.log" 2>&1
status=$?
if [ $status -ne 0 ] && grep -qF "Fix servo_bc/bonds: requires atom_style sphere" "$tmp/atomic.log"; then
  ok "refuses atom_style atomic (exit $status): requires atom_style sphere"
else
  bad "atom_style atomic (exit $status): $(tail -2 "$tmp/atomic.log")"
fi
# the cohesive layer (inputs/compare/cohesive_layer_short.sbc, the decks of
# servo-bc --decks) split by write_restart / read_restart inside increment 2:
# the bonds' pair state and the servo's state come back, and the split run
# writes the uninterrupted run's rows (to 1e-9 of the stress scale)
servo_bc=$here/../../build/servo-bc
if "$servo_bc" --decks "$tmp/coh" "$here/../../inputs/compare/cohesive_layer_short.sbc" > "$tmp/decks.log" 2>&1; then
  cd "$tmp/coh"
  sed "/^run  *0\$/d; s|^run .*|run 4000\nwrite_restart half.restart|; /jump SELF loop/d; s/$host.csv/split.csv/" \
    $host.in > part1.in
  { echo "read_restart half.restart"; sed -n '/^atom_modify/p' $host.in
    sed -n '/^pair_style/,$p' $host.in | sed "s/$host.csv/split.csv/"; } > part2.in
  for deck in $host part1 part2; do
    timeout 300 "$bin" -in $deck.in -log none > $deck.log 2>&1 || { tail -3 $deck.log; break; }
  done
  cd - > /dev/null
  # the bonds fix after fix servo_bc: its loads would miss what fix servo_bc measures
  sed -n '/^fix  *bonds /p' "$tmp/coh/$host.in" > "$tmp/coh/bonds_line"
  sed '/^fix  *bonds /d' "$tmp/coh/$host.in" | sed "/^fix  *servo /r $tmp/coh/bonds_line" > "$tmp/coh/late.in"
  (cd "$tmp/coh" && timeout 60 "$bin" -in late.in -log none > late.log 2>&1)
  status=$?
  if [ $status -ne 0 ] && grep -qF "fix servo_bc/bonds bonds must come before fix servo_bc servo" "$tmp/coh/late.log"; then
    ok "refuses fix servo_bc/bonds cohesive after fix servo_bc (exit $status), by fix ID"
  else
    bad "the bonds fix after fix servo_bc (exit $status): $(grep -m1 ERROR "$tmp/coh/late.log")"
  fi
  if [ "$host" = lammps ]; then  # a granular pair style beside the cohesive bonds: every contact twice
    sed 's|^pair_style .*|pair_style      gran/hooke/history 1e8 4e7 0 0 0.6 0|' "$tmp/coh/lammps.in" > "$tmp/coh/twice.in"
    (cd "$tmp/coh" && timeout 60 "$bin" -in twice.in -log none > twice.log 2>&1)
    status=$?
    if [ $status -ne 0 ] && grep -qF "pair_style gran/hooke/history computes them again" "$tmp/coh/twice.log"; then
      ok "refuses a granular pair style beside cohesive bonds (exit $status)"
    else
      bad "a granular pair style beside cohesive bonds (exit $status): $(grep -m1 ERROR "$tmp/coh/twice.log")"
    fi
  fi
  # the cohesive block: the law defined again with another kn, corrupted counts and values
  # a disc's pairs in the per-atom data: size 4 + 4 count, 0, 0, count, then per pair its partner's ID, the
  # intact flag, fs, m; the first disc with a bond
  corrupt_pair() {
    perl -e '
      my ($file, $k, $value) = @ARGV;
      open(my $f, "+<", $file) or exit 1; binmode $f; local $/; my $d = <$f>;
      for (my $at = 0; $at + 64 <= length($d); $at++) {
        my ($size, $w, $e, $count, $id, $intact) = unpack("d6", substr($d, $at, 48));
        next unless $count >= 1 && $count <= 12 && $count == int($count) && $size == 4 + 4 * $count && $w == 0 &&
          $e == 0 && $id >= 1 && $id == int($id) && $intact == 1;
        substr($d, $at + 8 * $k, 8) = pack("d", $value eq "nan" ? 9**9**9 / 9**9**9 : $value);
        seek($f, 0, 0); print $f $d; close $f; exit 0;
      }
      exit 1;' "$1" "$2" "$3"
  }
  coh_refused() {  # LABEL OFFSET VALUE EXPECTED [SED [CORRUPTER]]
    cp "$tmp/coh/half.restart" "$tmp/coh/bad.restart"
    [ "$2" = - ] || ${6:-corrupt_bonds} "$tmp/coh/bad.restart" "$2" "$3" || { bad "cohesive restart: no block"; return; }
    sed "s/read_restart half.restart/read_restart bad.restart/; ${5:-}" "$tmp/coh/part2.in" > "$tmp/coh/bad.in"
    (cd "$tmp/coh" && timeout 60 "$bin" -in bad.in -log none > bad.log 2>&1)
    local status=$?
    if [ $status -ge 1 ] && [ $status -le 125 ] && grep -qF "$4" "$tmp/coh/bad.log"; then
      ok "cohesive: refuses $1 (exit $status): $(grep -m1 -o 'ERROR.*' "$tmp/coh/bad.log" | cut -c1-110)"
    else
      bad "cohesive restart with $1 (exit $status): $(grep -m1 -E 'ERROR|terminate|signal' "$tmp/coh/bad.log")"
    fi
  }
  coh_refused "another law after read_restart" - - "the file's cohesive law differs: kn" \
    's/servo_bc\/bonds cohesive kn \([0-9.e+]*\)/servo_bc\/bonds cohesive kn 2\1/'
  coh_refused "a smallest radius 0" 12 0 "'smallest radius'"
  coh_refused "1e4 slots per atom" 13 1e4 "'slots per atom'"
  coh_refused "a disc count of 1" 15 1 "'disc count'"
  coh_refused "the gathered layout of 0.2.0 (model 3)" 4 3 "kept every contact on every rank"
  coh_refused "an intact flag 0.5" 5 0.5 "intact flag 0.5" "" corrupt_pair
  coh_refused "a NaN tangential spring" 6 nan "'bond state value'" "" corrupt_pair
  res=$(paste -d, "$tmp/coh/$host.csv" "$tmp/coh/split.csv" 2>/dev/null | awk -F, -f "$here/../sigma_diff.awk")
  set -- $res
  if [ "${1:-0}" = 6 ] && awk -v m="${2:-100}" 'BEGIN { exit !(m <= 1e-7) }'; then
    ok "cohesive layer split by a restart inside increment 2: $1 rows, the uninterrupted run's to $2 % of the stress scale$(
      cmp -s "$tmp/coh/$host.csv" "$tmp/coh/split.csv" && echo ", byte for byte")"
  else
    bad "cohesive layer split by a restart: ${1:-0} rows of 6, ${2:-?} % from the uninterrupted run: $(tail -2 "$tmp/coh/part2.log")"
  fi
else
  bad "servo-bc --decks for the cohesive layer: $(tail -2 "$tmp/decks.log")"
fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
