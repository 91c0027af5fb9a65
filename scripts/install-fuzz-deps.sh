#!/usr/bin/env bash
# Installs the Debian packages `make fuzz` needs beyond install-deps.sh: clang and its runtime
# libraries (libFuzzer, ASan, UBSan), only those that are missing.
# libclang-rt-dev: Debian's default clang's compiler-rt (libclang-rt-14-dev on Debian 12).
exec "$(dirname "$0")/install-deps.sh" clang libclang-rt-dev
