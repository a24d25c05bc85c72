#include "common/scenario_import/data_rate.h"

#include <gtest/gtest.h>

#include "common/config/config_error.h"

namespace rlpos {
namespace {

std::string ErrorOf(const std::string& text) {
  try {
    DataRateMbps(text, "/rate");
  } catch (const ConfigError& e) {
    return e.describe();
  }
  return "";
}

TEST(DataRate, Ns3UnitsAsMbps) {
  EXPECT_DOUBLE_EQ(DataRateMbps("58.5Mbps", "/rate"), 58.5);
  EXPECT_DOUBLE_EQ(DataRateMbps("117Mb/s", "/rate"), 117.0);
  EXPECT_DOUBLE_EQ(DataRateMbps("1Gbps", "/rate"), 1000.0);
  EXPECT_DOUBLE_EQ(DataRateMbps("500kbps", "/rate"), 0.5);
  EXPECT_DOUBLE_EQ(DataRateMbps("500Kbps", "/rate"), 0.5);  // ns-3: K is 1000 as k is
  EXPECT_DOUBLE_EQ(DataRateMbps("16250KBps", "/rate"), 130.0);
  EXPECT_DOUBLE_EQ(DataRateMbps("1MiB/s", "/rate"), 8.388608);
  EXPECT_DOUBLE_EQ(DataRateMbps("2000000", "/rate"), 2.0);  // no unit: bit/s
}

TEST(DataRate, BadRatesNameThePath) {
  EXPECT_EQ(ErrorOf("-5Mbps"), "/rate: negative data rate \"-5Mbps\"");
  EXPECT_EQ(ErrorOf("0Mbps"), "/rate: the data rate must be positive, got \"0Mbps\"");
  EXPECT_EQ(ErrorOf("fast"), "/rate: expected a data rate such as \"58.5Mbps\", got \"fast\"");
  EXPECT_EQ(ErrorOf("1.2.3Mbps"),
            "/rate: expected a data rate such as \"58.5Mbps\", got \"1.2.3Mbps\"");
  // ns-3 takes no space between the number and the unit.
  EXPECT_NE(ErrorOf("58.5 Mbps").find("unknown data rate unit \" Mbps\""), std::string::npos);
  EXPECT_NE(ErrorOf("58.5Mbit/s").find("unknown data rate unit \"Mbit/s\""), std::string::npos);
}

}  // namespace
}  // namespace rlpos
