#!/usr/bin/env bash
# Installs the Debian 12 packages acdplan needs to build, test and run.
# Idempotent: when every package is already installed it prints nothing and exits 0.
set -euo pipefail

packages=(
  build-essential cmake ccache pkg-config clang-format clang libclang-rt-14-dev lld
  libc++-14-dev libc++abi-14-dev
  libeigen3-dev libcgal-dev libgmp-dev libmpfr-dev
  libboost-dev libboost-filesystem-dev libboost-serialization-dev libboost-system-dev
  libompl-dev libode-dev libfcl-dev libyaml-cpp-dev libassimp-dev libpng-dev
  libgtest-dev libcli11-dev nlohmann-json3-dev libsqlite3-dev libexpat1-dev
  libminizip-dev
  python3-matplotlib ompl-demos
)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null || true)
  if [[ "$status" != "installed" ]]; then
    missing+=("$p")
  fi
done

if [[ ${#missing[@]} -eq 0 ]]; then
  exit 0
fi

if ! command -v apt-get >/dev/null 2>&1; then
  echo "install-deps: apt-get not found; install these packages by hand: ${missing[*]}" >&2
  exit 1
fi

sudo=()
if [[ $(id -u) -ne 0 ]]; then
  if ! command -v sudo >/dev/null 2>&1; then
    echo "install-deps: not root and sudo is missing; install: ${missing[*]}" >&2
    exit 1
  fi
  sudo=(sudo)
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
