#!/usr/bin/env bash
# Soak benchmark of `shelfdock detect --scan -`: streams N copies (default 1,000,000) of the
# example scan (811 beams, one shelf) through standard input, made on the fly (nothing on disk),
# and reports throughput and the resident memory sampled through the run: flat memory means one
# scan at a time whatever the stream's length. SOAK_NO_RETURNS=1 streams the same scan with
# every beam a no-return instead (reading, checking and writing without the detector's work).
#   bash scripts/soak_stream.sh [N] [BINARY]
set -euo pipefail
cd "$(dirname "$0")/.."
n="${1:-1000000}"
bin="${2:-build/bin/shelfdock}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
line="$(tr -d '\n' < config/example_scan.json)"
expect='"detections":\[{'
if [ -n "${SOAK_NO_RETURNS:-}" ]; then
  line="$(python3 -c 'import json,sys; s=json.load(open("config/example_scan.json")); s["ranges"]=[None]*len(s["ranges"]); s.pop("intensities",None); print(json.dumps(s))')"
  expect='"detections":\[\]'
fi

mkfifo "$work/in" "$work/out"
start=$(date +%s.%N)
yes "$line" | head -n "$n" > "$work/in" &
grep -c "$expect" < "$work/out" > "$work/found" &
counter=$!
/usr/bin/time -f "%M" -o "$work/maxrss" "$bin" detect --models config/models.yaml --scan - \
  < "$work/in" > "$work/out" &
timer=$!
# Sample the detector's resident memory every 2 s while it runs.
sleep 0.5
pid=$(pgrep -P "$timer" | head -n 1)
while kill -0 "$pid" 2>/dev/null; do
  rss=$(awk '/VmRSS/ {print $2}' "/proc/$pid/status" 2>/dev/null || true)
  [ -n "$rss" ] && echo "$(date +%s.%N) $rss" >> "$work/rss"
  sleep 2
done
wait "$timer" || true
wait "$counter" || true
end=$(date +%s.%N)

found=$(cat "$work/found")
awk -v n="$n" -v found="$found" -v t0="$start" -v t1="$end" '
  { t[NR] = $1 - t0; r[NR] = $2 }
  END {
    secs = t1 - t0
    printf "scans in: %d, lines out with the expected result: %d\n", n, found
    printf "time: %.1f s, throughput: %.0f scans/s\n", secs, n / secs
    q = int(NR / 10); if (q < 1) q = 1
    h = int(NR / 2); if (h < 1) h = 1
    printf "resident memory (MiB) at 10%% / 50%% / 90%% / end of the run: %.1f / %.1f / %.1f / %.1f\n",
      r[q] / 1024, r[h] / 1024, r[NR - q + 1] / 1024, r[NR] / 1024
    max = 0; for (i = 1; i <= NR; ++i) if (r[i] > max) max = r[i]
    printf "peak sampled: %.1f MiB over %d samples; peak (time -f %%M): %.1f MiB\n", max / 1024, NR, peak / 1024
  }' peak="$(cat "$work/maxrss")" "$work/rss"
[ "$found" -eq "$n" ]
