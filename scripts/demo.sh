#!/usr/bin/env bash
# The main job: builds shelfdock and runs one simulated docking on the built-in default scenario.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh > /tmp/shelfdock-build.log 2>&1 || { tail -50 /tmp/shelfdock-build.log; exit 1; }
exec build/bin/shelfdock dock "$@"
