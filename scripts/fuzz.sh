#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/, SHELFDOCK_FUZZ=ON, clang + ASan + UBSan) into build-fuzz/
# and runs each for SECONDS (default 60), FUZZ_JOBS (default 1) at a time, at nice. Not part of
# CI: clang is installed here on demand. Each target starts from its seed corpus in
# fuzz/corpus/<target>/, copied into build-fuzz/corpus/<target>/, which it grows; findings land in
# build-fuzz/findings/<target>/ and one summary line per target (executions, seconds, findings)
# is appended to build-fuzz/fuzz.log.
#   bash scripts/fuzz.sh [SECONDS] [TARGET[:SECONDS]...]
# FUZZ_NO_BUILD=1 runs the targets as already built.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
shift || true
jobs="${FUZZ_JOBS:-1}"
all_targets=(fuzz_scan_json fuzz_models_yaml fuzz_detector_yaml fuzz_docking_yaml
  fuzz_scenario_yaml fuzz_lidar_yaml fuzz_robot_yaml fuzz_camera_yaml fuzz_rosbag fuzz_pgm)
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=("${all_targets[@]}")

bash scripts/install_deps.sh
if ! command -v clang++ >/dev/null || ! compgen -G "/usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a" >/dev/null; then
  sudo_cmd=""
  [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends clang libclang-rt-dev
fi

if [ -z "${FUZZ_NO_BUILD:-}" ]; then
  CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DSHELFDOCK_FUZZ=ON -DSHELFDOCK_BUILD_TESTS=OFF -DSHELFDOCK_BUILD_BENCH=OFF >/dev/null
  nice cmake --build build-fuzz --parallel "$(nproc)" --target "${targets[@]%%:*}"
fi

run_one() {
  local t="${1%%:*}" seconds="$seconds"
  [[ "$1" == *:* ]] && seconds="${1#*:}"
  local corpus="build-fuzz/corpus/$t" findings="build-fuzz/findings/$t" log="build-fuzz/logs/$t.log"
  mkdir -p "$corpus" "$findings" build-fuzz/logs
  # The repository's seeds start the working corpus; new units are written to the working one.
  cp -n "fuzz/corpus/$t"/* "$corpus"/ 2>/dev/null || true
  local start end rc=0
  start=$(date +%s)
  # -timeout: an input taking over 5 s is a hang; -rss_limit_mb: over 2 GB is an out-of-memory.
  # -max_len 65536 lets bags and multi-scan files grow past libFuzzer's 4 KB default. Fork mode
  # (one worker) keeps fuzzing after a finding, so every target gets its full time.
  nice "build-fuzz/bin/$t" "$corpus" -max_total_time="$seconds" -timeout=5 \
    -rss_limit_mb=2048 -max_len=65536 -fork=1 -ignore_crashes=1 -ignore_timeouts=1 \
    -ignore_ooms=1 -artifact_prefix="$findings/" >"$log" 2>&1 || rc=$?
  end=$(date +%s)
  # Fork mode's last status line: "#EXECS: cov: ... oom/timeout/crash: O/T/C time: Ss ...".
  local status execs ott
  status=$(grep -aE '^#[0-9]+: cov:' "$log" | tail -1 || true)
  execs=$(echo "$status" | sed -E 's/^#([0-9]+):.*/\1/')
  ott=$(echo "$status" | grep -oE 'oom/timeout/crash: [0-9/]+' | cut -d' ' -f2 || true)
  local found
  found=$(find "$findings" -type f | wc -l)
  echo "$(date -u +%FT%TZ) $t seconds=$((end - start)) executions=${execs:-?} oom/timeout/crash=${ott:-?} findings=$found rc=$rc" |
    tee -a build-fuzz/fuzz.log
}

pids=()
for t in "${targets[@]}"; do
  run_one "$t" &
  pids+=($!)
  if [ ${#pids[@]} -ge "$jobs" ]; then
    wait "${pids[0]}" || true
    pids=("${pids[@]:1}")
  fi
done
for p in "${pids[@]}"; do wait "$p" || true; done
