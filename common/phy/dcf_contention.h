#pragma once
// Contention among stations that all want the channel, after Bianchi's model of saturated
// 802.11 DCF (IEEE JSAC 18(3), 2000): every backlogged station transmits in a slot with the same
// probability tau, fixed by its binary exponential backoff and by how often it collides.
// The airtime model charges each successful access with the idle slots and collisions that come
// with it: with one station that is the mean backoff (CWmin / 2 slots), with twenty saturated
// stations it is mostly collisions.

namespace rlpos {

struct DcfContention {
  double tau = 0.0;                     // per-slot transmission probability of a station
  double collision_probability = 0.0;   // that a transmission meets another one
  double idle_slots_per_success = 0.0;  // empty backoff slots per successful transmission
  double collisions_per_success = 0.0;  // collisions per successful transmission
};

// Bianchi's per-slot transmission probability of a station whose transmissions fail with
// probability `p`, under binary exponential backoff from cw_min to cw_max.
double BackoffTau(double p, int cw_min = 15, int cw_max = 1023);

// The backoff stages from cw_min to cw_max (log2 of their ratio), and BackoffTau with them
// counted once: for loops that ask tau of many p under one contention window.
int BackoffStages(int cw_min, int cw_max);
double BackoffTauAtStages(double p, int cw_min, int stages);

// `stations` may be fractional (an effective number of contenders); below 1 it counts as 1.
// cw_min and cw_max: the access category's contention window bounds (AC_BE: 15, 1023).
DcfContention SaturatedDcf(double stations, int cw_min = 15, int cw_max = 1023);

}  // namespace rlpos
