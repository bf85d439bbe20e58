#!/bin/bash
# Give the project an OpenFOAM v1912 build environment on top of Debian's binary packages.
#
# Debian's openfoam/libopenfoam ship the libraries (/usr/lib) and solvers (/usr/bin) but no
# headers and no wmake. Debian's *source* package holds the whole v1912 tree. This script:
#   1. downloads it (apt-get source --download-only openfoam=<installed version>) into the cache;
#   2. unpacks only what compiling needs (wmake/, src/, META-INFO/ and pimpleFoam for a check)
#      into  $COARSEDEM_CACHE/openfoam/<Debian version>/ ;
#   3. builds the wmake tools (wmake/src/Allmake: wmkdepend, lemon; seconds);
#   4. makes the lnInclude directories of the libraries the project compiles against;
#   5. checks that the headers match Debian's libraries: compiles a copy of pimpleFoam
#      against them, links it with Debian's libraries and runs it with -help.
# The tree is keyed by the installed Debian package version, so an upgraded libopenfoam gets a
# fresh tree; an existing complete tree is reused (the stamp .coarsedem-ready).
#
# Usage: wmake/foamSource.sh [-f]   (-f: remake the tree even if it is complete)
#
# Environment:
#   COARSEDEM_CACHE  cache directory (default /var/cache/coarsedem)
#   FOAM_SRC_DIR     use this existing OpenFOAM v1912 source tree instead (must have wmake/ and
#                    src/); wmake tools and lnInclude directories are made inside it
#
# Output: the path of the tree is written to <project>/platforms/foam-src-dir, where
# etc/wmakeEnv reads it.
set -euo pipefail
trap 'echo "wmake/foamSource.sh: ERROR: command failed at line $LINENO: $BASH_COMMAND" >&2' ERR

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
project="$(cd "$here/.." && pwd)"
cache="${COARSEDEM_CACHE:-/var/cache/coarsedem}"
force=0
[ "${1:-}" = "-f" ] && force=1

die() { echo "wmake/foamSource.sh: ERROR: $*" >&2; exit 1; }
say() { echo "wmake/foamSource.sh: $*"; }

# Libraries whose headers the project (and the pimpleFoam check) include. Add a library here
# if a new Make/options needs -I$(LIB_SRC)/<lib>/lnInclude.
lninclude_libs="
    OpenFOAM OSspecific/POSIX Pstream/mpi
    finiteVolume meshTools fileFormats surfMesh sampling fvOptions
    dynamicMesh dynamicFvMesh topoChangerFvMesh
    TurbulenceModels/turbulenceModels TurbulenceModels/incompressible
    transportModels/incompressible transportModels/twoPhaseMixture
    functionObjects/field lagrangian/basic
"

# ------------------------------------------------------------------ where the tree is
if [ -n "${FOAM_SRC_DIR:-}" ]; then
    tree="$(cd "$FOAM_SRC_DIR" 2>/dev/null && pwd)" || die "FOAM_SRC_DIR=$FOAM_SRC_DIR does not exist"
    [ -d "$tree/wmake" ] && [ -d "$tree/src/OpenFOAM" ] \
        || die "FOAM_SRC_DIR=$FOAM_SRC_DIR has no wmake/ or src/OpenFOAM: not an OpenFOAM source tree"
    user_tree=1
else
    version="$(dpkg-query -W -f='${source:Version}' libopenfoam 2>/dev/null || true)"
    [ -n "$version" ] || die "Debian package libopenfoam is not installed (apt-get install --no-install-recommends openfoam libopenfoam)"
    tree="$cache/openfoam/$version"
    user_tree=0
fi

mkdir -p "$project/platforms"
ready="$tree/.coarsedem-ready"
if [ "$force" = 0 ] && [ -f "$ready" ]; then
    echo "$tree" > "$project/platforms/foam-src-dir"
    say "up to date: $tree"
    exit 0
fi

