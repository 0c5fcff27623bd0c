#!/usr/bin/env bash
# Installs the Debian 12 packages simswift builds with, if any are missing.
set -euo pipefail
pkgs=(build-essential cmake pkg-config git
      ccache   # every build of scripts/test.sh and scripts/test-package.sh compiles through it (scripts/ccache.sh)
      libode-dev libeigen3-dev liburdfdom-dev libtinyxml-dev libyaml-cpp-dev
      libassimp-dev libosmesa6-dev libpng-dev libcairo2-dev
      libgtest-dev libbenchmark-dev ffmpeg gdb
      gnuplot-nox parallel
      slurmctld slurmd slurm-client munge   # the Slurm scale-out test (tests/slurm, a one-node cluster)
      python3-dev python3-pybind11 python3-pytest python3-numpy   # Python bindings (python/)
      libboost-math-dev   # the report's statistics (app/experiment/Statistics.cpp)
      libmsgpack-dev      # the LoLA protocol (sim/lola): msgpack-c
      libcli11-dev        # the programs' command lines (app/cli): CLI11, header-only
      libjs-three         # three.js r111 for `simswift view`'s page (served from /usr/share/javascript/three)
      chromium chromium-driver python3-selenium   # the viewer's browser test (tests/view/browser_test.py)
      libxml2-utils       # xmllint: the JUnit XML of `simswift test` checked against its schema (tests/scenario_tests)
      clang libclang-rt-14-dev)   # libFuzzer targets (docs/testing.md, "Fuzzing the loaders")
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# tests/record: the MCAP project's reader (@mcap/core from npm) reads a recording.
# Node.js and npm are asked for by command, not by package: a machine with
# NodeSource's nodejs (which carries npm) cannot also install Debian's npm
# ("held broken packages"), and needs neither.
command -v node >/dev/null || missing+=(nodejs)
command -v npm >/dev/null || missing+=(npm)
[ ${#missing[@]} -eq 0 ] && exit 0
echo "simswift: installing ${missing[*]}" >&2
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "simswift: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  SUDO=sudo
fi
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
