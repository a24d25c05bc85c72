#include "coordinator/reporting/text_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rlpos {
namespace {

std::string Pad(const std::string& text, std::size_t width, bool left) {
  const std::string fill(width > text.size() ? width - text.size() : 0, ' ');
  return left ? text + fill : fill + text;
}

std::string MarkdownCell(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '|')
      out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

std::string TableNumber(double value, int decimals, bool sign) {
  if (!std::isfinite(value))
    return "-";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, sign ? "%+.*f" : "%.*f", decimals, value);
  return buffer;
}

std::string TableNumber(const std::optional<double>& value, int decimals, bool sign) {
  return value ? TableNumber(*value, decimals, sign) : "-";
}

std::string FormatTextTable(const std::vector<TableColumn>& columns,
                            const std::vector<std::vector<std::string>>& rows) {
  std::vector<std::size_t> widths;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    std::size_t width = std::string(columns[c].title).size();
    for (const auto& row : rows)
      width = std::max(width, row[c].size());
    widths.push_back(width);
  }
  const auto line = [&](const std::vector<std::string>& cells) {
    std::string out;
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (c > 0)
        out += "  ";
      out += Pad(cells[c], widths[c], columns[c].left_aligned);
    }
    while (!out.empty() && out.back() == ' ')
      out.pop_back();
    return out + "\n";
  };
  std::vector<std::string> titles, rules;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    titles.push_back(columns[c].title);
    rules.push_back(std::string(widths[c], '-'));
  }
  std::string out = line(titles) + line(rules);
  for (const auto& row : rows)
    out += line(row);
  return out;
}

std::string FormatMarkdownTable(const std::vector<TableColumn>& columns,
                                const std::vector<std::vector<std::string>>& rows) {
  std::string header = "|", rule = "|";
  for (const auto& column : columns) {
    header += std::string(" ") + column.title + " |";
    rule += column.left_aligned ? "---|" : "---:|";
  }
  std::string out = header + "\n" + rule + "\n";
  for (const auto& row : rows) {
    out += "|";
    for (const auto& cell : row)
      out += " " + MarkdownCell(cell) + " |";
    out += "\n";
  }
  return out;
}

}  // namespace rlpos
