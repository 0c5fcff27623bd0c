#!/usr/bin/env bash
# The installed package as a team uses it: install a built tree into a
# temporary prefix, compile every installed header on its own, then
# configure, build and run examples/walk_test against the package
# (find_package(simswift 0.2)).
#   scripts/test-package.sh [build-dir] [jobs]
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
jobs="${2:-$(nproc)}"
prefix="$(mktemp -d)"
trap 'rm -rf "$prefix"' EXIT
cmake --install "$build" --prefix "$prefix" >/dev/null
check_header() {  # include-dir header-as-included
  echo "#include \"$2\"" | g++ -std=c++17 -fsyntax-only -Wall -I"$1" -x c++ - \
    || { echo "installed header $2 does not compile on its own" >&2; exit 1; }
}
for h in "$prefix"/include/simswift/*.hpp; do
  check_header "$prefix/include" "simswift/$(basename "$h")"
done
agent_inc="$prefix/include/simswift-agent"
while IFS= read -r h; do
  check_header "$agent_inc" "${h#"$agent_inc"/}"
done < <(find "$agent_inc" -name '*.hpp' | sort)
cmake -S examples/walk_test -B "$prefix/example-build" -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build "$prefix/example-build" -j"$jobs"
(cd "$prefix/example-build" && LD_LIBRARY_PATH="$prefix/lib" ctest --output-on-failure --no-tests=error -j"$jobs")
