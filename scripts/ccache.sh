# Sourced (from the source root) by scripts/test.sh and scripts/test-package.sh:
# every build they configure compiles through ccache (Debian's ccache,
# scripts/install-deps.sh), so a run compiles each translation unit once per
# flag set and a second run compiles nothing that has not changed.
#  - CCACHE_BASEDIR = the source root: absolute paths under it are hashed
#    relative to the build folder, so build/ and build-package/ (same depth,
#    same flags: `cmake --preset library` changes no compile flag) share
#    objects, and so do two clones of the project at the same path (a fresh
#    clone where the last one was). A clone at another path
#    misses every test unit: their command lines name the source and build
#    folders (SIMSWIFT_SOURCE_DIR, SIMSWIFT_BINARY_DIR: cmake/SimswiftTargets.cmake),
#    which the base directory does not rewrite (docs/testing.md, "Cost").
#  - The cache itself is where ccache keeps it by default, the user's cache
#    directory (~/.cache/ccache; CCACHE_DIR or ccache.conf's cache_dir if set):
#    it outlives `git clean -fdx` and a fresh clone, which a folder of the
#    work tree would not, and clones of the same user share it.
#  - CCACHE_DEPEND=1 (ccache's depend mode): a miss costs one compile and no
#    extra preprocessor run, since the compiler's own -MD output (CMake always
#    asks for it) names the headers: a cold cache costs about what no cache
#    does (measured: docs/testing.md, "Cost").
#  - SIMSWIFT_CCACHE=0 builds without it (the launcher is cleared, also in a
#    build folder configured with it before): to measure a cold build.
# Sets ccache_cmake (cmake's -D arguments for the launcher, or clearing it).
if [ "${SIMSWIFT_CCACHE:-1}" != 0 ] && command -v ccache >/dev/null; then
  export CCACHE_BASEDIR="$PWD" CCACHE_DEPEND=1
  ccache_cmake=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
else
  [ "${SIMSWIFT_CCACHE:-1}" != 0 ] && echo "simswift: ccache not found, building without it (scripts/install-deps.sh installs it)" >&2
  ccache_cmake=(-DCMAKE_C_COMPILER_LAUNCHER= -DCMAKE_CXX_COMPILER_LAUNCHER=)
fi
