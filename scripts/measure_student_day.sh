#!/usr/bin/env bash
# Measures what a student waits for, in a students' tree (`raylab distribute`), in French, as they
# type it: each step's wall and CPU time (user + system, of every process it started) and the machine's
# load before and after. Issue 41's targets, on 2 cores with the packages installed:
#   first command   the tree's README first command (setup.sh, configure, build raylab, draw)  3 min
#   first picture   then lab 1 written, `raylab lab 1` (its picture)                          (in it)
#   grade --lab N   an edit to lab N's file, then `raylab grade --lab N`                      10 s
#   page            an edit to lab N's file, until `raylab watch N` says the page is refreshed  3 s
#   semicolon       a `;` left out in the last lab, then `raylab grade`: every other lab graded 2 min
#
# Usage: scripts/measure_student_day.sh [RAYLAB]   (RAYLAB: the repository's built raylab, which writes
#        the tree; default build/bin/raylab)
# RAYLAB_MEASURE_DIR (default /var/tmp/raylab-student-day) holds the tree and the logs; emptied first.
# The compiler cache is off (CCACHE_DISABLE=1): a student's first build compiles everything.
# Not a test: times depend on the machine.
set -euo pipefail
top="$(cd "$(dirname "$0")/.." && pwd)"
raylab="${1:-$top/build/bin/raylab}"
work="${RAYLAB_MEASURE_DIR:-/var/tmp/raylab-student-day}"
[ -x "$raylab" ] || { echo "measure_student_day: no $raylab: build raylab first" >&2; exit 2; }
export CCACHE_DISABLE=1
unset CMAKE_CXX_COMPILER_LAUNCHER
# French, where the machine has the locale (`locale -a`); English otherwise, said.
if locale -a 2>/dev/null | grep -qi '^fr_FR\.utf-\?8$'; then
  export LANG=fr_FR.UTF-8
  unset LC_ALL
  export LC_NUMERIC=C # this script's own figures: 1.5, not 1,5
else
  echo "measure_student_day: no fr_FR.UTF-8 locale here (locale-gen): measured in English" >&2
fi

load() { cut -d' ' -f1-3 /proc/loadavg; }

# timed NAME COMMAND...: runs it in the tree, its output in $work/NAME.log; one line of wall, CPU and
# load. A command's exit status is printed, not fatal: `raylab grade` exits 1 when a check fails.
timed() {
  local name=$1 before status=0
  shift
  before=$(load)
  (cd "$work/tp1" && /usr/bin/time -f "%e %U %S" -o "$work/$name.time" "$@") >"$work/$name.log" 2>&1 || status=$?
  read -r wall user system < <(tail -n 1 "$work/$name.time") # after "Command exited with non-zero status N"
  printf '%-34s %8.1f s wall %8.1f s CPU  exit %d  load %s -> %s\n' "$name" "$wall" "$(echo "$user + $system" | bc)" \
    "$status" "$before" "$(load)"
}

# A change to a lab file that the compiler sees (a comment alone could be found in a cache).
edit() { # edit FILE TAG
  printf '\nnamespace { [[maybe_unused]] const int raylab_edit_%s = %s; }\n' "$2" "$RANDOM" >>"$1"
}

rm -rf "$work" && mkdir -p "$work"
"$raylab" distribute "$work/tp1" >"$work/distribute.log"
tp1="$work/tp1"
labs=()
for folder in "$tp1"/labs/lab*_*/; do labs+=("$(basename "$folder")"); done
IFS=$'\n' read -r -d '' -a labs < <(printf '%s\n' "${labs[@]}" | sort -V && printf '\0')
first=${labs[0]}
graded=${labs[$(( ${#labs[@]} > 2 ? 2 : 0 ))]} # the third lab: it uses others
last=${labs[${#labs[@]}-1]}
number() { echo "$1" | sed 's/^lab\([0-9]*\)_.*/\1/'; }
first_file() { ls "$tp1/labs/$1"/*.cpp | head -n 1; }
command=$(awk '/^```/ { block = ($0 == "```sh"); next } block && index($0, "--preset figures") { print; exit }' "$tp1/README.md")
echo "measure_student_day: $tp1 (labs ${labs[*]}), $(nproc) cores, LANG=${LANG:-}"
echo "  first command: $command"

timed "first command" bash -c "$command"
cp "$top/solutions/$first"/*.cpp "$tp1/labs/$first/"
timed "first picture (lab $(number "$first"))" build/bin/raylab lab "$(number "$first")"
ls "$tp1/out/student/" | grep -q "^lab$(number "$first")_" || echo "  no picture of lab $(number "$first") in out/student/" >&2

# Every lab written (the reference's files stand for the student's), graded once: the programs built.
for lab in "${labs[@]}"; do cp "$top/solutions/$lab"/*.cpp "$tp1/labs/$lab/"; done
timed "grade (every lab, first)" build/bin/raylab grade
n=$(number "$graded")
edit "$(first_file "$graded")" 1
timed "edit, grade --lab $n" build/bin/raylab grade --lab "$n"
edit "$(first_file "$graded")" 2
timed "edit, grade --lab $n (again)" build/bin/raylab grade --lab "$n"

# The live page: the time from a save to the console's "refreshed" line that follows it.
(cd "$tp1" && exec build/bin/raylab watch "$n" --no-open) >"$work/watch.log" 2>&1 &
watcher=$!
trap 'kill $watcher 2>/dev/null || true' EXIT
refreshed() { grep -c -E 'page refreshed|page à jour' "$work/watch.log" || true; }
for _ in $(seq 1 600); do [ "$(refreshed)" -ge 1 ] && break; sleep 0.1; done
for k in 1 2 3; do
  before=$(refreshed)
  start=$(date +%s.%N)
  edit "$(first_file "$graded")" "page$k"
  for _ in $(seq 1 1200); do [ "$(refreshed)" -gt "$before" ] && break; sleep 0.05; done
  printf '%-34s %8.1f s wall\n' "save -> page refreshed ($k)" "$(echo "$(date +%s.%N) - $start" | bc)"
done
kill "$watcher" 2>/dev/null || true
wait "$watcher" 2>/dev/null || true

# A `;` left out in the last lab: that lab lost, the others graded.
file=$(first_file "$last")
printf '\nint raylab_missing_semicolon = 1\n' >>"$file"
timed "missing ; in lab $(number "$last"), grade" build/bin/raylab grade
grep -E '^ *(TP|lab) ' "$work/missing ; in lab $(number "$last"), grade.log" | tail -n 12 || true
timed "missing ; in lab $(number "$last"), lab $(number "$first")" build/bin/raylab lab "$(number "$first")"
