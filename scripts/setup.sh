#!/usr/bin/env bash
# Installs what raylab needs on Debian or Ubuntu (as root, or through sudo), and says what to
# install elsewhere. Safe to run again: it installs only what is missing.
set -euo pipefail

packages=(cmake g++ make pkg-config libglm-dev libstb-dev zlib1g-dev doctest-dev libtomlplusplus-dev libcli11-dev nlohmann-json3-dev
          libzip-dev libcmark-dev libyaml-cpp-dev python3) # libyaml-cpp-dev: the autograder's tests only; python3: the tests parse junit.xml with its XML parser
# Optional, raylab works without them (docs/grading.md): the grader's sandbox on Linux, and ccache
# (the students of a class build the framework's files once).
optional=(bubblewrap ccache)

if ! command -v dpkg-query >/dev/null 2>&1; then
  cat <<'TXT'
setup.sh installs packages on Debian and Ubuntu only. Elsewhere, install:
  macOS (Homebrew): brew install cmake glm stb zlib doctest tomlplusplus cli11 nlohmann-json libzip cmark yaml-cpp
  Windows (vcpkg):  vcpkg install glm stb zlib doctest tomlplusplus cli11 nlohmann-json libzip cmark yaml-cpp
then run the cmake commands of README.md.
TXT
  exit 0
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
fi
for p in "${optional[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" && continue
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "$p" >/dev/null ||
    echo "setup: $p could not be installed; raylab works without it (docs/grading.md)"
done
echo "setup: all packages are installed"
