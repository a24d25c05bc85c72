#pragma once
// The summary as people and programs read it: a fixed-width table for the terminal
// (`rlpos-campaign results`), a Markdown table for the report, CSV for spreadsheets and JSON for
// scripts. Absent or undefined values (no baseline, one run's CI) are "-" in the tables, an
// empty cell in CSV and null in JSON, never a made-up 0.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "coordinator/reporting/campaign_summary.h"

namespace rlpos {

// Fixed-width columns, header and a rule first; rounded for reading. Header only when empty.
std::string FormatSummaryText(const std::vector<PositionerSummary>& summary);
// The same columns as a GitHub-flavoured Markdown table.
std::string FormatSummaryMarkdown(const std::vector<PositionerSummary>& summary);
// Header row (SummaryCsvColumns()) then one row per entry, numbers unrounded.
std::string FormatSummaryCsv(const std::vector<PositionerSummary>& summary);
const std::vector<std::string>& SummaryCsvColumns();
// An array of objects whose keys are SummaryCsvColumns(); null for absent or NaN.
nlohmann::json SummaryToJson(const std::vector<PositionerSummary>& summary);

}  // namespace rlpos
