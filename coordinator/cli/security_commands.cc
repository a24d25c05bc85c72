// rlpos-campaign security init DIR | add-worker DIR NAME | add-client DIR NAME: what they made
// and where each file goes.
#include <ctime>
#include <filesystem>
#include <iostream>

#include "coordinator/cli/campaign_commands.h"
#include "idl/dds/security/security_check.h"
#include "idl/dds/security/security_layout.h"
#include "idl/dds/security/security_setup.h"

namespace rlpos {

int InitSecurity(const std::string& dir, int days) {
  security::IssueOptions options;
  options.days = days;
  security::InitSecurityDir(dir, options);
  std::cout << "DDS Security folder " << dir << ": a CA, the governance and the identities "
            << "coordinator, worker and client (valid " << days << " days).\n"
            << "Each host needs ca_cert.pem, governance.p7s and its own identities/NAME; keep "
            << "private/ (the CA's key) on this machine only.\n";
  return kExitOk;
}

int AddSecurityIdentity(const std::string& dir, const std::string& name, DdsRole role, int days) {
  security::IssueOptions options;
  options.days = days;
  const std::string folder = security::AddIdentity(dir, name, role, options);
  // The new identity must pass the same check the daemons make at start; if not, it goes.
  try {
    security::CheckIdentity(dir, name, role, std::time(nullptr));
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove_all(folder, ignored);
    throw;
  }
  std::cout << "identity " << name << " (" << RoleName(role) << "): " << folder
            << "\nuse it with --security DIR --identity " << name << "\n";
  return kExitOk;
}

}  // namespace rlpos
