#!/usr/bin/env bash
# Builds and runs every test, then the sanitizer builds (what CI runs via
# .ci/run). Three build folders, run one after the other (and the package
# test's build-package/, see scripts/test-package.sh):
#   build/       Release, the whole suite (incl. the loader mutation fuzzer)
#   build-asan/  AddressSanitizer + UndefinedBehaviorSanitizer: the suite
#                minus the heavy physics statistics (ASAN_EXCLUDE below)
#   build-tsan/  ThreadSanitizer: the robot program (agent), bridge and runner tests,
#                same exclusions (the runner/robot hand-overs are ordered by
#                atomics TSan sees, docs/testing.md)
# Any sanitizer report fails the test that produced it. Every build compiles
# through ccache (scripts/ccache.sh: what it shares, where the cache is).
# Timings go to stderr: each stage's, and at the end the total and the
# cache's hit rate over this run's compilations (docs/testing.md, "Cost").
#   SIMSWIFT_SKIP_SANITIZERS=1 bash scripts/test.sh   # Release suite only
#   SIMSWIFT_CCACHE=0 bash scripts/test.sh            # without ccache
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
source scripts/ccache.sh
jobs="$(nproc)"
start=$SECONDS
stamp() { echo "simswift test.sh: $1 after $((SECONDS - start)) s" >&2; }
# This run's compilations, logged by ccache one by one (its stats log): the
# hit rate of this run alone, also when other builds share the cache (the
# cache's global counters are neither zeroed nor read).
run_tmp="$(mktemp -d)"
export CCACHE_STATSLOG="$run_tmp/ccache-stats.log"
summary() {
  echo "simswift test.sh: total $((SECONDS - start)) s" >&2
  if [ -s "$CCACHE_STATSLOG" ]; then
    echo "simswift test.sh: ccache over this run's $(grep -c '^# ' "$CCACHE_STATSLOG") compilations:" >&2
    ccache --show-log-stats | grep -E '^ *(Hits|Misses|Uncacheable)' >&2 || true
  fi
}
# The last lines of a run: every skipped test and why (each suite's ctest
# JUnit file). SIMSWIFT_CI=1 (.ci/run) fails the run on a skip not listed,
# with its reason, in scripts/ci-allowed-skips.txt: CI's machine (root,
# mount namespaces, gdb, Slurm's packages) runs every test.
finish() {
  local rc=$?
  summary
  python3 scripts/skipped-tests.py scripts/ci-allowed-skips.txt \
    release="$run_tmp/release.xml" asan="$run_tmp/asan.xml" tsan="$run_tmp/tsan.xml" || rc=1
  rm -rf "$run_tmp"
  exit "$rc"
}
trap finish EXIT

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${ccache_cmake[@]}" >/dev/null
cmake --build build -j"$jobs"
stamp "Release build"
(cd build && ctest --output-on-failure -j"$jobs" --timeout 900 --output-junit "$run_tmp/release.xml")
stamp "Release suite"

# The package as a team gets it: the library-only build (cmake --preset
# library) from an empty build-package/, installed and moved; headers (also
# after rUNSWift-style macros), Python and the examples against it.
scripts/test-package.sh build-package "$jobs"
stamp "installed package: library-only build, headers, Python, examples"

[ "${SIMSWIFT_SKIP_SANITIZERS:-0}" = 1 ] && exit 0

# Heavy physics statistics (MotionPhysics.*: many seeds of walking, kicking
# and getting up, 1-5 s each in Release, 10-30x that under a sanitizer): the
# code they run (walk, kick, get-up, the runner's lock-step) is already run
# under the sanitizers by MotionScenario.*, Determinism.* and the agent's
# walk/motion logic tests, so they would add time, not coverage. Cameras are off in the sanitizer builds: OSMesa's
# llvmpipe JIT is not instrumented and dominates the run time; the camera
# code itself is covered by the Release suite.
heavy='MotionPhysics\.|ExternalExperimentFull\.|SimswiftTestHeavy\.'
# -O1: the sanitizers' recommended level, and half the compile time of -O3.
# -g1: line tables only, what a report's stack trace needs (file:line of each
# frame); a third less compile CPU than -g and a quarter of the object size
# (docs/testing.md, "Cost").
# The sanitizer builds build what their suites run and nothing else: no
# benchmarks, no tools/ (run by hand, never by ctest); `all` is then the test
# programs and what they start (simswift, simswift-agent, the libagent and
# LoLA clients, libsimswift.so), so a program a new test needs is never left out.
# Unity builds (CMAKE_UNITY_BUILD, CMake's batches of 8 files): the sanitizer
# builds compile every unit a second and a third time, and a unity build
# roughly halves that (the headers each batch shares are compiled once;
# docs/testing.md, "Cost"). The Release build stays non-unity: it is the one
# that catches a missing #include, which a batch would hide. File-local names
# must therefore be unique within each target (a test helper two files
# share goes in a test support header).
san_cmake=(-DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELEASE=-O1 -DNDEBUG"
           -DSIMSWIFT_CAMERAS=OFF -DSIMSWIFT_BENCH=OFF -DSIMSWIFT_TOOLS=OFF "${ccache_cmake[@]}"
           -DSIMSWIFT_SANITIZE_DEBUG=-g1 -DCMAKE_UNITY_BUILD=ON)
# verify_asan_link_order=0: a launched program has libsimswift-shim.so
# preloaded ahead of ASan's runtime (docs/shim.md); the shim is never
# instrumented, so the order is harmless.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:halt_on_error=1:detect_stack_use_after_return=0:verify_asan_link_order=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan.supp:print_suppressions=0"
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1"

cmake -S . -B build-asan -DSIMSWIFT_SANITIZE=address,undefined "${san_cmake[@]}" >/dev/null
cmake --build build-asan -j"$jobs"
stamp "ASan+UBSan build"
# The Slurm test (tests/slurm) checks a bash script against a real cluster;
# the Release suite runs it, an instrumented simswift would only make it slower.
(cd build-asan && ctest --output-on-failure -j"$jobs" --timeout 900 --output-junit "$run_tmp/asan.xml" -E "$heavy|^slurm$")
stamp "ASan+UBSan suite"

# ThreadSanitizer: the code with threads (robot program, runner, bridge),
# through the agent, bridge and runner tests; no suppressions.
cmake -S . -B build-tsan -DSIMSWIFT_SANITIZE=thread "${san_cmake[@]}" >/dev/null
cmake --build build-tsan -j"$jobs" --target test_agent test_runner test_bridge simswift-agent
stamp "TSan build"
# Not the tests that launch a program built in this folder: a TSan-built
# program cannot take the preload library (libtsan must be the first
# library; with libsimswift-shim.so ahead of it TSan's start faults, and
# with LD_AUDIT's early library it finds no static TLS left, docs/shim.md),
# so these launches fail before the program runs. The Release and ASan+UBSan
# suites run them; TSan runs the same robot program builtin.
tsan_launch='LaunchedPrograms\.(ACrashEnds|SimswiftAgentGives|AtTheEndNothing)|ProgramView\.(TwoPrograms|AttachStartsAV5Program)'
(cd build-tsan && ctest --output-on-failure -j"$jobs" --timeout 900 --output-junit "$run_tmp/tsan.xml" -L 'agent|runner|bridge' -E "$heavy|$tsan_launch")
stamp "TSan suite"
