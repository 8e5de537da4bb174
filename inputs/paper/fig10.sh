#!/usr/bin/env bash
# Fig. 10 (Sect. 4.2.2): the stress norm of eq. 42 along simple shear
# F12 = 0.5 (100 increments) against the particle number, for the five packings
# of Fig. 6 (n0 = 25, 100, 200, 400, 600) under (D), (P) and (T), Table 4
# settings as in Figs. 7-9. Runs that already have a CSV in out/paper are
# reused (delete it to rerun); each run is limited to LIMIT seconds (default
# 1800). A run that stops early ((T) stagnates, see the docs) enters the
# full-path table with its last F12; the second table integrates every run
# over the range all of them reached, so that the norms compare.
#   fig10.sh [SET]     SET = table4 (default), active or converged (irregular_case.sh)
set -euo pipefail
. "$(dirname "$0")/common.sh"
set=${1:-table4}
limit=${LIMIT:-1800}
out=$top/out/paper
# the packing a run of this set read: its own (converged) or Fig. 6's
packing() { if [ -f "$out/packing_$1_$set.txt" ]; then echo "$out/packing_$1_$set.txt"; else echo "$out/packing_$1.txt"; fi; }
count() { awk '$1 != "box" && $1 !~ /^#/ && NF >= 3 { n++ } END { print n }' "$(packing "$1")"; }
for n0 in 25 100 200 400 600; do
  for bc in D P T; do
    csv=$out/irregular_${bc}_${n0}_${set}.csv
    [ -f "$csv" ] || timeout "$limit" bash "$top/inputs/paper/irregular_case.sh" "$bc" "$n0" "$set" > /dev/null ||
      echo "($bc) n0 $n0: stopped at F12 = $(last_F12 "$csv")"
  done
done
# a run that stopped leaves a picture of the state it stopped in (its log
# names it): the frame's polygon and any disc outside it, for the page
for log in "$out"/irregular_[DPT]_*_"$set".log; do
  picture=$(sed -n 's/^servo_bc: its picture is //p' "$log" | tail -n 1)
  name=$(basename "${log%.log}")
  [ -z "$picture" ] || cp "$picture" "$fig/fig10_stopped_${name#irregular_}.svg"
done
# how far each (P) and (T) frame left F X from increment 0 to 10 (F12 0 -> 0.05),
# in radii (frame_departure.sh): out/paper/fig10_SET_frame.md
{
  echo "| particles | (P) largest, radii | (P) mean | (T) largest | (T) mean |"
  echo "| --- | --- | --- | --- | --- |"
  for n0 in 25 100 200 400 600; do
    row="| $(count "$n0")"
    for bc in P T; do
      vtk=$out/vtk/irregular_${bc}_${n0}_${set}_particles_0000
      if [ -f "${vtk}00.vtk" ] && [ -f "${vtk}10.vtk" ]; then
        row="$row | $(bash "$top/inputs/paper/frame_departure.sh" "${vtk}00.vtk" "${vtk}10.vtk" 0.05 | awk '{ print $1 " | " $3 }')"
      else row="$row | – | –"; fi
    done
    echo "$row |"
  done
} > "$out/fig10_${set}_frame.md"
cat "$out/fig10_${set}_frame.md"
# common range: the smallest last F12 over all runs
fc=$(for f in "$out"/irregular_[DPT]_*_"$set".csv; do last_F12 "$f"; done | sort -g | head -1)
for range in full common; do
  table=$out/fig10_${set}_$range.csv
  echo "particles,D,P,T,D_to,P_to,T_to" > "$table"
  for n0 in 25 100 200 400 600; do
    row=$(count "$n0")
    ends=
    # sigma~ = sigma Rbar / kn, kn = 1e4 N/m (Sect. 4.2.1)
    scale=$(awk -v r="$(rbar "$(packing "$n0")")" 'BEGIN { printf "%.10g", r / 1e4 }')
    for bc in D P T; do
      csv=$out/irregular_${bc}_${n0}_${set}.csv
      if [ $range = full ]; then row="$row,$(path_norm "$csv" "$scale")"; else row="$row,$(path_norm "$csv" "$scale" "$fc")"; fi
      ends="$ends,$(last_F12 "$csv")"
    done
    echo "$row$ends" >> "$table"
  done
  echo "$range path$([ $range = common ] && echo " (F12 <= $fc)"):"; cat "$table"
  # the same as a table for the page (make figures): out/paper/fig10_SET_RANGE.md
  awk -F, 'NR == 1 { print "| particles | (D) | (P) | (T) | (D) to F̄12 | (P) to | (T) to |"; print "| --- | --- | --- | --- | --- | --- | --- |"; next }
    { printf "| %s | %.3g | %.3g | %.3g | %.3f | %.3f | %.3f |\n", $1, $2, $3, $4, $5, $6, $7 }' "$table" > "${table%.csv}.md"
  # one file per BC for the overlay: particles,norm
  series=()
  # a BC enters the full-path picture only when all its runs reached F12 = 0.5
  for c in 2 3 4; do
    bc=$(head -1 "$table" | cut -d, -f$c)
    if [ $range = full ] && awk -F, -v c=$((c + 3)) 'NR > 1 && $c < 0.5 - 1e-9 { bad = 1 } END { exit !bad }' "$table"; then
      echo "($bc) left out of the full-path picture: not every run reached F12 = 0.5"; continue
    fi
    awk -F, -v c=$c 'NR == 1 { print "particles,norm"; next } { print $1 "," $c }' "$table" > "$out/fig10_${set}_${range}_$bc.csv"
    series+=("$out/fig10_${set}_${range}_$bc.csv" "($bc)")
  done
  "$plot" "$fig/fig10_${set}_$range.svg" "Fig. 10: stress norm of eq. 42 ($range path)" "particles" "norm of sigma~ (eq. 42)" \
    particles 1 norm 1 "${series[@]}"
done
