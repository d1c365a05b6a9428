#!/usr/bin/env bash
# The students' tree on Windows, checked on Linux (issue 25): `raylab distribute` writes it, MinGW-w64
# cross-builds it (cmake/toolchains/mingw-w64.cmake) and Wine runs it, headless:
#   raylab lab 1 on the stubs       the not-done-yet line, exit status 0; in French on a French Windows
#   figures and grade, solutions    every figure rendered, every point
#   an endless loop in lab 1        its check stopped at the time limit, every other point kept
#   a crash in lab 2                its checks failed as crashed, the other labs' points kept
# and the grader alive each time, no agent left behind.
#
#   scripts/windows_check.sh [RAYLAB]   RAYLAB: a Linux build's raylab (default build/bin/raylab)
#
# Needs: apt-get install g++-mingw-w64-x86-64-posix libz-mingw-w64-dev wine wine64 (.ci/run does it).
# Wine has no Windows CMake: after each change of labs/ the tree is rebuilt here, on Linux, as a
# student's IDE would, so that raylab finds its programs fresh and starts no CMake (each run is checked
# for it). Under Wine, raylab's rebuild would start Linux's CMake, which Wine runs without waiting for
# its end: raylab would grade the old programs while CMake rebuilds them.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
raylab=${1:-$root/build/bin/raylab}
for tool in x86_64-w64-mingw32-g++-posix wine cmake patch; do
  command -v "$tool" >/dev/null || { echo "windows_check: $tool is missing (see this script's header)" >&2; exit 2; }
done
[ -x "$raylab" ] || { echo "windows_check: no $raylab: build raylab first (cmake --workflow --preset test)" >&2; exit 2; }

work=$(mktemp -d /tmp/raylab-windows.XXXXXX)
trap 'wineserver -k 2>/dev/null || true; rm -rf "$work"' EXIT
tree=$work/tree
export WINEPREFIX=$work/wine WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml=" DISPLAY=
unset LANG LANGUAGE LC_ALL LC_MESSAGES # English messages, whatever this machine's
start=$SECONDS
step() { printf '\n== %s (%d s)\n' "$1" $((SECONDS - start)); }
fail() { echo "windows_check: FAILED: $1" >&2; exit 1; }

# expect NAME STATUS OUTPUT TEXT...: the command NAME ended with STATUS and its OUTPUT holds each TEXT.
expect() {
  local name=$1 want=$2 status=$3 output=$4 text
  shift 4
  [ "$status" = "$want" ] || fail "$name: exit status $status, expected $want"
  for text in "$@"; do
    grep -qF -- "$text" <<<"$output" || fail "$name: no \`$text\` in its output"
  done
}

# winrun ARGS...: raylab.exe ARGS under Wine, in the tree; its output in $output, its status in $status.
# A run that hangs is stopped after 10 minutes (that is a failure: the grader must stop by itself).
winrun() {
  set +e
  output=$(cd "$tree" && timeout 600 wine build/bin/raylab.exe "$@" 2>&1)
  status=$?
  set -e
  printf '%s\n' "$output" | grep -v '^  PASS' || true
  if grep -qF "changed since the last build" <<<"$output"; then fail "raylab $*: it found its build stale"; fi
}

# The course's figures and points, from its labs' lab.toml (those course.toml lists).
lab_toml() { echo "$root"/labs/lab"$1"_*/lab.toml; }
lab_points() { awk '$1 == "points" && $2 == "=" { s += $3 } END { print s }' "$(lab_toml "$1")"; }
figures=0 total=0
for lab in $(sed -n 's/^labs = \[\(.*\)\]$/\1/p' "$root/course.toml" | tr ',' ' '); do
  figures=$((figures + $(grep -c '^\[\[figure\]\]' "$(lab_toml "$lab")")))
  total=$((total + $(lab_points "$lab")))
done
[ "$figures" -gt 0 ] && [ "$total" -gt 0 ] || fail "no figure or no point read from course.toml's labs"

# No agent still running (Wine shows one as Z:\...\raylab-agent.exe; nothing else runs them under Wine here).
no_agent_left() {
  sleep 1
  if pgrep -f 'raylab-agent\.exe' >/dev/null; then fail "$1: an agent outlived the grading"; fi
}

rebuild() {
  cmake --build "$tree/build" -j "$(nproc)" --config Release --target raylab raylab-agents >"$work/build.log" 2>&1 ||
    { tail -30 "$work/build.log"; fail "the MinGW build"; }
}

step "the students' tree, written by raylab distribute"
"$raylab" distribute "$tree" >/dev/null

step "cross-built with MinGW-w64 (raylab, raylab-agent)"
if command -v ccache >/dev/null; then
  export CMAKE_CXX_COMPILER_LAUNCHER=ccache CCACHE_BASEDIR=$tree CCACHE_NOHASHDIR=1
fi
# No link-time optimisation: grading needs the same pictures, not their speed (quicker links).
cmake -S "$tree" -B "$tree/build" --toolchain "$tree/cmake/toolchains/mingw-w64.cmake" -DCMAKE_BUILD_TYPE=Release \
  -DRAYLAB_LTO=OFF >"$work/configure.log" 2>&1 || { cat "$work/configure.log"; fail "configuring the MinGW build"; }
rebuild
wineboot --init >/dev/null 2>&1 || true

step "raylab lab 1 on the stubs"
winrun lab 1
expect "raylab lab 1" 0 "$status" "$output" "lab 1 not done yet: write fillGradient in labs/lab1_first_image/gradient.cpp"

step "raylab lab 1 in French, from Windows' display language alone (no LANG, LC_ALL nor LC_MESSAGES)"
# Wine takes its display language from this LC_ALL; cmd removes the variables from what raylab.exe sees.
set +e
output=$(cd "$tree" && LC_ALL=fr_FR.UTF-8 timeout 600 wine cmd /c \
  'set LC_ALL=&& set LANG=&& set LC_MESSAGES=&& build\bin\raylab.exe lab 1' 2>&1)
status=$?
set -e
printf '%s\n' "$output"
expect "raylab lab 1 (French Windows)" 0 "$status" "$output" \
  "TP 1 pas encore écrit" "écrivez fillGradient dans labs/lab1_first_image/gradient.cpp"

step "the solutions: raylab figures, raylab grade"
for lab in "$root"/solutions/lab*/; do
  cp "$lab"*.cpp "$tree/labs/$(basename "$lab")/"
done
rebuild
winrun figures
expect "raylab figures" 0 "$status" "$output" \
  "$figures figures: $figures rendered, 0 waiting for a lab not done yet, 0 failed"
[ "$(find "$tree/out/student" -name '*.png' | wc -l)" = $((figures + 1)) ] ||
  fail "raylab figures: not $figures figures and a contact sheet in out/student"
winrun grade
expect "raylab grade (solutions)" 0 "$status" "$output" "total: $total / $total" \
  "raylab: grading WITHOUT bubblewrap (there is no bubblewrap on this system)"
no_agent_left "raylab grade (solutions)"

step "an endless loop in lab 1: raylab grade --timeout 5"
patch -s -p1 -d "$tree/labs" <"$root/tests/instructors/bad_submissions/endless_loop.patch"
rebuild
began=$SECONDS
winrun grade --timeout 5
expect "raylab grade (endless loop)" 1 "$status" "$output" \
  "FAIL  lab1  fillGradient: a 1-pixel-wide or 1-pixel-high image has no NaN" \
  "this check stopped: it ran past the time limit (an endless loop?)" \
  "lab 1: $(($(lab_points 1) - 1)) / $(lab_points 1) points" "total: $((total - 1)) / $total" # the check's 1 point
echo "   (graded in $((SECONDS - began)) s, the loop stopped after 5)"
no_agent_left "raylab grade (endless loop)"

step "a crash in lab 2: raylab grade"
cp "$root/solutions/lab1_first_image/"*.cpp "$tree/labs/lab1_first_image/"
patch -s -p1 -d "$tree/labs" <"$root/tests/instructors/bad_submissions/crash.patch"
rebuild
winrun grade --timeout 30
expect "raylab grade (crash)" 1 "$status" "$output" \
  "FAIL  lab2  generateRay: the centre and the four corners of the default camera" \
  "this check crashed (segmentation fault: a bad pointer or index?)" "lab 1: $(lab_points 1) / $(lab_points 1) points" \
  "lab 3: $(lab_points 3) / $(lab_points 3) points" "total: $((total - 7)) / $total" # lab 2's checks that crash: 7 points
no_agent_left "raylab grade (crash)"

step "passed"
