# Sourced by the scaling benches (remap_scaling.sh, interior_scaling.sh): one run of the embedded
# runner timed, and the growth exponent of a measure with the particle count. Needs $bin (the
# runner) and $tmp (a scratch folder); DIMENSION (default 2) is the runs' dimension.

# timed_run NAME PACKING_LINES CONTACT_LINES WORDS COLUMN...: "seconds value..." of the last row of
# the run's results file, the values of the named columns
timed_run() {
  local name=$1 packing=$2 contact=$3 words=$4 t0 t1
  shift 4
  printf 'dimension %s\n%s\n%s\nservo_bc %s file %s/%s.csv\nrun\n' "${DIMENSION:-2}" "$packing" "$contact" "$words" \
    "$tmp" "$name" \
    > "$tmp/$name.sbc"
  t0=$(date +%s.%N)
  (cd "$tmp" && "$bin" "$name.sbc" > "$name.log" 2>&1) || { tail -3 "$tmp/$name.log"; exit 1; }
  t1=$(date +%s.%N)
  awk -F, -v t="$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }')" -v want="$*" \
    'NR == 1 { n = split(want, w, " "); for (k = 1; k <= n; k++) for (c = 1; c <= NF; c++) if ($c == w[k]) at[k] = c }
     END { printf "%s", t; for (k = 1; k <= n; k++) printf " %s", $at[k] }' "$tmp/$name.csv"
}

# the particle lines of a text packing (x y r, or x y z r): neither the header nor the box
particles() { awk '!/^#/ && $1 != "box" && NF >= 3 { n++ } END { print n }' "$1"; }

# least squares of log(measure) on log(particles) over "particles measure" lines
exponent() { awk '{ x = log($1); y = log($2); n++; sx += x; sy += y; sxx += x * x; sxy += x * y }
  END { if (n > 1) printf "%.2f", (n * sxy - sx * sy) / (n * sxx - sx * sx); else print "-" }'; }
