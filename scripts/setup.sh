#!/usr/bin/env bash
# scripts/setup.sh [--tests]: installs what raylab's build needs on Debian or Ubuntu (as root, or
# through sudo), with --tests what its test suite needs too, then checks that every piece is really
# there. Safe to run again: it installs only what is missing. Exits non-zero naming what is still
# missing and the command that installs it on this machine.
set -euo pipefail

# What it prints is in the reader's language, as raylab's own (framework/src/messages.cpp): French
# when LC_ALL, else LC_MESSAGES, else LANG (the first one set) is fr, fr_* or fr.*, English otherwise.
# French puts a no-break space (U+00A0, as framework/messages/fr.toml does) before : ; ? !
case "${LC_ALL:-${LC_MESSAGES:-${LANG:-}}}" in fr | fr_* | fr.*) french=1 ;; *) french=0 ;; esac
nb=$'\xc2\xa0'
# say ENGLISH FRENCH: the line in the reader's language.
say() { if ((french)); then printf '%s\n' "$2"; else printf '%s\n' "$1"; fi; }

# The build: the compiler and tools, the libraries (cpp-httplib: raylab watch's page), the grader's
# sandbox (bubblewrap, and libseccomp for its fallback where bubblewrap cannot start) and ccache (the
# students of a class build the framework's files once).
packages=(g++ cmake make patch pkg-config libglm-dev libstb-dev zlib1g-dev doctest-dev libtomlplusplus-dev
          libcli11-dev nlohmann-json3-dev libzip-dev libcmark-dev libyaml-cpp-dev libcpp-httplib-dev bubblewrap
          libseccomp-dev ccache)
# The test suite: git (the toy-lab test copies the tree as `git ls-files` lists it), python3 (the tests
# parse junit.xml with its XML parser), chromium (raylab report's
# HTML in a headless browser, and its fonts), mmdebstrap (the Gradescope zip set up in a bare Debian),
# similarity-tester (sim_c++: the class page's similar submissions, which grade-class finds with it
# where it is installed; Debian 13 has no such package). A test whose package is missing is skipped,
# saying so (tests/support/needs.h).
test_packages=(git python3 chromium fonts-dejavu-core mmdebstrap similarity-tester)
# What some archives lack, which costs tests only (skipped): Ubuntu has no chromium package but a snap's
# (chromium-browser, which a container cannot run); Debian 13 has no similarity-tester.
declare -A optional=([chromium]=1 [fonts-dejavu-core]=1 [similarity-tester]=1)
# The workflow presets (README.md's commands) need CMake 3.25.
cmake_needed=3.25
# Headers that a tree made by `raylab autograder` carries in third_party/ where the distribution lacks
# them (Ubuntu 22.04: libtomlplusplus-dev; cmake/RaylabDependencies.cmake).
declare -A third_party=([libglm-dev]=glm [libtomlplusplus-dev]=tomlplusplus [libcli11-dev]=cli11
                        [nlohmann-json3-dev]=nlohmann_json [libstb-dev]=stb)
# The sources of those whose repository has that include/ folder, for a system whose archive lacks one.
declare -A sources=([libtomlplusplus-dev]=https://github.com/marzer/tomlplusplus [libcli11-dev]=https://github.com/CLIUtils/CLI11
                    [nlohmann-json3-dev]=https://github.com/nlohmann/json)
# The programs the build runs, and the package of each.
declare -A tools=([c++]=g++ [cmake]=cmake [make]=make [patch]=patch [pkg-config]=pkg-config)

case "${1:-}" in
  --tests) packages+=("${test_packages[@]}") ;;
  "") ;;
  *) say "usage: scripts/setup.sh [--tests]" "usage${nb}: scripts/setup.sh [--tests]" >&2; exit 2 ;;
esac
top=$(cd "$(dirname "$0")/.." && pwd)

if ! command -v dpkg-query >/dev/null 2>&1; then
  if ((french)); then
    cat <<TXT
setup.sh n'installe des paquets que sous Debian et Ubuntu. Ailleurs, installez${nb}:
  macOS (Homebrew)${nb}: xcode-select --install; brew install cmake glm stb zlib doctest tomlplusplus cli11 nlohmann-json libzip cmark yaml-cpp cpp-httplib
  Windows (vcpkg)${nb}:  Visual Studio 2022 avec «${nb}Développement Desktop en C++${nb}», puis les bibliothèques de vcpkg.json
puis lancez les commandes cmake du README.md (LISEZMOI.md en français).
TXT
  else
    cat <<'TXT'
setup.sh installs packages on Debian and Ubuntu only. Elsewhere, install:
  macOS (Homebrew): xcode-select --install; brew install cmake glm stb zlib doctest tomlplusplus cli11 nlohmann-json libzip cmark yaml-cpp cpp-httplib
  Windows (vcpkg):  Visual Studio 2022 with "Desktop development with C++", then the libraries of vcpkg.json
then run the cmake commands of README.md.
TXT
  fi
  exit 0
fi

# The prefix that runs a command as root here: nothing as root, sudo for a user who has it.
as_root=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    as_root=(sudo)
  else
    as_root=(su root -c)
  fi
