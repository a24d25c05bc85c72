# Timing helpers for the benchmark scripts (sourced, not run).

# Prints the wall seconds of "$@" (its output discarded).
wall() {
  local start end
  start=$(date +%s.%N)
  "$@" >/dev/null
  end=$(date +%s.%N)
  echo "$end - $start" | bc -l
}

# Prints the median of the numbers on stdin, one per line (the mean of the middle two for an
# even count).
median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }
