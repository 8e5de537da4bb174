#!/usr/bin/env bash
# make install / make uninstall (docs/core.md, "Installing"): the library, its headers, the runner and the
# plotter, the Python modules, the docs, servo_bc.pc for pkg-config and a CMake package, under PREFIX (DESTDIR
# before it, as packagers stage). Every file installed is listed in PREFIX/share/servo_bc/manifest.txt, which
# uninstall reads.
#   scripts/install.sh install PREFIX BUILD VERSION PRIVATE_LIBS
#   scripts/install.sh uninstall PREFIX
set -euo pipefail
what=${1:?usage: install.sh install|uninstall PREFIX [BUILD VERSION PRIVATE_LIBS]}
prefix=${2:?PREFIX}
case $prefix in /*) ;; *) echo "install: PREFIX '$prefix' is not an absolute path" >&2; exit 2 ;; esac
root=${DESTDIR:-}$prefix
manifest=$root/share/servo_bc/manifest.txt

if [ "$what" = uninstall ]; then
  [ -f "$manifest" ] || { echo "uninstall: no servo_bc under '$prefix' ($manifest not found)" >&2; exit 1; }
  while IFS= read -r f; do rm -f "$root/$f"; done < "$manifest"
  rm -f "$manifest"
  # the folders the install made, deepest first, where they are empty now
  find "$root/include/sbc" "$root/lib/cmake/servo_bc" "$root/lib/python3" "$root/share/doc/servo_bc" \
    "$root/share/servo_bc" -depth -type d -empty -delete 2>/dev/null || true
  echo "uninstall: servo_bc removed from $prefix"
  exit 0
fi
[ "$what" = install ] || { echo "install.sh: '$what' (expected install or uninstall)" >&2; exit 2; }
build=${3:?BUILD}; version=${4:?VERSION}; private=${5:-}
top=$(cd "$(dirname "$0")/.." && pwd)
major=${version%%.*}
files=()
put() {  # SOURCE DEST-RELATIVE [MODE]
  install -D -m "${3:-644}" "$1" "$root/$2"
  files+=("$2")
}
link() {  # TARGET NAME-RELATIVE
  ln -sfn "$1" "$root/$2"
  files+=("$2")
}
for h in "$top"/src_core/include/sbc/*.h "$top"/src_core/include/sbc/embedded/*.h; do
  put "$h" "include/${h#"$top"/src_core/include/}"
done
put "$build/libservo_bc.a" lib/libservo_bc.a
put "$build/libservo_bc.so" "lib/libservo_bc.so.$version" 755
link "libservo_bc.so.$version" "lib/libservo_bc.so.$major"
link "libservo_bc.so.$major" lib/libservo_bc.so
put "$build/servo-bc" bin/servo-bc 755
put "$build/servo-bc-plot" bin/servo-bc-plot 755
# the Python modules (Debian's layout) and where they find the library
for m in servo_bc_core servo_bc servo_bc_bonds; do put "$top/yade_adapter/$m.py" "lib/python3/dist-packages/$m.py"; done
tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT
printf '"""Where make install put the servo_bc library (servo_bc_core.py reads it)."""\nLIBDIR = %s\n' \
  "'$prefix/lib'" > "$tmp"
put "$tmp" lib/python3/dist-packages/servo_bc_paths.py
for d in README.md CHANGELOG.md; do put "$top/$d" "share/doc/servo_bc/$d"; done
while IFS= read -r -d '' d; do put "$d" "share/doc/servo_bc/${d#"$top"/}"; done \
  < <(find "$top/docs" -type f \( -name '*.md' -o -name '*.rst' -o -name '*.txt' -o -name '*.svg' \) -print0)
# pkg-config
cat > "$tmp" <<PC
prefix=$prefix
libdir=\${prefix}/lib
includedir=\${prefix}/include

Name: servo_bc
Description: Boundary conditions on particle aggregates (DEM) and the aggregate as an FE material point
Version: $version
Libs: -L\${libdir} -lservo_bc
Libs.private: $private
Cflags: -I\${includedir}
PC
put "$tmp" lib/pkgconfig/servo_bc.pc
# CMake: find_package(servo_bc) gives the target servo_bc::servo_bc (the shared library), relocatable
cat > "$tmp" <<'CM'
# servo_bc's CMake package (make install): find_package(servo_bc) then target_link_libraries(app servo_bc::servo_bc)
get_filename_component(_servo_bc_prefix "${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)
if(NOT TARGET servo_bc::servo_bc)
  add_library(servo_bc::servo_bc SHARED IMPORTED)
  set_target_properties(servo_bc::servo_bc PROPERTIES
    IMPORTED_LOCATION "${_servo_bc_prefix}/lib/libservo_bc.so.@VERSION@"
    IMPORTED_SONAME "libservo_bc.so.@MAJOR@"
    INTERFACE_INCLUDE_DIRECTORIES "${_servo_bc_prefix}/include")
endif()
set(servo_bc_VERSION "@VERSION@")
unset(_servo_bc_prefix)
CM
sed -i "s/@VERSION@/$version/g; s/@MAJOR@/$major/g" "$tmp"
put "$tmp" lib/cmake/servo_bc/servo_bcConfig.cmake
cat > "$tmp" <<CV
# servo_bc $version: compatible with requests of the same major version not above it
set(PACKAGE_VERSION "$version")
if(PACKAGE_FIND_VERSION_MAJOR STREQUAL "$major" AND NOT PACKAGE_FIND_VERSION VERSION_GREATER PACKAGE_VERSION)
  set(PACKAGE_VERSION_COMPATIBLE TRUE)
  if(PACKAGE_FIND_VERSION STREQUAL PACKAGE_VERSION)
    set(PACKAGE_VERSION_EXACT TRUE)
  endif()
elseif(NOT PACKAGE_FIND_VERSION)
  set(PACKAGE_VERSION_COMPATIBLE TRUE)
endif()
CV
put "$tmp" lib/cmake/servo_bc/servo_bcConfigVersion.cmake
mkdir -p "$(dirname "$manifest")"
printf '%s\n' "${files[@]}" > "$manifest"
echo "install: servo_bc $version into $prefix (${#files[@]} files; make uninstall PREFIX=$prefix removes them)"
