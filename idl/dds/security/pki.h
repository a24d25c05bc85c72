#pragma once
// The small part of OpenSSL's libcrypto that RLpos's DDS Security needs: RSA keys, a
// self-signed CA, identity certificates signed by it, and S/MIME signatures of the governance
// and permissions documents in the clear-signed form Cyclone DDS reads (`openssl smime -sign
// -text`). Every failure throws PkiError naming the file and OpenSSL's reason.
#include <ctime>
#include <memory>
#include <stdexcept>
#include <string>

namespace rlpos::pki {

class PkiError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct KeyFree {
  void operator()(void* key) const;
};
struct CertFree {
  void operator()(void* cert) const;
};
// Opaque owners of EVP_PKEY and X509, so that callers need no OpenSSL header.
using Key = std::unique_ptr<void, KeyFree>;
using Cert = std::unique_ptr<void, CertFree>;

struct Validity {
  std::time_t not_before = 0;
  std::time_t not_after = 0;
};

// RSA 2048.
Key GenerateKey();
// `subject` in the /K=V/K=V form. Serial numbers are random (128 bits).
Cert MakeCaCertificate(const Key& key, const std::string& subject, const Validity& validity);
Cert IssueCertificate(const Key& key, const std::string& subject, const Validity& validity,
                      const Cert& ca, const Key& ca_key);

// PEM text; files are written by the caller (see WriteFileAtomically).
std::string KeyPem(const Key& key);
std::string CertPem(const Cert& cert);
// The clear-signed S/MIME message of `text` (detached signature, text/plain content).
std::string SignSmime(const std::string& text, const Cert& signer, const Key& key);

Key ReadKey(const std::string& file);
Cert ReadCert(const std::string& file);

// "" when `cert` is signed by `ca` and valid at `now`; otherwise the reason ("certificate has
// expired", "unable to get local issuer certificate"...).
std::string VerifyCertificate(const Cert& cert, const Cert& ca, std::time_t now);
bool KeyMatchesCert(const Key& key, const Cert& cert);
// The signed content of an S/MIME file if its signature is `ca`'s; throws PkiError naming the
// file and the reason otherwise.
std::string VerifySmimeFile(const std::string& file, const Cert& ca);

// "CN=name,OU=role,O=RLpos" (RFC 2253 order, as DDS Security permissions write subjects).
std::string SubjectRfc2253(const Cert& cert);
Validity CertValidity(const Cert& cert);

}  // namespace rlpos::pki
