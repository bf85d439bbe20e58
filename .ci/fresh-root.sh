#!/bin/bash
# README command 1 (or 2 with -test) on a fresh Debian 12 root: debootstrap --variant=minbase
# bookworm into DIR, clone this repository's HEAD into it and run the command in a chroot with
# /proc and /dev bound. Catches install steps that a machine with things already installed hides.
# Not part of .ci/run (it takes 20-40 minutes). Run as root:
#   .ci/fresh-root.sh [-test] [DIR]        (default DIR /work/freshroot; it is deleted first)
set -u
cmd='./Allwmake && tutorials/fluidizedBedMuller/Allrun -mode demo'
[ "${1:-}" = "-test" ] && { cmd='./Allwmake && tests/Alltest'; shift; }
R="${1:-/work/freshroot}"
repo="$(cd "$(dirname "$0")/.." && pwd)"
command -v debootstrap > /dev/null || apt-get install -y --no-install-recommends debootstrap || exit 1
umount -l "$R/proc" "$R/dev" 2>/dev/null
rm -rf "$R"
t0=$(date +%s)
# the archive this machine's apt uses for bookworm main (a mirror or snapshot stays in use)
archive="$(apt-get indextargets --format '$(SITE)' 'Created-By: Packages' 'Codename: bookworm' 'Component: main' 2>/dev/null | head -n1)"
[ -n "$archive" ] || { echo "fresh-root: apt on this machine has no 'deb' entry for bookworm main: no archive to" \
                            "bootstrap from (add one to /etc/apt/sources.list and run apt-get update)"; exit 1; }
echo "fresh-root: archive $archive"
debootstrap --variant=minbase bookworm "$R" "$archive" > "$R.debootstrap.log" 2>&1 ||
    { echo "fresh-root: debootstrap failed ($R.debootstrap.log)"; exit 1; }
echo "fresh-root: debootstrap $(( $(date +%s) - t0 )) s"
mount --bind /proc "$R/proc" && mount --bind /dev "$R/dev" || exit 1
trap 'umount -l "$R/proc" "$R/dev"' EXIT
cp /etc/resolv.conf "$R/etc/"
git clone -q "$repo" "$R/root/coarse-dem" || exit 1
echo "fresh-root: $(git -C "$R/root/coarse-dem" log --oneline -1 | cut -c1-60)"
t1=$(date +%s)
chroot "$R" /bin/bash -c "cd /root/coarse-dem && $cmd"
rc=$?
echo "fresh-root: '$cmd' exit $rc, $(( $(date +%s) - t1 )) s"
exit $rc
