#!/usr/bin/env bash
# Measures what three hostile students cost a class run (issue 34, docs/grading.md "A hostile class,
# measured"): `raylab grade-class` of N students, copies of solutions/, once without and once with
# three more that break the rules:
#   a staller  tests/instructors/bad_submissions/stops_itself.patch  lab 1 raises SIGSTOP (held until lab 1's time budget)
#   a forker   tests/instructors/bad_submissions/forks.patch         lab 3 forks 100,000 sleeping children a call
#   a flood    tests/instructors/bad_builds/huge_error.patch         lab 2's compile error is about 1 GB
# and prints each run's wall and CPU time, the disk its results take (out/ without the class's build
# folder) and its largest file, the hostile students' rows of grades.csv, and whether every other
# student got full points.
#
# Usage: scripts/measure_hostile_class.sh [N]        (N honest students, default 27: a class of 30 with the three)
#   RAYLAB              the raylab to run (default: build/bin/raylab of this tree, built with its grader)
#   RAYLAB_SANDBOX      passed on: `fallback` measures the fallback sandbox, else bubblewrap where it runs
#   RAYLAB_MEASURE_DIR  where the classes, results and builds go (default /var/tmp/raylab-hostile-class; emptied first)
# As root, each run's results go to a tmpfs of 300 MB (the disk of issue 34's report), so a result
# that would fill it shows as "disk full"; the class's build folder stays beside it. Not a test:
# times depend on the machine (tests/grading/grade_hostile_class.cpp is the test).
set -euo pipefail
source_repo="$(cd "$(dirname "$0")/.." && pwd)"
raylab="${RAYLAB:-$source_repo/build/bin/raylab}"
work="${RAYLAB_MEASURE_DIR:-/var/tmp/raylab-hostile-class}"
honest="${1:-27}"
[ -x "$raylab" ] || { echo "no $raylab: build it first (cmake --build build --target raylab raylab-agents)" >&2; exit 2; }
hostile=(
  "staller:$source_repo/tests/instructors/bad_submissions/stops_itself.patch"
  "forker:$source_repo/tests/instructors/bad_submissions/forks.patch"
  "flood:$source_repo/tests/instructors/bad_builds/huge_error.patch"
)

load() { cut -d' ' -f1-3 /proc/loadavg; }

# make_class DEST WITH_HOSTILE: the honest students (student01 ...), and the three when asked.
make_class() {
  local dest=$1 i entry
  mkdir -p "$dest"
  for i in $(seq -w 1 "$honest"); do cp -R "$source_repo/solutions" "$dest/student$i"; done
  [ "$2" = yes ] || return 0
  for entry in "${hostile[@]}"; do
    cp -R "$source_repo/solutions" "$dest/${entry%%:*}"
    patch -s --batch -p1 -d "$dest/${entry%%:*}" -i "${entry#*:}"
  done
}

# grade NAME CLASS: one run, its results in $work/NAME-out (a 300 MB tmpfs as root, copied to
# $work/NAME-results when it ends), the class's build in $work/build, shared by the runs (the framework
# is built once: each run then compiles its own students' files).
grade() {
  local name=$1 class=$2 out="$work/$1-out" before kit
  mkdir -p "$out"
  if [ "$(id -u)" = 0 ] && mount -t tmpfs -o size=300m tmpfs "$out" 2>/dev/null; then mounted=$out; fi
  before=$(load)
  /usr/bin/time -f "%e %U %S" -o "$work/$name.time" "$raylab" grade-class "$class" --out "$out" \
    --build-dir "$work/build" >"$work/$name.log" 2>&1 || echo "  ($name: grade-class exited with $?, see $work/$name.log)"
  read -r wall user system <"$work/$name.time"
  printf '%-8s %7.1f s wall %7.1f s CPU   load %s -> %s\n' "$name" "$wall" "$(echo "$user + $system" | bc)" "$before" "$(load)"
  printf '%-8s %7d KB of results, largest file %s; build folder %s\n' "" "$(du -sk "$out" | cut -f1)" \
    "$(find "$out" -type f -printf '%P (%s bytes)\n' | sort -t'(' -k2 -n | tail -1)" "$(du -sh "$work/build" | cut -f1)"
  cp -a "$out" "$work/$name-results"
  if [ -n "$mounted" ]; then umount "$out" && mounted=""; fi
  out="$work/$name-results"
  # Each student's time: from the previous result (the first: the framework's build) to theirs.
  kit=$(stat -c %.3Y "$work/build/grading-kit.log")
  stat -c '%.3Y %n' "$out"/students/*/result.json | sort -n |
    awk -v last="$kit" '{ n = split($2, p, "/"); printf "%s %.1f\n", p[n - 1], $1 - last; last = $1 }' >"$work/$name.seconds"
  awk '{ sum += $2 } END { print sum }' "$work/$name.seconds" >"$work/$name.students"
  printf '         students: %.0f s in all; an honest one %s%s\n' "$(cat "$work/$name.students")" \
    "$(awk '$1 ~ /^student/ { print $2 }' "$work/$name.seconds" | sort -n |
       awk '{ s[NR] = $1 } END { printf "%.1f s (median; %.1f to %.1f)", s[int((NR + 1) / 2)], s[1], s[NR] }')" \
    "$(awk '$1 !~ /^student/ { printf "; %s %.1f s", $1, $2 }' "$work/$name.seconds")"
  # Honest students: total == max on their row (their names hold no comma or quote).
  awk -F, 'NR == 1 { for (k = 1; k <= NF; k++) { if ($k == "total") t = k; if ($k == "max") m = k } next }
       $1 ~ /^student/ { n++; if ($t == $m) full++; else print "  NOT FULL: " $0 }
       END { printf "         %d of %d honest students with full points\n", full, n }' "$out/grades.csv"
  grep -E '^(staller|forker|flood),' "$out/grades.csv" | cut -c1-400 | sed 's/^/  /' || true
}

mounted=""
trap '[ -z "$mounted" ] || umount "$mounted"' EXIT
for old in "$work"/*-out; do mountpoint -q "$old" 2>/dev/null && umount "$old"; done
rm -rf "$work" && mkdir -p "$work"
echo "raylab $(git -C "$source_repo" rev-parse --short HEAD), $(nproc) cores, sandbox: ${RAYLAB_SANDBOX:-best available}," \
  "$honest honest students"
make_class "$work/class-without" no
make_class "$work/class-with" yes
grade without "$work/class-without"
grade with "$work/class-with"
echo "the three cost $(echo "$(cat "$work/with.students") - $(cat "$work/without.students")" | bc) s of the students' part"
