#!/usr/bin/env bash
# Installs what the project's targets need on a Debian machine, as root.
#   scripts/install-deps.sh core     compiler, make, valgrind, UMFPACK (make check)
#   scripts/install-deps.sh lammps   the Debian LAMMPS package (bench/, LAMMPS side)
#   scripts/install-deps.sh lammps-dev   LAMMPS, its headers and an MPI C++ compiler (make lammps)
#   scripts/install-deps.sh liggghts-dev   LIGGGHTS, its headers and an MPI C++ compiler (make liggghts)
#   scripts/install-deps.sh yade     the Debian YADE package (make yade, make check)
#   scripts/install-deps.sh fuzz     clang with libFuzzer (make fuzz)
#   scripts/install-deps.sh fe2      GetFEM's Python module, NumPy, SciPy (make fe2-patch, make fe2-demo)
#   scripts/install-deps.sh femxdem  YADE and esys-escript: FEMxDEM, the reference FEM x DEM code (make femxdem)
#   scripts/install-deps.sh install  pkg-config, CMake, pip and setuptools (make check-install)
# Already-installed tools are left alone; without root or apt-get it only reports.
set -euo pipefail
need=()
for what in "$@"; do
  case "$what" in
    core)
      command -v cc >/dev/null || need+=(gcc libc6-dev)
      command -v c++ >/dev/null || need+=(g++)   # tests/cxx_headers.cpp: the headers from C++
      command -v make >/dev/null || need+=(make)
      command -v valgrind >/dev/null || need+=(valgrind)
      command -v python3 >/dev/null || need+=(python3)   # tests/reliability.sh holds a file lock with it
      [ -f /usr/include/suitesparse/umfpack.h ] || need+=(libsuitesparse-dev)   # the condensed tangent's sparse solver
      ;;
    lammps)
      command -v lmp >/dev/null || need+=(lammps)
      ;;
    lammps-dev)
      command -v lmp >/dev/null || need+=(lammps)
      [ -f /usr/include/lammps/lammps.h ] || need+=(liblammps-dev)
      command -v mpicxx >/dev/null || need+=(libopenmpi-dev openmpi-bin)
      command -v g++ >/dev/null || need+=(g++)
      ;;
    liggghts-dev)
      command -v liggghts >/dev/null || need+=(liggghts)
      [ -f /usr/include/liggghts/pair_gran.h ] || need+=(libliggghts-dev)
      command -v mpicxx >/dev/null || need+=(libopenmpi-dev openmpi-bin)
      command -v g++ >/dev/null || need+=(g++)
      ;;
    fuzz)
      command -v clang >/dev/null || need+=(clang)
      ;;
    fe2)
      /usr/bin/python3 -c 'import getfem' 2>/dev/null || need+=(python3-getfem)
      /usr/bin/python3 -c 'import numpy, scipy.sparse.linalg' 2>/dev/null || need+=(python3-numpy python3-scipy)
      # the material points over MPI ranks (fe2/macro.py, comm)
      /usr/bin/python3 -c 'import mpi4py' 2>/dev/null || need+=(python3-mpi4py)
      command -v mpirun >/dev/null || need+=(openmpi-bin)
      ;;
    install)
      command -v pkg-config >/dev/null || need+=(pkgconf)
      command -v cmake >/dev/null || need+=(cmake)
      /usr/bin/python3 -c 'import setuptools' 2>/dev/null || need+=(python3-setuptools)
      /usr/bin/python3 -m pip --version >/dev/null 2>&1 || need+=(python3-pip)
      /usr/bin/python3 -c 'import wheel' 2>/dev/null || need+=(python3-wheel)
      ;;
    yade)
      command -v yade >/dev/null || need+=(yade python3-yade)
      ;;
    femxdem)
      command -v yade-double >/dev/null || need+=(yade python3-yade)
      [ -d /usr/lib/python3-escript/esys ] || need+=(python3-escript)
      ;;
    *) echo "install-deps: unknown set '$what' (expected core, lammps, lammps-dev, liggghts-dev, yade, femxdem, fuzz, fe2 or install)" >&2; exit 2 ;;
  esac
done
[ ${#need[@]} -eq 0 ] && exit 0
if [ "$(id -u)" != 0 ] || ! command -v apt-get >/dev/null; then
  echo "install-deps: missing ${need[*]}; install them (Debian: apt-get install ${need[*]})" >&2
  exit 1
fi
echo "install-deps: installing ${need[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null
