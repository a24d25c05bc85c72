#pragma once
// Tables of already formatted cells, as the terminal and Markdown show them: one layout for
// every table of `rlpos-campaign results` and of the report.
#include <optional>
#include <string>
#include <vector>

namespace rlpos {

struct TableColumn {
  const char* title;
  bool left_aligned;
};

// A number rounded for reading ("%.*f", "%+.*f" with `sign`); "-" for NaN, infinity or absent.
std::string TableNumber(double value, int decimals, bool sign = false);
std::string TableNumber(const std::optional<double>& value, int decimals, bool sign = false);

// Fixed-width columns two spaces apart, header and a rule first, no trailing blanks.
std::string FormatTextTable(const std::vector<TableColumn>& columns,
                            const std::vector<std::vector<std::string>>& rows);
// A GitHub-flavoured Markdown table ('|' in a cell escaped).
std::string FormatMarkdownTable(const std::vector<TableColumn>& columns,
                                const std::vector<std::vector<std::string>>& rows);

}  // namespace rlpos
