// Cyclone DDS's own enforcement of the permissions `rlpos-campaign security init` signs: an
// identity gets a reader or writer only on the topics of its role (creation fails with "Not
// Allowed By Security" otherwise). The check made before Cyclone (security_check.h) is skipped
// here by using DdsRole::kAny, so these refusals are Cyclone's, not ours. Exchanges between
// secured and unsecured processes are in tests/e2e/secured_campaign.sh.
#include <gtest/gtest.h>

#include <ctime>
#include <string>

#include "idl/dds/participant.h"
#include "idl/dds/security/security_check.h"
#include "idl/dds/security/security_setup.h"
#include "idl/dds/topics.h"
#include "tests/idl/dds/dds_test_support.h"
#include "tests/support/temp_dir.h"

namespace rlpos {
namespace {

class SecuredTopicsTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    temp_ = new testing::TempDir;
    security::InitSecurityDir(Dir());
  }
  static void TearDownTestSuite() {
    delete temp_;
    temp_ = nullptr;
  }
  static std::string Dir() { return temp_->File("sec"); }

  // A loopback participant of its own tag, secured with `identity`, role unchecked by RLpos.
  static DdsOptions Secured(const std::string& identity) {
    DdsOptions options = testing::TestOptions();
    options.security_dir = Dir();
    options.identity = identity;
    return options;
  }

  // The message of the DdsError that making an entity throws, or "" when it is made.
  template <typename Entity>
  static std::string RefusalOf(Participant& participant) {
    try {
      Entity entity(participant);
    } catch (const DdsError& e) {
      return e.what();
    }
    return "";
  }

  static testing::TempDir* temp_;
};
testing::TempDir* SecuredTopicsTest::temp_ = nullptr;

const char kRefused[] = "Not Allowed By Security";

TEST_F(SecuredTopicsTest, TheCoordinatorIdentityGetsExactlyItsReadersAndWriters) {
  Participant participant(Secured("coordinator"));
  EXPECT_EQ(RefusalOf<Writer<msg::JobAssignment>>(participant), "");
  EXPECT_EQ(RefusalOf<Writer<msg::CampaignReply>>(participant), "");
  EXPECT_EQ(RefusalOf<Reader<msg::WorkerStatus>>(participant), "");
  EXPECT_EQ(RefusalOf<Reader<msg::JobEvent>>(participant), "");
  EXPECT_EQ(RefusalOf<Reader<msg::CampaignRequest>>(participant), "");
  EXPECT_NE(RefusalOf<Writer<msg::JobEvent>>(participant).find(kRefused), std::string::npos);
  EXPECT_NE(RefusalOf<Writer<msg::CampaignRequest>>(participant).find(kRefused), std::string::npos);
}

TEST_F(SecuredTopicsTest, AWorkerCertificateCannotPublishAssignmentsOrReplies) {
  Participant participant(Secured("worker"));
  EXPECT_EQ(RefusalOf<Writer<msg::JobEvent>>(participant), "");
  EXPECT_EQ(RefusalOf<Writer<msg::WorkerStatus>>(participant), "");
  EXPECT_EQ(RefusalOf<Reader<msg::JobAssignment>>(participant), "");
  const std::string assignment = RefusalOf<Writer<msg::JobAssignment>>(participant);
  EXPECT_NE(assignment.find("DDS writer of rlpos_job_assignment: "), std::string::npos)
      << assignment;
  EXPECT_NE(assignment.find(kRefused), std::string::npos) << assignment;
  EXPECT_NE(RefusalOf<Writer<msg::CampaignReply>>(participant).find(kRefused), std::string::npos);
  // Nor read what clients ask.
  EXPECT_NE(RefusalOf<Reader<msg::CampaignRequest>>(participant).find(kRefused), std::string::npos);
}

TEST_F(SecuredTopicsTest, AClientCertificateCannotPublishJobEventsOrStatus) {
  Participant participant(Secured("client"));
  EXPECT_EQ(RefusalOf<Writer<msg::CampaignRequest>>(participant), "");
  EXPECT_EQ(RefusalOf<Reader<msg::CampaignReply>>(participant), "");
  EXPECT_NE(RefusalOf<Writer<msg::JobEvent>>(participant).find(kRefused), std::string::npos);
  EXPECT_NE(RefusalOf<Writer<msg::WorkerStatus>>(participant).find(kRefused), std::string::npos);
  EXPECT_NE(RefusalOf<Writer<msg::JobAssignment>>(participant).find(kRefused), std::string::npos);
}

TEST_F(SecuredTopicsTest, ARoleIsCheckedBeforeCycloneWithTheFileNamed) {
  DdsOptions options = Secured("worker");
  options.role = DdsRole::kCoordinator;
  try {
    Participant participant(options);
    FAIL() << "a worker identity started as coordinator";
  } catch (const security::SecuritySetupError& e) {
    EXPECT_NE(std::string(e.what()).find("identities/worker/permissions.p7s: identity \"worker\" "
                                         "is not allowed to publish rlpos_job_assignment"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(SecuredTopicsTest, AnExpiredIdentityNeverReachesCyclone) {
  security::IssueOptions past;
  past.now = std::time(nullptr) - 10 * 86400;
  past.days = 1;
  security::AddIdentity(Dir(), "old-worker", DdsRole::kWorker, past);
  DdsOptions options = Secured("old-worker");
  options.role = DdsRole::kWorker;
  try {
    Participant participant(options);
    FAIL() << "an expired identity made a participant";
  } catch (const security::SecuritySetupError& e) {
    EXPECT_NE(std::string(e.what()).find("identities/old-worker/cert.pem: expired on"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace rlpos
