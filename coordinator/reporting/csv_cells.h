#pragma once
// The cells of the report's CSV files, written one way everywhere: RFC 4180 quoting, numbers
// with as many digits as it takes to read the same double back, and an empty cell for a value
// that is absent or undefined (NaN), which spreadsheets and pandas read as missing.
#include <optional>
#include <string>
#include <vector>

namespace rlpos {

// The text as is, or quoted ("" for ") when it holds a comma, a quote or a line break.
std::string CsvText(const std::string& text);
// Shortest round-trip form ("120.5", "0.1", "1e-07"); "" for NaN or infinity.
std::string CsvNumber(double value);
std::string CsvNumber(const std::optional<double>& value);
// The value, or absent for NaN or infinity: what the CSV and JSON files carry for a number.
std::optional<double> Finite(double value);
std::optional<double> Finite(const std::optional<double>& value);
// The cells joined by commas, ending with "\n" (cells must already be CsvText/CsvNumber).
std::string CsvLine(const std::vector<std::string>& cells);

}  // namespace rlpos
