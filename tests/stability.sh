#!/usr/bin/env bash
# The fast part of the stability matrix (bench/stability.sh fast): every cell
# converges or stops with its documented error; no NaN, no hang, no crash.
# Prints "N passed, N failed". Usage: stability.sh [BUILD-DIR]
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
B=${1:-$top/build} bash "$top/bench/stability.sh" fast "$tmp" | grep -v '^stability:'
