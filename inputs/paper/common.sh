# Shared by fig*.sh: build, plotting and the run table.
top=$(cd "$(dirname "$0")/../.." && pwd)
make -s -C "$top" all
plot=$top/build/servo-bc-plot
fig=$top/docs/figures
mkdir -p "$fig" "$top/out/paper"
# sigma~ = sigma R / kn with R = 1.02e-3 m, kn = 1e4 N/m; the paper plots -sigma~ against -F12
S=-1.02e-7
# summary_row LABEL CSV: steps, iterations mean and max, wall time of one run
summary_row() {
  local log=${2%.csv}.log
  awk -F, -v label="$1" 'NR > 1 { s += $17; it += $16; if ($16 > m) m = $16; n++ }
    END { printf "| %s | %d | %d | %.1f | %d |", label, n, s, it / n, m }' "$2"
  awk '/finished/ { for (i = 1; i <= NF; i++) if ($i == "wall") printf " %s s |\n", $(i + 1) }' "$log"
}
table_header() {
  echo "| run | increments | relaxation steps | servo iterations (mean) | (max) | wall |"
  echo "| --- | --- | --- | --- | --- | --- |"
}
