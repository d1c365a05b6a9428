#!/usr/bin/env bash
# Measures the speed targets of docs/performance.md ("Targets"), each in a fresh clone of this
# repository's HEAD, without ccache (CCACHE_DISABLE=1), and prints for each its wall time, its CPU
# time (user + system, of every process it started) and the machine's load before and after: the
# machine may be shared, and CPU time is what the load inflates least.
#
# Usage: scripts/measure_performance.sh [figures] [test] [class] [bench] [clang]   (none: all)
#   figures  fresh clone, `cmake --workflow --preset figures`               (target: 3 min, 6 CPU-min)
#   test     fresh clone, `cmake --workflow --preset test`                  (target: 8 min)
#   class    `raylab grade-class` of 30 students: copies of solutions/, every sixth with a mistake of
#            framework/grader/labs/*/mistakes/, one whose lab 3 does not compile             (target: 3 min, 4 s a student)
#   bench    `raylab bench --impl reference --threads 1`                    (target: ratios <= 1.15)
#   clang    the same bench built with clang++: raylab's ns/ray, Clang over GCC (target: <= 1.10)
# RAYLAB_MEASURE_DIR (default /var/tmp/raylab-measure) holds the clones, builds and logs; emptied first.
# Not a test: times depend on the machine.
set -euo pipefail
source_repo="$(cd "$(dirname "$0")/.." && pwd)"
work="${RAYLAB_MEASURE_DIR:-/var/tmp/raylab-measure}"
export CCACHE_DISABLE=1
unset CMAKE_CXX_COMPILER_LAUNCHER
steps=("$@")
((${#steps[@]})) || steps=(figures test class bench clang)

load() { cut -d' ' -f1-3 /proc/loadavg; }

# timed NAME COMMAND...: runs it, its output in $work/NAME.log; one line of wall, CPU and load.
timed() {
  local name=$1 before
  shift
  before=$(load)
  if ! /usr/bin/time -f "%e %U %S" -o "$work/$name.time" "$@" >"$work/$name.log" 2>&1; then
    echo "$name: failed, see $work/$name.log" >&2
    return 1
  fi
  read -r wall user system <"$work/$name.time"
  printf '%-28s %8.1f s wall %8.1f s CPU   load %s -> %s\n' "$name" "$wall" "$(echo "$user + $system" | bc)" "$before" "$(load)"
}

fresh_clone() { # fresh_clone DIR
  rm -rf "$1"
  git clone -q --no-hardlinks "$source_repo" "$1"
}

# A Release build of raylab and raylab-reference in $work/clone (for class, bench and clang), once.
tool_build() {
  [ -x "$work/clone/build/bin/raylab-reference" ] && return
  fresh_clone "$work/clone"
  timed "build (raylab, reference)" bash -c "cd '$work/clone' && cmake --preset default >/dev/null && cmake --build build -j2 --target raylab raylab-reference"
}

make_class() { # make_class DEST N
  local dest=$1 n=$2 i k s
  rm -rf "$dest" && mkdir -p "$dest"
  local mistakes=("$source_repo"/framework/grader/labs/*/mistakes/*.patch)
  mistakes=("${mistakes[@]:0:4}")
  for i in $(seq -w 1 "$n"); do
    s="$dest/student$i"
    cp -R "$source_repo/solutions" "$s"
    k=$((10#$i))
    if ((k % 6 == 0)); then patch -s --batch -p1 -d "$s" -i "${mistakes[$(((k / 6 - 1) % ${#mistakes[@]}))]}"; fi
    if ((k == 7)); then echo "not C++" >>"$s/lab3_sphere/sphere_geometry.cpp"; fi
  done
}

rm -rf "$work" && mkdir -p "$work"
echo "raylab $(git -C "$source_repo" rev-parse --short HEAD), $(nproc) cores, $(c++ --version | head -1)"
for step in "${steps[@]}"; do
  case "$step" in
  figures)
    fresh_clone "$work/figures"
    timed "figures workflow" bash -c "cd '$work/figures' && cmake --workflow --preset figures"
    ;;
  test)
    fresh_clone "$work/test"
    timed "test workflow" bash -c "cd '$work/test' && cmake --workflow --preset test"
    ;;
  class)
    tool_build
    make_class "$work/class" 30
    timed "grade-class, 30 students" "$work/clone/build/bin/raylab" grade-class "$work/class" --out "$work/class-out"
    # The first student's result follows the framework's build; the others', one student each.
    mapfile -t done_at < <(stat -c %Y "$work"/class-out/students/*/result.json | sort -n)
    echo "  framework built once: $(($(stat -c %Y "$work/class-out/build/grading-kit.log") - $(stat -c %Y "$work/class-out/grade-class.lock"))) s;" \
      "then $(echo "scale=1; (${done_at[-1]} - ${done_at[0]}) / (${#done_at[@]} - 1)" | bc) s a student after the first" \
      "($(( ${#done_at[@]} )) graded; grades in $work/class-out/grades.csv)"
    ;;
  bench)
    tool_build
    "$work/clone/build/bin/raylab" bench --impl reference --threads 1 --repeats 9 | tee "$work/bench-gcc.txt"
    ;;
  clang)
    tool_build
    command -v clang++ >/dev/null || { echo "clang: no clang++ (apt-get install clang)"; continue; }
    timed "build with clang++" bash -c "cd '$work/clone' && CXX=clang++ cmake -S . -B build-clang -DCMAKE_BUILD_TYPE=Release && cmake --build build-clang -j2 --target raylab-reference"
    # In turn, so that both see the same load: raylab's ns per ray at each sample count, 1 thread.
    for k in 1 2 3; do
      for compiler in gcc clang; do
        dir=build; [ $compiler = clang ] && dir=build-clang
        "$work/clone/$dir/bin/raylab-reference" bench --threads 1 --repeats 5 >"$work/bench-$compiler-$k.txt"
      done
    done
    for compiler in gcc clang; do
      awk -v c=$compiler '$1 ~ /^[0-9]+$/ && $2 == "|" {print c, $1, $4}' "$work"/bench-$compiler-*.txt
    done | awk '{ns[$1" "$2] += $3; n[$1" "$2]++} END {for (s in ns) if (s ~ /^gcc/) {split(s, p, " ");
           g = ns[s] / n[s]; c = ns["clang " p[2]] / n["clang " p[2]];
           printf "  %3d spp: gcc %.2f ns/ray, clang %.2f ns/ray, clang / gcc %.3f\n", p[2], g, c, c / g}}' | sort -n -k1
    ;;
  *)
    echo "unknown step $step (figures, test, class, bench, clang)" >&2
    exit 2
    ;;
  esac
done
