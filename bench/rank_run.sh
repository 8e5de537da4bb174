# Sourced by the benchmarks that run one host deck on 1 and 2 ranks
# (bonds_million.sh, cohesive_million.sh).
# rank_run DIR HOST NP BIN: runs DIR/HOST.in on NP ranks (log DIR/HOST_npNP.log)
# and prints the loop time of its last run (s) and the largest resident set of
# a rank (kB). Each rank's /usr/bin/time line is appended to one file: two
# ranks writing to one stream interleave.
rank_run() {
  local dir=$1 host=$2 np=$3 bin=$4
  rm -f "$dir/${host}_np$np.time"
  (cd "$dir" && mpirun --allow-run-as-root --oversubscribe -np "$np" /usr/bin/time -a -o "${host}_np$np.time" \
    -f 'maxrss %M' "$bin" -in "$host.in" -log "${host}_np$np.log" -screen none) > "$dir/${host}_np$np.out" 2>&1
  awk '/^Loop time of/ { t = $4 } $1 == "maxrss" && $2 > kb { kb = $2 } END { print t + 0, kb + 0 }' \
    "$dir/${host}_np$np.log" "$dir/${host}_np$np.time"
}

# hosts_ranks OUT HOST...: for each host built under $B, writes OUT/HOST.in with
# the caller's `deck HOST`, runs it on 1 and 2 ranks and calls the caller's
# `row HOST NP T T1 KB` (T the loop time on NP ranks, T1 on one, s; KB the
# largest resident set of a rank)
hosts_ranks() {
  local out=$1 host bin np t1
  shift
  for host in "$@"; do
    bin=$B/lmp_servo
    [ "$host" = liggghts ] && bin=$B/liggghts_servo
    [ -x "$bin" ] || { echo "| $host | | not built ($bin) |"; continue; }
    deck "$host" > "$out/$host.in"
    t1=
    for np in 1 2; do
      set -- $(rank_run "$out" "$host" "$np" "$bin")
      [ "$np" = 1 ] && t1=$1
      row "$host" "$np" "$1" "$t1" "$2"
    done
  done
}
