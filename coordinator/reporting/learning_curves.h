#pragma once
// The report's learning curves: per train job, the reward, loss and epsilon of each episode,
// read from the learning_curve.csv artifact it sent home.
#include <string>
#include <vector>

#include "common/store/results_reader.h"

namespace rlpos {

struct LearningCurvePoint {
  std::string scenario, label;  // label: rl, rl@seed2, ...
  int episode = 0;
  std::string phase;  // train | eval
  double total_reward = 0, mean_loss = 0, epsilon = 0;
};

// The points of every train job of the campaign that has a learning curve, in job order. A
// curve file that is missing or unreadable adds a warning naming it and is skipped.
std::vector<LearningCurvePoint> ReadLearningCurves(ResultsReader& store,
                                                   const std::string& campaign_id,
                                                   std::vector<std::string>& warnings);

// CSV: scenario,label,episode,phase,total_reward,mean_loss,epsilon.
std::string FormatLearningCurvesCsv(const std::vector<LearningCurvePoint>& points);

}  // namespace rlpos
