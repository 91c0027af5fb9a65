#!/usr/bin/env bash
# Installs the Debian packages `make fuzz` needs beyond install-deps.sh: clang and its runtime
# libraries (libFuzzer, ASan, UBSan), only those that are missing.
set -euo pipefail
# libclang-rt-dev: Debian's default clang's compiler-rt (libclang-rt-14-dev on Debian 12).
packages=(clang libclang-rt-dev)
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
