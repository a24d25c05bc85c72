#include "common/phy/mcs_table.h"

#include <array>
#include <cmath>
#include <stdexcept>

namespace rlpos {
namespace {

// Coded bits per subcarrier per symbol (modulation bits x coding rate), MCS 0..11.
constexpr std::array<double, 12> kBitsPerSubcarrier = {0.5, 1.0, 1.5, 2.0,      3.0, 4.0,
                                                       4.5, 5.0, 6.0, 20.0 / 3, 7.5, 25.0 / 3};
constexpr std::array<double, 12> kMinSnrDb = {9, 12, 14, 17, 21, 25, 26, 27, 32, 34, 37, 39};

bool IsHe(const std::string& standard) {
  return standard == "802.11ax";
}

int DataSubcarriers(const std::string& standard, int width_mhz) {
  if (IsHe(standard)) {
    switch (width_mhz) {
      case 20:
        return 234;
      case 40:
        return 468;
      case 80:
        return 980;
      case 160:
        return 1960;
    }
  } else {
    switch (width_mhz) {
      case 20:
        return 52;
      case 40:
        return 108;
      case 80:
        return 234;
      case 160:
        return 468;
    }
  }
  throw std::invalid_argument("unsupported channel width " + std::to_string(width_mhz) + " MHz");
}

}  // namespace

int MaxMcs(const std::string& standard) {
  if (standard == "802.11n")
    return 7;
  if (IsHe(standard))
    return 11;
  return 9;
}

double McsDataRateMbps(const PhyProfile& phy, int mcs) {
  if (mcs < 0 || mcs > MaxMcs(phy.standard)) {
    throw std::invalid_argument("MCS " + std::to_string(mcs) + " out of range for " + phy.standard);
  }
  // Symbol duration: 3.2 us (HT/VHT) or 12.8 us (HE) plus the guard interval.
  const double symbol_us = (IsHe(phy.standard) ? 12.8 : 3.2) + phy.guard_interval_ns / 1000.0;
  const double bits =
      DataSubcarriers(phy.standard, phy.width_mhz) * kBitsPerSubcarrier[mcs] * phy.spatial_streams;
  return bits / symbol_us;
}

double McsMinSnrDb(int mcs) {
  if (mcs < 0 || mcs >= static_cast<int>(kMinSnrDb.size())) {
    throw std::invalid_argument("MCS " + std::to_string(mcs) + " has no SNR threshold");
  }
  return kMinSnrDb[mcs];
}

int RequiredMcs(const PhyProfile& phy, double demand_mbps) {
  for (int mcs = 0; mcs <= MaxMcs(phy.standard); ++mcs) {
    // A relative tolerance so that a demand given as an MCS rate maps back to that MCS.
    if (McsDataRateMbps(phy, mcs) >= demand_mbps * (1.0 - 1e-9))
      return mcs;
  }
  return -1;
}

double ThermalNoiseDbm(int width_mhz) {
  return -174.0 + 10.0 * std::log10(width_mhz * 1e6);
}

}  // namespace rlpos
