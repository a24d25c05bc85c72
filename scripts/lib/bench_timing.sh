# Timing helpers for the benchmark scripts (sourced, not run).

# Prints the wall seconds of "$@" (its output discarded).
wall() {
  local start end
  start=$(date +%s.%N)
  "$@" >/dev/null
  end=$(date +%s.%N)
  echo "$end - $start" | bc -l
}

# Prints the CPU seconds (user + system) of "$@"; its stdout goes to OUT.
# Usage: cpu_seconds OUT COMMAND...
cpu_seconds() {
  local out=$1 TIMEFORMAT='%U %S'
  shift
  { time "$@" >"$out" 2>/dev/null; } 2>&1 | awk '{print $1 + $2}'
}

# Prints the median of the numbers on stdin, one per line (the mean of the middle two for an
# even count).
median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }
