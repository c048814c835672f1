#!/usr/bin/env bash
# The main job: builds the shelfdock CLI (only that target) and runs one simulated docking on the
# built-in default scenario. Build progress and notes go to stderr; stdout is the docking outcome
# (one JSON object). The run's replay page is written to build/demo_replay.html.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)
echo "demo: checking packages (scripts/install_deps.sh)" >&2
bash scripts/install_deps.sh >&2
werror=OFF
[ "${CI:-}" = "true" ] && werror=ON
echo "demo: configuring build/ (Release)" >&2
log=$(mktemp)
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DSHELFDOCK_WERROR="$werror" > "$log" 2>&1 \
  || { tail -30 "$log" >&2; rm -f "$log"; exit 1; }
rm -f "$log"
echo "demo: building build/bin/shelfdock only ($(nproc) jobs; a fresh build takes some minutes, [done/total] below)" >&2
cmake --build build --target shelfdock --parallel "$(nproc)" >&2
echo "demo: built in $(( $(date +%s) - start )) s; running one docking: build/bin/shelfdock dock --html build/demo_replay.html $*" >&2
set +e
build/bin/shelfdock dock --html build/demo_replay.html "$@"
code=$?
set -e
echo "demo: replay page: build/demo_replay.html (open it in a browser); total $(( $(date +%s) - start )) s" >&2
exit $code
