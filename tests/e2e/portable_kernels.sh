#!/usr/bin/env bash
# The same policy on every x86-64 CPU: training B with seed 1 gives identical policy.pt bytes
# whichever kernels libtorch and OpenBLAS would pick here. Each CPU-dependent choice they read
# from the environment is set as another CPU would make it (only the ones this CPU can run);
# rlpos-sim must pin its own and train the same bytes under every one.
# Usage: portable_kernels.sh BIN_DIR SOURCE_DIR [--episodes N]
source "$(dirname "$0")/lib.sh" "$1" "$2"
episodes=${4:-300}
SIM=$BIN/rlpos-sim

settings=("ATEN_CPU_CAPABILITY=default" "OPENBLAS_CORETYPE=Prescott" "OPENBLAS_CORETYPE=Core2")
flags=$(grep -m1 '^flags' /proc/cpuinfo || true)
case " $flags " in *" avx2 "*)
  settings+=("ATEN_CPU_CAPABILITY=avx2" "OPENBLAS_CORETYPE=Haswell") ;;
esac
case " $flags " in *" avx512f "*)
  settings+=("ATEN_CPU_CAPABILITY=avx512" "OPENBLAS_CORETYPE=SkylakeX") ;;
esac

train() {  # train NAME [VAR=VALUE...]: trains B, seed 1, into $WORK/NAME
  local name=$1
  shift
  env "$@" "$SIM" train --scenario "$SRC/campaigns/scenarios/b.json" --fidelity analytic \
    --seed 1 --episodes "$episodes" --json --out "$WORK/$name" >"$WORK/$name.json" \
    2>"$WORK/$name.log" || fail "training with ${*:-no setting} failed: $(tail -n 3 "$WORK/$name.log")"
}

train reference
reference=$(sha256sum <"$WORK/reference/policy.pt")
for setting in "${settings[@]}"; do
  name=${setting//[=]/-}
  train "$name" "$setting"
  digest=$(sha256sum <"$WORK/$name/policy.pt")
  [ "$digest" = "$reference" ] || fail "policy.pt under $setting differs from the one trained with the environment's defaults"
  cmp -s "$WORK/reference.json" "$WORK/$name.json" \
    || fail "the training result under $setting differs: $(diff "$WORK/reference.json" "$WORK/$name.json" | head -n 4)"
done
echo "portable kernels: ${#settings[@]} settings, one policy.pt ($reference)"
