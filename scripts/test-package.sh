#!/usr/bin/env bash
# The package as a team gets it (docs/library.md):
#  1. from an empty build folder, configure with the documented preset
#     (`cmake --preset library`: the library, its Python module and the two
#     programs; no tests, benchmarks or tools), build it (timed), install it
#     into a temporary prefix, then MOVE the prefix: the data must be found
#     relative to the installed library, wherever it lands;
#  2. compile every installed header on its own, and after a team's
#     rUNSWift-style macros and globals (examples/team_glue/team/defs.hpp);
#  3. load a shipped scenario from the moved prefix with its `simswift`
#     program and with its Python module (PYTHONPATH into the prefix, run
#     from /, so neither the build tree nor the working folder can help),
#     after checking the module's folder is the one docs/library.md gives
#     (also configured for /usr on Debian: the multiarch folder) and not on
#     python3's sys.path;
#  4. configure, build and run examples/walk_test and examples/team_glue
#     against the moved package (find_package(simswift 0.2)).
#   scripts/test-package.sh [build-dir] [jobs]   (build-dir: default build-package; emptied first)
set -euo pipefail
cd "$(dirname "$0")/.."
src="$PWD"
build="${1:-build-package}"
jobs="${2:-$(nproc)}"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

# Through ccache (scripts/ccache.sh): the preset's flags are the Release
# build's, so after build/ every object comes from the cache; the folder is
# still empty and every compile and link still runs through the preset's
# configure (a hit is the compiler's output for the same command line).
source scripts/ccache.sh
rm -rf "$build"
t0=$SECONDS
cmake --preset library -B "$build" "${ccache_cmake[@]}" > "$tmp/configure.log"
# This build's own ccache log (added to scripts/test.sh's, if any): its hits.
parent_log="${CCACHE_STATSLOG:-}"
CCACHE_STATSLOG="$tmp/ccache.log" cmake --build "$build" -j"$jobs" >/dev/null
hits="from the cache: not built with ccache"
if [ -f "$tmp/ccache.log" ]; then
  hits="$(grep -c '^local_storage_hit$' "$tmp/ccache.log" || true) of $(grep -c '^# ' "$tmp/ccache.log" || true) compilations from the cache"
  [ -z "$parent_log" ] || cat "$tmp/ccache.log" >> "$parent_log"
fi
echo "test-package.sh: library-only build from an empty folder: $((SECONDS - t0)) s with -j$jobs ($hits)" >&2
cmake --install "$build" --prefix "$tmp/first" >/dev/null
mv "$tmp/first" "$tmp/moved"
prefix="$tmp/moved"

