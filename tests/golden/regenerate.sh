#!/usr/bin/env bash
# Rewrites the golden summaries (tests/golden/expected/*.json) from a build's test_golden, on
# purpose: after a change that alters a mesher's or the solver's output, run it, read the diff
# of the summaries (`git diff tests/golden/expected`) and commit them with the change.
#   tests/golden/regenerate.sh build/release
set -euo pipefail
if [ $# -ne 1 ]; then
  echo "usage: $0 BUILD_DIR" >&2
  exit 2
fi
binary="$1/tests/test_golden"
if [ ! -x "$binary" ]; then
  echo "$binary: not built (cmake --build $1 --target test_golden)" >&2
  exit 1
fi
# Every case writes its summary; those of cases no longer in the table are removed.
VOLMESH_GOLDEN_REGENERATE=1 "$binary" --gtest_filter='Cases/Golden.*:GoldenFiles.*' --gtest_brief=1
