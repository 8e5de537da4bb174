#!/usr/bin/env bash
# tests/reliability.sh BUILD: the reliability checks of docs/reliability.md.
#  1. every reproducer of tests/reliability/ (inputs that once crashed, hung,
#     ran silently or misled) ends in a clear error exit (1-125, "ERROR:" and a
#     message) or, where the input is legitimate, a correct run (exit 0, a CSV
#     of finite numbers), never a signal, a hang or exit 0 on ignored input;
#  2. the fuzz harnesses (fuzz/) replay their committed corpora, the
#     reproducers and a restart input of this version under ASan + UBSan.
set -uo pipefail
B=${1:-build}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
runner=$(cd "$B" && pwd)/servo-bc
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "reliability $1"; }
no() { fail=$((fail + 1)); echo "FAIL reliability $1"; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
cp "$here"/reliability/* "$TMP"/
chmod u+w "$TMP"/*

# the runner reproducers whose input is legitimate: the run must succeed
legitimate="runner_acc_as_value2.sbc"
for f in "$TMP"/runner_*.sbc; do
  name=$(basename "$f")
  (cd "$TMP" && timeout 120 "$runner" "$name" > "$TMP/$name.out" 2> "$TMP/$name.err")
  rc=$?
  message=$(grep -m1 "^ERROR: " "$TMP/$name.err" | cut -c1-160)
  if [[ " $legitimate " == *" $name "* ]]; then
    csv=$(sed -n 's/.*results: //p' "$TMP/$name.out")
    if [ $rc -eq 0 ] && [ -n "$csv" ] && [ "$(wc -l < "$TMP/$csv")" -gt 1 ] && ! grep -qiE "nan|inf" "$TMP/$csv"; then
      ok "$name: a correct run ($(($(wc -l < "$TMP/$csv") - 1)) finite rows in '$csv')"
    else
      no "$name: expected a correct run, exit $rc"; tail -n 2 "$TMP/$name.err"
    fi
  elif [ $rc -ge 1 ] && [ $rc -le 125 ] && [ -n "$message" ]; then
    ok "$name: exit $rc, $message"
  else
    no "$name: exit $rc (expected 1-125 with an ERROR line)"; tail -n 2 "$TMP/$name.err"
  fi
done

# the harnesses' replays (contract: a refusal names its cause; ASan, UBSan)
replay() {  # NAME INPUT...
  local out
  if out=$(cd "$TMP" && "$B/fuzz/$1_replay" "${@:2}" 2>&1); then
    ok "fuzz $1: $(echo "$out" | tail -n 1 | sed 's/.*: //')"
  else
    no "fuzz $1:"; echo "$out" | grep -m5 -E "ERROR|runtime error|fuzz:"
  fi
}
B=$(cd "$B" && pwd)
replay settings "$root/fuzz/corpus/settings"
replay packing "$root/fuzz/corpus/packing" "$TMP"/rp_*.txt
replay script "$root/fuzz/corpus/script" "$TMP"/runner_*.sbc
replay host "$root/fuzz/corpus/host" "$TMP"/host_*.txt
replay restart "$root/fuzz/corpus/restart" "$TMP"/restart_*.bin "$B/fuzz/corpus/restart/seed.bin"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