# ------------------------------------------------------------------ fetch + unpack (Debian tree)
if [ "$user_tree" = 0 ]; then
    upstream="${version#*:}"; upstream="${upstream%-*}"          # 1912.200626-1 -> 1912.200626
    mkdir -p "$cache/debsrc"
    tarball="$(ls "$cache"/debsrc/openfoam_"$upstream".orig.tar.* 2>/dev/null | head -n1 || true)"
    if [ -z "$tarball" ]; then
        say "downloading Debian's openfoam $version source package (about 45 MB)"
        (cd "$cache/debsrc" && apt-get -qq source --download-only "openfoam=$version") \
            || die "apt-get source --download-only openfoam=$version failed. Check that a deb-src line
    for bookworm main is enabled (Allwmake adds /etc/apt/sources.list.d/coarsedem-src.sources)
    and run 'apt-get update'."
        tarball="$(ls "$cache"/debsrc/openfoam_"$upstream".orig.tar.* 2>/dev/null | head -n1 || true)"
        [ -n "$tarball" ] || die "no openfoam_$upstream.orig.tar.* in $cache/debsrc after apt-get source"
    fi
    dsc="$cache/debsrc/openfoam_${version#*:}.dsc"
    if [ -f "$dsc" ]; then
        sum="$(sha256sum "$tarball" | cut -c1-64)"
        grep -q "$sum" "$dsc" || die "$tarball does not match the sha256 in $dsc: delete both and run again"
    fi

    say "unpacking wmake/ src/ META-INFO/ of $(basename "$tarball") into $tree"
    rm -rf "$tree" "$tree.tmp"
    mkdir -p "$tree.tmp"
    top="$(set +o pipefail; tar -tf "$tarball" | head -n1 | cut -d/ -f1)"   # head stops tar early
    tar -C "$tree.tmp" --no-same-owner --strip-components=1 -xf "$tarball" \
        "$top/wmake" "$top/src" "$top/META-INFO" \
        "$top/applications/solvers/incompressible/pimpleFoam"
    # Debian's etc/ (controlDict, cellModels, ...) is what its libraries were built with; a
    # solver started with WM_PROJECT_DIR=<tree> then finds the same files as Debian's solvers.
    ln -s /usr/share/openfoam/etc "$tree.tmp/etc"
    # wmake links with -L$WM_PROJECT_DIR/platforms/$WM_OPTIONS/lib: that is Debian's /usr/lib
    mkdir -p "$tree.tmp/platforms/linux64GccDPInt32Opt"
    ln -s /usr/lib "$tree.tmp/platforms/linux64GccDPInt32Opt/lib"
    mv "$tree.tmp" "$tree"
fi

# ------------------------------------------------------------------ wmake tools + lnInclude
# shellcheck source=../etc/wmakeEnv
FOAM_SRC_DIR="$tree" . "$project/etc/wmakeEnv"

say "building the wmake tools"
"$tree/wmake/src/Allmake" >/dev/null || die "wmake/src/Allmake failed in $tree"

say "making lnInclude directories"
for lib in $lninclude_libs; do
    [ -d "$tree/src/$lib" ] || die "$tree/src/$lib does not exist"
    (cd "$tree/src" && wmakeLnInclude -u "$lib" >/dev/null 2>&1) || die "wmakeLnInclude $lib failed"
done

# ------------------------------------------------------------------ check headers vs. Debian's libraries
# A copy of pimpleFoam compiled here and linked against /usr/lib must run. This catches a
# label-size / precision / ABI mismatch once, when the tree is made (about 20 s).
if [ -d "$tree/applications/solvers/incompressible/pimpleFoam" ]; then
    say "checking: compile a copy of pimpleFoam against Debian's libraries"
    chk="$(mktemp -d /tmp/coarsedem-foamcheck.XXXXXX)"
    cp -r "$tree/applications/solvers/incompressible/pimpleFoam/." "$chk/"
    rm -rf "$chk/SRFPimpleFoam" "$chk/overPimpleDyMFoam" "$chk/pimpleDyMFoam"
    printf 'pimpleFoam.C\n\nEXE = %s/pimpleFoamCheck\n' "$chk/bin" > "$chk/Make/files"
    if ! (cd "$chk" && wmake > "$chk/log.wmake" 2>&1); then
        tail -n 30 "$chk/log.wmake" >&2
        die "the pimpleFoam check did not compile/link against Debian's OpenFOAM (log: $chk/log.wmake)"
    fi
    if ! WM_PROJECT_DIR=/usr/share/openfoam "$chk/bin/pimpleFoamCheck" -help > "$chk/log.run" 2>&1 \
       || ! grep -q 'Usage: pimpleFoamCheck' "$chk/log.run"; then
        cat "$chk/log.run" >&2
        die "the pimpleFoam check compiled but does not run (log: $chk/log.run)"
    fi
    rm -rf "$chk"
    say "check passed: headers in $tree match Debian's libraries"
fi

date -u +%FT%TZ > "$ready"
echo "$tree" > "$project/platforms/foam-src-dir"
say "ready: $tree"
