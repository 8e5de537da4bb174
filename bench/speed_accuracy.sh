#!/usr/bin/env bash
# The speed-accuracy trade of one case (issue 9, docs/speed-accuracy.md).
#   bash bench/speed_accuracy.sh SWEEP [OUT]       (JOBS=2 runs two at a time;
#   KEEP=1 keeps the runs already in OUT whose script is unchanged)
# SWEEP (bench/speed_accuracy/*.sweep) names the case, a runner script whose
# servo_bc line holds the paper's settings, and one run per line:
#   case FILE.sbc
#   KNOB LABEL [WORDS...]
# WORDS are appended to the servo_bc line (later words win); timestep=DT
# replaces the time step. KNOB "reference" is the run every other one is
# measured against (tight tolerances, fine increments); KNOB "paper" is the
# case as written. For every run OUT/results.csv records the DEM steps, servo
# iterations, wall time and, against the reference, the path error (eq. 42 on
# the difference, relative to the reference's norm) and the largest error of
# sigma before the reference's first peak (% of the stress scale), by
# scripts/path_error.awk; a run that stops records the runner's message.
# OUT/pareto.svg: log10 path error against log10 DEM steps, one line per knob,
# and the non-dominated runs (OUT/front.csv); OUT/results.md: the table in
# markdown, errors in %, the front marked.
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
# results files are read by column name (scripts/columns.awk)
COLUMNS_AWK=$(cat "$top/scripts/columns.awk")
B=${B:-$top/build}
sweep=${1:?usage: speed_accuracy.sh SWEEP [OUT]}
name=$(basename "$sweep" .sweep)
out=${2:-$top/out/speed_accuracy/$name}
jobs=${JOBS:-1}
[ -x "$B/servo-bc" ] || { echo "speed_accuracy: $B/servo-bc not built (make)"; exit 1; }
case_file=$(awk '$1 == "case" { print $2; exit }' "$sweep")
[ -f "$top/$case_file" ] || { echo "speed_accuracy: $sweep: case '$case_file' not found"; exit 1; }
mkdir -p "$out/runs"
out=$(cd "$out" && pwd)

# script KNOB LABEL WORDS...: the case with WORDS appended to its servo_bc
# line; for KNOB "preset" the case's own `relax TOL WINDOW` is dropped first,
# so that the preset's relaxation tolerance applies (explicit words win over
# a preset; the case's gains, which carry its physics, stay)
script() {
  local knob=$1 label=$2 dt="" words=() w
  shift 2
  for w in "$@"; do
    case $w in timestep=*) dt=${w#timestep=} ;; *) words+=("$w") ;; esac
  done
  awk -v extra="${words[*]:-}" -v dt="$dt" -v csv="$out/runs/$label.csv" -v knob="$knob" '
    $1 == "servo_bc" {
      line = $0
      if (knob == "preset") gsub(/ relax [^ ]+ [^ ]+/, "", line)
      print line (extra != "" ? " " extra : "") " file " csv; next }
    $1 == "timestep" && dt != "" { print "timestep " dt; next }
    { print }' "$top/$case_file" > "$out/runs/$label.sbc"
}

grep -v '^[[:space:]]*\(#\|$\|case \)' "$sweep" > "$out/runs.txt"
: > "$out/todo.txt"
while read -r knob label words; do
  old=""
  [ -f "$out/runs/$label.sbc" ] && old=$(cat "$out/runs/$label.sbc")
  # shellcheck disable=SC2086
  script "$knob" "$label" $words
  # KEEP=1: a run already in OUT with the same script and a finished log is kept
  if [ "${KEEP:-0}" = 1 ] && [ "$old" = "$(cat "$out/runs/$label.sbc")" ] &&
     grep -q '^ERROR\|^servo_bc: finished' "$out/runs/$label.log" 2>/dev/null; then
    continue
  fi
  echo "$label" >> "$out/todo.txt"
done < "$out/runs.txt"
xargs -P "$jobs" -I{} sh -c '"$0" "$1/runs/{}.sbc" > "$1/runs/{}.log" 2>&1 || true' "$B/servo-bc" "$out" \
  < "$out/todo.txt"

