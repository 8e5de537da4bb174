#!/usr/bin/env bash
# Headers to compile against the Debian LAMMPS package (docs/lammps/README.md): Debian's
# liblammps-dev lacks fmt/ (the library carries its own fmt 7 as fmt::v7_lmp)
# and the neighbour-request header; both come from the Debian source package
# of the same version. Usage: scripts/lammps-headers.sh DEST  (DEST/fmt/, DEST/*.h)
set -euo pipefail
dest=${1:?usage: lammps-headers.sh DEST}
[ -f "$dest/fmt/format.h" ] && [ -f "$dest/fix_neigh_history.h" ] && exit 0
if [ "$(id -u)" != 0 ]; then
  echo "lammps-headers: run as root (apt-get source needs the deb-src lines)" >&2; exit 1
fi
src=/etc/apt/sources.list.d/debian.sources
if [ -f "$src" ] && ! grep -q "deb-src" "$src"; then
  sed -i 's/^Types: deb$/Types: deb deb-src/' "$src"
  apt-get update -qq
fi
tmp=$(mktemp -d)
(cd "$tmp" && apt-get source --download-only -qq lammps >/dev/null)
tarball=$(ls "$tmp"/lammps_*.orig.tar.* | head -n 1)
mkdir -p "$dest"
tar -xf "$tarball" -C "$tmp" --wildcards '*/src/fmt/*' '*/src/neigh_request.h' '*/src/lammpsplugin.h' '*/src/version.h' '*/src/GRANULAR/pair_gran_hooke_history.h' '*/src/fix_neigh_history.h'
top=$(ls -d "$tmp"/*/src | head -n 1)
cp -r "$top/fmt" "$dest/"
cp "$top/neigh_request.h" "$top/lammpsplugin.h" "$top/version.h" "$top/GRANULAR/pair_gran_hooke_history.h" "$top/fix_neigh_history.h" "$dest/"
rm -rf "$tmp"
echo "lammps-headers: fmt and neighbour-request headers in $dest"
