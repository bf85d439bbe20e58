#!/bin/bash
# Build LIGGGHTS 3.8.0 with the project's patches and fix couple/coarse, as a shared library and
# the `liggghts` executable, and install them into the project (platforms/liggghts by default).
#
# Called by ../Allwmake; can be run alone (after Allwmake installed the packages):
#   liggghts-fix/build.sh [-j N] [-f]        (-f: ignore the build key, rebuild/reinstall)
#
# Environment:
#   COARSEDEM_CACHE   cache directory (default /var/cache/coarsedem): holds the Debian source
#                     tarball, the patched source tree and the CMake build directory
#   LIGGGHTS_SRC_DIR  use this LIGGGHTS source tree (top directory or its src/) instead of
#                     Debian's orig tarball; it is copied, never modified
#   LIGGGHTS_PREFIX   install prefix (default <project>/platforms/liggghts)
#
# Why it is built like this:
# - LIGGGHTS styles are compiled in (the style map is private), so a new fix means building
#   LIGGGHTS. That takes ~10 min on 2 cores, hence the cache.
# - The patched source tree and the build directory persist in the cache, keyed by the source
#   (tarball sha256 + patches). The fix sources are copied in only when their content changed,
#   so a changed fix recompiles one file and relinks (seconds), not the whole of LIGGGHTS.
# - A build key (hash of every input: source key, fix sources, src/core/coarse_dem.h if they include it, this
#   script, CMakeLists.txt) is stored next to the installed files; with an unchanged key the
#   script does nothing.
set -euo pipefail
trap 'echo "liggghts-fix/build.sh: ERROR: command failed at line $LINENO: $BASH_COMMAND" >&2' ERR

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
project="$(cd "$here/.." && pwd)"
cache="${COARSEDEM_CACHE:-/var/cache/coarsedem}"
prefix="${LIGGGHTS_PREFIX:-$project/platforms/liggghts}"
jobs="$(nproc 2>/dev/null || echo 2)"
force=0

while [ $# -gt 0 ]; do
    case "$1" in
        -j) jobs="$2"; shift 2 ;;
        -j*) jobs="${1#-j}"; shift ;;
        -f) force=1; shift ;;
        -h|-help|--help) sed -n '2,14p' "$0"; exit 0 ;;
        *) echo "liggghts-fix/build.sh: unknown option '$1'" >&2; exit 2 ;;
    esac
done

die() { echo "liggghts-fix/build.sh: ERROR: $*" >&2; exit 1; }
say() { echo "liggghts-fix/build.sh: $*"; }

hash_files() { # sha256 over the names and contents of the given files (order matters)
    local f
    for f in "$@"; do echo "== ${f##*/}"; cat "$f"; done | sha256sum | cut -c1-64
}

patches=( "$here"/patches/*.patch )
[ -e "${patches[0]}" ] || patches=()
fix_sources=( "$here/fix_couple_coarse.h" "$here/fix_couple_coarse.cpp" )
for f in "${fix_sources[@]}"; do [ -f "$f" ] || die "missing fix source $f"; done
core_header="$project/src/core/coarse_dem.h"

# ------------------------------------------------------------------ 1. the pristine source
mkdir -p "$cache/debsrc" "$cache/liggghts"
if [ -n "${LIGGGHTS_SRC_DIR:-}" ]; then
    src_top="$LIGGGHTS_SRC_DIR"
    [ -f "$src_top/src/lammps.cpp" ] || { [ -f "$src_top/lammps.cpp" ] && src_top="$src_top/.."; }
    [ -f "$src_top/src/lammps.cpp" ] || die "LIGGGHTS_SRC_DIR=$LIGGGHTS_SRC_DIR is not a LIGGGHTS tree (no src/lammps.cpp)"
    src_top="$(cd "$src_top" && pwd)"
    # key the copy by the tree's content (a few MB: hashing takes about a second)
    source_id="dir:$(cd "$src_top" && find src -maxdepth 1 -type f \( -name '*.cpp' -o -name '*.h' -o -name '*.sh' -o -name '*.txt' \) | LC_ALL=C sort | xargs sha256sum | sha256sum | cut -c1-64)"
else
    tarball="$(ls "$cache"/debsrc/liggghts_*.orig.tar.* 2>/dev/null | head -n1 || true)"
    if [ -z "$tarball" ]; then
        say "fetching Debian's liggghts source package into $cache/debsrc"
        say "(a '404 Not Found' for liggghts_*.debian.tar.xz is expected: only the orig tarball is used)"
        # The Debian patch tarball of liggghts 3.8.0+repack1-9 is missing on the mirror, so
        # apt-get source fails after fetching the orig tarball: judge by the tarball instead. apt's
        # messages keep their text; the archive's address is the machine's, not the build's: left out.
        (cd "$cache/debsrc" && apt-get -qq source --download-only liggghts 2>&1 | sed -E 's#[a-z]+://[^ ]+#<archive URL>#g') || true
        tarball="$(ls "$cache"/debsrc/liggghts_*.orig.tar.* 2>/dev/null | head -n1 || true)"
        [ -n "$tarball" ] || die "could not download the liggghts source package. Check that a
    deb-src line for bookworm main is enabled (Allwmake adds /etc/apt/sources.list.d/coarsedem-src.sources),
    run 'apt-get update', then 'cd $cache/debsrc && apt-get source --download-only liggghts'."
    fi
    # check the tarball against the checksum of the .dsc when there is one
    dsc="$(ls "$cache"/debsrc/liggghts_*.dsc 2>/dev/null | head -n1 || true)"
    sum="$(sha256sum "$tarball" | cut -c1-64)"
    if [ -n "$dsc" ] && ! grep -q "$sum" "$dsc"; then
        die "$tarball does not match the sha256 in $dsc: delete both and run again"
    fi
    source_id="tar:$sum"
fi

srckey="$( { echo "$source_id"; hash_files "$here/CMakeLists.txt" ${patches[@]+"${patches[@]}"}; } | sha256sum | cut -c1-16)"
work="$cache/liggghts/$srckey"

# ------------------------------------------------------------------ 2. unpack + patch (once per source key)
if [ ! -f "$work/.patched" ]; then
    say "preparing patched source tree $work"
    rm -rf "$work" "$work.tmp"
    mkdir -p "$work.tmp"
    if [ -n "${LIGGGHTS_SRC_DIR:-}" ]; then
        cp -a "$src_top/src" "$work.tmp/src"
        [ -f "$src_top/LICENSE" ] && cp -a "$src_top/LICENSE" "$work.tmp/" || true
    else
        tar -C "$work.tmp" --no-same-owner --strip-components=1 -xf "$tarball"
    fi
    for p in ${patches[@]+"${patches[@]}"}; do
        if (cd "$work.tmp" && patch -p1 -R -s -f --dry-run < "$p" >/dev/null 2>&1); then
            say "patch ${p##*/}: already applied in the given tree, skipped"
        elif (cd "$work.tmp" && patch -p1 -s -f --dry-run < "$p" >/dev/null 2>&1); then
            (cd "$work.tmp" && patch -p1 -s -f < "$p")
            say "applied ${p##*/}"
        else
            echo "---- patch output:" >&2
            (cd "$work.tmp" && patch -p1 -f --dry-run < "$p" >&2) || true
            die "patch ${p##*/} does not apply to the LIGGGHTS source. Update the patch in
    liggghts-fix/patches/ for this source tree (or remove it if the tree already has the fix)."
        fi
    done
    touch "$work.tmp/.patched"
    mv "$work.tmp" "$work"
