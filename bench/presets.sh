#!/usr/bin/env bash
# The accuracy presets on the four cases of bench/speed_accuracy/ (docs/speed-accuracy.md,
# "Presets with a stated accuracy"): every preset at the case's own time step
# or at DT, and the paper's settings as written. Prints one markdown row per
# run: case, run, time step, DEM steps, servo iterations per increment (mean),
# wall time, the largest `unbalanced` and `frame_residual` of its rows, and
# its path error against the `tight` run at the same time step (eq. 42 on the
# difference, scripts/path_error.awk) with the largest error before the first
# peak in % of the stress scale. A run that stops prints its message.
# Each preset runs as defined (FIRE on the interior, fire_damping.h) and, as
# PRESET-local, with the local damping of eq. 10 instead (`damping 0.7 0.7`).
#   bash bench/presets.sh [OUT]       (CASES="regular_P regular_T" to choose,
#                                      RUNS="balanced balanced-fire" to choose runs,
#                                      DT_regular_P=1e-4 ... to set time steps)
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
# results files are read by column name (scripts/columns.awk)
COLUMNS_AWK=$(cat "$top/scripts/columns.awk")
B=${B:-$top/build}
out=${1:-$top/out/presets}
mkdir -p "$out"
cases=${CASES:-regular_P regular_T irregular_P mixed_layer}
runs=${RUNS:-fast balanced tight fast-local balanced-local tight-local}
case " $runs " in *" tight "*) ;; *) runs="tight $runs" ;; esac # the reference
[ -x "$B/servo-bc" ] || { echo "presets: $B/servo-bc not built (make)"; exit 1; }

# the time steps of the preset runs: about 0.1 of each case's critical step
# (the paper's settings keep the case's own)
dt_of() {
  case $1 in
    regular_P | regular_T) echo "${DT_regular:-1e-4}" ;;
    irregular_P) echo "${DT_irregular:-7.5e-5}" ;;
    mixed_layer) echo "${DT_mixed:-5e-6}" ;;
  esac
}

# script CASE LABEL DT WORDS: the case with its servo_bc line cut to the BC,
# F, increments and stress (the loading path), WORDS appended, at time step DT
script() {
  local c=$1 label=$2 dt=$3 words=$4
  awk -v extra="$words" -v dt="$dt" -v csv="$out/$c.$label.csv" '
    $1 == "servo_bc" {
      line = $1 " " $2
      for (i = 3; i <= NF; i++) {
        if ($i == "F") { line = line " F " $(i+1) " " $(i+2) " " $(i+3) " " $(i+4); i += 4 }
        else if ($i == "increments") { line = line " increments " $(i+1); i++ }
        else if ($i == "stress") { line = line " stress " $(i+1) " " $(i+2) " " $(i+3); i += 3 }
      }
      print line " " extra " file " csv; next }
    $1 == "timestep" && dt != "" { print "timestep " dt; next }
    { print }' "$top/bench/speed_accuracy/$c.sbc" > "$out/$c.$label.sbc"
}

run() {
  local c=$1 label=$2 t0 t1
  t0=$(date +%s.%N)
  "$B/servo-bc" "$out/$c.$label.sbc" > "$out/$c.$label.log" 2>&1
  t1=$(date +%s.%N)
  awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.1f", b - a }' > "$out/$c.$label.wall"
}

echo "| case | run | Δt (s) | DEM steps | iterations per increment | wall (s) | max unbalanced | max frame residual | path error against tight | max Δσ̄ before the peak (%) |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
for c in $cases; do
  dt=$(dt_of "$c")
  sed "s|^servo_bc .*|& file $out/$c.paper.csv|" "$top/bench/speed_accuracy/$c.sbc" > "$out/$c.paper.sbc"
  for p in $runs; do
    case $p in
      *-local) script "$c" "$p" "$dt" "accuracy ${p%-local} damping 0.7 0.7" ;;
      *) script "$c" "$p" "$dt" "accuracy $p" ;;
    esac
    run "$c" "$p"
  done
  run "$c" paper
  for p in paper $runs; do
    csv=$out/$c.$p.csv
    step=$dt
    [ $p = paper ] && step=$(awk '$1 == "timestep" { print $2 }' "$out/$c.paper.sbc")
    read -r steps its u r < <(awk -F, "$COLUMNS_AWK"'NR > 1 { st += $col("relax_steps"); it += $col("iterations"); n++
        if ($col("unbalanced") > u) u = $col("unbalanced"); if ($col("frame_residual") > r) r = $col("frame_residual") }
      END { if (n) printf "%d %.0f %.2g %.2g\n", st, it / n, u, r; else print "- - - -" }' "$csv" 2>/dev/null)
    read -r e m < <(awk -F, -f "$top/scripts/columns.awk" -f "$top/scripts/first_peak.awk" -f "$top/scripts/path_error.awk" "$out/$c.tight.csv" "$csv" \
      2>/dev/null | awk '{ printf "%.2g %.3g\n", $1, $2 }')
    msg=$(grep -m1 '^ERROR' "$out/$c.$p.log" | sed 's/^ERROR: [^:]*:[0-9]*: //')
    echo "| $c | $p | $step | ${steps:--} | ${its:--} | $(cat "$out/$c.$p.wall" 2>/dev/null) | ${u:--} | ${r:--} | ${e:--} | ${m:--}${msg:+ (stopped: $msg)} |"
  done
done | tee "$out/presets.md"
# one figure per case: sigma12 against the increment for every run that left rows
for c in $cases; do
  args=()
  for p in paper $runs; do
    [ -s "$out/$c.$p.csv" ] && args+=("$out/$c.$p.csv" "$p")
  done
  [ ${#args[@]} -gt 0 ] && "$B/servo-bc-plot" "$out/$c.svg" "$c: the presets (FIRE) and eq. 10 (-local)" increment \
    "sigma12 (N/m)" increment 1 sigma12 1 "${args[@]}" > /dev/null
done
