#!/usr/bin/env bash
# The READMEs' commands on bare Debian systems, as a newcomer types them (issue 32). For each release
# a bare root is unpacked (mmdebstrap --variant=minbase: apt and nothing else, no compiler, no sudo),
# a clean clone of the committed HEAD goes in, and there, in a chroot (/proc, /sys, /dev mounted;
# bubblewrap cannot start in a chroot, so the grader's fallback sandbox runs, as in Docker):
#   root-figures   as root, no sudo: README.md's figures command, in /root/raylab
#   root-tests     then README.md's test command there (the whole suite: each test passed or skipped)
#   root-students  as root: `raylab distribute /root/tp1`, then the two commands tp1/README.md writes
#                  (the student's pictures, then the framework's suite)
#   user-figures   in a fresh root, as a user with sudo (NOPASSWD): README.md's figures command
# Each must pass on its first run. The commands are read from the READMEs, so the check follows them.
#
#   scripts/bare_machine_check.sh [RELEASE...]    (as root; default: bookworm trixie)
#   RAYLAB_BARE_USER_RELEASES="bookworm"           the releases of user-figures (default: all)
#   RAYLAB_BARE_TESTS="trixie"                     the releases of root-tests (default: none; 1: all). The
#                                                  whole suite once more a release, about 15 minutes warm:
#                                                  CI runs it on Debian 13 only, within its 45 minutes
#   RAYLAB_BARE_DIR=/var/tmp/raylab-bare           where the bare tarballs, compiler caches and roots go
#   RAYLAB_DEBIAN_MIRROR=http://deb.debian.org/debian   else the first of this machine's apt sources
#
# Only the bare tarballs are cached (<release>-minbase.tar, remade when a week old), never an
# installed package: each run installs everything as a newcomer would. What each release compiles is
# cached (ccache-<release>/, bind-mounted into the root, shared by root's and the user's runs), so that
# a re-run of an unchanged tree compiles little. The suite's own bare Debian 12 (the Gradescope zip's
# test, tests/autograder) is a fixture, not what a newcomer installs: when this machine has made it,
# the root uses it rather than making it again. Needs: mmdebstrap, git, mount, chroot (setup.sh --tests).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
if [ "$#" -eq 0 ]; then set -- bookworm trixie; fi
releases=("$@")
read -r -a user_releases <<<"${RAYLAB_BARE_USER_RELEASES:-$*}"
tests_releases=${RAYLAB_BARE_TESTS:-}
if [ "$tests_releases" = 1 ]; then tests_releases="$*"; fi
dir=${RAYLAB_BARE_DIR:-/var/tmp/raylab-bare}
say() { printf '\n== bare_machine_check: %s\n' "$*"; }
die() { echo "bare_machine_check: $*" >&2; exit 1; }
for release in $tests_releases; do
  [[ " ${releases[*]} " == *" $release "* ]] || die "RAYLAB_BARE_TESTS names $release, which is not a release of this run (${releases[*]})"
done

[ "$(id -u)" -eq 0 ] || die "run as root (it makes chroots): sudo $0 $*"
command -v mmdebstrap >/dev/null || die "needs mmdebstrap: apt-get install -y mmdebstrap"
git -C "$top" rev-parse --verify -q HEAD >/dev/null || die "$top is not a git clone with a commit"

