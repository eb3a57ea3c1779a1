#!/usr/bin/env bash
# Installs what nineball needs from Debian 12's archive, only what is missing.
set -euo pipefail

packages=(cmake ninja-build g++ pkg-config
  libbox2d-dev libsfml-dev libspdlog-dev libgtest-dev libgmock-dev libbenchmark-dev
  nlohmann-json3-dev libcli11-dev libx11-dev fonts-dejavu-core xvfb xauth xdotool x11-apps x11-utils
  pybind11-dev python3-dev python3-numpy python3-pytest python3-matplotlib
  python3-pip python3-venv python3-setuptools python3-wheel python3-tqdm
  python3-distributed python3-mypy)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=()
  [[ $(id -u) -eq 0 ]] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" >/dev/null
fi
