#pragma once
// ns-3 DataRate strings ("58.5Mbps", "1Gb/s", "500kbps", "1000000") as Mbit/s.
#include <string>

namespace rlpos {

// Parses a number followed by one of ns-3's DataRate units (bps, b/s, Bps, B/s with the
// prefixes k, K, M, G and the binary Ki, Mi, Gi; no unit: bit/s). Throws ConfigError at `path`
// when the text is not such a rate or the rate is not positive.
double DataRateMbps(const std::string& text, const std::string& path);

}  // namespace rlpos
