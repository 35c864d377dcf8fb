#!/usr/bin/env bash
# Sets everything up, then runs the whole test suite through CTest
# (CPU tests, GL tests on a headless EGL context, GUI tests under xvfb-run).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
echo "== running tests"
ctest --test-dir build --output-on-failure --parallel "$(nproc)" --timeout 600
