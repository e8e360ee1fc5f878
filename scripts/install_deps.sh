#!/usr/bin/env bash
# Installs what the package needs on Debian 12 (idempotent; does nothing slow when all is present).
set -euo pipefail
# clang + libclang-rt-14-dev: libFuzzer for the fuzz tests of scripts/test.sh; python3-*: the Python bindings;
# libsuitesparse-dev: COLAMD, the fill-reducing pivot order of the IRREF (optional for users, used by CI)
pkgs=(g++ cmake make libcgal-dev libcgal-demo libeigen3-dev libgmp-dev libmpfr-dev libboost-dev clang libclang-rt-14-dev
      python3-dev pybind11-dev python3-pybind11 python3-numpy python3-scipy python3-pytest libsuitesparse-dev)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "install_deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
