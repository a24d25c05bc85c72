// rlpos-campaign's request over DDS (coordinator/cli/campaign_client.cc) when another
// participant on the domain matches before the coordinator does, as on an unsecured network.
#include "cli/campaign_client.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "dds_test_support.h"
#include "process/child_process.h"

namespace rlpos {
namespace {

std::string Slurp(const std::string& path) {
  std::string text;
  if (FILE* f = std::fopen(path.c_str(), "r")) {
    char buffer[512];
    std::size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, f)) > 0)
      text.append(buffer, n);
    std::fclose(f);
  }
  return text;
}

// A bystander reads requests and forges a reply before any coordinator's reader exists: the
// client's first request reaches the bystander alone. A request reader and reply writer that
// match afterwards (the late coordinator, in the same child process) still get the request,
// because the client sends it again when a reader matches, and their answer is the one taken.
TEST(CampaignClient, ACoordinatorThatMatchesAfterAnotherReaderStillGetsTheRequest) {
  const DdsOptions options = testing::TestOptions();
  char pattern[] = "/tmp/rlpos-dds-XXXXXX";
  ASSERT_NE(::mkdtemp(pattern), nullptr);
  const std::string dir = pattern;
  msg::CampaignReply reply;
  {
    ChildProcess child({testing::SelfExecutable(), testing::kChildLateCoordinatorFlag,
                        std::to_string(options.domain), options.loopback_tag},
                       dir + "/child.out", dir + "/child.err");
    ASSERT_TRUE(testing::WaitFor([&] { return Slurp(dir + "/child.out") == "ready\n"; }, 20.0))
        << Slurp(dir + "/child.err");
    msg::CampaignRequest request;
    request.kind = msg::RequestKind::kCancel;
    request.campaign_id = "0123456789ab";
    try {
      reply = SendCampaignRequest(options, request, 30.0, {}, [](const msg::CampaignReply& r) {
        return r.campaign_id == "0123456789ab" ? "" : "forged";
      });
    } catch (const std::exception& e) {
      ADD_FAILURE() << e.what() << "; child: " << Slurp(dir + "/child.out")
                    << Slurp(dir + "/child.err");
    }
    ASSERT_TRUE(testing::WaitFor([&] { return child.Poll(); }, 40.0));
    EXPECT_TRUE(child.exit_status().exited);
    EXPECT_EQ(child.exit_status().code, 0) << Slurp(dir + "/child.err");
  }
  EXPECT_EQ(reply.campaign_id, "0123456789ab");
  EXPECT_EQ(reply.jobs, 3);
  for (const char* name : {"/child.out", "/child.err"})
    std::remove((dir + name).c_str());
  ::rmdir(dir.c_str());
}

}  // namespace
}  // namespace rlpos
