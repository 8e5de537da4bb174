#!/usr/bin/env bash
# make figures: every figure and table of docs/reproduction-*.md, regenerated
# by the scripts that made them, then the generated tables spliced into the
# pages (scripts/splice_tables.sh; the blocks marked "generated" there).
#   FIGURES="fig2 fig11" make figures     only those (default: all but bpm)
# Names: fig2 fig4 fig5 fig6 fig7_9 fig10 fig11 cohesive_sweep bpm. The whole
# set takes several hours on two cores (docs/reproduction-*.md give each
# script's time; bpm, the thesis' test matrix, about one hour more). A script
# that fails is reported and the others still run; the exit status is that
# of the first failure.
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top" || exit 1
mkdir -p out
all="fig2 fig4 fig5 fig6 fig7_9 fig10 fig11 cohesive_sweep"
status=0
for name in ${FIGURES:-$all}; do
  case $name in
    fig7_9) cmds=("bash inputs/paper/fig7_9.sh table4" "bash inputs/paper/fig7_9.sh converged") ;;
    fig10) cmds=("bash inputs/paper/fig10.sh table4" "bash inputs/paper/fig10.sh converged") ;;
    fig11) cmds=("bash inputs/paper/fig11.sh both 410 converged" "bash inputs/paper/fig11.sh both 410 paper") ;;
    fig2 | fig4 | fig5 | fig6 | cohesive_sweep) cmds=("bash inputs/paper/$name.sh") ;;
    bpm) cmds=("bash scripts/bpm_reproduce.sh") ;;
    *) echo "figures: unknown name '$name' (expected some of: $all bpm)" >&2; exit 2 ;;
  esac
  log=out/figures_${name}.log
  : > "$log"
  for cmd in "${cmds[@]}"; do
    start=$(date +%s)
    echo "figures: $cmd"
    if ! $cmd >> "$log" 2>&1; then
      echo "figures: FAILED: $cmd (log: out/figures_${name}.log)"
      [ $status -ne 0 ] || status=1
    fi
    echo "figures: $cmd: $(( $(date +%s) - start )) s"
  done
done
bash scripts/splice_tables.sh docs/reproduction-*.md || status=1
exit $status
