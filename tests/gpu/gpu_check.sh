#!/usr/bin/env bash
# The GLSL-against-C++ parity tests on whatever GL the machine gives (on a GPU machine: its
# driver), one line of result each and their failures in full: where a driver computes a
# method differently from llvmpipe, this names the function.
#
#   tests/gpu/gpu_check.sh TEST_DIR OUT_DIR
#
# TEST_DIR: the test executables (build/tests/gpu's, or copies: tests/gpu/gpu_pack.sh); each found is run.
# OUT_DIR: gets gpu_check.log. The tests read assets from the source tree they were built in
# (WEFT_SOURCE_ASSETS): on another machine, make that path lead to this checkout's assets/.
# Exits non-zero when a test fails.
set -uo pipefail
if [ $# -lt 2 ] || [ "${1:-}" = "--help" ]; then sed -n '2,12p' "$0"; exit 2; fi
DIR=$(realpath "$1") OUT=$2
mkdir -p "$OUT"
LOG=$(realpath "$OUT")/gpu_check.log
: >"$LOG"
failed=0
for t in gpu_context_test microcylinder_parity_test method_parity_test iwasaki_parity_test vertex_facet_test \
  visible_vertices_test weave_parity_test vertex_normal_map_parity_test sheer_parity_test tone_map_parity_test \
  uniform_budget_test weave_culling_test; do
  [ -x "$DIR/$t" ] || { echo "$t: not in $DIR" | tee -a "$LOG"; continue; }
  start=$(date +%s)
  if "$DIR/$t" --gtest_brief=1 >>"$LOG" 2>&1; then
    echo "$t: passed ($(($(date +%s) - start)) s)" | tee -a "$LOG"
  else
    echo "$t: FAILED ($(($(date +%s) - start)) s)" | tee -a "$LOG"
    failed=1
  fi
done
exit $failed
