#!/usr/bin/env bash
# Installs what raylab needs on Debian or Ubuntu (as root, or through sudo), and says what to
# install elsewhere. Safe to run again: it installs only what is missing.
set -euo pipefail

packages=(cmake g++ make pkg-config libglm-dev libstb-dev zlib1g-dev doctest-dev libtomlplusplus-dev libcli11-dev nlohmann-json3-dev
          libzip-dev libcmark-dev libyaml-cpp-dev python3) # libyaml-cpp-dev: the autograder's tests only; python3: the tests parse junit.xml with its XML parser
# Optional, raylab works without them (docs/grading.md): the grader's sandbox on Linux (bubblewrap, and
# libseccomp for its fallback where bubblewrap cannot start), and ccache
# (the students of a class build the framework's files once).
optional=(bubblewrap libseccomp-dev ccache)

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
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  # A package the distribution lacks (Ubuntu 22.04: libtomlplusplus-dev) is named, not asked for: a
  # tree made by `raylab autograder` carries such headers in third_party/ (cmake/RaylabDependencies.cmake).
  available=()
  for p in "${missing[@]}"; do
    if apt-cache policy "$p" 2>/dev/null | grep -q "Candidate: [0-9]"; then
      available+=("$p")
    else
      echo "setup: $p is not in this system's archive: raylab takes it from third_party/ when the tree has it"
    fi
  done
  if ((${#available[@]})); then
    echo "setup: installing ${available[*]}"
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${available[@]}" >/dev/null
  fi
fi
for p in "${optional[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" && continue
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "$p" >/dev/null ||
    echo "setup: $p could not be installed; raylab works without it (docs/grading.md)"
done
echo "setup: done"
