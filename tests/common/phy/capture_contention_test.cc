#include "common/phy/capture_contention.h"

#include <gtest/gtest.h>

#include <vector>

namespace rlpos {
namespace {

CaptureParams WithCapture(double probability) {
  CaptureParams params;
  params.probability = probability;
  return params;
}

TEST(CaptureContention, EqualStationsShareEquallyAndNeverCapture) {
  const std::vector<double> snr(20, 30.0);
  const CaptureShares s = ContendWithCapture(snr, 1.0, WithCapture(1.0));
  for (std::size_t i = 0; i < snr.size(); ++i) {
    EXPECT_NEAR(s.access_weight[i], 1.0, 1e-9);
    EXPECT_DOUBLE_EQ(s.capture_share[i], 0.0);
  }
}

TEST(CaptureContention, WithoutCaptureItIsBianchisFixedPoint) {
  // Unequal stations but no capture: everyone fails as in the symmetric model.
  const std::vector<double> snr = {20, 25, 30, 35, 40};
  const CaptureShares s = ContendWithCapture(snr, 1.0, WithCapture(0.0));
  for (std::size_t i = 0; i < snr.size(); ++i) {
    EXPECT_NEAR(s.access_weight[i], 1.0, 1e-9);
    EXPECT_DOUBLE_EQ(s.capture_share[i], 0.0);
  }
}

TEST(CaptureContention, AStrongStationWinsAccessesAndPaysWithCaptures) {
  std::vector<double> snr(10, 30.0);
  snr[0] = 40.0;
  const CaptureShares s = ContendWithCapture(snr, 1.0, WithCapture(0.5));
  EXPECT_GT(s.access_weight[0], 1.2);
  EXPECT_GT(s.capture_share[0], 0.05);
  EXPECT_LT(s.capture_share[0], 0.5);
  for (std::size_t i = 1; i < snr.size(); ++i) {
    EXPECT_LT(s.access_weight[i], 1.0);
    EXPECT_NEAR(s.access_weight[i], s.access_weight[1], 1e-9);
    EXPECT_DOUBLE_EQ(s.capture_share[i], 0.0);  // none of them is 4 dB above another
  }
}

TEST(CaptureContention, BelowThePreambleThresholdThereIsNoCapture) {
  const std::vector<double> snr = {33.9, 30.0, 30.0, 30.0};
  const CaptureShares s = ContendWithCapture(snr, 1.0, WithCapture(1.0));
  EXPECT_NEAR(s.access_weight[0], 1.0, 1e-9);
  EXPECT_DOUBLE_EQ(s.capture_share[0], 0.0);
  const std::vector<double> over = {34.0, 30.0, 30.0, 30.0};
  EXPECT_GT(ContendWithCapture(over, 1.0, WithCapture(1.0)).capture_share[0], 0.0);
}

TEST(CaptureContention, AnIdleChannelHasNoCollisionsToCapture) {
  const std::vector<double> snr = {40, 20, 20};
  const CaptureShares quiet = ContendWithCapture(snr, 0.0, WithCapture(1.0));
  EXPECT_NEAR(quiet.access_weight[0], 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(quiet.capture_share[0], 0.0);
  const CaptureShares busy = ContendWithCapture(snr, 1.0, WithCapture(1.0));
  const CaptureShares light = ContendWithCapture(snr, 0.3, WithCapture(1.0));
  EXPECT_GT(busy.capture_share[0], light.capture_share[0]);
  EXPECT_GT(light.capture_share[0], 0.0);
}

}  // namespace
}  // namespace rlpos
