# Results files read by column name (columns.h; `servo-bc --columns`): put
# this file first, awk -F, -f scripts/columns.awk -f PROGRAM.awk FILE..., and
# write $col("sigma11") for a column. col(NAME) is the field of that column
# in the current file's header (the first occurrence, so that on files pasted
# side by side it is the first file's); a name no header has stops awk with
# status 2 and no output, so a misspelt column never passes for a number.
function col(name) {
  if (!(name in at)) { printf "no column %s in %s\n", name, FILENAME > "/dev/stderr"; missing = 1; exit 2 }
  return at[name]
}
# has(NAME): whether the header has that column (a 3D file has sigma33).
# sigmas(NM): the sigma components of the file's dimension into NM[1..n], n
# returned (sigma11 sigma12 sigma21 sigma22; nine in 3D).
function has(name) { return name in at }
function sigmas(nm,    list) {
  list = has("sigma33") ? "sigma11 sigma12 sigma13 sigma21 sigma22 sigma23 sigma31 sigma32 sigma33" : "sigma11 sigma12 sigma21 sigma22"
  return split(list, nm, " ")
}
FNR == 1 { for (i = NF; i >= 1; i--) at[$i] = i }
END { if (missing) exit 2 }
