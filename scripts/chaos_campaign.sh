#!/usr/bin/env bash
# The long chaos test: 20 SIGKILLs to workers and 10 to the coordinator during a 54-job campaign
# (tests/e2e/campaigns/chaos_long.json), after an undisturbed run of it; every job must succeed
# exactly once with the undisturbed metrics. CI runs a shorter version (ctest -R e2e.chaos).
# Usage: scripts/chaos_campaign.sh [WORKER_KILLS] [COORDINATOR_KILLS] [BUILD_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
RLPOS_CHAOS_WORKER_KILLS=${1:-20} RLPOS_CHAOS_COORDINATOR_KILLS=${2:-10} \
  RLPOS_CHAOS_CAMPAIGN=$here/tests/e2e/campaigns/chaos_long.json \
  bash "$here/tests/e2e/chaos.sh" "${3:-$here/build}/bin" "$here"