fi

# ------------------------------------------------------------------ 3. the build key
# the core's header counts only if the fix includes it (it does not today: a change of the core's
# header would otherwise rebuild LIGGGHTS, ten minutes, for nothing)
uses_core_header() { grep -q '#include *"coarse_dem.h"' "${fix_sources[@]}"; }
buildkey="$( { echo "$srckey"; hash_files "$here/build.sh" "${fix_sources[@]}";
               if [ -f "$core_header" ] && uses_core_header; then hash_files "$core_header"; fi; } |
            sha256sum | cut -c1-16)"
if [ "$force" = 0 ] && [ -f "$prefix/.build-key" ] && [ "$(cat "$prefix/.build-key")" = "$buildkey" ] \
   && [ -x "$prefix/bin/liggghts" ] && [ -f "$prefix/lib/libliggghts.so" ]; then
    say "up to date (key $buildkey): $prefix"
    exit 0
fi

# ------------------------------------------------------------------ 4. fix sources into the tree
# Copy only what changed, so make's timestamps recompile only the changed file.
new_header=0
for f in "${fix_sources[@]}"; do
    dst="$work/src/${f##*/}"
    if ! cmp -s "$f" "$dst"; then
        cp "$f" "$dst"
        say "updated ${f##*/} in the LIGGGHTS tree"
        case "$f" in *.h) new_header=1 ;; esac
    fi
done
# style_*.h list every style header; regenerate them when a fix header changed or never made.
# (Make.sh also rewrites version_liggghts.h with the date, hence not every time.)
if [ "$new_header" = 1 ] || [ ! -f "$work/src/style_fix.h" ]; then
    say "generating style headers (Make.sh style, Make.sh models)"
    (cd "$work/src" && sh Make.sh style >/dev/null && sh Make.sh models >/dev/null)
fi
grep -q 'fix_couple_coarse.h' "$work/src/style_fix.h" || die "style_fix.h does not list fix_couple_coarse.h"

# ------------------------------------------------------------------ 5. configure, build, install
build="$work/build"
if [ ! -f "$build/CMakeCache.txt" ]; then
    say "configuring (cmake) in $build"
    cmake -S "$here" -B "$build" -DLIGGGHTS_SRC="$work/src" \
          -DCOARSEDEM_CORE_INCLUDE="$project/src/core" \
          -DCMAKE_INSTALL_PREFIX="$work/install" -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
# point the include of the core at this project (the cache may be shared by several clones)
cmake "$build" -DCOARSEDEM_CORE_INCLUDE="$project/src/core" >/dev/null
say "building with $jobs jobs (a full build takes about 10 minutes on 2 cores)"
cmake --build "$build" -j "$jobs"
cmake --install "$build" >/dev/null

rm -rf "$prefix.tmp"
mkdir -p "$prefix.tmp"
cp -a "$work/install/." "$prefix.tmp/"
echo "$buildkey" > "$prefix.tmp/.build-key"
rm -rf "$prefix"
mv "$prefix.tmp" "$prefix"

# ------------------------------------------------------------------ 6. check
# (output captured first: grep -q would stop reading early and pipefail would see SIGPIPE)
help="$(cd /tmp && "$prefix/bin/liggghts" -log none -h 2>&1 || true)"
if ! grep -q 'couple/coarse' <<< "$help"; then
    rm -f "$prefix/.build-key"
    die "the built liggghts does not list fix couple/coarse in 'liggghts -h'"
fi
say "installed LIGGGHTS into $prefix (key $buildkey); fix couple/coarse is available"
