#include "worker/env/analytic/mcs_error_rates.h"

#include <ns3/double.h>
#include <ns3/error-rate-model.h>
#include <ns3/object-factory.h>
#include <ns3/wifi-remote-station-manager.h>

#include <cmath>
#include <stdexcept>

#include "common/phy/airtime_model.h"
#include "common/phy/mcs_table.h"
#include "worker/env/network/ns3_object_spec.h"
#include "worker/env/network/wifi_channel_plan.h"

namespace rlpos {
namespace {

// The 0.01 dB step TableBasedErrorRateModel rounds `snr_db` to, computed as it does (from the
// linear ratio the caller hands it).
double RoundedStep(double snr_db) {
  const double db = 10.0 * std::log10(std::pow(10.0, snr_db / 10));
  return std::floor(db * 100.0 + 0.5);
}

// The range scanned for the table's ends: every AWGN table of ns-3.37 lies well inside.
constexpr long kLowestStep = -5000;   // -50 dB
constexpr long kHighestStep = 10000;  // 100 dB

// Whether ns-3.37's TableBasedErrorRateModel has an AWGN table for `tx` (else it falls back to
// YansErrorRateModel with the exact SNR): HT's MCS count modulo 8, then BCC 0-9, LDPC 0-11.
bool Tabled(const ns3::WifiTxVector& tx) {
  const ns3::WifiMode mode = tx.GetMode();
  int mcs = mode.GetMcsValue();
  if (mode.GetModulationClass() == ns3::WIFI_MOD_CLASS_HT)
    mcs %= 8;
  return mcs < (tx.IsLdpc() ? 12 : 10);
}

}  // namespace

struct McsErrorRates::Fallback {
  ns3::Ptr<ns3::ErrorRateModel> model;
  std::vector<ns3::WifiTxVector> tx;  // per MCS
  uint64_t mpdu_bits = 0;
  double Success(int mcs, double ratio) const {
    const ns3::WifiTxVector& v = tx[static_cast<std::size_t>(mcs)];
    return model->GetChunkSuccessRate(v.GetMode(), v, ratio, mpdu_bits, v.GetNss());
  }
};

McsErrorRates::McsErrorRates(const Scenario& scenario) : fallback_(std::make_unique<Fallback>()) {
  const WifiSpec& w = scenario.wifi;
  const WifiChannelPlan plan = PlanUavChannels(scenario).front();
  fallback_->model = ns3::ObjectFactory(kErrorRateModel).Create<ns3::ErrorRateModel>();
  fallback_->mpdu_bits = static_cast<uint64_t>(MpduBytes(scenario.traffic.packet_size)) * 8;
  // The BER threshold of the rate manager the radios get (IdealWifiManager's default if it has
  // none), as UavNetwork reads it off a radio.
  double ber = 1e-6;
  auto manager = CreateFromSpec(w.rate_manager, "/wifi/rate_manager",
                                ns3::WifiRemoteStationManager::GetTypeId());
  ns3::TypeId::AttributeInformation info;
  if (manager->GetInstanceTypeId().LookupAttributeByName("BerThreshold", &info)) {
    ns3::DoubleValue value;
    manager->GetAttribute("BerThreshold", value);
    ber = value.Get();
  }
  for (int mcs = 0; mcs <= MaxMcs(w.standard); ++mcs) {
    fallback_->tx.push_back(SingleUserTxVector(plan, w, mcs));
    const ns3::WifiTxVector& tx = fallback_->tx.back();
    // What WifiPhy::CalculateSnr asks of the PHY's error rate model (a twin of this one).
    thresholds_db_.push_back(10.0 * std::log10(fallback_->model->CalculateSnr(tx, ber)));
    PerMcs rates;
    rates.tabled = Tabled(tx);
    if (rates.tabled) {
      const auto at = [&](long step) {
        return fallback_->Success(mcs, std::pow(10.0, (step / 100.0) / 10));
      };
      rates.below = at(kLowestStep);
      rates.above = at(kHighestStep);
      if (rates.below != 0.0 || rates.above != 1.0)
        throw std::logic_error("MPDU success of MCS " + std::to_string(mcs) +
                               " is not 0 at -50 dB and 1 at 100 dB");
      // The rate grows with the SNR: bisect for the first step above 0 and the last below 1.
      long lo = kLowestStep, hi = kHighestStep;  // at(lo) == 0, at(hi) > 0
      while (hi - lo > 1) {
        const long mid = lo + (hi - lo) / 2;
        (at(mid) > 0.0 ? hi : lo) = mid;
      }
      const long first = hi;
      lo = kLowestStep;  // at(lo) < 1, at(hi) == 1
      hi = kHighestStep;
      while (hi - lo > 1) {
        const long mid = lo + (hi - lo) / 2;
        (at(mid) < 1.0 ? lo : hi) = mid;
      }
      rates.first_step = first;
      for (long step = first; step <= lo; ++step)
        rates.success.push_back(at(step));
    }
    per_mcs_.push_back(std::move(rates));
  }
}

McsErrorRates::~McsErrorRates() = default;

double McsErrorRates::MpduSuccessRate(int mcs, double snr_db) const {
  const PerMcs& rates = per_mcs_.at(static_cast<std::size_t>(mcs));
  if (!rates.tabled)
    return fallback_->Success(mcs, std::pow(10.0, snr_db / 10));
  const double step = RoundedStep(snr_db);
  if (step < static_cast<double>(rates.first_step))
    return rates.below;
  const double k = step - static_cast<double>(rates.first_step);
  if (k >= static_cast<double>(rates.success.size()))
    return rates.above;
  return rates.success[static_cast<std::size_t>(k)];
}

}  // namespace rlpos
