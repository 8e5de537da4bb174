# Checks of fix servo_bc shared by the LAMMPS-family hosts (LAMMPS, LIGGGHTS),
# sourced by tests/lammps/closed_form.sh and tests/liggghts/closed_form.sh.
# The caller sets HOST (label), BIN (absolute path of the host binary), DECK
# (its closed-form lattice deck: 5 x 5 discs, spacing 2 mm, R = 1.02 mm, kt = 0,
# `fix servo all servo_bc D F 1.002 0 0 0.997 increments 2 relax 1e-22 20 file
# ${csv}`, interior integrated by `fix integrate servo_interior ...`) and TMP.
. "$(dirname "${BASH_SOURCE[0]}")/csv_columns.sh"
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "$HOST $1"; }
no() { fail=$((fail + 1)); echo "FAIL $HOST $1"; }

# run_deck NP DECK CSV LOG [VAR VALUE ...]: the deck on NP MPI ranks (1: no
# mpirun), in TMP, with the index variables given
run_deck() {
  local np=$1 deck=$2 csv=$3 log=$4 vars=()
  shift 4
  while [ $# -ge 2 ]; do vars+=(-var "$1" "$2"); shift 2; done
  if [ "$np" = 1 ]; then
    (cd "$TMP" && timeout 300 "$BIN" -in "$deck" -var csv "$csv" "${vars[@]}" -log none > "$log" 2>&1)
  else
    (cd "$TMP" && timeout 300 mpirun --allow-run-as-root --oversubscribe -np "$np" "$BIN" -in "$deck" -var csv "$csv" \
      "${vars[@]}" -log none > "$log" 2>&1)
  fi
}

# cubic_form NP LABEL FORM [VAR VALUE ...]: the 3d deck $DECK (a 4 x 4 x 4
# simple cubic lattice, d = 2 mm, kn 1e4 N/m, at accuracy tight, its
# variables given) on NP ranks against the closed forms of docs/frame3d.md:
# FORM prestressed (R = 1.02 mm, (D) or (P) under F = diag(0.999, 0.998,
# 0.997)): P_ii = -N^2 kn (2R - d F_ii) / ((N - 1)^2 d^2), P_ij = 0 (i != j),
# every row within 1e-6 of max |P|; FORM touching (R = 1 mm, frictionless,
# (T) under F = diag(1 - e1, 1 - e2, 1)): P_ii = -kn (1 - F_ii) (N - 1)^2 /
# (d (N - 3/2)^2), within 1e-5 of max |P|; |hill_mandel| <= 1e-6
cubic_form() {
  local out np=$1 label=$2 form=$3 name
  shift 3
  name=$(echo "$label" | tr -c 'A-Za-z0-9\n' _)
  run_deck "$np" "$DECK" "$TMP/cubic$name$np.csv" "$TMP/cubic$name$np.log" "$@"
  out=$(awk -F, -v form="$form" "$COLUMNS_AWK"'NR > 1 {
      n++
      for (i = 1; i <= 3; i++) for (j = 1; j <= 3; j++) {
        if (i != j) e = 0
        else if (form == "touching") e = -1e4 * (1 - $col("F" i i)) * 9 / (2e-3 * 2.5 * 2.5)
        else e = -16 * 1e4 * (2.04e-3 - 2e-3 * $col("F" i i)) / (9 * 4e-6)
        p = e < 0 ? -e : e; if (p > pmax) pmax = p
        d = $col("P" i j) - e; if (d < 0) d = -d; if (d > worst) worst = d
      }
      h = $col("hill_mandel"); if (h < 0) h = -h; if (h > hm) hm = h
    }
    END { printf "%d %.3g %.3g %.6g", n, worst / pmax, hm, pmax }' "$TMP/cubic$name$np.csv" 2>/dev/null)
  set -- $out
  local tol=1e-6
  [ "$form" = touching ] && tol=1e-5
  if [ "${1:-0}" = 3 ] && awk -v w="$2" -v h="$3" -v t="$tol" 'BEGIN { exit !(w <= t && h <= 1e-6) }'; then
    ok "3d $label, 4^3 lattice, $np rank(s): 3 rows, max |P - closed form| = $2 of max |P| ($4 N/m^2), |hill_mandel| <= $3"
  else
    no "3d $label on $np rank(s): rows ${1:-0} of 3, max |P - closed form| ${2:-?} of max |P| (limit $tol), hill_mandel ${3:-?}"
    grep -m2 "ERROR\|servo_bc:" "$TMP/cubic$name$np.log"
  fi
}

# layer3d_form NP [VAR VALUE ...]: the stress stage of the 3D layer (mixed:
# zlo D D D, zhi D D T, the side faces P P P) on the touching 4 x 4 x 4
# lattice of $DECK (its variables given: 2 mm spheres, friction) under P33* =
# -1e4 N/m^2 in 2 increments at accuracy tight, against docs/frame3d.md: F33
# = 1 - p d (N - 3/2)^2 / (kn (N - 1)^2) = 1 - 1/720 within 1e-6 of 1 - F33
# and P33 = -1e4 within 1e-6; |hill_mandel| <= 1e-6. (Its shear stage is a
# mechanism for rotating spheres: docs/frame3d.md, "The 3D layer".)
layer3d_form() {
  local out np=$1
  shift
  sed 's/servo_bc ${bc} F .* increments 2 accuracy tight/servo_bc mixed stress P33 -1e4 2 F 1 0 0 0 1 0 0 0 1 increments 1 accuracy tight/' \
    "$DECK" > "$TMP/layer3d.in"
  run_deck "$np" layer3d.in "$TMP/layer3d$np.csv" "$TMP/layer3d$np.log" "$@"
  out=$(awk -F, "$COLUMNS_AWK"'NR > 1 {
      n++
      h = $col("hill_mandel"); if (h < 0) h = -h; if (h > hm) hm = h
      if (n == 3) { e = (1 - $col("F33")) / (1 / 720) - 1; e = e < 0 ? -e : e
                    s = ($col("P33") + 1e4) / 1e4; s = s < 0 ? -s : s; if (s > e) e = s }
    }
    END { printf "%d %.3g %.3g", n, e, hm }' "$TMP/layer3d$np.csv" 2>/dev/null)
  set -- $out
  if [ "${1:-0}" = 4 ] && awk -v e="$2" -v h="$3" 'BEGIN { exit !(e <= 1e-6 && h <= 1e-6) }'; then
    ok "3d layer (mixed), stress stage on the 4^3 touching lattice, $np rank(s): F33 and P33 within $2 of the closed form, |hill_mandel| <= $3"
  else
    no "3d layer on $np rank(s): rows ${1:-0} of 4, stress stage ${2:-?} of the closed form (limit 1e-6), hill_mandel ${3:-?}"
    grep -m2 "ERROR\|servo_bc:" "$TMP/layer3d$np.log"
  fi
}

# cubic_restart_check PART2_HEAD_FILE: (P) on the frictional 4^3 lattice of
# $DECK split by write_restart and read_restart after 60 steps (inside
# increment 1: each increment of the lattice takes 40 steps; part 1 must end
# with fewer rows than the whole run, which is checked): the uninterrupted run's
# rows (the rotation vectors in the fix's per-atom restart data); part 2 is
# the deck's variables, read_restart, PART2_HEAD_FILE (what the host does not
# keep in its restart file) and the deck from fix servo on
cubic_restart_check() {
  sed "/^run  *0\$/d; s|^run .*|run 60\nwrite_restart $TMP/cubic.restart|; /jump SELF loop/d" "$DECK" > "$TMP/cubic_part1.in"
  { sed -n '/^variable  *[a-zA-Z0-9]*  *index/p' "$DECK"; echo "read_restart $TMP/cubic.restart"; cat "$1"
    sed -n '/^fix  *servo /,$p' "$DECK"; } > "$TMP/cubic_part2.in"
  run_deck 1 "$DECK" "$TMP/cubic_full.csv" "$TMP/cubic_full.log" bc P kt 5e3 mu 0.5
  run_deck 1 cubic_part1.in "$TMP/cubic_split.csv" "$TMP/cubic_part1.log" bc P kt 5e3 mu 0.5
  local rows_part1 rows_full
  rows_part1=$(wc -l < "$TMP/cubic_split.csv") rows_full=$(wc -l < "$TMP/cubic_full.csv")
  if [ "$rows_part1" -ge 2 ] && [ "$rows_part1" -lt "$rows_full" ]; then
    ok "3d restart: part 1 ends inside the path ($((rows_part1 - 1)) of $((rows_full - 1)) rows written)"
  else
    no "3d restart: part 1 wrote $((rows_part1 - 1)) of $((rows_full - 1)) rows (expected a split inside the path)"
  fi
  [ -s "$TMP/cubic.restart" ] && run_deck 1 cubic_part2.in "$TMP/cubic_split.csv" "$TMP/cubic_part2.log" bc P kt 5e3 mu 0.5 || tail -3 "$TMP/cubic_part2.log"
  TOLERANCE=1e-12 same_csvs "3d (P) frictional, a run split by write_restart/read_restart inside increment 1$(
    cmp -s "$TMP/cubic_full.csv" "$TMP/cubic_split.csv" && echo ", byte for byte")" 3 "$TMP/cubic_full.csv" "$TMP/cubic_split.csv"
}

