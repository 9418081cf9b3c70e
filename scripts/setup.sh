#!/usr/bin/env bash
# Installs the Debian 12 packages Handover needs, only those that are missing.
# Non-interactive; uses sudo when not run as root.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git
  libeigen3-dev libyaml-cpp-dev liburdfdom-dev
  libmujoco-dev libqhull-dev libgl-dev libegl-dev libglfw3-dev
  libfcl-dev libccd-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  python3 python3-matplotlib python3-numpy ffmpeg xvfb parallel
  libegl-mesa0 libgl1-mesa-dri   # render: Mesa EGL (surfaceless platform) and its software GL driver
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
    echo "setup: need root (or sudo) to install: ${missing[*]}" >&2; exit 2; fi
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
