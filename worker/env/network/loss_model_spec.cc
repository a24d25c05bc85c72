#include "worker/env/network/loss_model_spec.h"

#include <ns3/double.h>

#include <set>

#include "worker/env/network/ns3_object_spec.h"

namespace rlpos {

ns3::Ptr<ns3::PropagationLossModel> CreateLossModel(const Scenario& scenario, double frequency_hz) {
  std::set<const ns3::Object*> user_frequency;
  auto loss = CreateFromSpec(scenario.propagation, "/propagation",
                             ns3::PropagationLossModel::GetTypeId(), "Frequency", &user_frequency)
                  ->GetObject<ns3::PropagationLossModel>();
  // Loss models default to their own frequency (ITU-R P.1411: 2.4 GHz): align them with the
  // channel unless the scenario chose one.
  SetAttributeInTree(loss, "Frequency", ns3::DoubleValue(frequency_hz), user_frequency);
  return loss;
}

}  // namespace rlpos