check_header() {  # include-dir header-as-included [prelude]
  { [ -n "${3:-}" ] && echo "#include \"$3\""; echo "#include \"$2\""; } |
    g++ -std=c++17 -fsyntax-only -Wall -I"$1" -I"$src/examples/team_glue" -x c++ - \
    || { echo "installed header $2 does not compile${3:+ after $3}" >&2; exit 1; }
}
for h in "$prefix"/include/simswift/*.hpp; do
  check_header "$prefix/include" "simswift/$(basename "$h")"
  check_header "$prefix/include" "simswift/$(basename "$h")" team/defs.hpp
done
agent_inc="$prefix/include/simswift-agent"
while IFS= read -r h; do
  check_header "$agent_inc" "${h#"$agent_inc"/}"
done < <(find "$agent_inc" -name '*.hpp' | sort)

# The data from the moved prefix: the program, then the Python module.
scenario="$prefix/share/simswift/scenarios/stand_one.yaml"
(cd / && "$prefix/bin/simswift" run "$scenario" --check >/dev/null)
# The interpreter the module was built for (CMakeLists.txt prefers /usr/bin/python3).
python="$(sed -n 's/^_\{0,1\}Python3_EXECUTABLE:[A-Z]*=//p' "$build/CMakeCache.txt" | head -n1)"
# Where the configure step says the module goes (CMakeLists.txt prints it).
module_dir() { sed -n 's/^-- simswift: the Python module installs into \([^ ]*\) .*/\1/p' "$1"; }
example_python=()
if [ -n "$(module_dir "$tmp/configure.log")" ]; then
  [ -n "$python" ] || { echo "test-package.sh: no Python3_EXECUTABLE in $build/CMakeCache.txt" >&2; exit 1; }
  # docs/library.md's two rows ("Python": where the module is installed):
  # under any prefix but /usr P/lib/python3/dist-packages, which the install
  # used; configured for /usr on Debian /usr/lib/<multiarch>/python3/dist-packages
  # (a second configure, nothing built); python3's sys.path has neither.
  doc_dirs=("P/lib/python3/dist-packages" "/usr/lib/<multiarch>/python3/dist-packages")
  for d in "${doc_dirs[@]}"; do
    grep -qF "\`$d\`" docs/library.md || { echo "test-package.sh: docs/library.md no longer says $d" >&2; exit 1; }
  done
  installed="$(grep '/simswift\.cpython-[^/]*\.so$' "$build/install_manifest.txt" || true)"
  [ "$installed" = "$tmp/first/lib/python3/dist-packages/$(basename "$installed")" ] ||
    { echo "test-package.sh: the module was installed as '$installed', not in ${doc_dirs[0]} (docs/library.md)" >&2; exit 1; }
  pydir="$prefix/lib/python3/dist-packages"
  searched=("$(module_dir "$tmp/configure.log")")
  if [ -f /etc/debian_version ]; then
    cmake -S . -B "$tmp/usr-configure" -DCMAKE_INSTALL_PREFIX=/usr -DSIMSWIFT_TESTS=OFF -DSIMSWIFT_BENCH=OFF \
          -DSIMSWIFT_CAMERAS=OFF > "$tmp/usr-configure.log"
    usr_dir="/usr/lib/$(gcc -print-multiarch)/python3/dist-packages"
    [ "$(module_dir "$tmp/usr-configure.log")" = "$usr_dir" ] ||
      { echo "test-package.sh: configured for /usr, the module goes to '$(module_dir "$tmp/usr-configure.log")', not $usr_dir (docs/library.md)" >&2; exit 1; }
    searched+=("$usr_dir")
  fi
  for d in "${searched[@]}"; do
    ! env -u PYTHONPATH "$python" -c 'import sys; print("\n".join(sys.path))' | grep -qxF "$d" ||
      { echo "test-package.sh: $python searches $d: docs/library.md says it does not" >&2; exit 1; }
  done
  (cd / && PYTHONPATH="$pydir" "$python" - "$scenario" "$prefix" <<'PY'
import sys
import simswift
scenario, prefix = sys.argv[1], sys.argv[2]
assert simswift.__file__.startswith(prefix), simswift.__file__
sim = simswift.Simulation(scenario)
sim.run(0.5)
assert sim.ticks == 50, sim.ticks
assert not sim.robot(0).fallen
fsr = float(sim.robot(0).sensors.fsr.sum())
assert 0.8 * 5.305 < fsr < 1.2 * 5.305, fsr  # kg: the NAO V5's mass (Aldebaran's datasheet)
print(f"python from the moved prefix: {scenario} ran 0.5 s, FSR sum {fsr:.2f} kg", file=sys.stderr)
PY
  )
else
  echo "test-package.sh: no Python module built (pybind11 not found): skipped the Python checks" >&2
  example_python=(-DWALK_TEST_PYTHON=OFF)
fi

for example in walk_test team_glue; do
  cmake -S "examples/$example" -B "$tmp/$example-build" -DCMAKE_PREFIX_PATH="$prefix" "${example_python[@]}" >/dev/null
  cmake --build "$tmp/$example-build" -j"$jobs"
  (cd "$tmp/$example-build" && LD_LIBRARY_PATH="$prefix/lib" ctest --output-on-failure --no-tests=error -j"$jobs")
done