# host_refusals_3d: what a 3d deck of the round-4 reproducers did silently,
# refused by name: the tangent file (the embedded runner's), a fix group that
# leaves part of the specimen to no integrator
host_refusals_3d() {
  refuses "keyword tangent (the embedded runner's)" 's/accuracy tight/accuracy tight tangent affine t.csv/' \
    "keyword 'tangent' (affine t.csv) is the embedded runner's"
  refuses "a fix group without part of the specimen" 's/^fix  *servo all servo_bc/group part id 1:21 23:42 44:64\nfix servo part servo_bc/' \
    "2 atoms outside group part are integrated by no fix: the fix's group holds the whole specimen"
}

# thermo3d_check: the fix's vector in 3d holds the components a 3d path adds: f_servo[26] (F33), f_servo[36]
# (sigma33) and f_servo[31] (P33), printed after the run, equal the CSV's last row
thermo3d_check() {
  deck_with 's/^thermo_style .*/thermo_style    custom step f_servo[26] f_servo[36] f_servo[31]\nthermo_modify   format float %.15g/' \
    "$TMP/thermo3d.in"
  printf 'variable a equal f_servo[26]\nvariable b equal f_servo[36]\nvariable c equal f_servo[31]\nprint "thermo3d ${a} ${b} ${c}"\n' \
    >> "$TMP/thermo3d.in"
  run_deck 1 thermo3d.in "$TMP/thermo3d.csv" "$TMP/thermo3d.log" bc P kt 5e3 mu 0.5
  local got
  got=$(awk -F, "$COLUMNS_AWK"'FNR == NR { if (FNR > 1) { f = $col("F33"); s = $col("sigma33"); p = $col("P33") }; next }
      NF == 4 && ($1 ~ /^[0-9]+$/ || $1 == "thermo3d") { t1 = $2; t2 = $3; t3 = $4 }
      END { d = (t1 - f) / f; e = (t2 - s) / s; g = (t3 - p) / p; d = d < 0 ? -d : d; e = e < 0 ? -e : e; g = g < 0 ? -g : g
            m = d > e ? d : e; m = m > g ? m : g; printf "%s %s %.2g", f, s, (s != 0 && t2 != "" ? m : 1) }' \
      "$TMP/thermo3d.csv" FS=' ' "$TMP/thermo3d.log" 2>/dev/null)
  set -- $got
  if [ -n "${3:-}" ] && awk -v m="$3" 'BEGIN { exit !(m <= 1e-9) }'; then
    ok "3d thermo: f_servo[26] F33 $1, f_servo[36] sigma33 $2 Pa and f_servo[31] P33 as the CSV's last row (to $3)"
  else
    no "3d thermo: f_servo[26], [36], [31] against the CSV's last row: ${got:-nothing read}"; grep -m1 ERROR "$TMP/thermo3d.log"
  fi
}

# screen_none_check: a results file that cannot be written, under -screen
# none: the fix's ERROR line in the log file (LIGGGHTS' Error::one writes the
# screen only), exit 1
screen_none_check() {
  deck_with 's|file ${csv}|file /proc/servo_bc_none/x.csv|' "$TMP/lost.in"
  (cd "$TMP" && timeout 60 "$BIN" -in lost.in -var csv x.csv -var bc P -log lost.log -screen none > /dev/null 2>&1)
  local rc=$?
  if [ $rc -ge 1 ] && [ $rc -le 123 ] && grep -q "ERROR.*Fix servo_bc: keyword 'file': cannot write '/proc/servo_bc_none/x.csv'" "$TMP/lost.log"; then
    ok "-screen none: the fix's error on its results file is in the log (exit $rc)"
  else
    no "-screen none: exit $rc, log: $(grep -m1 ERROR "$TMP/lost.log" || tail -n 1 "$TMP/lost.log")"
  fi
}

# restart_corruption_check: the restart file of cubic_restart_check with one
# value of fix servo_bc's block changed at a time (the round-4 reproducers:
# its length, the controller's length, finished, a frame mass, a frame
# position, then 16 values spread over the block set to 1e300 and nudged by one ulp): each
# read back by cubic_part2.in ends in the fix's error, never a signal, a
# hang or a run
restart_corruption_check() {
  local cases
  cases=$(python3 - "$TMP/cubic.restart" "$TMP" <<'PY'
import struct, sys
b = bytes(open(sys.argv[1], 'rb').read())
at = b.find(struct.pack('d', 8.020002e7))
n = int(struct.unpack_from('d', b, at + 8)[0])      # the block's length after the magic (sbc/saved.h)
v = lambda k: struct.unpack_from('d', b, at + 8 * k)[0]
nf = int(v(4)); q = int(v(6) if v(5) == -3.0 else v(5)) # the frame's particles (after the 3D marker)
named = {'length': 1, 'controller_length': 5 + nf + 2 * q, 'frame_mass': 5 + nf + q,
         'finished': 6 + nf + 2 * q + int(v(5 + nf + 2 * q)), 'frame_X': (7 if v(5) == -3.0 else 6) + 3}
cases = [(k, name, 1e6 if name == 'length' else 5e5 if name == 'controller_length' else
          1.0 if name == 'finished' else 1e300) for name, k in named.items()]
for k in range(2, n + 1, max(1, n // 16)):
    cases += [(k, 'v%d_1e300' % k, 1e300), (k, 'v%d_ulp' % k, None)]
for k, name, value in cases:
    c = bytearray(b)
    if value is None:
        c[at + 8 * k: at + 8 * k + 8] = struct.pack('<q', struct.unpack('<q', c[at + 8 * k: at + 8 * k + 8])[0] ^ 1)
    else:
        struct.pack_into('d', c, at + 8 * k, value)
    if c != b:
        open('%s/bad_%s.restart' % (sys.argv[2], name), 'wb').write(c); print(name)
PY
) || { no "restart corruption: the block of fix servo_bc not found in $TMP/cubic.restart"; return; }
  local name rc bad=0 count=0 sample=""
  for name in $cases; do
    sed "s|read_restart .*|read_restart $TMP/bad_$name.restart|" "$TMP/cubic_part2.in" > "$TMP/bad_restart.in"
    run_deck 1 bad_restart.in "$TMP/bad_restart.csv" "$TMP/bad_restart.log" bc P kt 5e3 mu 0.5
    rc=$?
    count=$((count + 1))
    if [ $rc -ge 1 ] && [ $rc -le 123 ] && grep -q "ERROR.*Fix servo_bc: restart" "$TMP/bad_restart.log"; then
      case $name in length | controller_length | finished | frame_mass)
        sample="$sample; $name: $(grep -m1 -o 'Fix servo_bc: restart.*' "$TMP/bad_restart.log" | cut -c1-110)" ;; esac
    else
      bad=$((bad + 1)); echo "  restart corruption $name: exit $rc"; grep -m1 ERROR "$TMP/bad_restart.log" || tail -2 "$TMP/bad_restart.log"
    fi
  done
  if [ "$bad" -eq 0 ] && [ "$count" -ge 10 ]; then
    ok "3d restart: $count corruptions of fix servo_bc's block each refused by the fix$sample"
  else
    no "3d restart: $bad of $count corruptions of fix servo_bc's block not refused"
  fi
}

# deck_with SED-EXPRESSION OUT: the lattice deck edited
deck_with() { sed "$1" "$DECK" > "$2"; }

# lattice_form LABEL CSV ROWS TOL: every row of the 5 x 5 lattice (spacing
# d = 2 mm, 2R = 2.04 mm, kn 1e4) against the affine closed form of
# tests/test_lattice.c at its measured F: P11 = -N kn (2R - d F11)/((N-1) d),
# P22 likewise, P12 = P21 = 0, relative to P11, within TOL; ROWS rows
lattice_form() {
  local out
  out=$(awk -F, "$COLUMNS_AWK"'NR > 1 {
      p11 = -5 * 1e4 * (2.04e-3 - 2e-3 * $col("F11")) / (4 * 2e-3);
      p22 = -5 * 1e4 * (2.04e-3 - 2e-3 * $col("F22")) / (4 * 2e-3);
      e = ($col("P11") - p11) / p11; if (e < 0) e = -e; if (e > m) m = e;
      e = ($col("P22") - p22) / p22; if (e < 0) e = -e; if (e > m) m = e;
      e = $col("P12"); e = (e < 0 ? -e : e) / -p11; if (e > m) m = e;
      e = $col("P21"); e = (e < 0 ? -e : e) / -p11; if (e > m) m = e;
      n++ }
    END { printf "%d %.3g", n, m }' "$2" 2>/dev/null)
  set -- "$1" "$3" "$4" $out
  if [ "${4:-0}" = "$2" ] && awk -v m="$5" -v t="$3" 'BEGIN { exit !(m <= t) }'; then
    ok "$1: $2 increments, max relative error $5"
  else
    no "$1: increments ${4:-0}, max relative error ${5:-?}"
  fi
}

# closed_form LABEL CSV: the frictionless lattice under F = diag(1.002, 0.997)
# in 2 increments, 1e-9
closed_form() { lattice_form "$1" "$2" 3 1e-9; }

# frictional_tight LABEL CSV: the frictional lattice (ks = kn/5, mu 0.4) under
# F = diag(0.99, 0.995) in 4 increments at accuracy tight (tests/test_accuracy.c):
# the affine closed form to 1e-6 (quasi-static loading leaves the tangential
# springs unloaded)
frictional_tight() { lattice_form "$1" "$2" 5 1e-6; }

# frictional_checks FRICTION-SED: the frictional lattice at accuracy tight, (D)
# on 1 and 2 ranks and (P) serially; FRICTION-SED turns the deck's ks = 0 into 2e3
frictional_checks() {
  local bc np
  for bc in D P; do
    deck_with "$1; s/servo_bc D F 1.002 0 0 0.997 increments 2 relax 1e-22 20/servo_bc $bc F 0.99 0 0 0.995 increments 4 accuracy tight/" \
      "$TMP/friction_$bc.in"
    for np in 1 2; do
      [ $bc = P ] && [ $np = 2 ] && continue
      run_deck $np "friction_$bc.in" "$TMP/friction_${bc}_$np.csv" "$TMP/friction_${bc}_$np.log" \
        || { echo "$HOST frictional ($bc) -np $np failed:"; tail -3 "$TMP/friction_${bc}_$np.log"; }
      frictional_tight "$np rank(s) ($bc) frictional lattice, accuracy tight" "$TMP/friction_${bc}_$np.csv"
    done
  done
}

# same_csvs LABEL INCREMENTS A.csv B.csv...: every other CSV equals A to
# TOLERANCE (default 1e-8) of each quantity's scale in the run (F, P and sigma
# by their largest component, the overlap by itself: a near-zero shear
# component is not compared with itself)
same_csvs() {
  local label=$1 want=$2 res
  shift 2
  res=$(paste -d, "$@" | awk -F, -v files=$# "$COLUMNS_AWK"'
    NR == 1 { nc = split("F11 F12 F21 F22 P11 P12 P21 P22 sigma11 sigma12 sigma21 sigma22 overlap_mean", name, " ")
              for (j = 1; j <= nc; j++) { c[j] = col(name[j]); g[j] = int((j - 1) / 4) + 1 } }
    NR > 1 { n++; w = NF / files; for (j = 1; j <= nc; j++) for (k = 0; k < files; k++) v[n, j, k] = $(c[j] + w * k)
             for (j = 1; j <= nc; j++) { a = $c[j] < 0 ? -$c[j] : $c[j]; if (a > S[g[j]]) S[g[j]] = a } }
    END { for (r = 1; r <= n; r++) for (j = 1; j <= nc; j++)
            for (k = 1; k < files; k++) { d = (v[r, j, k] - v[r, j, 0]) / S[g[j]]; if (d < 0) d = -d; if (d > m) m = d }
          printf "%d %.3g", n, m }' 2>/dev/null)
  set -- $res
  if [ "${1:-0}" = "$want" ] && awk -v m="$2" -v tol="${TOLERANCE:-1e-8}" 'BEGIN { exit !(m <= tol) }'; then
    ok "$label: $want increments, max difference $2 of each tensor's scale"
  else
    no "$label: increments ${1:-0}, max relative difference ${2:-?}"
  fi
}

# refused_deck LABEL DECK EXPECTED: the deck (in TMP) ends in "ERROR...Fix
# servo_bc" with the expected text and a non-zero exit, never a crash
refused_deck() {
  run_deck 1 "$2" "$TMP/bad.csv" "$TMP/bad.log"
  local rc=$?
  if [ $rc -ne 0 ] && [ $rc -lt 124 ] && grep -q "ERROR.*Fix servo_bc.*$3" "$TMP/bad.log"; then
    ok "refuses $1"
  else
    no "$1 (exit $rc):"; grep -m1 ERROR "$TMP/bad.log" || tail -2 "$TMP/bad.log"
  fi
}

# refuses LABEL SED-EXPRESSION EXPECTED: the lattice deck so edited is refused
refuses() {
  deck_with "$2" "$TMP/bad.in"
  refused_deck "$1" bad.in "$3"
}

# outputs_checks: the results file may not name the input deck (refused, the
# deck intact: the core overwrites only its own files, output_file.h)
outputs_checks() {
  slow_step_check
  deck_with 's|file ${csv}|file self.in|' "$TMP/self.in"
  local sum
  sum=$(md5sum < "$TMP/self.in")
  refused_deck "a results file that names the input deck" self.in \
    "cannot write 'self.in': it exists and is not a servo_bc results file"
  if [ "$(md5sum < "$TMP/self.in")" = "$sum" ]; then ok "the deck named as the results file is intact"
  else no "the deck named as the results file was changed"; fi
  # an output index past the fix's 36: the host itself refuses it
  deck_with 's/^thermo_style .*/thermo_style    custom step f_servo[37]/' "$TMP/index.in"
  run_deck 1 index.in "$TMP/index.csv" "$TMP/index.log"
  local rc=$?
  if [ $rc -ne 0 ] && grep -q "ERROR.*Thermo fix vector is accessed out-of-range" "$TMP/index.log"; then
    ok "refuses an output index that does not exist (f_servo[37], by the host)"
  else
    no "an output index that does not exist (exit $rc):"; grep -m1 ERROR "$TMP/index.log"
  fi
}

# slow_step_check: a time step of 1/1143 of the critical step runs (a short
# run, exit 0) with the core's warning (time_step.h)
slow_step_check() {
  deck_with '/jump SELF loop/d; s/^timestep .*/timestep 1e-6/; s/^run  *[1-9][0-9]*.*/run 100/' "$TMP/slow.in"
  run_deck 1 slow.in "$TMP/slow.csv" "$TMP/slow.log"
  local rc=$?
  if [ $rc -eq 0 ] && [ "$(grep -c "WARNING: Fix servo_bc: time step 1e-06 s is 1/1143 of the critical step 0.00114342 s" \
       "$TMP/slow.log")" = 1 ]; then
    ok "warns once of a time step of 1/1143 of the critical step"
  else
    no "no warning (or more than one) at a time step of 1/1143 of the critical step (exit $rc):"; grep -m2 -E 'WARN|ERROR' "$TMP/slow.log"
  fi
}

# bad_words_checks: every line of tests/bad_words.txt as the deck's servo_bc
# words, refused with the core's message
bad_words_checks() {
  local words expect
  while IFS=$'\t' read -r words expect; do
    case "$words" in '#'* | '') continue ;; esac
    refuses "'$words'" "s|servo_bc D F 1.002 0 0 0.997 increments 2 relax 1e-22 20|servo_bc $words|" "$expect"
  done < "$(dirname "${BASH_SOURCE[0]}")/bad_words.txt"
}

# the checks every LAMMPS-family host passes on DECK
lattice_checks() {
  run_deck 1 "$DECK" "$TMP/serial.csv" "$TMP/serial.log" || { echo "$HOST failed:"; tail -5 "$TMP/serial.log"; }
  closed_form "serial (D) closed form" "$TMP/serial.csv"
  run_deck 2 "$DECK" "$TMP/np2.csv" "$TMP/np2.log" || { echo "$HOST -np 2 failed:"; tail -5 "$TMP/np2.log"; }
  closed_form "2 ranks (D) closed form" "$TMP/np2.csv"
  # 1, 2 and 4 ranks (frame atoms spread over the ranks): the same CSV to 1e-8.
  # Frictionless with a tight relaxation, so that each equilibrium is unique:
  # with friction, the rank-dependent force summation order seeds round-off
  # that the path-dependent contacts amplify (LAMMPS: 1.9e-5 after 4 increments)
  deck_with 's/servo_bc D F 1.002 0 0 0.997 increments 2 relax 1e-22 20/servo_bc P F 0.999 -0.01 -0.01 0.999 increments 3 relax 1e-20 20 gain_force 1e3 gain_moment 1e3 tol_force 1e-12 tol_moment 1e-12/' \
    "$TMP/ranks.in"
  for np in 1 2 4; do
    run_deck $np ranks.in "$TMP/ranks$np.csv" "$TMP/ranks$np.log" || { echo "$HOST -np $np failed:"; tail -3 "$TMP/ranks$np.log"; }
  done
  same_csvs "(P) on 1, 2, 4 ranks ($(grep -h "MPI processor grid" "$TMP/ranks4.log" | head -n 1 | sed 's/^ *//'))" 4 \
    "$TMP/ranks1.csv" "$TMP/ranks2.csv" "$TMP/ranks4.csv"
  # (P): the affine state is periodic with anti-periodic forces: the same closed form
  deck_with 's/servo_bc D F 1.002 0 0 0.997 increments 2 relax 1e-22 20/servo_bc P F 1.002 0 0 0.997 increments 2 relax 1e-22 20 tol_force 1e-14 tol_moment 1e-14 gain_force 1e3 gain_moment 1e3/' \
    "$TMP/periodic.in"
  run_deck 1 periodic.in "$TMP/periodic.csv" "$TMP/periodic.log" || { echo "$HOST (P) failed:"; tail -5 "$TMP/periodic.log"; }
  closed_form "serial (P) closed form" "$TMP/periodic.csv"
  # an accuracy preset of the shared grammar (secant update, relative tolerance), tightened,
  # with the local damping of eq. 10: this prestressed frictionless lattice is an unstable
  # equilibrium (compressed chains of length L buckle sideways when ks < f/L = 230 N/m;
  # in the embedded engine FIRE finds the buckled state at ks 0 and 150 N/m, not at 250),
  # which only eq. 10's symmetric dynamics keep
  deck_with 's/servo_bc D F 1.002 0 0 0.997 increments 2 relax 1e-22 20/servo_bc P F 1.002 0 0 0.997 increments 2 accuracy fast relax 1e-22 20 tol_relative 1e-13 damping 0.7 0.7/' \
    "$TMP/preset.in"
  run_deck 1 preset.in "$TMP/preset.csv" "$TMP/preset.log" || { echo "$HOST (P) accuracy fast failed:"; tail -5 "$TMP/preset.log"; }
  closed_form "serial (P) closed form, accuracy fast with update secant" "$TMP/preset.csv"
  # bad input: the core's message, named by the fix; stdout unbuffered, since an
  # error followed by MPI_Abort can otherwise leave no message on a pipe
  bad_words_checks
  refuses "a frame group that does not exist" 's/increments 2 relax/frame nosuch increments 2 relax/' \
    "group 'nosuch' does not exist"
  refuses "frame atoms under another integrator" 's/^fix  *integrate servo_interior/fix integrate all/' \
    "frame atoms are also integrated by fix integrate"
  refuses "a group without a frame" 's/^fix  *servo all/group one id 1\nfix             servo one/' "cannot form a frame"
  # the centre disc moved out through the right edge after the frame is built:
  # confine.h stops the run at increment 0, naming the atom (on 2 ranks too)
  refuses "an interior atom outside the frame" \
    's/^fix  *integrate servo_interior.*/&\nregion mid block 0.003 0.005 0.003 0.005 -0.001 0.001 units box\nset region mid x 0.0105/' \
    "servo_bc: increment 0: interior particle 13 escaped through a gap between frame particles (its centre (0.0105, 0.004) m"
  deck_with 's/^fix  *integrate servo_interior.*/&\nregion mid block 0.003 0.005 0.003 0.005 -0.001 0.001 units box\nset region mid x 0.0105/' \
    "$TMP/escape.in"
  run_deck 2 escape.in "$TMP/escape.csv" "$TMP/escape.log"
  if grep -q "ERROR: Fix servo_bc: servo_bc: increment 0: interior particle [0-9]* escaped" "$TMP/escape.log" &&
     [ "$(wc -l < "$TMP/escape.csv")" = 1 ]; then
    ok "2 ranks stop alike on the escaped atom; the CSV keeps its header alone"
  else
    no "2 ranks, escaped atom:"; grep -m1 ERROR "$TMP/escape.log" || tail -2 "$TMP/escape.log"
  fi
}

# restart_check: a run split by write_restart (TMP/part1.in) and read_restart
# (TMP/part2.in) writes the same CSV as the uninterrupted run (TMP/full.in),
# byte for byte; part2 with another F is refused (decks from restart_decks)
# corrupt_restart FILE WHICH VALUE: overwrite one double of fix servo_bc's
# restart block (found by its marker, fix_servo_bc_restart.cpp RESTART_MAGIC; marker,
# length, seal, checksum, the frame's length, the frame (2D: Q, then 8 values
# per particle, the corners), the IDs, the masses, ...) and seal it again
# (tests/restart_edit.py): WHICH is an offset from the marker, or corner (the
# frame's first corner index), mass (the first frame mass), last (the block's
# last value)
corrupt_restart() {
  local which=$2
  case $which in corner) which='5 + 1 + 8 * v(5)' ;; mass) which='5 + v(4) + v(5)' ;; last) which='v(1)' ;; esac
  python3 "$(dirname "${BASH_SOURCE[0]}")/restart_edit.py" "$1" 8.020002e7 "$which" "$3"
}

