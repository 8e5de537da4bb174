#!/usr/bin/env bash
# make install into a temporary prefix, used as a user would (docs/core.md, "Installing"): the C example
# inputs/fe2/material_point.c built once with pkg-config and once with a three-line CMake project, each run
# against the installed shared library (its SONAME libservo_bc.so.MAJOR found in the prefix); servo_bc_core
# imported from the installed tree and from `pip install --no-build-isolation .` (Debian's setuptools, no
# index), each loading the prefix's library; make uninstall leaves no file. Prints "N passed, N failed".
# Usage: install.sh BUILD VERSION LDLIBS
set -u
B=$(cd "${1:?usage: install.sh BUILD VERSION LDLIBS}" && pwd); version=${2:?}; libs=${3:-}
top=$(cd "$(dirname "$0")/.." && pwd)
py=/usr/bin/python3
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "install: $1"; }
no() { fail=$((fail + 1)); echo "FAIL install: $1"; }
prefix=$T/prefix
if bash "$top/scripts/install.sh" install "$prefix" "$B" "$version" "$libs" > "$T/install.log" 2>&1; then
  ok "$(tail -n 1 "$T/install.log")"
else
  no "make install failed:"; tail -n 3 "$T/install.log"; echo "$pass passed, $fail failed"; exit 1
fi
soname=$(readelf -d "$prefix/lib/libservo_bc.so.$version" | sed -n 's/.*Library soname: \[\(.*\)\]/\1/p')
[ "$soname" = "libservo_bc.so.${version%%.*}" ] && [ -L "$prefix/lib/$soname" ] &&
  ok "the shared library's SONAME $soname, linked in the prefix" || no "SONAME '$soname'"

# the C example with pkg-config, run against the installed library
export PKG_CONFIG_PATH=$prefix/lib/pkgconfig
flags=$(pkg-config --cflags --libs servo_bc 2>&1)
if cc -std=c11 -o "$T/mp_pc" "$top/inputs/fe2/material_point.c" $flags 2> "$T/cc.log" &&
   LD_LIBRARY_PATH=$prefix/lib "$T/mp_pc" > "$T/mp_pc.out" 2>&1 &&
   LD_LIBRARY_PATH=$prefix/lib ldd "$T/mp_pc" | grep -q "libservo_bc.so.${version%%.*} => $prefix/lib/"; then
  ok "pkg-config ($flags): inputs/fe2/material_point.c built and run on the prefix's library: $(tail -n 1 "$T/mp_pc.out" | cut -c1-90)"
else
  no "pkg-config build or run:"; tail -n 3 "$T/cc.log" "$T/mp_pc.out" 2>/dev/null
fi

# the C example with CMake
mkdir -p "$T/cmake_app"
cp "$top/inputs/fe2/material_point.c" "$T/cmake_app/"
cat > "$T/cmake_app/CMakeLists.txt" <<'CM'
cmake_minimum_required(VERSION 3.13)
project(material_point C)
find_package(servo_bc 0.3 REQUIRED)
add_executable(material_point material_point.c)
target_link_libraries(material_point servo_bc::servo_bc)
CM
if cmake -S "$T/cmake_app" -B "$T/cmake_build" -DCMAKE_PREFIX_PATH="$prefix" > "$T/cmake.log" 2>&1 &&
   cmake --build "$T/cmake_build" >> "$T/cmake.log" 2>&1 &&
   "$T/cmake_build/material_point" > "$T/mp_cmake.out" 2>&1 && cmp -s "$T/mp_pc.out" "$T/mp_cmake.out"; then
  ok "CMake (find_package(servo_bc 0.3), servo_bc::servo_bc): the same program prints the same lines"
else
  no "CMake build or run:"; tail -n 5 "$T/cmake.log" "$T/mp_cmake.out" 2>/dev/null
fi

# Python: the installed modules, and pip's, each finding the prefix's library (not build/)
probe='import servo_bc_core as c; print(c.version(), c.library()._name, len(c.columns()))'
got=$(cd "$T" && PYTHONPATH=$prefix/lib/python3/dist-packages $py -c "$probe" 2>&1)
case $got in "$version $prefix/lib/libservo_bc.so 25") ok "servo_bc_core from the installed tree: $got" ;;
  *) no "servo_bc_core from the installed tree: $got" ;; esac
(cd "$top" && SERVO_BC_PREFIX=$prefix $py -m pip install --no-build-isolation --no-deps --no-index --quiet \
  --prefix "$T/pip" . > "$T/pip.log" 2>&1)
site=$(dirname "$(find "$T/pip" -name servo_bc_core.py | head -n 1)")
got=$(cd "$T" && PYTHONPATH=$site $py -c "$probe" 2>&1)
case $got in "$version $prefix/lib/libservo_bc.so 25") ok "pip install --no-build-isolation . (in $site): $got" ;;
  *) no "pip install: $got"; tail -n 5 "$T/pip.log" ;; esac

# uninstall
if bash "$top/scripts/install.sh" uninstall "$prefix" > "$T/uninstall.log" 2>&1 &&
   [ "$(find "$prefix" -type f -o -type l | wc -l)" = 0 ]; then
  ok "make uninstall: no file left under the prefix"
else
  no "uninstall left $(find "$prefix" -type f -o -type l | wc -l) files: $(find "$prefix" -type f | head -n 3)"
fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
