#!/usr/bin/env bash
# One case, one packing, every engine (make compare CASE=FILE.sbc).
# `servo-bc --decks` writes the case (a runner script: packing, frictional
# contact law, density, time step, servo_bc words, run) for the embedded
# engine, LAMMPS, LIGGGHTS and YADE; this runs every host that is built or
# installed (serial; LAMMPS and LIGGGHTS also on 2 ranks), collects the CSVs
# and writes the report folder OUT (default out/compare/CASE-NAME):
#   report.md       engines, wall time, steps, ns per particle-step; sigma
#                   differences against the embedded engine per component (max
#                   and mean, before the first peak and over the whole path)
#   sigma11.svg sigma12.svg overlap.svg rotation.svg relax_steps.svg iterations.svg
#                   every engine against the increment i (F = I + (i/N)(F_N - I))
#   sigma11_difference.svg sigma12_difference.svg, difference_ENGINE.csv
#                   each engine minus the embedded engine, in % of the stress scale
#   steps.csv       servo iterations and relaxation steps per increment and engine
#   ENGINE.csv ENGINE.log, the decks and the packing files
# A host that is not there is skipped with one line. RANKS="1" skips the 2-rank
# runs. ENGINES="liggghts yade" (a subset of embedded lammps liggghts yade)
# runs only those again and reports them with the results already in OUT
# (ENGINES=none: the report alone, from the CSVs there).
# Exit status 0 when every engine that ran finished its path.
# Usage: scripts/compare.sh CASE.sbc [OUT]
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
# results files are read by column name (scripts/columns.awk)
COLUMNS_AWK=$(cat "$top/scripts/columns.awk")
B=${B:-$top/build}
case_file=${1:?usage: compare.sh CASE.sbc [OUT]}
name=$(basename "$case_file" .sbc)
out=${2:-$top/out/compare/$name}
ranks=${RANKS:-1 2}
only=${ENGINES:-}
mkdir -p "$out"
out=$(cd "$out" && pwd)
# wanted HOST: whether this call runs HOST (every host without ENGINES)
wanted() { [ -z "$only" ] || [[ " $only " == *" $1 "* ]]; }
rm -f "$out"/*.svg "$out"/report.md "$out"/difference_*.csv "$out"/diff_*.md "$out"/steps.csv
for h in embedded lammps liggghts yade; do
  wanted $h || continue
  rm -f "$out/$h".csv "$out/$h".log "$out/${h}"_np*.*
  [ -f "$out/times.txt" ] && sed -i "/^${h}\(_np[0-9]*\)\? /d" "$out/times.txt"
done
"$B/servo-bc" --decks "$out" "$case_file" > /dev/null || exit 1
particles=$(grep -vc '^#\|^box' "$out/packing.txt")
engines=() failed=0

# run ENGINE COMMAND...: in OUT, timed, log in OUT/ENGINE.log
run() {
  local engine=$1 t0 t1 rc
  shift
  t0=$(date +%s.%N)
  (cd "$out" && "$@" > "$engine.log" 2>&1)
  rc=$?
  t1=$(date +%s.%N)
  # the wall time of every run that left results, finished or stopped
  [ -s "$out/$engine.csv" ] &&
    echo "$engine $(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }')" >> "$out/times.txt"
  if [ $rc -eq 0 ] && [ -s "$out/$engine.csv" ]; then
    engines+=("$engine")
  else
    failed=1
    echo "compare: $engine failed (exit $rc): $(grep -a -m1 'ERROR' "$out/$engine.log" || tail -n 1 "$out/$engine.log")"
    [ -s "$out/$engine.csv" ] && engines+=("$engine")
  fi
}
mpi() { mpirun --allow-run-as-root --oversubscribe -np "$@"; }
# keep ENGINE...: report the results already in OUT of engines this call does not run
keep() { local e; for e in "$@"; do [ -s "$out/$e.csv" ] && engines+=("$e"); done; }

if wanted embedded; then
  run embedded "$B/servo-bc" embedded.sbc
else
  keep embedded
  [ -s "$out/embedded.csv" ] || { echo "compare: ENGINES leaves out embedded, and $out has no embedded.csv"; exit 1; }
fi
for host in lammps liggghts; do
  bin=$B/lmp_servo
  [ $host = liggghts ] && bin=$B/liggghts_servo
  if ! wanted $host; then
    keep $host $(for np in $ranks; do [ "$np" != 1 ] && echo ${host}_np$np; done)
    continue
  fi
  if [ ! -x "$bin" ]; then
    echo "compare: $host skipped ($bin not built: make $host)"
    continue
  fi
  for np in $ranks; do
    if [ "$np" = 1 ]; then
      run $host "$bin" -in $host.in -log none
    elif command -v mpirun > /dev/null; then
      sed "s/file $host.csv/file ${host}_np$np.csv/" "$out/$host.in" > "$out/${host}_np$np.in"
      run ${host}_np$np mpi "$np" "$bin" -in ${host}_np$np.in -log none
    fi
  done
done
if ! wanted yade; then
  keep yade
elif command -v yade > /dev/null && [ -f "$B/libservo_bc.so" ]; then
  run yade env SERVO_BC_YADE="$top/yade_adapter" SERVO_BC_LIB="$B/libservo_bc.so" yade -n -x yade.py
else
  echo "compare: yade skipped (not installed or $B/libservo_bc.so not built: make yade)"
fi

# overlays against the increment
for plot in "sigma11.svg|sigma11 (N/m)|sigma11" "sigma12.svg|sigma12 (N/m)|sigma12" \
            "overlap.svg|mean overlap (eq. 39)|overlap_mean" "rotation.svg|mean rotation (rad, eq. 41)|rotation_mean" \
            "relax_steps.svg|relaxation steps|relax_steps" "iterations.svg|servo iterations|iterations"; do
  IFS='|' read -r file label column <<< "$plot"
  series=()
  for e in "${engines[@]}"; do series+=("$out/$e.csv" "$e"); done
  "$B/servo-bc-plot" "$out/$file" "$name: $label" "increment" "$label" increment 1 "$column" 1 "${series[@]}" \
    > /dev/null || echo "compare: could not draw $file"
done

# the differences themselves, in % of the stress scale, against the increment
scale=$(awk -F, "$COLUMNS_AWK"'NR == 1 { nc = sigmas(nm); for (k = 1; k <= nc; k++) cs[k] = col(nm[k]) }
  NR > 1 { for (k = 1; k <= nc; k++) { v = $cs[k] < 0 ? -$cs[k] : $cs[k]; if (v > s) s = v } } END { print s + 0 }' "$out/embedded.csv")
series=()
for e in "${engines[@]}"; do
  [ "$e" = embedded ] && continue
  paste -d, "$out/embedded.csv" "$out/$e.csv" | awk -F, -v s="$scale" "$COLUMNS_AWK"'
    NR == 1 { w = NF / 2; i = col("increment"); nc = sigmas(nm)
              printf "increment"; for (k = 1; k <= nc; k++) { cs[k] = col(nm[k]); printf ",d%s", nm[k] }; print ""; next }
    $i != "" && $(i + w) != "" { printf "%s", $i; for (k = 1; k <= nc; k++) printf ",%.6g", 100 * ($(cs[k] + w) - $cs[k]) / (s > 0 ? s : 1); print "" }' \
    > "$out/difference_$e.csv"
  series+=("$out/difference_$e.csv" "$e")
done
for k in 11 12; do
  [ ${#series[@]} -gt 0 ] && "$B/servo-bc-plot" "$out/sigma${k}_difference.svg" \
    "$name: sigma$k of each engine minus the embedded engine's" increment "% of the stress scale" increment 1 \
    dsigma$k 1 "${series[@]}" > /dev/null
done

# steps.csv: iterations and relaxation steps per increment, engine by engine
{
  printf 'increment'
  for e in "${engines[@]}"; do printf ',%s_iterations,%s_relax_steps' "$e" "$e"; done
  echo
  paste -d, $(for e in "${engines[@]}"; do echo "$out/$e.csv"; done) | awk -F, -v n=${#engines[@]} "$COLUMNS_AWK"'
    NR == 1 { w = NF / n; i = col("increment"); it = col("iterations"); rs = col("relax_steps") }
    NR > 1 { printf "%s", $i; for (k = 0; k < n; k++) printf ",%s,%s", $(it + w * k), $(rs + w * k); print "" }'
} > "$out/steps.csv"

# report.md
for e in "${engines[@]}"; do
  [ "$e" = embedded ] && continue
  paste -d, "$out/embedded.csv" "$out/$e.csv" |
    awk -F, -v e="$e" -f "$top/scripts/columns.awk" -f "$top/scripts/first_peak.awk" -f "$top/scripts/compare_diff.awk" > "$out/diff_$e.md"
done
{
  echo "# $name: every engine on one case"
  echo
  echo "Case \`$case_file\`, $particles particles; decks written by \`servo-bc --decks\` into this folder."
  echo "Stress differences are against the embedded engine, in % of the stress scale (max |σ̄| of the"
  echo "embedded run over the path); *before the peak* = up to the first peak of |σ̄ij| of the"
  echo "embedded run for the F̄ij the path moves farthest from I (σ̄12, in 3D σ̄13, unless another: σ̄33 on a"
  echo "triaxial path), a maximum that the next 10 increments stay below (the whole path when there is none)."
  echo
  echo "| engine | increments | wall time (s) | DEM steps | ns per particle-step | servo iterations | max Δσ̄ before the peak | max Δσ̄, whole path |"
  echo "| --- | --- | --- | --- | --- | --- | --- | --- |"
  for e in "${engines[@]}"; do
    wall=$(awk -v e="$e" '$1 == e { print $2 }' "$out/times.txt" 2>/dev/null)
    diffs=$(awk -F'|' '$3 ~ /σ̄/ { if ($4 + 0 > b) b = $4 + 0; if ($6 + 0 > w) w = $6 + 0; n++ }
      END { if (n) printf "%.3g|%.3g", b, w; else printf "|" }' "$out/diff_$e.md" 2>/dev/null || echo "|")
    awk -F, -v e="$e" -v wall="${wall:-nan}" -v n="$particles" -v d="${diffs:-|}" "$COLUMNS_AWK"'NR > 1 { inc++; steps += $col("relax_steps"); it += $col("iterations") }
      END { ns = (wall == "nan" || steps == 0) ? "-" : sprintf("%.0f", wall / steps / n * 1e9)
            split(d, x, "|")
            printf "| %s | %d | %s | %d | %s | %d | %s | %s |\n", e, inc - 1, (wall == "nan" ? "failed" : wall), steps, ns, it, x[1], x[2] }' \
      "$out/$e.csv"
  done
  echo
  echo "| engine | component | max, before the peak | mean, before the peak | max, whole path | mean, whole path |"
  echo "| --- | --- | --- | --- | --- | --- |"
  for e in "${engines[@]}"; do
    [ "$e" = embedded ] || cat "$out/diff_$e.md"
  done
} > "$out/report.md"
echo "compare: report in $out/report.md (${engines[*]})"
exit $failed
