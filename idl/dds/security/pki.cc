#include "idl/dds/security/pki.h"

#include <openssl/bio.h>
#include <openssl/bn.h>
#include <openssl/err.h>
#include <openssl/evp.h>
#include <openssl/pem.h>
#include <openssl/pkcs7.h>
#include <openssl/rand.h>
#include <openssl/rsa.h>
#include <openssl/x509.h>
#include <openssl/x509v3.h>

#include <cstdio>
#include <vector>

namespace rlpos::pki {

void KeyFree::operator()(void* key) const {
  EVP_PKEY_free(static_cast<EVP_PKEY*>(key));
}
void CertFree::operator()(void* cert) const {
  X509_free(static_cast<X509*>(cert));
}

namespace {

struct BioFree {
  void operator()(BIO* bio) const { BIO_free(bio); }
};
using Bio = std::unique_ptr<BIO, BioFree>;

EVP_PKEY* K(const Key& key) {
  return static_cast<EVP_PKEY*>(key.get());
}
X509* C(const Cert& cert) {
  return static_cast<X509*>(cert.get());
}

// OpenSSL's last queued reason, e.g. "no start line"; clears the queue.
std::string OpenSslReason() {
  std::string reason;
  unsigned long code;
  while ((code = ERR_get_error()) != 0) {
    const char* text = ERR_reason_error_string(code);
    reason = text != nullptr ? text : "error " + std::to_string(code);
  }
  return reason.empty() ? "unknown OpenSSL error" : reason;
}

[[noreturn]] void Fail(const std::string& what) {
  throw PkiError(what + ": " + OpenSslReason());
}

std::string BioText(BIO* bio) {
  char* data = nullptr;
  const long n = BIO_get_mem_data(bio, &data);
  return std::string(data, static_cast<std::size_t>(n));
}

Bio FileBio(const std::string& file) {
  Bio bio(BIO_new_file(file.c_str(), "r"));
  if (!bio) {
    ERR_clear_error();
    throw PkiError(file + ": cannot be read");
  }
  return bio;
}

X509_NAME* ParseSubject(const std::string& subject) {
  // "/O=RLpos/CN=name": fields never hold '/' here (names are checked by the caller).
  X509_NAME* name = X509_NAME_new();
  std::size_t at = 0;
  while (at < subject.size()) {
    if (subject[at] != '/')
      break;
    const std::size_t next = subject.find('/', at + 1);
    const std::string field =
        subject.substr(at + 1, next == std::string::npos ? next : next - at - 1);
    const std::size_t eq = field.find('=');
    if (eq == std::string::npos ||
        X509_NAME_add_entry_by_txt(name, field.substr(0, eq).c_str(), MBSTRING_UTF8,
                                   reinterpret_cast<const unsigned char*>(field.c_str() + eq + 1),
                                   -1, -1, 0) != 1) {
      X509_NAME_free(name);
      Fail("certificate subject \"" + subject + "\"");
    }
    at = next == std::string::npos ? subject.size() : next;
  }
  return name;
}

void AddExtension(X509* cert, X509* issuer, int nid, const char* value) {
  X509V3_CTX ctx;
  X509V3_set_ctx_nodb(&ctx);
  X509V3_set_ctx(&ctx, issuer, cert, nullptr, nullptr, 0);
  X509_EXTENSION* ext = X509V3_EXT_conf_nid(nullptr, &ctx, nid, value);
  if (ext == nullptr)
    Fail("certificate extension");
  X509_add_ext(cert, ext, -1);
  X509_EXTENSION_free(ext);
}

Cert BuildCert(const Key& key, const std::string& subject, const Validity& validity, X509* issuer,
               EVP_PKEY* issuer_key, bool is_ca) {
  Cert cert(X509_new());
  X509* x = C(cert);
  X509_set_version(x, 2);
  unsigned char serial[16];
  if (RAND_bytes(serial, sizeof serial) != 1)
    Fail("certificate serial");
  serial[0] &= 0x7f;  // positive
  BIGNUM* bn = BN_bin2bn(serial, sizeof serial, nullptr);
  BN_to_ASN1_INTEGER(bn, X509_get_serialNumber(x));
  BN_free(bn);
  ASN1_TIME_set(X509_getm_notBefore(x), validity.not_before);
  ASN1_TIME_set(X509_getm_notAfter(x), validity.not_after);
  X509_NAME* name = ParseSubject(subject);
  X509_set_subject_name(x, name);
  X509_set_issuer_name(x, issuer != nullptr ? X509_get_subject_name(issuer) : name);
  X509_NAME_free(name);
  X509_set_pubkey(x, K(key));
  X509* signer = issuer != nullptr ? issuer : x;
  AddExtension(x, signer, NID_basic_constraints, is_ca ? "critical,CA:TRUE" : "CA:FALSE");
  AddExtension(x, signer, NID_key_usage,
               is_ca ? "critical,keyCertSign,cRLSign,digitalSignature"
                     : "critical,digitalSignature,keyEncipherment");
  AddExtension(x, signer, NID_subject_key_identifier, "hash");
  if (X509_sign(x, issuer_key != nullptr ? issuer_key : K(key), EVP_sha256()) <= 0)
    Fail("signing the certificate of " + subject);
  return cert;
}

}  // namespace

Key GenerateKey() {
  EVP_PKEY* key = EVP_RSA_gen(2048);
  if (key == nullptr)
    Fail("generating an RSA key");
  return Key(key);
}

Cert MakeCaCertificate(const Key& key, const std::string& subject, const Validity& validity) {
  return BuildCert(key, subject, validity, nullptr, nullptr, true);
}

Cert IssueCertificate(const Key& key, const std::string& subject, const Validity& validity,
                      const Cert& ca, const Key& ca_key) {
  return BuildCert(key, subject, validity, C(ca), K(ca_key), false);
}

std::string KeyPem(const Key& key) {
  Bio bio(BIO_new(BIO_s_mem()));
  if (PEM_write_bio_PrivateKey(bio.get(), K(key), nullptr, nullptr, 0, nullptr, nullptr) != 1)
    Fail("writing a private key");
  return BioText(bio.get());
}

std::string CertPem(const Cert& cert) {
  Bio bio(BIO_new(BIO_s_mem()));
  if (PEM_write_bio_X509(bio.get(), C(cert)) != 1)
    Fail("writing a certificate");
  return BioText(bio.get());
}

std::string SignSmime(const std::string& text, const Cert& signer, const Key& key) {
  const int flags = PKCS7_DETACHED | PKCS7_TEXT | PKCS7_STREAM;
  Bio in(BIO_new_mem_buf(text.data(), static_cast<int>(text.size())));
  PKCS7* p7 = PKCS7_sign(C(signer), K(key), nullptr, in.get(), flags);
  if (p7 == nullptr)
    Fail("signing a document");
  Bio out(BIO_new(BIO_s_mem()));
  const int ok = SMIME_write_PKCS7(out.get(), p7, in.get(), flags);
  PKCS7_free(p7);
  if (ok != 1)
    Fail("writing a signed document");
  return BioText(out.get());
}

Key ReadKey(const std::string& file) {
  Bio bio = FileBio(file);
  EVP_PKEY* key = PEM_read_bio_PrivateKey(bio.get(), nullptr, nullptr, nullptr);
  if (key == nullptr)
    Fail(file + ": not a PEM private key");
  return Key(key);
}

Cert ReadCert(const std::string& file) {
  Bio bio = FileBio(file);
  X509* cert = PEM_read_bio_X509(bio.get(), nullptr, nullptr, nullptr);
  if (cert == nullptr)
    Fail(file + ": not a PEM certificate");
  return Cert(cert);
}

std::string VerifyCertificate(const Cert& cert, const Cert& ca, std::time_t now) {
  X509_STORE* store = X509_STORE_new();
  X509_STORE_add_cert(store, C(ca));
  X509_STORE_CTX* ctx = X509_STORE_CTX_new();
  X509_STORE_CTX_init(ctx, store, C(cert), nullptr);
  X509_STORE_CTX_set_time(ctx, 0, now);
  const int ok = X509_verify_cert(ctx);
  std::string reason;
  if (ok != 1)
    reason = X509_verify_cert_error_string(X509_STORE_CTX_get_error(ctx));
  X509_STORE_CTX_free(ctx);
  X509_STORE_free(store);
  ERR_clear_error();
  return reason;
}

bool KeyMatchesCert(const Key& key, const Cert& cert) {
  const bool ok = X509_check_private_key(C(cert), K(key)) == 1;
  ERR_clear_error();
  return ok;
}

std::string VerifySmimeFile(const std::string& file, const Cert& ca) {
  Bio bio = FileBio(file);
  BIO* content = nullptr;
  PKCS7* p7 = SMIME_read_PKCS7(bio.get(), &content);
  if (p7 == nullptr)
    Fail(file + ": not an S/MIME signed document");
  Bio content_owner(content);
  X509_STORE* store = X509_STORE_new();
  X509_STORE_add_cert(store, C(ca));
  // The signer is the CA itself; its validity at signing time is checked by the peers.
  X509_STORE_set_flags(store, X509_V_FLAG_PARTIAL_CHAIN);
  Bio out(BIO_new(BIO_s_mem()));
  const int ok = PKCS7_verify(p7, nullptr, store, content, out.get(), PKCS7_TEXT);
  PKCS7_free(p7);
  X509_STORE_free(store);
  if (ok != 1)
    Fail(file + ": signature not valid for this CA");
  return BioText(out.get());
}

std::string SubjectRfc2253(const Cert& cert) {
  Bio bio(BIO_new(BIO_s_mem()));
  X509_NAME_print_ex(bio.get(), X509_get_subject_name(C(cert)), 0, XN_FLAG_RFC2253);
  return BioText(bio.get());
}

Validity CertValidity(const Cert& cert) {
  auto to_time = [](const ASN1_TIME* t) {
    struct tm tm {};
    ASN1_TIME_to_tm(t, &tm);
    return timegm(&tm);
  };
  return {to_time(X509_get0_notBefore(C(cert))), to_time(X509_get0_notAfter(C(cert)))};
}

}  // namespace rlpos::pki
