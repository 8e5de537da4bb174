# first_peak(s, n): index of the first peak of |s[1..n]| (sigma12 per
# increment): the running maximum that the next 10 entries stay below
# (relaxation noise makes single dips); n when there is none. Shared by
# scripts/compare_diff.awk and scripts/path_error.awk (awk -f first_peak.awk -f ...).
function first_peak(s, n,    k, cur, top, at, below) {
  top = -1; below = 0
  for (k = 1; k <= n; k++) {
    cur = s[k] < 0 ? -s[k] : s[k]
    if (cur > top) { top = cur; at = k; below = 0 }
    else if (++below >= 10) return at
  }
  return n
}
