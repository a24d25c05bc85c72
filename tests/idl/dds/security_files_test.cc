// `rlpos-campaign security`'s folder and the check every daemon makes before Cyclone loads an
// identity: what init and add-worker make, and one named file and cause for each way an
// identity can be wrong (missing, expired, not yet valid, wrong CA, wrong key, subject
// mismatch, role not allowed). No DDS here: Cyclone's own enforcement is in
// secured_topics_test.cc.
#include <gtest/gtest.h>

#include <ctime>
#include <filesystem>
#include <string>

#include "idl/dds/security/pki.h"
#include "idl/dds/security/security_check.h"
#include "idl/dds/security/security_layout.h"
#include "idl/dds/security/security_setup.h"
#include "tests/support/temp_dir.h"

namespace rlpos::security {
namespace {

namespace fs = std::filesystem;
using rlpos::testing::ReadFile;
using rlpos::testing::TempDir;
using rlpos::testing::WriteFile;

constexpr std::time_t kDay = 86400;

// The message of the SecuritySetupError `check` throws, or "" when it throws none.
template <typename F>
std::string ErrorOf(F check) {
  try {
    check();
  } catch (const SecuritySetupError& e) {
    return e.what();
  }
  return "";
}

class SecurityFilesTest : public ::testing::Test {
 protected:
  // One CA folder for the suite: RSA keys take a while to make.
  static void SetUpTestSuite() {
    temp_ = new TempDir;
    InitSecurityDir(Dir());
  }
  static void TearDownTestSuite() {
    delete temp_;
    temp_ = nullptr;
  }
  static std::string Dir() { return temp_->File("sec"); }
  static std::time_t Now() { return std::time(nullptr); }

  static TempDir* temp_;
};
TempDir* SecurityFilesTest::temp_ = nullptr;

TEST_F(SecurityFilesTest, InitMakesTheCaGovernanceAndOneIdentityPerRole) {
  for (const char* file : {"ca_cert.pem", "governance.p7s", "private/ca_key.pem"})
    EXPECT_TRUE(fs::is_regular_file(Dir() + "/" + file)) << file;
  EXPECT_EQ(fs::status(Dir() + "/private").permissions() & fs::perms::all, fs::perms::owner_all);
  for (auto role : {DdsRole::kCoordinator, DdsRole::kWorker, DdsRole::kClient}) {
    const IdentityFiles files = CheckIdentity(Dir(), RoleName(role), role, Now());
    EXPECT_TRUE(fs::path(files.cert).is_absolute());
    EXPECT_EQ(fs::status(files.key).permissions() & fs::perms::all,
              fs::perms::owner_read | fs::perms::owner_write);
    const std::string subject = pki::SubjectRfc2253(pki::ReadCert(files.cert));
    EXPECT_EQ(subject, std::string("CN=") + RoleName(role) + ",OU=" + RoleName(role) + ",O=RLpos");
  }
}

TEST_F(SecurityFilesTest, PermissionsGrantEachRoleExactlyItsTopics) {
  const pki::Cert ca = pki::ReadCert(CaCertFile(Dir()));
  const std::string coordinator =
      pki::VerifySmimeFile(FilesOf(Dir(), "coordinator").permissions, ca);
  EXPECT_NE(coordinator.find("<publish><topics><topic>rlpos_job_assignment</topic><topic>"
                             "rlpos_campaign_reply</topic></topics></publish>"),
            std::string::npos)
      << coordinator;
  const std::string worker = pki::VerifySmimeFile(FilesOf(Dir(), "worker").permissions, ca);
  EXPECT_EQ(worker.find("<topic>rlpos_job_assignment</topic></topics></publish>"),
            std::string::npos);
  EXPECT_NE(worker.find("<default>DENY</default>"), std::string::npos);
  const std::string governance = pki::VerifySmimeFile(GovernanceFile(Dir()), ca);
  EXPECT_NE(governance.find("<allow_unauthenticated_participants>false"), std::string::npos);
  EXPECT_NE(governance.find("<data_protection_kind>ENCRYPT"), std::string::npos);
}

TEST_F(SecurityFilesTest, AWorkerIdentityMayNotActAsCoordinatorOrClient) {
  EXPECT_NE(ErrorOf([] {
              CheckIdentity(Dir(), "worker", DdsRole::kCoordinator, Now());
            }).find("identity \"worker\" is not allowed to publish rlpos_job_assignment"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] {
              CheckIdentity(Dir(), "worker", DdsRole::kClient, Now());
            }).find("not allowed to publish rlpos_campaign_request"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] {
              CheckIdentity(Dir(), "client", DdsRole::kWorker, Now());
            }).find(FilesOf(Dir(), "client").permissions),
            std::string::npos);
}

TEST_F(SecurityFilesTest, AddWorkerIssuesANamedWorkerIdentity) {
  AddIdentity(Dir(), "host-b", DdsRole::kWorker);
  const IdentityFiles files = CheckIdentity(Dir(), "host-b", DdsRole::kWorker, Now());
  EXPECT_EQ(pki::SubjectRfc2253(pki::ReadCert(files.cert)), "CN=host-b,OU=worker,O=RLpos");
  EXPECT_THROW(AddIdentity(Dir(), "host-b", DdsRole::kWorker), std::invalid_argument);
  for (const char* bad : {"", "../x", ".hidden", "a/b", "x y", "a<b"})
    EXPECT_THROW(AddIdentity(Dir(), bad, DdsRole::kWorker), std::invalid_argument) << bad;
  // Nothing of the refused ones is left in identities/.
  for (const auto& entry : fs::directory_iterator(Dir() + "/identities"))
    EXPECT_EQ(entry.path().filename().string().find(".partial"), std::string::npos);
}

