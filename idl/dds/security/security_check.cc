#include "idl/dds/security/security_check.h"

#include <filesystem>
#include <set>
#include <system_error>
#include <vector>

#include "idl/dds/security/pki.h"
#include "idl/dds/security/security_documents.h"

namespace rlpos::security {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void Fail(const std::string& file, const std::string& cause) {
  throw SecuritySetupError(file + ": " + cause);
}

void RequireFile(const std::string& file) {
  std::error_code error;
  if (!fs::is_regular_file(file, error))
    Fail(file, "missing (`rlpos-campaign security init|add-worker` makes it)");
}

std::string Between(const std::string& text, const std::string& open, const std::string& close,
                    std::size_t from = 0) {
  const std::size_t start = text.find(open, from);
  if (start == std::string::npos)
    return {};
  const std::size_t end = text.find(close, start + open.size());
  if (end == std::string::npos)
    return {};
  return text.substr(start + open.size(), end - start - open.size());
}

std::string Trim(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos)
    return {};
  return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

// A subject's RDNs as a set, so that "CN=a,OU=b,O=c" equals "O=c/OU=b/CN=a".
std::set<std::string> Rdns(const std::string& subject) {
  std::set<std::string> rdns;
  std::string field;
  for (char c : subject + ",") {
    if (c == ',' || c == '/') {
      if (!Trim(field).empty())
        rdns.insert(Trim(field));
      field.clear();
    } else {
      field += c;
    }
  }
  return rdns;
}

std::time_t ParsePermissionsTime(const std::string& text, const std::string& file) {
  struct tm tm {};
  const char* end = strptime(text.c_str(), "%Y-%m-%dT%H:%M:%S", &tm);
  if (end == nullptr || *end != '\0')
    Fail(file, "validity time \"" + text + "\" is not YYYY-MM-DDThh:mm:ss");
  return timegm(&tm);
}

std::string When(std::time_t t) {
  return PermissionsTime(t) + " UTC";
}

// Every <topic> inside every `section` (publish or subscribe) of the permissions.
std::set<std::string> GrantedTopics(const std::string& permissions, const std::string& section) {
  std::set<std::string> topics;
  const std::string open = "<" + section + ">";
  const std::string close = "</" + section + ">";
  std::size_t at = 0;
  while ((at = permissions.find(open, at)) != std::string::npos) {
    const std::string block = Between(permissions, open, close, at);
    std::size_t t = 0;
    while ((t = block.find("<topic>", t)) != std::string::npos) {
      topics.insert(Trim(Between(block, "<topic>", "</topic>", t)));
      t += 7;
    }
    at += open.size();
  }
  return topics;
}

void CheckPermissions(const std::string& file, const std::string& text, const pki::Cert& cert,
                      const std::string& cert_file, const std::string& name, DdsRole role,
                      std::time_t now) {
  const std::string subject = Trim(Between(text, "<subject_name>", "</subject_name>"));
  const std::string cert_subject = pki::SubjectRfc2253(cert);
  if (Rdns(subject) != Rdns(cert_subject)) {
    Fail(file, "subject mismatch: grants \"" + subject + "\" but " + cert_file + " is \"" +
                   cert_subject + "\"");
  }
  const std::time_t not_before =
      ParsePermissionsTime(Trim(Between(text, "<not_before>", "</not_before>")), file);
  const std::time_t not_after =
      ParsePermissionsTime(Trim(Between(text, "<not_after>", "</not_after>")), file);
  if (now > not_after)
    Fail(file, "expired on " + When(not_after));
  if (now < not_before)
    Fail(file, "not valid before " + When(not_before));
  for (const char* section : {"publish", "subscribe"}) {
    const auto granted = GrantedTopics(text, section);
    const auto needed =
        std::string(section) == "publish" ? PublishedTopics(role) : SubscribedTopics(role);
    for (const auto& topic : needed) {
      if (granted.count(topic) == 0 && granted.count("*") == 0) {
        Fail(file, "identity \"" + name + "\" is not allowed to " + section + " " + topic +
                       ", which the " + RoleName(role) + " does (use a " + RoleName(role) +
                       " identity: --identity NAME)");
      }
    }
  }
}

}  // namespace

IdentityFiles CheckIdentity(const std::string& dir_in, const std::string& name, DdsRole role,
                            std::time_t now) {
  try {
    CheckIdentityName(name);
  } catch (const std::invalid_argument& e) {
    throw SecuritySetupError(std::string("--identity: ") + e.what());
  }
  std::error_code error;
  if (!fs::is_directory(dir_in, error))
    Fail(dir_in, "no such folder (make one with `rlpos-campaign security init DIR`)");
  const std::string dir = fs::absolute(dir_in, error).lexically_normal().string();
  IdentityFiles files = FilesOf(dir, name);
  if (!fs::is_directory(IdentityDir(dir, name), error))
    Fail(IdentityDir(dir, name),
         "no such identity (issue one with `rlpos-campaign security "
         "add-worker DIR NAME`, or pick one with --identity)");
  for (const auto& file :
       {files.ca_cert, files.governance, files.cert, files.key, files.permissions}) {
    RequireFile(file);
  }
  try {
    const pki::Cert ca = pki::ReadCert(files.ca_cert);
    if (const std::string reason = pki::VerifyCertificate(ca, ca, now); !reason.empty())
      Fail(files.ca_cert, "CA certificate not valid: " + reason);
    const pki::Cert cert = pki::ReadCert(files.cert);
    if (const std::string reason = pki::VerifyCertificate(cert, ca, now); !reason.empty()) {
      const auto validity = pki::CertValidity(cert);
      if (now > validity.not_after)
        Fail(files.cert, "expired on " + When(validity.not_after));
      if (now < validity.not_before)
        Fail(files.cert, "not valid before " + When(validity.not_before));
      if (reason.find("issuer") != std::string::npos ||
          reason.find("signature") != std::string::npos)
        Fail(files.cert,
             "not issued by the CA of " + files.ca_cert + " (wrong CA: " + reason + ")");
      Fail(files.cert, reason);
    }
    if (!pki::KeyMatchesCert(pki::ReadKey(files.key), cert))
      Fail(files.key, "is not the key of " + files.cert);
    pki::VerifySmimeFile(files.governance, ca);
    const std::string permissions = pki::VerifySmimeFile(files.permissions, ca);
    CheckPermissions(files.permissions, permissions, cert, files.cert, name, role, now);
  } catch (const pki::PkiError& e) {
    throw SecuritySetupError(e.what());
  }
  return files;
}

}  // namespace rlpos::security
