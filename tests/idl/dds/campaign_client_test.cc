// rlpos-campaign's request over DDS (coordinator/cli/campaign_client.cc) when another
// participant on the domain matches before the coordinator does, as on an unsecured network.
#include "coordinator/cli/campaign_client.h"

#include <gtest/gtest.h>

#include <string>

#include "common/process/child_process.h"
#include "tests/idl/dds/dds_test_support.h"
#include "tests/support/temp_dir.h"

namespace rlpos {
namespace {

// A bystander reads requests and forges a reply before any coordinator's reader exists: the
// client's first request reaches the bystander alone. A request reader and reply writer that
// match afterwards (the late coordinator, in the same child process) still get the request,
// because the client sends it again when a reader matches, and their answer is the one taken.
TEST(CampaignClient, ACoordinatorThatMatchesAfterAnotherReaderStillGetsTheRequest) {
  const DdsOptions options = testing::TestOptions();
  const testing::TempDir dir;
  const auto out = [&] { return testing::ReadFile(dir.File("child.out")); };
  const auto err = [&] { return testing::ReadFile(dir.File("child.err")); };
  msg::CampaignReply reply;
  {
    ChildProcess child({testing::SelfExecutable(), testing::kChildLateCoordinatorFlag,
                        std::to_string(options.domain), options.loopback_tag},
                       dir.File("child.out"), dir.File("child.err"));
    ASSERT_TRUE(testing::WaitFor([&] { return out() == "ready\n"; }, 20.0)) << err();
    msg::CampaignRequest request;
    request.kind = msg::RequestKind::kCancel;
    request.campaign_id = "0123456789ab";
    try {
      reply = SendCampaignRequest(options, request, 30.0, {}, [](const msg::CampaignReply& r) {
        return r.campaign_id == "0123456789ab" ? "" : "forged";
      });
    } catch (const std::exception& e) {
      ADD_FAILURE() << e.what() << "; child: " << out() << err();
    }
    ASSERT_TRUE(testing::WaitFor([&] { return child.Poll(); }, 40.0));
    EXPECT_TRUE(child.exit_status().exited);
    EXPECT_EQ(child.exit_status().code, 0) << err();
  }
  EXPECT_EQ(reply.campaign_id, "0123456789ab");
  EXPECT_EQ(reply.jobs, 3);
}

}  // namespace
}  // namespace rlpos
