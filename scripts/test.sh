#!/usr/bin/env bash
# The test command: installs dependencies, builds everything, checks formatting and runs every test.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
bash scripts/check_format.sh
# The browser tests' npm packages (playwright-core, pinned by the lockfile; no browser download).
(cd tests/browser && npm ci --no-audit --no-fund --loglevel=error)
# tools/mcap's Node packages, exactly as locked (for the MCAP round-trip test).
(cd tools/mcap && npm ci --no-audit --no-fund --loglevel=error)
ctest --test-dir build --output-on-failure --parallel "$(nproc)" --timeout 600
