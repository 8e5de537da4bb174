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
legitimate="runner_acc_as_value2.sbc runner_r3_D_ignores_P_keywords.sbc runner_r3_lattice_slow_step.sbc"
for f in "$TMP"/runner_*.sbc; do
  name=$(basename "$f")
  # the inputs (scripts, packings, restart blocks) must be there after the run, unchanged
  before=$(cd "$TMP" && find . -maxdepth 1 -type f \( -name '*.sbc' -o -name '*.txt' -o -name '*.bin' \) | sort |
           xargs md5sum)
  (cd "$TMP" && timeout 120 "$runner" "$name" > "$TMP/$name.out" 2> "$TMP/$name.err")
  rc=$?
  after=$(cd "$TMP" && echo "$before" | awk '{ print $2 }' | xargs md5sum 2>&1)
  if [ "$before" != "$after" ]; then
    no "$name: the run changed an input:"; diff <(echo "$before") <(echo "$after") | head -4
    continue
  fi
  message=$(grep -m1 "^ERROR: " "$TMP/$name.err" | cut -c1-160)
  if [[ " $legitimate " == *" $name "* ]]; then
    csv=$(sed -n 's/.*results: //p' "$TMP/$name.out")
    if [ $rc -eq 0 ] && [ -n "$csv" ] && [ "$(wc -l < "$TMP/$csv")" -gt 1 ] && ! grep -qiE "nan|inf" "$TMP/$csv"; then
      ok "$name: a correct run ($(($(wc -l < "$TMP/$csv") - 1)) finite rows in '$csv')"
    else
      no "$name: expected a correct run, exit $rc"; tail -n 2 "$TMP/$name.err"
    fi
  elif [ "$name" = runner_r4_chain_uniaxial.sbc ]; then   # a 3D test: its time series, and E in the log
    if [ $rc -eq 0 ] && [ "$(wc -l < "$TMP/r4_chain.csv")" -eq 101 ] && ! grep -qiE "nan|inf" "$TMP/r4_chain.csv" &&
       grep -q "^uniaxial: E 3.141" "$TMP/$name.out"; then
      ok "$name: a correct run of the chain one sphere thick ($(grep -o 'E [0-9.e+]* Pa' "$TMP/$name.out"), pi E_b / 4)"
    else
      no "$name: expected a correct run, exit $rc"; tail -n 2 "$TMP/$name.err"
    fi
  elif [ $rc -ge 1 ] && [ $rc -le 125 ] && [ -n "$message" ]; then
    ok "$name: exit $rc, $message"
  else
    no "$name: exit $rc (expected 1-125 with an ERROR line)"; tail -n 2 "$TMP/$name.err"
  fi
done

# a time step far below the critical one: warned, and as accurate as at 0.087 of it
# (sigma11 within the balance's 1e-5 of each other)
sed 's/timestep 1e-6/timestep 1e-4/; s/slow_step.csv/usual_step.csv/' "$TMP/runner_r3_lattice_slow_step.sbc" > "$TMP/usual_step.sbc"
(cd "$TMP" && timeout 120 "$runner" usual_step.sbc > usual_step.out 2>&1)
slow=$(tail -n 1 "$TMP/slow_step.csv" | cut -d, -f10) usual=$(tail -n 1 "$TMP/usual_step.csv" | cut -d, -f10)
if grep -q "^WARNING: servo_bc: time step 1e-06 s is 1/1143 of the critical step" "$TMP/runner_r3_lattice_slow_step.sbc.out" &&
   ! grep -q "^WARNING" "$TMP/usual_step.out" &&
   awk -v a="$slow" -v b="$usual" 'BEGIN { d = a - b; exit !(a < 0 && (d < 0 ? -d : d) <= 1e-5 * (b < 0 ? -b : b)) }'; then
  ok "slow time step: warned at 1/1143 of the critical step, sigma11 $slow against $usual N/m at 1e-4 s"