restart_check() {
  run_deck 1 full.in "$TMP/full.csv" "$TMP/full.log" || { echo "$HOST full run failed:"; tail -3 "$TMP/full.log"; }
  local rows_half=0
  run_deck 1 part1.in "$TMP/split.csv" "$TMP/part1.log" && rows_half=$(($(wc -l < "$TMP/split.csv") - 1)) &&
    run_deck 1 part2.in "$TMP/split.csv" "$TMP/part2.log"
  if [ "$(wc -l < "$TMP/split.csv" 2>/dev/null)" = 5 ] && cmp -s "$TMP/full.csv" "$TMP/split.csv"; then
    ok "restart: the split run writes the uninterrupted run's CSV byte for byte"
  else
    no "restart:"; tail -3 "$TMP/part2.log"; diff "$TMP/full.csv" "$TMP/split.csv" | head -5
  fi
  # corrupted restart files (sbc/saved.h): each value checked, named, never a crash
  local what k v expect
  for what in "length:1:1e300:its length is 1.0000000000000001e+300" "frame length:4:-5:'frame length'" "corner:corner:1e9:'corner'" \
              "mass:mass:nan:'frame mass'" "FIRE:last:-1:'FIRE steps'"; do
    IFS=: read -r label k v expect <<< "$what"
    cp "$TMP/half.restart" "$TMP/bad.restart"
    corrupt_restart "$TMP/bad.restart" "$k" "$v" || { no "restart: cannot find the fix's block in the file"; continue; }
    sed "s|$TMP/half.restart|$TMP/bad.restart|" "$TMP/part2.in" > "$TMP/part2_corrupt.in"
    refused_deck "a restart file with a corrupted $label, by name" part2_corrupt.in "$expect"
  done
  # a run that went on past its restart file (killed later, say) and is
  # continued from that file: the rows written after it are dropped
  sed "s|^write_restart .*|write_restart $TMP/later.restart\nrun 12000|" "$TMP/part1.in" > "$TMP/later1.in"
  sed "s|$TMP/half.restart|$TMP/later.restart|" "$TMP/part2.in" > "$TMP/later2.in"
  run_deck 1 later1.in "$TMP/later.csv" "$TMP/later1.log"
  local rows_before
  rows_before=$(($(wc -l < "$TMP/later.csv") - 1))
  run_deck 1 later2.in "$TMP/later.csv" "$TMP/later2.log"
  # the rows the restart file had seen: those of the first part (part1.in)
  if [ "$rows_half" -ge 1 ] && [ "$rows_before" -gt "$rows_half" ] && cmp -s "$TMP/full.csv" "$TMP/later.csv" &&
     grep -q "continued after its row of increment $((rows_half - 1)) ($rows_half rows kept)" "$TMP/later2.log"; then
    ok "restart: continued from a restart file that $rows_before rows had passed, the CSV equals the uninterrupted run's"
  else
    no "restart continued after later rows ($rows_before rows before):"; grep -m1 -E "ERROR|continued" "$TMP/later2.log"
    diff "$TMP/full.csv" "$TMP/later.csv" | head -5
  fi
  sed "s/servo_bc P F 0.999 -0.01/servo_bc P F 0.999 -0.02/" "$TMP/part2.in" > "$TMP/part2_bad.in"
  run_deck 1 part2_bad.in "$TMP/bad3.csv" "$TMP/bad3.log"
  if [ $? -ne 0 ] && grep -q "ERROR: Fix servo_bc: restart: keyword 'F': F12" "$TMP/bad3.log"; then
    ok "restart refuses a contradicting F"
  else
    no "restart with another F:"; grep -m1 ERROR "$TMP/bad3.log"
  fi
}

