# Shared by fig*.sh: build, plotting and the run table.
top=$(cd "$(dirname "$0")/../.." && pwd)
# results files are read by column name (scripts/columns.awk)
COLUMNS_AWK=$(cat "$top/scripts/columns.awk")
make -s -C "$top" all
plot=$top/build/servo-bc-plot
fig=$top/docs/figures
mkdir -p "$fig" "$top/out/paper"
# sigma~ = sigma R / kn with R = 1.02e-3 m, kn = 1e4 N/m; the paper plots -sigma~ against -F12
S=-1.02e-7
# summary_row LABEL CSV: steps, iterations mean and max, wall time of one run
summary_row() {
  local log=${2%.csv}.log
  awk -F, -v label="$1" "$COLUMNS_AWK"'NR > 1 { s += $col("relax_steps"); it += $col("iterations"); if ($col("iterations") > m) m = $col("iterations"); n++ }
    END { printf "| %s | %d | %d | %.1f | %d |", label, n, s, it / n, m }' "$2"
  awk '/finished/ { for (i = 1; i <= NF; i++) if ($i == "wall") printf " %s s |\n", $(i + 1) }' "$log"
}
table_header() {
  echo "| run | increments | relaxation steps | servo iterations (mean) | (max) | wall |"
  echo "| --- | --- | --- | --- | --- | --- |"
}
# rbar PACKING: mean radius of all P + Q particles (Sect. 4.2.1), m
rbar() { awk '$1 != "box" && $1 !~ /^#/ && NF >= 3 { s += $3; n++ } END { printf "%.10g", s / n }' "$1"; }
# path_norm CSV SCALE [FMAX]: eq. 42, (sum_ij int (SCALE sigma_ij)^2 dF12)^(1/2),
# trapezoid over the rows with F12 <= FMAX (default: all)
path_norm() {
  awk -F, -v s="$2" -v fmax="${3:-1e300}" "$COLUMNS_AWK"'NR > 1 && $col("F12") <= fmax + 1e-12 { f = $col("F12"); a = ($col("sigma11")^2 + $col("sigma12")^2 + $col("sigma21")^2 + $col("sigma22")^2) * s * s
      if (n++) sum += 0.5 * (a + prev) * (f - fp); prev = a; fp = f }
    END { printf "%.6g", sqrt(sum) }' "$1"
}
# last_F12 CSV: F12 of the last converged increment
last_F12() { awk -F, "$COLUMNS_AWK"'NR > 1 { f = $col("F12") } END { print f }' "$1"; }
