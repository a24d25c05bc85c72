#pragma once
// rlpos-sim render SCENARIO [--position X,Y,Z]... | [--result RESULT.json] |
//   [--placement LABEL=X,Y,Z[;X,Y,Z]...]... [--trajectory FILE.csv] [--side] --out FILE.png|.svg
// A map of the scenario (worker/map): the baseline placement unless told another, with each UE's
// link to its serving UAV; several --placement draw the placements of several positioners in
// one picture (what a campaign report shows).
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "worker/programs/rlpos_sim/commands.h"

namespace rlpos::sim {

struct RenderCommand {
  CLI::App* command = nullptr;
  std::vector<std::string> positions;   // x,y,z per UAV
  std::string result;                   // a position, train or eval JSON
  std::vector<std::string> placements;  // LABEL=x,y,z[;x,y,z]
  std::string trajectory;               // trajectory.csv of rlpos-sim train
  bool side = false;
  std::string out;
};

// Adds `render` to `app`; the scenario file goes into options.scenario_file.
void AddRender(CLI::App& app, RenderCommand& render, CommonOptions& options);
int RunRender(const CommonOptions& options, const RenderCommand& render);

}  // namespace rlpos::sim