fi
# A command run as root on this machine, as a person would type it; the one that installs packages.
root_command() {
  if [ "$(id -u)" -eq 0 ]; then echo "$*"
  elif command -v sudo >/dev/null 2>&1; then echo "sudo $*"
  else echo "su root -c '$*'"
  fi
}
install_command() { root_command "apt-get install -y $*"; }
in_archive() { [[ $(apt-cache policy "$1" 2>/dev/null || true) =~ Candidate:\ [0-9] ]]; }
installed() { [ "$(dpkg-query -W -f='${Status}' "$1" 2>/dev/null || true)" = "install ok installed" ]; }
run_as_root() {
  if [ "${as_root[0]:-}" = su ]; then su root -c "$(printf '%q ' "$@")"; else "${as_root[@]}" "$@"; fi
}

missing=()
for p in "${packages[@]}"; do installed "$p" || missing+=("$p"); done
if ((${#missing[@]})); then
  say "setup: updating the package lists" "setup${nb}: mise à jour des listes de paquets"
  run_as_root apt-get update -qq
  available=()
  for p in "${missing[@]}"; do
    # in_archive reads the whole answer before it is matched: a pipe into `grep -q` would end apt-cache
    # early (SIGPIPE) and, under pipefail, make a present package look absent.
    if in_archive "$p"; then
      available+=("$p")
    elif [ -n "${third_party[$p]:-}" ] && [ -e "$top/third_party/${third_party[$p]}" ]; then
      say "setup: $p is not in this system's archive: raylab takes it from third_party/${third_party[$p]}" \
          "setup${nb}: $p n'est pas dans l'archive de ce système${nb}: raylab le prend dans third_party/${third_party[$p]}"
    elif [ -n "${optional[$p]:-}" ]; then
      say "setup: $p is not in this system's archive: the tests that need it will be skipped" \
          "setup${nb}: $p n'est pas dans l'archive de ce système${nb}: les tests qui en ont besoin seront ignorés"
    fi
  done
  if ((${#available[@]})); then
    say "setup: installing ${available[*]}" "setup${nb}: installation de ${available[*]}"
    run_as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${available[@]}"
  fi
fi

# The check: every package, and the tools the build runs, really there.
still=()
for p in "${packages[@]}"; do
  installed "$p" && continue
  [ -n "${third_party[$p]:-}" ] && [ -e "$top/third_party/${third_party[$p]}" ] && continue
  [ -n "${optional[$p]:-}" ] && continue
  still+=("$p")
done
for tool in "${!tools[@]}"; do
  command -v "$tool" >/dev/null 2>&1 || [[ " ${still[*]} " == *" ${tools[$tool]} "* ]] || still+=("${tools[$tool]}")
done
if ((${#still[@]})); then
  say "setup: still missing: ${still[*]}" "setup${nb}: il manque encore${nb}: ${still[*]}" >&2
  installable=()
  for p in "${still[@]}"; do
    if in_archive "$p"; then
      installable+=("$p")
    elif [ -n "${sources[$p]:-}" ]; then # header-only (Ubuntu 22.04's toml++): its include/ in third_party/
      say "setup: $p is in no archive of this system: put its headers in $top/third_party/${third_party[$p]}/include/ (git clone --depth 1 ${sources[$p]} $top/third_party/${third_party[$p]}), or use a newer release" \
          "setup${nb}: $p n'est dans aucune archive de ce système${nb}: mettez ses en-têtes dans $top/third_party/${third_party[$p]}/include/ (git clone --depth 1 ${sources[$p]} $top/third_party/${third_party[$p]}), ou utilisez une version plus récente du système" >&2
    else
      say "setup: $p is in no archive of this system: use a newer release of it" \
          "setup${nb}: $p n'est dans aucune archive de ce système${nb}: utilisez une version plus récente du système" >&2
    fi
  done
  if ((${#installable[@]})); then
    say "setup: install them with: $(install_command "${installable[@]}")" \
        "setup${nb}: installez-les avec${nb}: $(install_command "${installable[@]}")" >&2
  fi
  exit 1
fi
# CMake: the distribution's may be older than the presets (Ubuntu 22.04: 3.22).
cmake_version=$(cmake --version | sed -n '1s/^cmake version \([0-9]*\.[0-9]*\).*/\1/p')
if [ "$(printf '%s\n' "$cmake_needed" "$cmake_version" | sort -V | head -n 1)" != "$cmake_needed" ]; then
  say "setup: cmake is $cmake_version here; README.md's workflow presets need $cmake_needed or newer. Install a newer one (Ubuntu: $(root_command snap install cmake --classic)), or build without the presets: cmake -S . -B build -DCMAKE_BUILD_TYPE=Release && cmake --build build --target figures" \
      "setup${nb}: cmake est ici en version $cmake_version${nb}; les presets de workflow (cmake --workflow) demandent $cmake_needed ou plus récent. Installez-en un plus récent (Ubuntu${nb}: $(root_command snap install cmake --classic)), ou compilez sans les presets${nb}: cmake -S . -B build -DCMAKE_BUILD_TYPE=Release && cmake --build build --target figures" >&2
  exit 1
fi
if [ -n "${1:-}" ]; then
  say "setup: done, everything raylab needs and its tests need is installed" \
      "setup${nb}: terminé, tout ce dont raylab et ses tests ont besoin est installé"
else
  say "setup: done, everything raylab needs is installed" "setup${nb}: terminé, tout ce dont raylab a besoin est installé"
fi
