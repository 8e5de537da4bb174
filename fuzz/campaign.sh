#!/usr/bin/env bash
# fuzz/campaign.sh DIR RUNS NAME...: a libFuzzer campaign of RUNS executions
# for each harness DIR/NAME_fuzzer, on 2 workers at most, starting from the
# committed corpus fuzz/corpus/NAME (new inputs collect in DIR/corpus/NAME;
# merge the interesting ones back with -merge=1). Findings (crash-*, leak-*,
# timeout-*) stop the campaign with a non-zero exit. Prints per harness the
# executions, the wall time and the coverage reached.
set -uo pipefail
dir=$(mkdir -p "$1" && cd "$1" && pwd) runs=$2; shift 2
here=$(cd "$(dirname "$0")" && pwd)
status=0
for name in "$@"; do
  work="$dir/corpus/$name"
  mkdir -p "$work" "$dir/findings/$name"
  log="$dir/$name.log"
  start=$(date +%s)
  # inputs up to 1 KB (a script of ~40 lines); restart blocks up to 4 KB (a 16-particle frame and its state)
  len=1024
  [ "$name" = restart ] && len=4096
  "$dir/${name}_fuzzer" -runs="$runs" -max_len=$len -timeout=20 -rss_limit_mb=4096 -print_final_stats=1 \
    -artifact_prefix="$dir/findings/$name/" "$work" "$here/corpus/$name" > "$log" 2>&1
  rc=$?
  secs=$(( $(date +%s) - start ))
  execs=$(grep -m1 "stat::number_of_executed_units" "$log" | awk '{print $2}')
  cov=$(grep -E "^#[0-9]+.*cov:" "$log" | tail -n 1 | sed 's/.*cov: \([0-9]*\).*/\1/')
  if [ $rc -eq 0 ]; then
    echo "fuzz $name: ${execs:-?} executions in $secs s, coverage $cov edges, no finding"
  else
    echo "FINDING fuzz $name (exit $rc): $(ls "$dir/findings/$name" | head -n 3 | tr '\n' ' ')"
    grep -m3 -E "ERROR|runtime error|fuzz:" "$log"
    status=1
  fi
done
exit $status
