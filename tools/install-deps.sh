#!/usr/bin/env bash
# Installs the Debian packages fddem needs to build, test, benchmark and plot (`fddem plot`:
# numpy, matplotlib; ffmpeg for --movie; pandas, optional, for DataFrames from the fddem package).
# Run as root on Debian 12 (bookworm). Safe to run again: apt-get skips what is present.
set -euo pipefail
packages=(
    build-essential cmake ninja-build pkg-config git
    clang-format clang-tidy
    clang libclang-rt-14-dev
    libeigen3-dev libtomlplusplus-dev libcli11-dev libfmt-dev
    libfftw3-dev libfftw3-mpi-dev libhypre-dev libopenmpi-dev openmpi-bin zlib1g-dev
    libgtest-dev libgmock-dev libbenchmark-dev
    python3 python3-numpy python3-matplotlib
    ffmpeg python3-pandas
)
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -eq 0 ]; then
    echo "install-deps: all ${#packages[@]} packages present"
    exit 0
fi
if [ "$(id -u)" -ne 0 ]; then
    echo "install-deps: missing packages (${missing[*]}); run this script as root" >&2
    exit 1
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}"
