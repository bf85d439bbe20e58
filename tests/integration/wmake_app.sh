# wmake_app.sh -- building a test's OpenFOAM application (sourced after result.sh):
#   wmake_app SOURCE_DIR WORK_DIR WHAT    the project's wmake environment (etc/wmakeEnv), a copy of the
#                                         application in WORK_DIR (emptied first), built with wmake into
#                                         WORK_DIR/bin (out of the project's bin/); a PASS line saying WHAT
#                                         it links, or a FAIL line with the log's tail and finish
wmake_app() {
    local src="$1" work="$2" what="$3" name
    name="$(basename "$src")"
    # shellcheck source=../../etc/wmakeEnv
    if ! . "$project/etc/wmakeEnv"; then
        result fail "etc/wmakeEnv: no OpenFOAM build environment (run ./Allwmake)"
        finish
    fi
    rm -rf "$work"
    mkdir -p "$work/bin"
    cp -r "$src" "$work/"
    export FOAM_USER_APPBIN="$work/bin"
    if (cd "$work/$name" && wmake) > "$work/log.wmake" 2>&1; then
        result ok "$name compiled and linked with wmake ($what)"
    else
        tail -n 30 "$work/log.wmake"
        result fail "wmake of $name failed (see $work/log.wmake)"
        finish
    fi
}
