#!/usr/bin/env bash
# Feeds `shelfdock detect` and `shelfdock bag` the hostile inputs of issue 10, made in a
# temporary directory (the 1 GB file is sparse), and prints per input: exit code, wall time,
# peak resident memory and the first line of what shelfdock said.
#   bash scripts/hostile_inputs.sh [BINARY]
set -euo pipefail
cd "$(dirname "$0")/.."
bin="${1:-build/bin/shelfdock}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

python3 - "$work" <<'PY'
import json, os, random, sys
w = sys.argv[1]
scan = json.load(open("config/example_scan.json"))
def put(name, obj_or_text):
    text = obj_or_text if isinstance(obj_or_text, str) else json.dumps(obj_or_text)
    open(os.path.join(w, name), "w").write(text + "\n")
# 10 M beams on one JSON Lines line (about 20 MB).
with open(os.path.join(w, "ten_million_beams.jsonl"), "w") as f:
    f.write('{"angle_min": -1, "angle_max": 1, "angle_increment": 2e-7, "range_min": 0.05, '
            '"range_max": 25, "ranges": [' + "1," * 9_999_999 + "1]}\n")
s = dict(scan); s["ranges"] = [None] * len(scan["ranges"]); s.pop("intensities", None)
put("all_nan.json", s)
s = dict(scan); s["ranges"] = scan["ranges"][:400]; s.pop("intensities", None)
put("wrong_length.json", s)
s = dict(scan); s["intensities"] = scan["intensities"][:10]
put("wrong_intensities.json", s)
s = dict(scan); s["angle_increment"] = 0.0
put("zero_increment.json", s)
s = dict(scan); s["angle_increment"] = -scan["angle_increment"]
put("negative_increment.json", s)
random.seed(1)
open(os.path.join(w, "garbage.bin"), "wb").write(bytes(random.randrange(256) for _ in range(1 << 20)))
PY
truncate -s 1G "$work/one_gigabyte.json"
printf '{"angle_min": 0, "ranges": [' > "$work/one_gigabyte_line.jsonl"
truncate -s 1G "$work/one_gigabyte_line.jsonl"
# A truncated bag: the first half of a real recording (../shared/data/real, when present).
bag_src="$(ls ../shared/data/real/*.bag 2>/dev/null | head -n 1 || true)"
if [ -n "$bag_src" ]; then
  head -c $(($(stat -c %s "$bag_src") / 2)) "$bag_src" > "$work/truncated.bag"
fi

run() {
  local name="$1"
  shift
  local rc=0
  /usr/bin/time -f "%e %U %S %M" -o "$work/time" "$bin" "$@" > "$work/out" 2> "$work/err" || rc=$?
  read -r secs user sys kb < <(tail -n 1 "$work/time")
  local said
  said="$(cat "$work/err" "$work/out" | head -n 1 | sed "s|$work/||" | cut -c1-100)"
  printf '| %s | %d | %.2f | %.2f | %.0f | `%s` |\n' "$name" "$rc" "$secs" \
    "$(awk -v u="$user" -v s="$sys" 'BEGIN { print u + s }')" "$((kb / 1024))" "$said"
}

echo "| input | exit | wall [s] | CPU [s] | peak RSS [MiB] | first line out |"
echo "|---|---|---|---|---|---|"
m=(--models config/models.yaml)
run "10 M beams (JSON Lines)" detect "${m[@]}" --scan "$work/ten_million_beams.jsonl"
run "all NaN (811 nulls)" detect "${m[@]}" --scan "$work/all_nan.json"
run "400 ranges, angles say 811" detect "${m[@]}" --scan "$work/wrong_length.json"
run "10 intensities, 811 ranges" detect "${m[@]}" --scan "$work/wrong_intensities.json"
run "zero angle_increment" detect "${m[@]}" --scan "$work/zero_increment.json"
run "negative increment, angles ascending" detect "${m[@]}" --scan "$work/negative_increment.json"
run "1 GB file of zero bytes" detect "${m[@]}" --scan "$work/one_gigabyte.json"
run "1 GB file, one endless line" detect "${m[@]}" --scan "$work/one_gigabyte_line.jsonl"
run "1 MiB of random bytes" detect "${m[@]}" --scan "$work/garbage.bin"
run "1 MiB of random bytes as a bag" bag --bag "$work/garbage.bin"
if [ -f "$work/truncated.bag" ]; then
  run "truncated bag (half of $(basename "$bag_src"))" bag --bag "$work/truncated.bag" --out "$work/t.jsonl"
fi
