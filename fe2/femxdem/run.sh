#!/usr/bin/env bash
# FEMxDEM beside servo_bc on one macro problem (docs/fe2.md, "FEMxDEM side by side"): FEMxDEM's biaxial example
# shrunk (fe2/femxdem/femxdem_biaxial.py), one of its RVEs exported into servo_bc (P) points, and the same macro
# problem on servo_bc's FE^2 (fe2/femxdem/servo_bc_biaxial.py); the table of both (fe2/femxdem/table.py).
# Needs Debian's yade and python3-escript (scripts/install-deps.sh femxdem) and the core's library (make).
# Usage: fe2/femxdem/run.sh [OUT (out/femxdem)]; FEMXDEM_DISCS (121), FEMXDEM_ELEMENTS (1), FEMXDEM_STEPS (4),
# FEMXDEM_STRAIN (0.0025) by environment.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
out=$(mkdir -p "${1:-out/femxdem}" && cd "${1:-out/femxdem}" && pwd)
yade=$(command -v yade-double || true)
module=/usr/lib/x86_64-linux-gnu/yade-double/py/yade/FEMxDEM
escript=/usr/lib/python3-escript
if [ -z "$yade" ] || [ ! -f "$module/msFEM2D.py" ] || [ ! -d "$escript/esys" ]; then
  echo "fe2/femxdem/run.sh: FEMxDEM needs Debian's yade (yade-double, $module) and python3-escript ($escript);" \
       "run scripts/install-deps.sh femxdem" >&2
  exit 1
fi
# YADE imports as a module through a link named yadeimport.py (FEMxDEM's simDEM.py imports it)
ln -sf "$yade" "$out/yadeimport.py"
cd "$out"
echo "femxdem: preparing the RVE (${FEMXDEM_DISCS:-121} discs, FEMxDEM's prepareRVE.py protocol)"
"$yade" -n -x "$here/prepare_rve.py" 2>&1 | grep '^prepare_rve' || { echo "fe2/femxdem/run.sh: prepare_rve.py failed" >&2; exit 1; }
echo "femxdem: FEMxDEM's biaxial (femxdem_biaxial.py)"
PYTHONPATH="$escript:$module:$out:$here" LD_LIBRARY_PATH="$escript/lib" \
  /usr/bin/python3 -W ignore "$here/femxdem_biaxial.py" 2> femxdem.log | grep '^femxdem' \
  || { tail -20 femxdem.log >&2; echo "fe2/femxdem/run.sh: FEMxDEM's run failed (log: $out/femxdem.log)" >&2; exit 1; }
echo "femxdem: servo_bc's FE^2 on the exported RVE (servo_bc_biaxial.py)"

SERVO_BC_LIB="${SERVO_BC_LIB:-$root/build/libservo_bc.so}" PYTHONPATH="$root/fe2:$here" \
  /usr/bin/python3 "$here/servo_bc_biaxial.py" "$out"
/usr/bin/python3 "$here/table.py" "$out" "$root/build/servo-bc-plot"
