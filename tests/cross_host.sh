#!/usr/bin/env bash
# Every engine on the same case, through the compare command (scripts/compare.sh,
# `make compare`): the paper's regular 100-particle packing, the first 30 of
# the 300 increments of eq. 38 (inputs/compare/regular_{D,P,T}_30.sbc),
# the default words. The embedded engine, LAMMPS, LIGGGHTS and YADE serial,
# LAMMPS and LIGGGHTS also on 2 ranks, where LAMMPS on 2 ranks (newton on)
# must agree with 1 rank within 0.01 % (the default preset's 1e-4). For every engine and every
# sigma component, every converged increment up to the first stress peak
# (the report's "before the peak"): within 0.5 % of the stress scale of the
# embedded engine; and LIGGGHTS within 0.5 % of LAMMPS; a 3D case, (P) on the
# 4^3 lattice, likewise over nine components. Every host must be
# there (make check builds and installs them). Prints "N passed, N failed";
# KEEP=DIR keeps the report folders there.
# Usage: cross_host.sh   (binaries from build/, or B=DIR)
set -u
here=$(cd "$(dirname "$0")" && pwd)
. "$here/csv_columns.sh"
top=$(cd "$here/.." && pwd)
tmp=${KEEP:-$(mktemp -d)}
mkdir -p "$tmp"
pass=0 fail=0
# hosts that are not there are skipped with one line each, never an error
bin=${B:-$top/build}
mkdir -p "$tmp/only_embedded"
ln -sf "$bin/servo-bc" "$bin/servo-bc-plot" "$tmp/only_embedded/"
printf 'dimension 2\nlattice square 5 5 spacing 2e-3 radius 1.02e-3\ncontact frictional kn 1e4 ks 0 mu 0.4\ndensity 2e3\ntimestep 1e-5\nservo_bc D F 1.002 0 0 0.997 increments 2\nrun\n' \
  > "$tmp/tiny.sbc"
B=$tmp/only_embedded bash "$top/scripts/compare.sh" "$tmp/tiny.sbc" "$tmp/tiny" > "$tmp/tiny.log" 2>&1
rc=$?
if [ $rc -eq 0 ] && [ "$(grep -c 'skipped' "$tmp/tiny.log")" = 3 ] && grep -q '^| embedded | 2 |' "$tmp/tiny/report.md"; then
  pass=$((pass + 1)); echo "compare without hosts: embedded only, $(grep -c skipped "$tmp/tiny.log") one-line notices, exit 0"
else
  fail=$((fail + 1)); echo "FAIL compare without hosts (exit $rc):"; cat "$tmp/tiny.log"
fi
# ENGINES: run only some engines again, report them with the results already
# there (here a planted lammps.csv, a copy of the embedded one, is kept)
cp "$tmp/tiny/embedded.csv" "$tmp/tiny/lammps.csv"
echo "lammps 1.00" >> "$tmp/tiny/times.txt"
ENGINES=embedded B=$tmp/only_embedded bash "$top/scripts/compare.sh" "$tmp/tiny.sbc" "$tmp/tiny" > "$tmp/tiny2.log" 2>&1
rc=$?
if [ $rc -eq 0 ] && grep -q '^| embedded | 2 |' "$tmp/tiny/report.md" && grep -q '^| lammps | 2 | 1.00 |' "$tmp/tiny/report.md" &&
  grep -q '^| lammps | σ̄11 | 0 | 0 | 0 | 0 |' "$tmp/tiny/report.md" && ! grep -q skipped "$tmp/tiny2.log"; then
  pass=$((pass + 1)); echo "compare ENGINES=embedded: embedded run again, the lammps results kept and reported"
else
  fail=$((fail + 1)); echo "FAIL compare ENGINES=embedded (exit $rc):"; cat "$tmp/tiny2.log" "$tmp/tiny/report.md"
