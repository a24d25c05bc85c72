#include "idl/dds/security/security_documents.h"

#include <vector>

#include "idl/dds/security/security_layout.h"

namespace rlpos::security {

namespace {

const char* const kDomains = "<domains><id_range><min>0</min><max>230</max></id_range></domains>";

std::string TopicList(const std::vector<std::string>& topics) {
  std::string xml = "<topics>";
  for (const auto& topic : topics)
    xml += "<topic>" + topic + "</topic>";
  return xml + "</topics>";
}

}  // namespace

std::string GovernanceXml() {
  return std::string(
             "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
             "<dds xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" "
             "xsi:noNamespaceSchemaLocation=\"http://www.omg.org/spec/DDS-SECURITY/20170901/"
             "omg_shared_ca_governance.xsd\">\n"
             "<domain_access_rules>\n<domain_rule>\n") +
         kDomains +
         "\n<allow_unauthenticated_participants>false</allow_unauthenticated_participants>\n"
         "<enable_join_access_control>true</enable_join_access_control>\n"
         "<discovery_protection_kind>ENCRYPT</discovery_protection_kind>\n"
         "<liveliness_protection_kind>ENCRYPT</liveliness_protection_kind>\n"
         "<rtps_protection_kind>ENCRYPT</rtps_protection_kind>\n"
         "<topic_access_rules>\n<topic_rule>\n"
         "<topic_expression>*</topic_expression>\n"
         "<enable_discovery_protection>true</enable_discovery_protection>\n"
         "<enable_liveliness_protection>true</enable_liveliness_protection>\n"
         "<enable_read_access_control>true</enable_read_access_control>\n"
         "<enable_write_access_control>true</enable_write_access_control>\n"
         "<metadata_protection_kind>ENCRYPT</metadata_protection_kind>\n"
         "<data_protection_kind>ENCRYPT</data_protection_kind>\n"
         "</topic_rule>\n</topic_access_rules>\n"
         "</domain_rule>\n</domain_access_rules>\n</dds>\n";
}

std::string PermissionsTime(std::time_t t) {
  struct tm tm {};
  gmtime_r(&t, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%S", &tm);
  return text;
}

std::string PermissionsXml(const std::string& name, const std::string& subject, DdsRole role,
                           std::time_t not_before, std::time_t not_after) {
  // Without <partitions> a rule allows only the default partition, which is all RLpos uses.
  std::string rule = std::string("<allow_rule>\n") + kDomains + "\n";
  const auto published = PublishedTopics(role);
  const auto subscribed = SubscribedTopics(role);
  if (!published.empty())
    rule += "<publish>" + TopicList(published) + "</publish>\n";
  if (!subscribed.empty())
    rule += "<subscribe>" + TopicList(subscribed) + "</subscribe>\n";
  rule += "</allow_rule>\n";
  return std::string(
             "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
             "<dds xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" "
             "xsi:noNamespaceSchemaLocation=\"http://www.omg.org/spec/DDS-SECURITY/20170901/"
             "omg_shared_ca_permissions.xsd\">\n"
             "<permissions>\n<grant name=\"") +
         name + "\">\n<subject_name>" + subject + "</subject_name>\n<validity><not_before>" +
         PermissionsTime(not_before) + "</not_before><not_after>" + PermissionsTime(not_after) +
         "</not_after></validity>\n" + rule +
         "<default>DENY</default>\n</grant>\n"
         "</permissions>\n</dds>\n";
}

}  // namespace rlpos::security
