#!/usr/bin/env bash
# Installs uuvplan's build and test dependencies from Debian packages (bookworm).
# Idempotent and non-interactive: packages already present are not fetched again.
# Usage: scripts/install-deps.sh [--bench]
#   --bench  also the optional benchmark dependencies (bench/plain_identify.py: NumPy, SciPy;
#            bench/method_coverage.sh: PyYAML);
#            the build and the tests never need them.
set -euo pipefail

packages=(
  cmake g++ make pkg-config universal-ctags
  ccache clang-format-14  # rebuilds of unchanged files; the format check (scripts/format.sh)
  libeigen3-dev libnlopt-cxx-dev coinor-libipopt-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libyaml-cpp-dev libcli11-dev nlohmann-json3-dev
  libbz2-dev liblz4-dev libzstd-dev  # compressed ROS bag and MCAP chunks (`uuvplan import`)
  # figures (`uuvplan report`): PLplot, its cairo drivers (pngcairo, svgcairo)
  libplplot-dev plplot-driver-cairo
  # the report's render test opens the HTML in headless Chromium
  chromium fonts-dejavu-core
  clang-14 libclang-rt-14-dev  # the sanitizer and fuzz stage (scripts/sanitize.sh)
)
bench_packages=(python3 python3-numpy python3-scipy python3-yaml)
if [ "${1:-}" = "--bench" ]; then packages+=("${bench_packages[@]}"); fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "install-deps: installing ${missing[*]}" >&2
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
