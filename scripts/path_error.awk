# Error of a servo_bc stress path against a reference path (issue 9):
#   awk -F, -f scripts/columns.awk -f scripts/first_peak.awk -f scripts/path_error.awk REF.csv RUN.csv
# prints "path_error max_before_peak points last":
#   path_error       ||sigma_run - sigma_ref|| / ||sigma_ref||, both by the
#                    path norm of eq. 42, (sum_ij int sigma_ij^2 dF12)^(1/2),
#                    trapezoidal, over the run's range of F12
#   max_before_peak  max over the run's points up to the reference's first
#                    peak of |sigma12| (scripts/first_peak.awk) of
#                    max_ij |sigma_run - sigma_ref|, % of the stress scale
#                    (max |sigma_ij| of the reference)
#   points, last     points of the run compared, and its last |F12|
# The reference is interpolated linearly in F12 at the run's points, so the
# two may use different increments. Rows with the F12 of the row after them
# (a mixed BC's stress stage) count once, as their last row, in both.
function param(x) { return x < 0 ? -x : x }
# the stress components by name (scripts/columns.awk), each file's own
FNR == 1 { file++; nc = split("sigma11 sigma12 sigma21 sigma22", name, " "); for (k = 1; k <= nc; k++) sc[file, k] = col(name[k])
  f12[file] = col("F12"); next }
# (a reference row with the F12 of the row before replaces it: the last row
# of a stress stage stands for it, as in the run; F12 is the measured one of
# eq. 15, equal to within round-off, 1e-12, in a stress stage)
function same(a, b) { return (a - b < 0 ? b - a : a - b) <= 1e-12 }
file == 1 { p1 = param($f12[1]); if (!(nr > 0 && same(rp[nr], p1))) nr++
  rp[nr] = p1; for (c = 1; c <= nc; c++) rs[nr, c] = $sc[1, c]; next }
file == 2 { n++; p[n] = param($f12[2]); for (c = 1; c <= nc; c++) s[n, c] = $sc[2, c] }
function keep(q, m, k) { return k == m || !same(q[k + 1], q[k]) }
END {
  if (nr < 2 || n < 1) { print "path_error: a CSV has no increments" > "/dev/stderr"; exit 1 }
  for (k = 1; k <= nr; k++) {
    s12[k] = rs[k, 2]
    for (c = 1; c <= nc; c++) { v = rs[k, c] < 0 ? -rs[k, c] : rs[k, c]; if (v > scale) scale = v }
  }
  peak = rp[first_peak(s12, nr)]
  j = 1; err2 = 0; pts = 0; maxd = 0; have = 0
  for (k = 1; k <= n; k++) {
    if (!keep(p, n, k)) continue
    while (j < nr - 1 && rp[j + 1] < p[k]) j++
    if (p[k] > rp[nr] * (1 + 1e-12) + 1e-15) break
    h = rp[j + 1] - rp[j]; t = h > 0 ? (p[k] - rp[j]) / h : 1
    if (t < 0) t = 0
    e2 = 0; dmax = 0
    for (c = 1; c <= nc; c++) {
      d = s[k, c] - (rs[j, c] + t * (rs[j + 1, c] - rs[j, c]))
      e2 += d * d; d = d < 0 ? -d : d; if (d > dmax) dmax = d
    }
    if (have) err2 += 0.5 * (p[k] - plast) * (e2 + e2last)
    have = 1; plast = p[k]; e2last = e2; pts++
    if (p[k] <= peak * (1 + 1e-12) && dmax > maxd) maxd = dmax
  }
  ref2 = 0
  for (k = 2; k <= nr && rp[k] <= plast * (1 + 1e-12); k++) {
    a = 0; b = 0
    for (c = 1; c <= nc; c++) { a += rs[k - 1, c] ^ 2; b += rs[k, c] ^ 2 }
    ref2 += 0.5 * (rp[k] - rp[k - 1]) * (a + b)
  }
  printf "%.6g %.6g %d %.6g\n", (ref2 > 0 ? sqrt(err2 / ref2) : 0), 100 * maxd / (scale > 0 ? scale : 1), pts, plast
}
