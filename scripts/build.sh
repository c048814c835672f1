#!/usr/bin/env bash
# Configures and builds shelfdock into build/ (Release). Extra arguments go to cmake's configure.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
werror=OFF
[ "${CI:-}" = "true" ] && werror=ON
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DSHELFDOCK_WERROR="$werror" \
  -DSHELFDOCK_BUILD_PYTHON=ON "$@"
cmake --build build --parallel "$(nproc)"
