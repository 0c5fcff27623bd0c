#!/usr/bin/env bash
# Installs what is missing, builds in Release and runs a scenario
# (default: one robot standing for 10 s of simulated time).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target simswift
./build/simswift run "${1:-scenarios/stand_one.yaml}" "${@:2}"
