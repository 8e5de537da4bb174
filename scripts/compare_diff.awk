# Rows of the difference table of scripts/compare.sh: the embedded CSV and an
# engine's CSV pasted side by side (paste -d,), -v e=ENGINE. Per sigma
# component: max and mean of |sigma_e - sigma_embedded| in % of the stress
# scale (max |sigma| of the embedded run), up to the first peak of |sigma_ij|
# of the embedded run for the F_ij its last row moved farthest from the
# identity (the layer's shear, F12 or in 3D F13, unless another moved
# strictly farther: F33 on a triaxial path) (scripts/first_peak.awk), and
# over the whole path; increments missing from either run are left out and
# counted.
# columns by name (scripts/columns.awk, given before this file)
NR == 1 { w = NF / 2; i = col("increment"); nc = sigmas(nm); shear = nc == 9 ? 3 : 2
  for (c = 1; c <= nc; c++) { cs[c] = col(nm[c]); cf[c] = col("F" substr(nm[c], 6)) } } # w: columns per file
NR > 1 && $i != "" {
  n++
  for (c = 1; c <= nc; c++) {
    a[n, c] = $cs[c]; v = a[n, c] < 0 ? -a[n, c] : a[n, c]; if (v > scale) scale = v
    have[n] = $(i + w) != ""; b[n, c] = $(cs[c] + w)
    f[c] = $cf[c] - (substr(nm[c], 6, 1) == substr(nm[c], 7, 1)); if (f[c] < 0) f[c] = -f[c]
  }
}
END {
  along = shear
  for (c = 1; c <= nc; c++) if (f[c] > f[along] * (1 + 1e-9) + 1e-15) along = c
  for (k = 1; k <= n; k++) s12[k] = a[k, along]
  peak = first_peak(s12, n)
  for (c = 1; c <= nc; c++) name[c] = "σ̄" substr(nm[c], 6)
  for (c = 1; c <= nc; c++) {
    m1 = s1 = m2 = s2 = n1 = n2 = 0
    for (k = 1; k <= n; k++) {
      if (!have[k]) continue
      d = b[k, c] - a[k, c]; d = 100 * (d < 0 ? -d : d) / (scale > 0 ? scale : 1)
      if (k <= peak) { if (d > m1) m1 = d; s1 += d; n1++ }
      if (d > m2) m2 = d; s2 += d; n2++
    }
    printf "| %s | %s | %.4g | %.4g | %.4g | %.4g |\n", e, name[c], m1, (n1 ? s1 / n1 : 0), m2, (n2 ? s2 / n2 : 0)
  }
  missing = 0; for (k = 1; k <= n; k++) missing += !have[k]
  if (missing) printf "| %s | (%d of %d increments missing) | | | | |\n", e, missing, n
  printf "| %s | (first peak of sigma%s at increment %d) | | | | |\n", e, substr(nm[along], 6), peak - 1
}