else
  no "slow time step: warning or sigma11 ($slow against $usual N/m)"; head -n 3 "$TMP/runner_r3_lattice_slow_step.sbc.out"
fi

# round 4 (docs/reliability.md): the 3D runner's messages name the component, the particles and their lines,
# the face names, the timestep line; the bonded model's one-word vtk and a vtk family over the CSV refused
while IFS='|' read -r name expect; do
  grep -q "^ERROR: [^:]*:[0-9]*: .*$expect" "$TMP/$name.err" && ok "round 4 $name: the message names it: $expect" ||
    { no "round 4 $name: expected '$expect'"; head -n 2 "$TMP/$name.err"; }
done <<'CASES'
runner_r4_F13_inf.sbc|keyword 'F': F13 'inf' is not valid
runner_r4_F33_nan.sbc|keyword 'F': F33 'nan' is not valid
runner_r4_F_eight_values.sbc|keyword 'F': 8 values (expected 4 for a 2D F or 9 for a 3D F
runner_r4_coincident_spheres.sbc|rp_r4_coincident.txt lines 23 and 66: spheres 21 and 64 have coincident centres
runner_r4_top_edge_in_3d.sbc|keyword 'top' names a 2D edge, but the words are 3D
runner_r4_vtk_one_word_3d.sbc|'vtk v' (one word) is the bonded model's snapshot
runner_r4_vtk_spheres_is_csv.sbc|'v_spheres_000000.vtk' and vtk 'v' would write the same file
runner_r4_torn_packing.sbc|rp_r4_torn.txt: its first line announces 26 particles and it holds 25
CASES
grep -q "^ERROR: runner_r4_timestep_line.sbc:5: servo_bc: time step 0.0003 s is 0.671 of the critical step" \
  "$TMP/runner_r4_timestep_line.sbc.err" && ok "round 4: a time step above 0.6 of critical is refused at its own line (5)" ||
  { no "round 4: the time step's line"; head -n 2 "$TMP/runner_r4_timestep_line.sbc.err"; }

# round 3 (docs/reliability.md): the runner's files, each refused by name with the inputs intact
refused_by() {  # LABEL EXPECTED-TEXT RC ERRFILE [FILE-THAT-MUST-BE-INTACT SUM]
  local label=$1 expect=$2 rc=$3 errfile=$4
  if [ "$rc" -ge 1 ] && [ "$rc" -le 125 ] && grep -q "^ERROR: .*$expect" "$errfile" &&
     { [ -z "${5:-}" ] || [ "$(md5sum < "$5")" = "$6" ]; }; then
    ok "$label: exit $rc, $(grep -m1 '^ERROR: ' "$errfile" | cut -c1-150)"
  else
    no "$label: exit $rc (expected an ERROR with '$expect'$([ -n "${5:-}" ] && echo ", $5 intact"))"; tail -n 2 "$errfile"
  fi
}
(cd "$TMP" && "$runner" --decks '' r3_decks_empty_dir.sbc > /dev/null 2> decks_empty.err); rc=$?
refused_by "--decks ''" "the folder name is empty" $rc "$TMP/decks_empty.err"
(cd "$TMP" && "$runner" --decks two r3_decks_two_runs.sbc > /dev/null 2> decks_two.err); rc=$?
refused_by "--decks with two runs" "a second run (the first is on line 7)" $rc "$TMP/decks_two.err"
mkdir -p "$TMP/here" && cp "$TMP/r3_embedded.sbc" "$TMP/here/embedded.sbc"
sum=$(md5sum < "$TMP/here/embedded.sbc")
(cd "$TMP/here" && "$runner" --decks . embedded.sbc > /dev/null 2> ../decks_dot.err); rc=$?
refused_by "--decks . on embedded.sbc" "is this script" $rc "$TMP/decks_dot.err" "$TMP/here/embedded.sbc" "$sum"
(cd "$TMP" && "$runner" --check r3_check_ready_but_unwritable.sbc > /dev/null 2> check_unwritable.err); rc=$?
refused_by "--check with an output that cannot be written" "cannot write '/proc/nope/out.csv'" $rc \
  "$TMP/check_unwritable.err"
(cd "$TMP" && "$runner" --check runner_r3_check_vs_run_rose.sbc > /dev/null 2> check_rose.err); rc=$?
refused_by "--check refuses the rose that run refuses" "is this script" $rc "$TMP/check_rose.err"
# a second writer of a results file, while a process holds it
: > "$TMP/shared.csv"
python3 -c 'import fcntl, sys, time
f = open(sys.argv[1], "r+"); fcntl.lockf(f, fcntl.LOCK_EX); print("locked", flush=True); time.sleep(30)' \
  "$TMP/shared.csv" > "$TMP/holder.out" & holder=$!
for _ in $(seq 100); do grep -q locked "$TMP/holder.out" 2>/dev/null && break; sleep 0.05; done
(cd "$TMP" && "$runner" r3_concurrent_run2.sbc > /dev/null 2> concurrent.err); rc=$?
kill $holder 2>/dev/null; wait $holder 2>/dev/null
refused_by "a second writer of a results file" "cannot write 'shared.csv': process $holder is writing it" $rc \
  "$TMP/concurrent.err"
# the file size limit: a message naming the file and the reason, and no torn row
(cd "$TMP" && ulimit -f 20 && "$runner" r3_full_disk.sbc > /dev/null 2> full_disk.err); rc=$?
torn=$(awk -F, '{ if (NF != 25) bad++ } END { print bad + 0 }' "$TMP/full_disk.csv")
last=$(tail -c 1 "$TMP/full_disk.csv" | od -An -c | tr -d ' ')
if [ "$torn" = 0 ] && [ "$last" = '\n' ]; then
  refused_by "a results file past the file size limit ($(($(wc -l < "$TMP/full_disk.csv") - 1)) whole rows kept)" \
    "results file 'full_disk.csv': cannot write the row of increment [0-9]* (File too large)" $rc "$TMP/full_disk.err"
else
  no "file size limit: $torn rows of the wrong width, last byte '$last'"
fi

# round 4: the tangent file and a VTK snapshot past the file size limit: the tangent file and the results file end
# with whole rows, the snapshot is removed, and each message names the system's reason
(cd "$TMP" && ulimit -f 100 && "$runner" r4_full_tangent.sbc > /dev/null 2> full_tangent.err); rc=$?
torn=$(awk -F, 'FILENAME ~ /_t/ && NF != 82 { bad++ } FILENAME ~ /_u/ && NF != 40 { bad++ } END { print bad + 0 }' \
       "$TMP/r4_full_t.csv" "$TMP/r4_full_u.csv")
if [ "$torn" = 0 ] && [ "$(tail -c 1 "$TMP/r4_full_t.csv" | od -An -c | tr -d ' ')" = '\n' ]; then
  refused_by "a tangent file past the file size limit ($(($(wc -l < "$TMP/r4_full_t.csv") - 1)) whole rows kept)" \
    "keyword 'tangent': file './r4_full_t.csv': cannot write the row of increment [0-9]* (File too large); the file ends" \
    $rc "$TMP/full_tangent.err"
else
  no "a tangent file past the file size limit: $torn torn rows"
fi
(cd "$TMP" && ulimit -f 20 && "$runner" r4_full_vtk.sbc > /dev/null 2> full_vtk.err); rc=$?
if [ ! -e "$TMP/r4_full_spheres_000000.vtk" ]; then
  refused_by "a VTK snapshot past the file size limit (the partial file removed)" \
    "vtk: cannot write 'r4_full_spheres_000000.vtk' (File too large); the partial file is removed" $rc "$TMP/full_vtk.err"
else
  no "a VTK snapshot past the file size limit: the partial file is there"
fi

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
