#include "idl/dds/security/security_setup.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "idl/dds/security/pki.h"
#include "idl/dds/security/security_documents.h"
#include "idl/dds/security/security_layout.h"

namespace rlpos::security {

namespace fs = std::filesystem;

namespace {

// Certificates start an hour early, so that hosts whose clocks lag a little accept them.
constexpr std::time_t kClockSkew = 3600;
constexpr std::time_t kDay = 86400;

void WriteNewFile(const std::string& file, const std::string& text, mode_t mode) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, mode);
  if (fd < 0)
    throw std::runtime_error(file + ": cannot create: " + std::strerror(errno));
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR)
      continue;
    if (n <= 0) {
      const int error = errno;
      ::close(fd);
      throw std::runtime_error(file + ": cannot write: " + std::strerror(error));
    }
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0)
    throw std::runtime_error(file + ": cannot write: " + std::strerror(errno));
}

void MakeDir(const std::string& dir, mode_t mode) {
  if (::mkdir(dir.c_str(), mode) != 0)
    throw std::runtime_error(dir + ": cannot create: " + std::strerror(errno));
}

std::time_t Now(const IssueOptions& options) {
  return options.now != 0 ? options.now : std::time(nullptr);
}

void CheckDays(int days, const char* what) {
  if (days < 1 || days > 36500)
    throw std::invalid_argument(std::string(what) + ": must be in 1..36500 days");
}

// Writes identity NAME's files into a new `folder`.
void WriteIdentity(const std::string& folder, const std::string& name, DdsRole role,
                   const pki::Cert& ca, const pki::Key& ca_key, const IssueOptions& options) {
  const std::time_t now = Now(options);
  const pki::Validity ca_validity = pki::CertValidity(ca);
  pki::Validity validity{now - kClockSkew, now + options.days * kDay};
  validity.not_after = std::min(validity.not_after, ca_validity.not_after);
  const pki::Key key = pki::GenerateKey();
  const pki::Cert cert = pki::IssueCertificate(
      key, std::string("/O=RLpos/OU=") + RoleName(role) + "/CN=" + name, validity, ca, ca_key);
  const std::string permissions = PermissionsXml(name, pki::SubjectRfc2253(cert), role,
                                                 validity.not_before, validity.not_after);
  MakeDir(folder, 0755);
  WriteNewFile(folder + "/cert.pem", pki::CertPem(cert), 0644);
  WriteNewFile(folder + "/key.pem", pki::KeyPem(key), 0600);
  WriteNewFile(folder + "/permissions.p7s", pki::SignSmime(permissions, ca, ca_key), 0644);
}

// Runs `build` on a temporary sibling of `target` and renames it to `target`; removes the
// sibling if anything fails.
template <typename Build>
void BuildThenRename(const std::string& target, Build build) {
  const std::string partial = target + ".partial-" + std::to_string(::getpid());
  std::error_code ignored;
  fs::remove_all(partial, ignored);
  try {
    build(partial);
    if (::rename(partial.c_str(), target.c_str()) != 0)
      throw std::runtime_error(target + ": cannot create: " + std::strerror(errno));
  } catch (...) {
    fs::remove_all(partial, ignored);
    throw;
  }
}

}  // namespace

void InitSecurityDir(const std::string& dir, const IssueOptions& options) {
  CheckDays(options.days, "--days");
  CheckDays(options.ca_days, "--ca-days");
  std::error_code error;
  if (fs::exists(dir, error)) {
    if (!fs::is_directory(dir, error) || !fs::is_empty(dir, error)) {
      throw std::invalid_argument(dir +
                                  ": already exists; init makes a new folder (issue more "
                                  "identities with `rlpos-campaign security add-worker`)");
    }
    fs::remove(dir, error);  // empty: rename replaces it
  }
  BuildThenRename(dir, [&](const std::string& out) {
    MakeDir(out, 0755);
    MakeDir(out + "/private", 0700);
    MakeDir(out + "/identities", 0755);
    const std::time_t now = Now(options);
    const pki::Key ca_key = pki::GenerateKey();
    const pki::Cert ca = pki::MakeCaCertificate(ca_key, "/O=RLpos/CN=RLpos CA",
                                                {now - kClockSkew, now + options.ca_days * kDay});
    WriteNewFile(CaKeyFile(out), pki::KeyPem(ca_key), 0600);
    WriteNewFile(CaCertFile(out), pki::CertPem(ca), 0644);
    WriteNewFile(GovernanceFile(out), pki::SignSmime(GovernanceXml(), ca, ca_key), 0644);
    for (DdsRole role : {DdsRole::kCoordinator, DdsRole::kWorker, DdsRole::kClient})
      WriteIdentity(out + "/identities/" + RoleName(role), RoleName(role), role, ca, ca_key,
                    options);
  });
}

std::string AddIdentity(const std::string& dir, const std::string& name, DdsRole role,
                        const IssueOptions& options) {
  CheckIdentityName(name);
  CheckDays(options.days, "--days");
  if (role == DdsRole::kAny)
    throw std::invalid_argument("an identity needs a role: coordinator, worker or client");
  std::error_code error;
  if (!fs::is_directory(dir, error))
    throw std::invalid_argument(dir + ": no such folder (make one with `security init DIR`)");
  if (!fs::is_regular_file(CaKeyFile(dir), error)) {
    throw std::invalid_argument(CaKeyFile(dir) +
                                ": missing: issue identities where `security init` made the CA");
  }
  const pki::Cert ca = pki::ReadCert(CaCertFile(dir));
  const pki::Key ca_key = pki::ReadKey(CaKeyFile(dir));
  const std::string target = IdentityDir(dir, name);
  if (fs::exists(target, error))
    throw std::invalid_argument(target + ": already exists");
  BuildThenRename(
      target, [&](const std::string& out) { WriteIdentity(out, name, role, ca, ca_key, options); });
  return target;
}

}  // namespace rlpos::security
