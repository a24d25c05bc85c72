#include "idl/dds/security/security_config.h"

#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace rlpos::security {

namespace {

std::string XmlEscaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string Library(const std::string& plugin, const std::string& function) {
  const std::string dir = PluginDir();
  const std::string path = (dir.empty() ? "" : dir + "/") + "libdds_security_" + plugin + ".so";
  std::error_code error;
  if (!dir.empty() && !std::filesystem::exists(path, error)) {
    throw std::runtime_error(path +
                             ": missing: Cyclone DDS's security plugins are not where "
                             "this build found them (reinstall libddsc0debian)");
  }
  return "<Library path=\"" + XmlEscaped(path) + "\" initFunction=\"init_" + function +
         "\" finalizeFunction=\"finalize_" + function + "\"/>";
}

std::string Uri(const std::string& file) {
  return "file:" + XmlEscaped(file);
}

}  // namespace

std::string PluginDir() {
#ifdef RLPOS_DDS_SECURITY_PLUGIN_DIR
  return RLPOS_DDS_SECURITY_PLUGIN_DIR;
#else
  return "";
#endif
}

std::string SecurityElementXml(const IdentityFiles& files) {
  return "<Security><Authentication>" + Library("auth", "authentication") + "<IdentityCA>" +
         Uri(files.ca_cert) + "</IdentityCA><IdentityCertificate>" + Uri(files.cert) +
         "</IdentityCertificate><PrivateKey>" + Uri(files.key) +
         "</PrivateKey></Authentication><AccessControl>" + Library("ac", "access_control") +
         "<PermissionsCA>" + Uri(files.ca_cert) + "</PermissionsCA><Governance>" +
         Uri(files.governance) + "</Governance><Permissions>" + Uri(files.permissions) +
         "</Permissions></AccessControl><Cryptographic>" + Library("crypto", "crypto") +
         "</Cryptographic></Security>";
}

}  // namespace rlpos::security