ref=$(awk '$1 == "reference" { print $2; exit }' "$out/runs.txt")
[ -s "$out/runs/$ref.csv" ] && ! grep -q '^ERROR' "$out/runs/$ref.log" ||
  { echo "speed_accuracy: the reference run failed: $(grep -m1 ERROR "$out/runs/$ref.log")"; exit 1; }
{
  echo "knob,label,words,increments,steps,iterations,wall_s,path_error,max_before_peak_pct,status"
  while read -r knob label words; do
    log=$out/runs/$label.log csv=$out/runs/$label.csv
    steps=$(awk -F, "$COLUMNS_AWK"'NR > 1 { s += $col("relax_steps"); it += $col("iterations") } END { print s + 0, it + 0 }' "$csv" 2>/dev/null || echo "0 0")
    wall=$(sed -n 's/.*wall \([0-9.]*\) s$/\1/p' "$log")
    status=ok
    if grep -q '^ERROR' "$log"; then
      status=$(grep -m1 '^ERROR' "$log" | sed 's/^ERROR: //; s/"/'"'"'/g')
    fi
    if [ -s "$csv" ] && [ "$(wc -l < "$csv")" -gt 2 ]; then
      err=$(awk -F, -f "$top/scripts/columns.awk" -f "$top/scripts/first_peak.awk" -f "$top/scripts/path_error.awk" "$out/runs/$ref.csv" "$csv" |
        awk '{ print $1 "," $2 }')
    else
      err=","
    fi
    incs=$(awk -F, "$COLUMNS_AWK"'NR > 1 { n = $col("increment") } END { print n + 0 }' "$csv" 2>/dev/null)
    echo "$knob,$label,\"$words\",$incs,${steps% *},${steps#* },${wall:-},$err,\"$status\""
  done < "$out/runs.txt"
} > "$out/results.csv"

# the front: complete runs that no other complete run beats in both steps and error
awk -F, 'NR > 1 && $10 == "\"ok\"" && $8 > 0 { n++; k[n] = $1; l[n] = $2; s[n] = $5; e[n] = $8 }
  END { print "label,log10_steps,log10_path_error"
    for (i = 1; i <= n; i++) { dom = 0
      for (j = 1; j <= n; j++) if (j != i && s[j] <= s[i] && e[j] <= e[i] && (s[j] < s[i] || e[j] < e[i])) dom = 1
      if (!dom) printf "%s,%.6g,%.6g\n", l[i], log(s[i]) / log(10), log(e[i]) / log(10) } }' "$out/results.csv" |
  { read -r head; echo "$head"; sort -t, -k2 -g; } > "$out/front.csv"
plot_args=()
for knob in $(awk '$1 != "reference" { print $1 }' "$out/runs.txt" | awk '!seen[$0]++'); do
  awk -F, -v k="$knob" 'NR == 1 { print "log10_steps,log10_path_error" }
    NR > 1 && $1 == k && $10 == "\"ok\"" && $8 > 0 { printf "%.6g,%.6g\n", log($5) / log(10), log($8) / log(10) }' \
    "$out/results.csv" > "$out/knob_$knob.csv"
  plot_args+=("$out/knob_$knob.csv" "$knob")
done
"$B/servo-bc-plot" "$out/pareto.svg" "$name: cost against path error (eq. 42)" "log10 DEM steps" \
  "log10 relative path error" log10_steps 1 log10_path_error 1 "${plot_args[@]}" "$out/front.csv" front > /dev/null
# results.md: one row per run, errors in %, * on the front
{
  echo "| knob | run | words | increments | DEM steps | servo iterations | wall (s) | path error (%) | max before the peak (%) | front |"
  echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
  awk -F'"' 'NR > 1 { split($1, a, ","); split($3, b, ",")
    st = $4; sub(/^[^:]*:[0-9]*: servo_bc [A-Za-z]*: /, "", st); sub(/ \(.*/, "", st); st = $4 == "ok" ? "" : "stopped at " st
    printf "%s|%s|%s|%s|%s|%s|%s|%s|%s|%s\n", a[1], a[2], $2, b[2], b[3], b[4], b[5], b[6], b[7], st }' "$out/results.csv" |
  while IFS='|' read -r knob label words incs steps its wall pe mx st; do
    on=""; grep -q "^$label," "$out/front.csv" && on="*"
    pe=$(awk -v v="$pe" 'BEGIN { if (v == "") print "-"; else printf "%.3g", 100 * v }')
    mx=$(awk -v v="$mx" 'BEGIN { if (v == "") print "-"; else printf "%.3g", v }')
    echo "| $knob | $label | \`${words:-(as written)}\` | $incs${st:+, $st} | $steps | $its | ${wall:--} | $pe | $mx | $on |"
  done
} > "$out/results.md"
column -s, -t < "$out/results.csv"
echo "speed_accuracy: $out/results.csv, $out/pareto.svg"