fi
# one path in every host: DEM steps per converged increment (the mean over the
# path) within 2x of the embedded engine's, each engine serial
steps_parity() {  # LABEL DIR
  local res
  res=$(awk -F, 'NR == 1 { for (c = 2; c <= NF; c++) if ($c ~ /_relax_steps$/) { name[c] = $c; sub(/_relax_steps$/, "", name[c]) } next }
    { n++; for (c in name) s[c] += $c }
    END { for (c in name) if (name[c] == "embedded") e = s[c]
          for (c in name) { r = e > 0 ? s[c] / e : 0; printf "%s %.0f %.3f\n", name[c], s[c] / n, r } }' "$2/steps.csv" 2>/dev/null)
  if [ "$(echo "$res" | grep -c .)" -ge 4 ] && echo "$res" | awk '{ if (!($3 >= 0.5 && $3 <= 2)) bad++ } END { exit bad > 0 }'; then
    pass=$((pass + 1)); echo "one path ($1): DEM steps per increment $(echo "$res" | sort | awk '{ printf "%s%s %s (%.2fx)", (NR > 1 ? ", " : ""), $1, $2, $3 }')"
  else
    fail=$((fail + 1)); echo "FAIL one path ($1): steps per increment and ratio to the embedded engine: $(echo $res)"
  fi
}
for bc in D P; do
  dir=$tmp/lattice7_${bc}_tight
  RANKS=1 bash "$top/scripts/compare.sh" "$top/inputs/compare/lattice7_${bc}_tight.sbc" "$dir" | grep -v "^compare: report"
  steps_parity "7 x 7 frictional lattice ($bc), accuracy tight" "$dir"
done
for bc in D P T; do
  ranks="1 2"
  dir=$tmp/regular_${bc}_30
  RANKS=$ranks bash "$top/scripts/compare.sh" "$top/inputs/compare/regular_${bc}_30.sbc" "$dir" | grep -v "^compare: report"
  engines="lammps liggghts yade lammps_np2 liggghts_np2"
  for e in $engines; do
    # the largest "max, before the peak" over the four components, and the
    # increments compared
    res=$(awk -F'|' -v e=" $e " '$2 == e && $3 ~ /σ̄/ { v = $4 + 0; if (v > m) m = v; n++ } END { printf "%d %s", n, (n ? m : 100) }' \
      "$dir/report.md" 2>/dev/null)
    set -- $res
    incs=$(($(wc -l < "$dir/$e.csv" 2>/dev/null || echo 1) - 1))
    if [ "${1:-0}" = 4 ] && [ "$incs" = 31 ] && awk -v m="$2" 'BEGIN { exit !(m <= 0.5) }'; then
      pass=$((pass + 1)); echo "cross-host ($bc), 100 particles, 31 increments: max |sigma_$e - sigma_embedded| = $2 % of the stress scale"
    else
      fail=$((fail + 1)); echo "FAIL cross-host ($bc) $e: $incs increments of 31, max difference ${2:-?} % of the stress scale"
    fi
  done
  # the rank count (LAMMPS' default newton on: ghost forces summed back in
  # another order) within the default preset's stated accuracy, 1e-4 = 0.01 %
  {
    m=$(paste -d, "$dir/lammps.csv" "$dir/lammps_np2.csv" 2>/dev/null | awk -F, "$COLUMNS_AWK"'NR > 1 { w = NF / 2; n++
        for (c = col("sigma11"); c <= col("sigma22"); c++) { d = $c - $(c + w); if (d < 0) d = -d; if (d > m) m = d; a = $c < 0 ? -$c : $c; if (a > S) S = a } }
      END { if (n == 31 && S > 0) printf "%.3g", 100 * m / S; else print 100 }')
    if awk -v m="$m" 'BEGIN { exit !(m <= 0.01) }'; then
      pass=$((pass + 1)); echo "cross-host ($bc): LAMMPS 2 ranks against 1 rank (newton on): $m % of the stress scale"
    else
      fail=$((fail + 1)); echo "FAIL cross-host ($bc): LAMMPS 2 ranks against 1 rank: $m % of the stress scale"
    fi
  }
  steps_parity "regular 100 particles ($bc), the default words" "$dir"
  set -- $(paste -d, "$dir/embedded.csv" "$dir/lammps.csv" "$dir/liggghts.csv" 2>/dev/null \
    | awk -F, -v scale_from=1 -v a=2 -v b=3 -f "$here/sigma_diff.awk")
  if [ "${1:-0}" = 31 ] && awk -v e="${2:-100}" 'BEGIN { exit !(e <= 0.5) }'; then
    pass=$((pass + 1)); echo "cross-host ($bc): max |sigma_liggghts - sigma_lammps| = $2 % of the stress scale"
  else
    fail=$((fail + 1)); echo "FAIL cross-host ($bc) liggghts against lammps: increments ${1:-0}, max difference ${2:-?} %"
  fi
done
# compare_3d CASE LABEL MEASURE LIMIT WHAT: a 3D (P) case through `servo-bc --decks` and
# compare on every engine, 1 and 2 ranks: each host's nine sigma components within 0.5 % of
# the stress scale of the embedded engine at every increment, and MEASURE (an awk program
# on the host's CSV that prints one number, 1 unless it read 3 rows) at most LIMIT
compare_3d() {
  local case=$1 label=$2 measure=$3 limit=$4 what=$5 dir e res got
  dir=$tmp/$(basename "$case" .sbc)
  (cd "$top" && RANKS="1 2" bash scripts/compare.sh "$case" "$dir" | grep -v "^compare: report")
  for e in lammps liggghts yade lammps_np2 liggghts_np2; do
    res=$(awk -F'|' -v e=" $e " '$2 == e && $3 ~ /σ̄/ { v = $6 + 0; if (v > m) m = v; n++ } END { printf "%d %s", n, (n ? m : 100) }' \
      "$dir/report.md" 2>/dev/null)
    set -- $res
    got=$(awk -F, "$COLUMNS_AWK$measure" "$dir/$e.csv" 2>/dev/null)
    if [ "${1:-0}" = 9 ] && awk -v m="$2" -v g="${got:-1}" -v l="$limit" 'BEGIN { exit !(m <= 0.5 && g <= l) }'; then
      pass=$((pass + 1)); echo "cross-host 3D (P), $label: max |sigma_$e - sigma_embedded| = $2 % of the stress scale (9 components), $what $got"
    else
      fail=$((fail + 1)); echo "FAIL cross-host 3D (P) $label $e: ${1:-0} components, max difference ${2:-?} % (limit 0.5 %), $what ${got:-?} (limit $limit)"
    fi
  done
}
# keyword remap x (inputs/compare/lattice7_P_remap.sbc): the interior follows the frame's
# affine move, so on every engine and rank count each increment is one servo iteration of
# two relaxation windows (40 DEM steps) and P11 is -N kn (2R - d F11) / ((N - 1) d) to 1e-9
dir=$tmp/lattice7_P_remap
(cd "$top" && RANKS="1 2" bash scripts/compare.sh inputs/compare/lattice7_P_remap.sbc "$dir" | grep -v "^compare: report")
for e in embedded lammps liggghts yade lammps_np2 liggghts_np2; do
  got=$(awk -F, "$COLUMNS_AWK"'NR > 2 { n++; if ($col("iterations") != 1 || $col("relax_steps") != 40) bad++
      want = -7 * 1e4 * (2.04e-3 - 2e-3 * $col("F11")) / (6 * 2e-3); d = ($col("P11") - want) / want; if (d < 0) d = -d; if (d > m) m = d }
    END { printf "%d %d %.3g", n, bad, m }' "$dir/$e.csv" 2>/dev/null)
  set -- $got
  if [ "${1:-0}" = 4 ] && [ "${2:-1}" = 0 ] && awk -v m="${3:-1}" 'BEGIN { exit !(m <= 1e-9) }'; then
    pass=$((pass + 1)); echo "remap x, 7 x 7 lattice (P), $e: 4 increments of one servo iteration and 40 DEM steps, P11 against the closed form $3"
  else
    fail=$((fail + 1)); echo "FAIL remap x, 7 x 7 lattice (P), $e: ${1:-0} increments, ${2:-?} not of one iteration and 40 steps, P11 off by ${3:-?}"
  fi
done
# the million-disc decks (inputs/lammps/million.in, inputs/liggghts/million.in) through
# bench/million.sh at 12 x 12 discs: each host on 1 and 2 ranks meets the closed form to
# 1e-9, and 2 ranks give 1 rank's rows to 1e-9 of max |P| (the figures of time are not tested)
out=$(bash "$top/bench/million.sh" "$B/lmp_servo" "$B/liggghts_servo" "$B/servo-bc" 12 2>&1) || true
for hr in "lammps 1" "lammps 2" "liggghts 1" "liggghts 2"; do
  set -- $hr
  got=$(echo "$out" | awk -v h="$1" -v r="$2" '$1 == h && $2 == r { print $3, $(NF - 1), $NF }')
  set -- $got
  if [ "${1:-0}" -ge 160 ] && awk -v c="${2:-1}" -v d="${3:--}" 'BEGIN { exit !(c <= 1e-9 && (d == "-" || d <= 1e-9)) }'; then
    pass=$((pass + 1)); echo "million deck at 12 x 12, $hr rank(s): $1 steps, P against the closed form $2, against 1 rank ${3}"
  else
    fail=$((fail + 1)); echo "FAIL million deck at 12 x 12, $hr rank(s): ${got:-no row}"; echo "$out" | tail -6
  fi
done
# the prestressed frictional 4^3 lattice: P11 at the last increment against the closed form
# -N^2 kn (2R - d F11) / ((N - 1)^2 d^2) within 1e-6
compare_3d inputs/compare/cubic_P_3d.sbc "4^3 lattice" \
  'NR > 1 { n++; e = -16 * 1e4 * (2.04e-3 - 2e-3 * $col("F11")) / (9 * 4e-6); d = ($col("P11") - e) / e }
   END { if (n == 3) printf "%.3g", d < 0 ? -d : d; else print 1 }' 1e-6 "P11 against the closed form within"
# a generated periodic sphere packing (71 spheres; every host's fix finds the periodic frame
# of 62 from the centres alone): |hill_mandel| within tight's 1e-6 on every row
compare_3d inputs/compare/irregular_P_3d.sbc "irregular 71 spheres" \
  'NR > 1 { n++; h = $col("hill_mandel"); if (h < 0) h = -h; if (h > m) m = h }
   END { if (n == 3) printf "%.3g", m; else print 1 }' 1e-6 "|hill_mandel| <="
# layer_3d CASE LABEL P33* FIRST ROWS: the 3D layer CASE in every host: P33 held to 1e-4 of P33* and
# |hill_mandel| <= 1e-4 on the ROWS rows from increment FIRST on, P13 at the last within 5 % of the
# embedded engine's. Not 0.5 % of the stress scale: the free components of these small frictional
# layers part by a few % between hosts, as under a mere translation (docs/frame3d.md, "Irregular packings")
layer_3d() {
  local case=$1 label=$2 pstar=$3 first=$4 rows=$5 dir ref e
  dir=$tmp/$(basename "$case" .sbc)
  (cd "$top" && RANKS="1 2" bash scripts/compare.sh "$case" "$dir" | grep -v "^compare: report")
  layer_row() { awk -F, -v s="$pstar" -v f="$first" -v want="$rows" "$COLUMNS_AWK"'NR > 1 + f { n++
      d = ($col("P33") - s) / s; if (d < 0) d = -d; if (d > m) m = d
      h = $col("hill_mandel"); if (h < 0) h = -h; if (h > hm) hm = h; p13 = $col("P13") }
    END { if (n == want) printf "%.3g %.3g %.12g", m, hm, p13; else print "none" }' "$dir/$1.csv" 2>/dev/null; }
  set -- $(layer_row embedded)
  ref=${3:-0}
  for e in embedded lammps liggghts yade lammps_np2 liggghts_np2; do
    set -- $(layer_row $e)
    if [ $# = 3 ] && awk -v m="$1" -v h="$2" -v p="$3" -v r="$ref" 'BEGIN { d = (p - r) / r; if (d < 0) d = -d
        exit !(m <= 1e-4 && h <= 1e-4 && r > 0 && d <= 0.05) }'; then
      pass=$((pass + 1)); echo "3D layer, $label ($e): P33 within $1 of P33*, |hill_mandel| <= $2, P13 = $3 N/m^2 (embedded $ref)"
    else
      fail=$((fail + 1)); echo "FAIL 3D layer, $label ($e): P33 error, |hill_mandel|, P13: ${*:-none} (limits 1e-4, 1e-4, 5 % of $ref)"
    fi
  done
}
# 70 spheres touching, a stress stage to P33* = -1000 N/m^2 (increment 0 at 0), then F13 = 0.001
layer_3d inputs/compare/irregular_layer_3d.sbc "irregular 70 spheres" -1000 1 2
# 71 spheres compressed by 0.2 %, P33* = -1.5e4 N/m^2 held from increment 0 (`stress P33 -1.5e4 0`),
# then F13 = 0.001 in 2 increments
layer_3d inputs/compare/irregular_layer_prestressed_3d.sbc "prestressed irregular 71 spheres" -1.5e4 0 3
# the frame seal (seal.h) in every host: the chain on the wall of a gap in
# the frame carries its closed-form load, sigma22 = -120 N/m (-100 N/m where a
# host leaves the seal out and the chain falls into the gap), to 1e-6
dir=$tmp/seal_chain_D
(cd "$top" && RANKS="1 2" bash scripts/compare.sh inputs/compare/seal_chain_D.sbc "$dir" | grep -v "^compare: report")
for e in embedded lammps liggghts yade lammps_np2 liggghts_np2; do
  got=$(awk -F, "$COLUMNS_AWK"'NR > 1 { n++; s = $col("sigma22") } END { if (n == 3) printf "%.12g", s; else print "none" }' "$dir/$e.csv" 2>/dev/null)
  if awk -v s="${got:-none}" 'BEGIN { d = s + 120; if (d < 0) d = -d; exit !(s != "none" && d <= 1.2e-4) }'; then
    pass=$((pass + 1)); echo "seal ($e): the chain on the wall, sigma22 = $got N/m (closed form -120)"
  else
    fail=$((fail + 1)); echo "FAIL seal ($e): sigma22 = ${got:-none} N/m at increment 2, expected -120 (the seal's load)"
  fi
done
# the frame seal in 3D (seal.h, walls on the surface's triangles) in every
# host: a column of four spheres squeezed between the walls of the bottom and
# top faces of a cube of eight corners carries its closed-form load,
# sigma33 = -kn (eps L - 2 g) / (5 L^2) = -4483.24 N/m^2 at F33 = 0.97 (0
# where a host leaves the seal out), to 1e-6
dir=$tmp/seal_column_3d
(cd "$top" && RANKS="1 2" bash scripts/compare.sh inputs/compare/seal_column_3d.sbc "$dir" | grep -v "^compare: report")
want=$(awk 'BEGIN { L = 7.1e-3; printf "%.12g", -1e4 * (0.03 * L - 1e-4) / (5 * L * L) }')
for e in embedded lammps liggghts yade lammps_np2 liggghts_np2; do
  got=$(awk -F, "$COLUMNS_AWK"'NR > 1 { n++; s = $col("sigma33") } END { if (n == 3) printf "%.12g", s; else print "none" }' "$dir/$e.csv" 2>/dev/null)
  if awk -v s="${got:-none}" -v w="$want" 'BEGIN { d = (s - w) / w; if (d < 0) d = -d; exit !(s != "none" && d <= 1e-6) }'; then
    pass=$((pass + 1)); echo "seal 3D ($e): the column between the walls, sigma33 = $got N/m^2 (closed form $want)"
  else
    fail=$((fail + 1)); echo "FAIL seal 3D ($e): sigma33 = ${got:-none} N/m^2 at increment 2, expected $want (the walls' load)"
  fi
done
# the cohesive mixed layer (eqs. 7-8) in every host, every contact the core's
# (fix servo_bc/bonds cohesive, servo_bc.Cohesive): within 0.5 % of the stress
# scale before the peak, and the bonds broken within one of the embedded
# engine's (6 or 7 of 54 on this path): the bond loop is the same in every
# host, but the hosts' sums add in another order, a relaxation ends a step
# earlier or later (servo iterations at increment 0: 54, 52, 55, 52 in the
# embedded engine, LAMMPS, LIGGGHTS, YADE), and a bond at the margin of eq. 8
# goes either way (0.2.0: 48 intact everywhere on 1 rank, 47 on 2 ranks; 0.3.0:
# 47, 48, 47, 48)
dir=$tmp/cohesive_layer_short
(cd "$top" && RANKS="1 2" bash scripts/compare.sh inputs/compare/cohesive_layer_short.sbc "$dir" | grep -v "^compare: report")
intact() { grep -a -o 'bonds intact [0-9]*' "$dir/$1.log" 2>/dev/null | tail -n 1 | awk '{ print $3 }'; }
want=$(intact embedded)
for e in lammps liggghts yade lammps_np2 liggghts_np2; do
  res=$(awk -F'|' -v e=" $e " '$2 == e && $3 ~ /σ̄/ { v = $4 + 0; if (v > m) m = v; n++ } END { printf "%d %s", n, (n ? m : 100) }' \
    "$dir/report.md" 2>/dev/null)
  set -- $res
  incs=$(($(wc -l < "$dir/$e.csv" 2>/dev/null || echo 1) - 1))
  got=$(intact "$e")
  if [ "${1:-0}" = 4 ] && [ "$incs" = 6 ] && awk -v m="$2" 'BEGIN { exit !(m <= 0.5) }' && [ -n "$want" ] &&
    [ "$want" -lt 54 ] && awk -v g="${got:-x}" -v w="$want" -v s=1 'BEGIN { d = g - w; exit !(g != "x" && d * d <= s * s) }'; then
    pass=$((pass + 1)); echo "cohesive layer ($e), 37 particles: max |sigma_$e - sigma_embedded| = $2 % of the stress scale, bonds intact $got of 54 (embedded $want)"
  else
    fail=$((fail + 1)); echo "FAIL cohesive layer ($e): $incs increments of 6, max difference ${2:-?} % (limit 0.5 %), bonds intact ${got:-?} (embedded ${want:-?})"
  fi
done
# the frictional mixed layer, short (37 discs): every engine within 0.5 % of
# the stress scale of the embedded engine over the whole path
dir=$tmp/mixed_layer_short
(cd "$top" && RANKS="1 2" bash scripts/compare.sh inputs/compare/mixed_layer_short.sbc "$dir" | grep -v "^compare: report")
for e in lammps liggghts yade lammps_np2 liggghts_np2; do
  set -- $(paste -d, "$dir/embedded.csv" "$dir/$e.csv" 2>/dev/null | awk -F, -v scale_from=1 -v a=1 -v b=2 -f "$here/sigma_diff.awk")
  if [ "${1:-0}" = 6 ] && awk -v m="${2:-100}" 'BEGIN { exit !(m <= 0.5) }'; then
    pass=$((pass + 1)); echo "mixed layer ($e), 37 particles: max |sigma_$e - sigma_embedded| = $2 % of the stress scale"
  else
    fail=$((fail + 1)); echo "FAIL mixed layer ($e): ${1:-0} increments of 6, max difference ${2:-?} % (limit 0.5 %)"
  fi
done
# Reference CSVs (tests/reference/CASE/ENGINE.csv): every engine's results of
# these 2D cases, byte for byte, as committed before the core became
# dimension-free; a commit that means to change a result writes them again
# (REFERENCE_UPDATE=1) and says why in its message
refs=$top/tests/reference
for c in lattice7_D_tight lattice7_P_tight regular_D_30 regular_P_30 regular_T_30 seal_chain_D cohesive_layer_short \
         mixed_layer_short; do
  for e in embedded lammps liggghts yade lammps_np2 liggghts_np2; do
    [ -f "$tmp/$c/$e.csv" ] || [ -f "$refs/$c/$e.csv" ] || continue
    if [ "${REFERENCE_UPDATE:-0}" = 1 ] && [ -f "$tmp/$c/$e.csv" ]; then
      mkdir -p "$refs/$c" && cp "$tmp/$c/$e.csv" "$refs/$c/$e.csv"
    fi
    if cmp -s "$tmp/$c/$e.csv" "$refs/$c/$e.csv"; then
      pass=$((pass + 1)); echo "reference $c/$e.csv: byte for byte ($(($(wc -l < "$refs/$c/$e.csv") - 1)) rows)"
    else
      fail=$((fail + 1)); echo "FAIL reference $c/$e.csv: differs from tests/reference (first difference: $(
        cmp "$tmp/$c/$e.csv" "$refs/$c/$e.csv" 2>&1 | head -n 1))"
    fi
  done
done
[ -n "${KEEP:-}" ] || rm -rf "$tmp"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
