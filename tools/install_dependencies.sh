#!/usr/bin/env bash
# Installs the Debian packages pound builds with, skipping those already present.
set -euo pipefail
# libboost-program-options-dev brings Boost's headers too (Graph: reverse Cuthill-McKee ordering).
packages=(g++ cmake ninja-build libeigen3-dev libboost-program-options-dev libfmt-dev
          libspectra-dev  # the lowest modes of large models (shift-invert Lanczos, on Eigen)
          nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev python3-matplotlib
          libboost-mpi-dev openmpi-bin libopenmpi-dev  # pound batch under mpirun
          clang libclang-rt-dev  # clang and its libFuzzer runtime, for tools/fuzz.sh
          clang-format  # tools/check_format.sh, run by CI
          python3-pyflakes  # tools/check_python.sh, run by CI
          pybind11-dev python3-dev python3-numpy python3-pytest python3-pandas  # the Python module
          python3-venv python3-wheel)  # pip install . --no-build-isolation (docs/python.md)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
    missing+=("$package")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
echo "installing: ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
