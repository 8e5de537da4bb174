# Cross-host difference of two servo_bc CSVs pasted side by side
# (paste -d, A.csv B.csv | awk -F, -f tests/sigma_diff.awk): prints the number
# of increments and max |sigma_B - sigma_A| over the four components, in % of
# the stress scale (max |sigma_A| of the run).
NR > 1 {
  for (c = 10; c <= 13; c++) {
    a = $c < 0 ? -$c : $c; if (a > s) s = a
    d = $c - $(c + 20); if (d < 0) d = -d; if (d > m) m = d
  }
  n++
}
END { printf "%d %.4g", n, (s > 0 ? 100 * m / s : 100) }
