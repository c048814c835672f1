#!/usr/bin/env bash
# Installs the Debian 12 packages shelfdock needs to build and test. Idempotent: packages already
# installed are left alone, and apt is only called when something is missing.
set -euo pipefail

packages=(
  build-essential cmake ninja-build ccache clang-format pkg-config python3
  libeigen3-dev libceres-dev libyaml-cpp-dev nlohmann-json3-dev libcli11-dev
  libgtest-dev libgmock-dev googletest libbenchmark-dev libapriltag-dev
  librosbag-storage-dev libsensor-msgs-dev pluginlib-dev
  chromium
  pybind11-dev python3-dev python3-numpy python3-pytest python3-yaml
)
# Node.js and npm run the browser tests (tests/browser). A machine may already have them from
# elsewhere (e.g. NodeSource's nodejs, which bundles npm): take Debian's only when none is there.
command -v node > /dev/null && command -v npm > /dev/null || packages+=(nodejs npm)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

# Node.js and npm for tools/mcap (ROS 2 recordings): Debian's, unless a node with npm is already
# on PATH (a NodeSource node ships its own npm, and Debian's npm package would conflict with it).
if ! command -v npm >/dev/null 2>&1; then
  for p in nodejs npm; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
fi

if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install_deps: installing ${missing[*]}"
sudo_cmd=""
[ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo_cmd apt-get update -qq
$sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
