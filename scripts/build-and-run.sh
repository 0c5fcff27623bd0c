#!/usr/bin/env bash
# Installs what is missing, builds in Release and runs the default job: the
# small find-ball experiment scenarios/findball_quick.yaml (3 robots, 2016 vs
# 2017 ball search, 30 trials; a few minutes on 2 cores), then says where its
# report is. Other jobs:
#   bash scripts/build-and-run.sh scenarios/thesis_findball.yaml      # an experiment file (has setups:)
#   bash scripts/build-and-run.sh scenarios/walk_one.yaml --realtime  # a scenario: simswift run
#   bash scripts/build-and-run.sh scenarios/tests/reference.yaml --short   # a test file (has tests:): simswift test
#   bash scripts/build-and-run.sh experiment FILE.yaml --jobs 2       # any simswift command line
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
# simswift-agent too: test files and scenarios may launch it as a robot program.
cmake --build build -j"$(nproc)" --target simswift simswift-agent
if [ $# -eq 0 ]; then
  set -- experiment scenarios/findball_quick.yaml
elif [ -f "$1" ]; then
  # A file: an experiment (it has a top-level setups: list), a test file
  # (tests:) or a scenario.
  if grep -q '^setups:' "$1"; then set -- experiment "$@";
  elif grep -q '^tests:' "$1"; then set -- test "$@";
  else set -- run "$@"; fi
fi
exec ./build/simswift "$@"