# The mirror: RAYLAB_DEBIAN_MIRROR, else the first URI of this machine's Debian sources.
mirror=${RAYLAB_DEBIAN_MIRROR:-}
if [ -z "$mirror" ]; then
  mirror=$(sed -n 's/^URIs:[[:space:]]*\([^[:space:]]*\/debian\)$/\1/p' /etc/apt/sources.list.d/*.sources 2>/dev/null | head -n 1)
  [ -n "$mirror" ] || mirror=$(sed -n 's/^deb[[:space:]]\+\(http[^[:space:]]*\/debian\)[[:space:]].*/\1/p' /etc/apt/sources.list 2>/dev/null | head -n 1)
  [ -n "$mirror" ] || mirror=http://deb.debian.org/debian
fi

# The commands, as the READMEs write them: the first line of a ```sh block that runs the workflow
# preset, its trailing comment removed.
readme_command() { # FILE PRESET
  awk -v want="--preset $2" '/^```/ { block = ($0 == "```sh"); next }
       block && index($0, want) { sub(/[[:space:]]+#.*$/, ""); print; exit }' "$1"
}
figures_command=$(readme_command "$top/README.md" figures)
[ -n "$figures_command" ] || die "README.md has no \`--preset figures\` command in a sh block"
tests_command=$(readme_command "$top/README.md" test)
[ -n "$tests_command" ] || die "README.md has no \`--preset test\` command in a sh block"

mkdir -p "$dir"
root=""                 # the root in use, for the trap
results=()              # "step seconds status", for the summary
unmount_root() {
  [ -n "$root" ] || return 0
  local m
  # The deepest first; a busy mount is detached (-l) rather than left behind.
  for m in $(awk -v r="$root/" 'index($2, r) == 1 { print $2 }' /proc/mounts | sort -r); do
    umount "$m" 2>/dev/null || umount -l "$m"
  done
}
trap 'unmount_root' EXIT
trap 'exit 130' INT TERM

# The bare tarball of a release: made once a week, in a .partial file renamed when whole.
bare_tarball() { # RELEASE
  local tarball=$dir/$1-minbase.tar
  if [ ! -s "$tarball" ] || [ -n "$(find "$tarball" -mtime +7)" ]; then
    say "$1: making the bare root (mmdebstrap --variant=minbase, from $mirror)" >&2
    local security=${mirror%/debian}/debian-security
    mmdebstrap --quiet --variant=minbase --format=tar "$1" "$tarball.partial" \
      "deb $mirror $1 main" "deb $mirror $1-updates main" "deb $security $1-security main"
    mv "$tarball.partial" "$tarball"
  fi
  echo "$tarball"
}

# A fresh root of RELEASE in $root, mounted, with the clone at CLONE (a path in the root).
fresh_root() { # RELEASE NAME CLONE
  unmount_root
  root=$dir/$2
  # A run that was stopped may have left this root mounted: unmounted first, and removed without
  # leaving its file system, so that /dev, bound into it, is never walked into.
  unmount_root
  rm -rf --one-file-system "$root" && mkdir -p "$root"
  tar -C "$root" -xf "$(bare_tarball "$1")"
  cp /etc/resolv.conf "$root/etc/resolv.conf" # apt-get needs names
  mount -t proc proc "$root/proc"
  mount -t sysfs sysfs "$root/sys"
  mount --rbind /dev "$root/dev" && mount --make-rslave "$root/dev"
  mkdir -p "$dir/ccache-$1" "$root/var/cache/raylab-ccache"
  mount --bind "$dir/ccache-$1" "$root/var/cache/raylab-ccache"
  local fixture=/var/tmp/raylab-debian12-minimal
  if [ -e "$fixture/.raylab-made" ]; then
    mkdir -p "$root$fixture" && mount --bind "$fixture" "$root$fixture"
  fi
  git clone -q --no-hardlinks "$top" "$root$3"
}

# in_root STEP USER COMMAND: runs COMMAND (bash) in the root as USER with a login's bare environment
# and the compiler cache; the log in $dir/logs/, its tail shown when it fails. Returns its status.
in_root() {
  local step=$1 user=$2 command=$3 home=/root log=$dir/logs/$1.log start=$SECONDS status=0
  [ "$user" = root ] || home=/home/$user
  mkdir -p "$dir/logs"
  say "$step: $command"
  local as=()
  [ "$user" = root ] || as=(setpriv "--reuid=$user" "--regid=$user" --init-groups)
  chroot "$root" /usr/bin/env -i HOME="$home" USER="$user" LOGNAME="$user" TERM=dumb \
    PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    CCACHE_DIR=/var/cache/raylab-ccache CCACHE_UMASK=000 RAYLAB_TREES_CCACHE_DIR=/var/cache/raylab-ccache \
    "${as[@]}" /bin/bash -c "cd ~ && $command" >"$log" 2>&1 || status=$?
  results+=("$step $((SECONDS - start)) $status")
  if [ "$status" -ne 0 ]; then
    echo "bare_machine_check: $step FAILED (status $status); the end of $log:" >&2
    tail -n 60 "$log" >&2
  else
    echo "passed in $((SECONDS - start)) s"
  fi
  return "$status"
}

failed=0
for release in "${releases[@]}"; do
  fresh_root "$release" "$release-root" /root/raylab
  in_root "$release-root-figures" root "cd raylab && $figures_command" || { failed=1; continue; }
  if [[ " $tests_releases " == *" $release "* ]]; then
    in_root "$release-root-tests" root "cd raylab && $tests_command" || failed=1
  fi
  # The students' tree compiles through ccache too: what its README's command configures finds the
  # launcher in the environment (setup.sh has installed ccache by then).
  in_root "$release-root-distribute" root "raylab/build/bin/raylab distribute /root/tp1" || { failed=1; continue; }
  # Its README's first command (the student's pictures), then its second (the framework's suite).
  for preset in figures test; do
    students_command=$(readme_command "$root/root/tp1/README.md" $preset)
    [ -n "$students_command" ] || { echo "bare_machine_check: tp1/README.md has no \`--preset $preset\` command" >&2; failed=1; break; }
    in_root "$release-root-students-$preset" root "cd tp1 && export CMAKE_CXX_COMPILER_LAUNCHER=ccache CCACHE_BASEDIR=/root/tp1 \
      CCACHE_NOHASHDIR=1 && $students_command" || { failed=1; break; }
  done
done
for release in "${user_releases[@]}"; do
  # A fresh root, with sudo and a user allowed it (as a lab machine's); the release's compiler cache,
  # which every user may write (CCACHE_UMASK above).
  fresh_root "$release" "$release-user" /home/student/raylab
  chroot "$root" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin DEBIAN_FRONTEND=noninteractive /bin/bash -c \
    'apt-get update -qq && apt-get install -y -qq sudo >/dev/null && useradd --no-create-home --shell /bin/bash student &&
     echo "student ALL=(ALL) NOPASSWD: ALL" >/etc/sudoers.d/student && chown -R student: /home/student'
  chmod -R a+rwX "$dir/ccache-$release"
  in_root "$release-user-figures" student "cd raylab && $figures_command" || failed=1
done
unmount_root

say "summary (seconds; the logs in $dir/logs/)"
printf '%s\n' "${results[@]}" | awk '{ printf "%-28s %6s s  %s\n", $1, $2, ($3 == 0 ? "passed" : "FAILED, status " $3) }'
if [ "$failed" -ne 0 ]; then die "a READMEs' command failed on a bare system (above)"; fi
# The roots are large (the builds): only a failing one is kept, to look into.
for release in "${releases[@]}"; do rm -rf --one-file-system "$dir/$release-root"; done
for release in "${user_releases[@]}"; do rm -rf --one-file-system "$dir/$release-user"; done
say "every README command passed on bare ${releases[*]} roots"