TEST_F(SecurityFilesTest, ExpiredAndNotYetValidIdentitiesNameTheirFile) {
  IssueOptions past;
  past.now = Now() - 30 * kDay;
  past.days = 2;
  AddIdentity(Dir(), "expired", DdsRole::kWorker, past);
  const std::string expired =
      ErrorOf([] { CheckIdentity(Dir(), "expired", DdsRole::kWorker, Now()); });
  EXPECT_NE(expired.find(FilesOf(Dir(), "expired").cert + ": expired on "), std::string::npos)
      << expired;
  IssueOptions future;
  future.now = Now() + 7 * kDay;
  AddIdentity(Dir(), "future", DdsRole::kWorker, future);
  const std::string early =
      ErrorOf([] { CheckIdentity(Dir(), "future", DdsRole::kWorker, Now()); });
  EXPECT_NE(early.find("not valid before"), std::string::npos) << early;
}

TEST_F(SecurityFilesTest, AnIdentityOfAnotherCaIsRefusedAsWrongCa) {
  TempDir other;
  InitSecurityDir(other.File("sec"));
  TempDir mixed;
  fs::copy(Dir(), mixed.File("sec"), fs::copy_options::recursive);
  fs::copy(other.File("sec/identities/worker/cert.pem"),
           mixed.File("sec/identities/worker/cert.pem"), fs::copy_options::overwrite_existing);
  const std::string error =
      ErrorOf([&] { CheckIdentity(mixed.File("sec"), "worker", DdsRole::kWorker, Now()); });
  EXPECT_NE(error.find("identities/worker/cert.pem: not issued by the CA"), std::string::npos)
      << error;
  EXPECT_NE(error.find("wrong CA"), std::string::npos) << error;

  // Permissions signed by another CA.
  fs::copy(Dir() + "/identities/worker/cert.pem", mixed.File("sec/identities/worker/cert.pem"),
           fs::copy_options::overwrite_existing);
  fs::copy(other.File("sec/identities/worker/permissions.p7s"),
           mixed.File("sec/identities/worker/permissions.p7s"),
           fs::copy_options::overwrite_existing);
  const std::string permissions =
      ErrorOf([&] { CheckIdentity(mixed.File("sec"), "worker", DdsRole::kWorker, Now()); });
  EXPECT_NE(permissions.find("permissions.p7s: signature not valid for this CA"), std::string::npos)
      << permissions;
}

TEST_F(SecurityFilesTest, SwappedPermissionsAreASubjectMismatch) {
  TempDir copy;
  fs::copy(Dir(), copy.File("sec"), fs::copy_options::recursive);
  fs::copy(Dir() + "/identities/client/permissions.p7s",
           copy.File("sec/identities/worker/permissions.p7s"),
           fs::copy_options::overwrite_existing);
  const std::string error =
      ErrorOf([&] { CheckIdentity(copy.File("sec"), "worker", DdsRole::kAny, Now()); });
  EXPECT_NE(error.find("subject mismatch: grants \"CN=client,OU=client,O=RLpos\""),
            std::string::npos)
      << error;
}

TEST_F(SecurityFilesTest, MissingTamperedOrMismatchedFilesAreNamed) {
  TempDir copy;
  const std::string dir = copy.File("sec");
  fs::copy(Dir(), dir, fs::copy_options::recursive);
  const auto error = [&](const std::string& name) {
    return ErrorOf([&] { CheckIdentity(dir, name, DdsRole::kAny, Now()); });
  };
  EXPECT_NE(ErrorOf([&] {
              CheckIdentity(copy.File("none"), "worker", DdsRole::kAny, Now());
            }).find("none: no such folder"),
            std::string::npos);
  EXPECT_NE(error("nobody").find("identities/nobody: no such identity"), std::string::npos);
  EXPECT_NE(error("../private").find("--identity: identity name"), std::string::npos);

  fs::copy(Dir() + "/identities/client/key.pem", dir + "/identities/worker/key.pem",
           fs::copy_options::overwrite_existing);
  EXPECT_NE(error("worker").find("identities/worker/key.pem: is not the key of"),
            std::string::npos);

  const std::string governance = ReadFile(dir + "/governance.p7s");
  const std::string tampered =
      std::string(governance).replace(governance.find("<max>230</max>"), 14, "<max>231</max>");
  WriteFile(dir + "/governance.p7s", tampered);
  EXPECT_NE(error("client").find("governance.p7s: signature not valid"), std::string::npos);

  WriteFile(dir + "/identities/coordinator/cert.pem", "not a certificate\n");
  EXPECT_NE(error("coordinator").find("identities/coordinator/cert.pem: not a PEM certificate"),
            std::string::npos);
  fs::remove(dir + "/ca_cert.pem");
  EXPECT_NE(error("worker").find("ca_cert.pem: missing"), std::string::npos);
}

TEST(SecurityInit, RefusesAFolderInUseAndLeavesNothingHalfWritten) {
  TempDir temp;
  WriteFile(temp.File("taken"), "x");
  EXPECT_THROW(InitSecurityDir(temp.File("taken")), std::invalid_argument);
  EXPECT_EQ(ReadFile(temp.File("taken")), "x");
  // A folder that cannot be created leaves no partial sibling behind.
  EXPECT_THROW(InitSecurityDir(temp.File("missing-parent/sec")), std::runtime_error);
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(temp.path()))
    ++entries;
  EXPECT_EQ(entries, 1u);
  IssueOptions zero;
  zero.days = 0;
  EXPECT_THROW(InitSecurityDir(temp.File("sec"), zero), std::invalid_argument);
  EXPECT_FALSE(fs::exists(temp.File("sec")));
}

}  // namespace
}  // namespace rlpos::security
