// Agreement of the analytic throughput estimate with packet-level ns-3 over two grids of UAV
// positions: Spearman rank correlation and median relative error.
//   zone  5 x 3 points spread over the whole zone at 10 and 30 m (near and far from the UEs)
//   ues   3 x 3 x 3 points over the UEs' bounding box, at 10, 20 and 30 m: where a positioner
//         ends up, and where the differences are small
//   rlpos-bench-calibration SCENARIO.json [DURATION_S] [--positions]
// --positions also prints each position's analytic and packet-level throughput.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include "common/scenario/scenario_checks.h"
#include "tests/bench/bench_scenario.h"
#include "tests/support/program_usage.h"
#include "worker/env/network/uav_network.h"
#include "worker/env/uav_env/analytic_evaluator.h"

namespace {

std::vector<double> Ranks(const std::vector<double>& v) {
  std::vector<std::size_t> order(v.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return v[a] < v[b]; });
  std::vector<double> rank(v.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && v[order[j + 1]] == v[order[i]])
      ++j;
    for (std::size_t k = i; k <= j; ++k)
      rank[order[k]] = 0.5 * (i + j);  // ties: mean rank
    i = j + 1;
  }
  return rank;
}

double Pearson(const std::vector<double>& a, const std::vector<double>& b) {
  const double ma = std::accumulate(a.begin(), a.end(), 0.0) / a.size();
  const double mb = std::accumulate(b.begin(), b.end(), 0.0) / b.size();
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return sab / std::sqrt(saa * sbb);
}

std::vector<rlpos::Vec3> ZoneGrid(const rlpos::Scenario& s) {
  const rlpos::Box& zone = s.uavs[0].zone;
  std::vector<rlpos::Vec3> grid;
  for (double z : {10.0, 30.0}) {
    for (double fx : {0.1, 0.3, 0.5, 0.7, 0.9}) {
      for (double fy : {0.15, 0.5, 0.85}) {
        grid.push_back({zone.xmin + fx * (zone.xmax - zone.xmin),
                        zone.ymin + fy * (zone.ymax - zone.ymin),
                        std::clamp(z, zone.zmin, zone.zmax)});
      }
    }
  }
  return grid;
}

std::vector<rlpos::Vec3> UeGrid(const rlpos::Scenario& s) {
  rlpos::Box box{1e9, -1e9, 1e9, -1e9, 0, 0};
  for (const auto& ue : s.ues) {
    box.xmin = std::min(box.xmin, ue.position.x);
    box.xmax = std::max(box.xmax, ue.position.x);
    box.ymin = std::min(box.ymin, ue.position.y);
    box.ymax = std::max(box.ymax, ue.position.y);
  }
  const rlpos::Box& zone = s.uavs[0].zone;
  std::vector<rlpos::Vec3> grid;
  for (double z : {10.0, 20.0, 30.0}) {
    for (double fx : {0.0, 0.5, 1.0}) {
      for (double fy : {0.0, 0.5, 1.0}) {
        grid.push_back({std::clamp(box.xmin + fx * (box.xmax - box.xmin), zone.xmin, zone.xmax),
                        std::clamp(box.ymin + fy * (box.ymax - box.ymin), zone.ymin, zone.ymax),
                        std::clamp(z, zone.zmin, zone.zmax)});
      }
    }
  }
  return grid;
}

void Compare(const rlpos::Scenario& s, const char* label, std::vector<rlpos::Vec3> grid,
             bool per_position) {
  grid.erase(
      std::remove_if(grid.begin(), grid.end(),
                     [&](const rlpos::Vec3& p) { return rlpos::BuildingContaining(s, p) >= 0; }),
      grid.end());
  std::vector<double> analytic, packet;
  {
    rlpos::AnalyticEvaluator evaluator(s);
    for (const auto& p : grid)
      analytic.push_back(evaluator.Evaluate({p}).throughput_mbps);
  }
  for (const auto& p : grid)
    packet.push_back(rlpos::EvaluatePosition(s, {p}).aggregate_throughput_mbps);
  std::vector<double> errors;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    if (per_position) {
      std::printf("%s (%4.0f, %4.0f, %4.0f)  analytic %7.1f  packet %7.1f Mbit/s\n", label,
                  grid[i].x, grid[i].y, grid[i].z, analytic[i], packet[i]);
    }
    if (packet[i] > 0)
      errors.push_back(std::abs(analytic[i] - packet[i]) / packet[i]);
  }
  std::sort(errors.begin(), errors.end());
  const double median_error = errors.empty() ? NAN : errors[errors.size() / 2];
  std::printf(
      "%-8s %-5s %zu positions, %.1f s each: Spearman %.3f, median |error| %.1f %%, mean "
      "analytic %.1f vs packet %.1f Mbit/s\n",
      s.name.c_str(), label, grid.size(), s.simulation.duration - s.simulation.warmup,
      Pearson(Ranks(analytic), Ranks(packet)), 100 * median_error,
      std::accumulate(analytic.begin(), analytic.end(), 0.0) / analytic.size(),
      std::accumulate(packet.begin(), packet.end(), 0.0) / packet.size());
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  constexpr char kUsage[] =
      "usage: rlpos-bench-calibration SCENARIO.json [DURATION_S] [--positions]\n";
  if (rlpos::testing::PrintedHelp(argc, argv, kUsage))
    return 0;
  if (argc < 2 || argc > 4)
    return rlpos::testing::UsageError(kUsage);
  const std::optional<rlpos::Scenario> scenario =
      LoadBenchScenario(argv[1], argc > 2 ? argv[2] : "2");
  if (!scenario)
    return 1;
  const rlpos::Scenario& s = *scenario;
  const bool per_position = argc > 3 && std::string(argv[3]) == "--positions";
  Compare(s, "zone", ZoneGrid(s), per_position);
  Compare(s, "ues", UeGrid(s), per_position);
  return 0;
}
