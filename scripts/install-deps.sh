#!/usr/bin/env bash
# Installs the Debian packages Columba builds against, only those that are missing; with
# arguments, those packages instead (scripts/install-fuzz-deps.sh).
set -euo pipefail
packages=("$@")
[ ${#packages[@]} -gt 0 ] || packages=(build-essential cmake pkg-config libembree-dev libtbb-dev libpugixml-dev
          libopenexr-dev libpng-dev libstb-dev libcli11-dev nlohmann-json3-dev libgtest-dev libgmock-dev
          libbenchmark-dev libfmt-dev libtinyobjloader-dev libnlopt-dev zlib1g-dev clang-format
          python3-dev python3-numpy python3-pytest python3-matplotlib pybind11-dev mkdocs libcairo2-dev liblcms2-dev
          fonts-dejavu-core)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "Installing: ${missing[*]}"
if [ "$(id -u)" -eq 0 ]; then sudo=""; else sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
