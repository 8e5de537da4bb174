# Cross-host difference of servo_bc CSVs pasted side by side
# (paste -d, A.csv B.csv | awk -F, -f tests/sigma_diff.awk): prints the number
# of increments and max |sigma_B - sigma_A| over the four components, in % of
# the stress scale (max |sigma_A| of the run). With more files pasted, -v a=I
# -v b=J compare the I-th and J-th (from 1) and -v scale_from=K takes the scale
# from the K-th.
BEGIN { if (!a) a = 1; if (!b) b = 2; if (!scale_from) scale_from = a }
# columns per file, and sigma11 ... sigma22 by name in the header (columns.h)
NR == 1 { for (i = NF; i >= 1; i--) { if ($i == "increment") files++; if ($i == "sigma11") s11 = i }
          if (!s11) { print "sigma_diff.awk: no column sigma11" > "/dev/stderr"; exit 2 }
          w = NF / files; next }
{
  for (c = s11; c < s11 + 4; c++) {
    v = $(c + w * (scale_from - 1)); v = v < 0 ? -v : v; if (v > s) s = v
    d = $(c + w * (b - 1)) - $(c + w * (a - 1)); if (d < 0) d = -d; if (d > m) m = d
  }
  n++
}
END { printf "%d %.4g", n, (s > 0 ? 100 * m / s : 100) }
