// Fuzz of the reader of policy files (ReadSavedTensors): a policy folder reaches a worker from
// elsewhere (a campaign's content-hashed artifact, a user's download) and rlpos-sim reads its
// policy.pt. Mutations of a shipped policy.pt, from a fixed seed: each must be refused with a
// one-line std::runtime_error naming the file, or read into tensors whose floats fit their
// shapes; anything else (another exception, a crash, an ASan or UBSan report in the
// RLPOS_SANITIZE build) fails. Fewer inputs than the wire's: each is a 250 KB archive. The
// CRC-32 turns away most edits of data.pkl before it is run; SavedTensorsTest.DamagedPickles*
// runs the unpickler on damaged pickles with their CRCs made right.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "tests/fuzz/fuzz_input.h"
#include "worker/learning/agent_base/saved_tensors.h"

namespace rlpos {
namespace {

constexpr int kPolicyInputs = 20000;
constexpr std::uint64_t kPolicySeed = 20261127;

TEST(PolicyFileFuzz, ReadSavedTensorsRefusesOrReads) {
  std::ifstream in(std::string(RLPOS_SOURCE_DIR) + "/policies/generalist-multi/policy.pt",
                   std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  const std::string valid = bytes.str();
  ASSERT_GT(valid.size(), 1000u);
  ASSERT_FALSE(ReadSavedTensorsFromBytes(valid, "policy.pt").empty());
  testing::FuzzInput fuzz(kPolicySeed);
  long accepted = 0, refused = 0;
  for (int i = 0; i < kPolicyInputs; ++i) {
    const std::string input = fuzz.Chance(0.05) ? fuzz.RandomBytes(4096) : fuzz.Mutate(valid);
    try {
      for (const SavedTensor& t : ReadSavedTensorsFromBytes(input, "policy.pt")) {
        std::size_t count = 1;
        for (const std::int64_t size : t.sizes) {
          ASSERT_GE(size, 0) << "input " << i;
          count *= static_cast<std::size_t>(size);
        }
        ASSERT_EQ(t.values.size(), count) << "input " << i << ": " << t.name;
      }
      ++accepted;
    } catch (const std::runtime_error& e) {
      const std::string message = e.what();
      ASSERT_EQ(message.rfind("policy.pt: ", 0), 0u) << "input " << i << ": " << message;
      ASSERT_EQ(message.find('\n'), std::string::npos) << "input " << i << ": " << message;
      ++refused;
    }
  }
  std::printf("policy.pt: %ld accepted, %ld refused\n", accepted, refused);
  EXPECT_GT(accepted, 0) << "no input was accepted; the fuzz never got deep";
  EXPECT_GT(refused, 0) << "no input was refused; the fuzz never mutated";
}

}  // namespace
}  // namespace rlpos