# restart_friction_check FRICTION-SED HEAD: frictional (P) with sliding contacts
# (tangential history in the host's restart file), split after 9000 steps
# (inside increment 1 of 4): the uninterrupted run's CSV to 1e-12 of each
# tensor's scale. LAMMPS: 5e-15 in the last increment, because read_restart
# builds the neighbour lists from the positions of the split step, where the
# uninterrupted run still uses lists of an earlier step, and the contact
# forces add up in another order; with `neigh_modify every 1 check no` in
# both runs the CSVs are equal byte for byte (measured)
restart_friction_check() {
  split_restart_check "frictional (P), a run split by write_restart/read_restart inside increment 1" \
    "servo_bc P F 1 0.02 0 1 increments 4" 9000 "$1" "$2" f
}
# restart_remap_check FRICTION-SED HEAD: the same with remap x, split on the step
# where increment 0 converged, whose remap velocity (the per-atom values the fix
# writes to the restart file) the next step takes back; local damping, since
# FIRE's stop could zero a velocity that was wrongly kept (measured in LAMMPS:
# with the values not restored the rows differ by 5.2e-3 of the scale)
restart_remap_check() {
  split_restart_check "frictional (P) with remap x, a run split by write_restart/read_restart on the step of increment 1's remap" \
    "servo_bc P F 0.999 0.001 0 0.998 increments 3 remap x damping 0.7 0.7" first "$1" "$2" r
}
# split_restart_check LABEL SERVO SPLIT FRICTION-SED HEAD PREFIX: SPLIT steps, or
# `first`: the steps of increment 0 in the uninterrupted run
split_restart_check() {
  local label=$1 servo=$2 split=$3 p=$6
  deck_with "$4; s/servo_bc D F 1.002 0 0 0.997 increments 2 relax 1e-22 20/$servo/" "$TMP/${p}full.in"
  run_deck 1 "${p}full.in" "$TMP/${p}full.csv" "$TMP/${p}full.log" || tail -3 "$TMP/${p}full.log"
  # the run's setup is the controller's first step: increment 0's last step is the host's step S0 - 1
  [ "$split" = first ] && split=$(awk -F, 'NR == 1 { for (c = 1; c <= NF; c++) if ($c == "relax_steps") s = c } NR == 2 { print $s - 1 }' "$TMP/${p}full.csv")
  sed "/^run  *0\$/d; s|^run .*|run ${split:-1}\nwrite_restart $TMP/${p}half.restart|; /jump SELF loop/d" "$TMP/${p}full.in" > "$TMP/${p}part1.in"
  { echo "read_restart $TMP/${p}half.restart"; sed "$4" "$5"; sed -n '/^fix  *servo /,$p' "$TMP/${p}full.in"; } > "$TMP/${p}part2.in"
  run_deck 1 "${p}part1.in" "$TMP/${p}split.csv" "$TMP/${p}part1.log" &&
    run_deck 1 "${p}part2.in" "$TMP/${p}split.csv" "$TMP/${p}part2.log" || tail -3 "$TMP/${p}part2.log"
  TOLERANCE=1e-12 same_csvs "$label$(cmp -s "$TMP/${p}full.csv" "$TMP/${p}split.csv" && echo ", byte for byte")" \
    "$(($(wc -l < "$TMP/${p}full.csv") - 1))" "$TMP/${p}full.csv" "$TMP/${p}split.csv"
}

# the split decks of restart_check from DECK: the (P) servo words below, the
# first part cut after 2000 steps, inside increment 2 (the whole path takes
# about 3900 steps at the default preset); PART2_HEAD holds the host's lines before
# `fix servo` after read_restart (contact law, neighbours)
RESTART_SERVO="servo_bc P F 0.999 -0.01 -0.01 0.999 increments 3 relax 1e-20 20 gain_force 1e3 gain_moment 1e3 tol_force 1e-12 tol_moment 1e-12"
restart_decks() {  # PART2_HEAD_FILE
  deck_with "s/servo_bc D F 1.002 0 0 0.997 increments 2 relax 1e-22 20/$RESTART_SERVO/" "$TMP/full.in"
  sed "/^run  *0\$/d; s|^run .*|run 2000\nwrite_restart $TMP/half.restart|; /jump SELF loop/d" "$TMP/full.in" > "$TMP/part1.in"
  { echo "read_restart $TMP/half.restart"; cat "$1"; sed -n '/^fix  *servo /,$p' "$TMP/full.in"; } > "$TMP/part2.in"
}

finish() {
  echo "$pass passed, $fail failed"
  [ "$fail" -eq 0 ]
}
