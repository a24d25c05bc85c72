#include "idl/dds/dds_config.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "idl/dds/participant.h"
#include "tests/idl/dds/dds_test_support.h"

namespace rlpos {
namespace {

DdsOptions Options(int domain, const std::string& config, const std::string& tag) {
  DdsOptions options;
  options.domain = domain;
  options.config = config;
  options.loopback_tag = tag;
  return options;
}

// The message of the std::invalid_argument CheckDdsOptions throws ("" and a failure if none).
std::string Rejection(const DdsOptions& options) {
  try {
    CheckDdsOptions(options);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted domain " << options.domain << " tag \"" << options.loopback_tag
                << "\" config \"" << options.config << "\"";
  return "";
}

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(CheckDdsOptions, DomainRange) {
  EXPECT_NO_THROW(CheckDdsOptions(Options(0, "", "rlpos-test")));
  EXPECT_NO_THROW(CheckDdsOptions(Options(230, "", "rlpos-test")));
  const std::string high = Rejection(Options(231, "", "rlpos-test"));
  EXPECT_TRUE(Contains(high, "--domain")) << high;
  EXPECT_TRUE(Contains(high, "231")) << high;
  EXPECT_TRUE(Contains(Rejection(Options(-1, "", "rlpos-test")), "-1"));
}

TEST(CheckDdsOptions, ConfigAndTagExcludeEachOther) {
  const std::string both = Rejection(Options(0, "file:///etc/cyclone.xml", "rlpos-test"));
  EXPECT_TRUE(Contains(both, "--loopback")) << both;
  EXPECT_TRUE(Contains(both, "--dds-config")) << both;
  DdsOptions config = Options(0, "file:///etc/cyclone.xml", "");
  config.insecure = true;
  EXPECT_NO_THROW(CheckDdsOptions(config));
}

TEST(CheckDdsOptions, SecureByDefaultOffLoopback) {
  // Off loopback (a config of one's own, or Cyclone's defaults) needs --security or --insecure.
  for (const char* config : {"file:///etc/cyclone.xml", ""}) {
    const std::string refused = Rejection(Options(0, config, ""));
    EXPECT_TRUE(Contains(refused, "--security DIR")) << refused;
    EXPECT_TRUE(Contains(refused, "--insecure")) << refused;
    DdsOptions secured = Options(0, config, "");
    secured.security_dir = "sec";
    EXPECT_NO_THROW(CheckDdsOptions(secured));
    DdsOptions insecure = Options(0, config, "");
    insecure.insecure = true;
    EXPECT_NO_THROW(CheckDdsOptions(insecure));
  }
  // Loopback may go either way.
  DdsOptions loopback = Options(0, "", "rlpos-test");
  EXPECT_NO_THROW(CheckDdsOptions(loopback));
  loopback.security_dir = "sec";
  loopback.identity = "host-b";
  EXPECT_NO_THROW(CheckDdsOptions(loopback));
  DdsOptions both = loopback;
  both.insecure = true;
  EXPECT_TRUE(Contains(Rejection(both), "--insecure and --security"));
  DdsOptions identity_alone = Options(0, "", "rlpos-test");
  identity_alone.identity = "host-b";
  EXPECT_TRUE(Contains(Rejection(identity_alone), "--identity needs --security"));
  // The participant refuses before any DDS call.
  EXPECT_THROW(Participant(Options(3, "", "")), std::invalid_argument);
}

TEST(LoopbackConfigXml, SecurityGoesInsideTheLoopbackDomain) {
  const std::string xml = LoopbackConfigXml("t", 2.0, "<Security/>");
  EXPECT_TRUE(Contains(xml, "</Discovery><Security/></Domain></CycloneDDS>")) << xml;
}

TEST(CheckDdsOptions, TagCharacters) {
  EXPECT_NO_THROW(CheckDdsOptions(Options(3, "", "rlpos-Test_1.2")));
  const std::string space = Rejection(Options(3, "", "my tag"));
  EXPECT_TRUE(Contains(space, "--loopback")) << space;
  EXPECT_TRUE(Contains(space, "\"my tag\"")) << space;
  // Anything that would need escaping in the XML.
  for (const char* tag : {"a<b", "a&b", "a\"b", "a/b", "t\xc3\xa9"}) {
    EXPECT_FALSE(Rejection(Options(3, "", tag)).empty()) << tag;
  }
}

TEST(CheckDdsOptions, ParticipantRefusesBadOptionsBeforeAnyDds) {
  EXPECT_THROW(Participant(Options(231, "", "rlpos-test")), std::invalid_argument);
  EXPECT_THROW(Participant(Options(1, "", "bad tag")), std::invalid_argument);
}

TEST(LoopbackConfigXml, LoopbackOnlyWithTheTagAndLease) {
  const std::string xml = LoopbackConfigXml("rlpos-test-42-7");
  EXPECT_TRUE(Contains(xml, "name=\"lo\"")) << xml;
  EXPECT_TRUE(Contains(xml, "<Tag>rlpos-test-42-7</Tag>")) << xml;
  EXPECT_TRUE(Contains(xml, "<Peer Address=\"127.0.0.1\"/>")) << xml;
  EXPECT_TRUE(Contains(xml, "<LeaseDuration>2.000s</LeaseDuration>")) << xml;
  EXPECT_EQ(xml.rfind("<CycloneDDS>", 0), 0u) << xml;
  EXPECT_TRUE(Contains(LoopbackConfigXml("x", 0.5), "<LeaseDuration>0.500s</LeaseDuration>"));
  // One interface only: nothing but lo.
  std::size_t interfaces = 0;
  for (auto at = xml.find("<NetworkInterface"); at != std::string::npos;
       at = xml.find("<NetworkInterface", at + 1)) {
    ++interfaces;
  }
  EXPECT_EQ(interfaces, 1u);
}

TEST(DdsArgs, FlagsOfEachMode) {
  EXPECT_EQ(DdsArgs(Options(7, "", "rlpos-run-1")),
            (std::vector<std::string>{"--domain", "7", "--loopback", "rlpos-run-1"}));
  EXPECT_EQ(DdsArgs(Options(0, "file:///etc/cyclone.xml", "")),
            (std::vector<std::string>{"--domain", "0", "--dds-config", "file:///etc/cyclone.xml"}));
  EXPECT_EQ(DdsArgs(Options(12, "", "")), (std::vector<std::string>{"--domain", "12"}));
  DdsOptions secured = Options(3, "", "t");
  secured.security_dir = "/etc/rlpos/sec";
  secured.identity = "host-b";
  EXPECT_EQ(DdsArgs(secured),
            (std::vector<std::string>{"--domain", "3", "--loopback", "t", "--security",
                                      "/etc/rlpos/sec", "--identity", "host-b"}));
  DdsOptions insecure = Options(3, "", "");
  insecure.insecure = true;
  EXPECT_EQ(DdsArgs(insecure), (std::vector<std::string>{"--domain", "3", "--insecure"}));
}

TEST(TestOptions, EveryCallHasItsOwnLoopbackTag) {
  const DdsOptions a = testing::TestOptions();
  const DdsOptions b = testing::TestOptions();
  EXPECT_NE(a.loopback_tag, b.loopback_tag);
  EXPECT_EQ(a.domain, b.domain);
  EXPECT_TRUE(a.config.empty());
  EXPECT_NO_THROW(CheckDdsOptions(a));
}

}  // namespace
}  // namespace rlpos
