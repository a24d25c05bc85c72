// libtorch's thread count: one by default, the operator's OMP_NUM_THREADS when set.
#include "worker/learning/agent/torch_threads.h"

#include <ATen/Parallel.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

namespace rlpos {
namespace {

// Sets or clears OMP_NUM_THREADS for one test and puts the old value back.
class OmpNumThreads {
 public:
  explicit OmpNumThreads(const char* value) {
    if (const char* old = std::getenv("OMP_NUM_THREADS"))
      old_ = old;
    if (value)
      setenv("OMP_NUM_THREADS", value, 1);
    else
      unsetenv("OMP_NUM_THREADS");
  }
  ~OmpNumThreads() {
    if (old_)
      setenv("OMP_NUM_THREADS", old_->c_str(), 1);
    else
      unsetenv("OMP_NUM_THREADS");
  }

 private:
  std::optional<std::string> old_;
};

TEST(TorchThreads, OneUnlessTheEnvironmentAsks) {
  const OmpNumThreads unset(nullptr);
  at::set_num_threads(2);
  EXPECT_EQ(UseOneTorchThreadUnlessAsked(), 1);
  EXPECT_EQ(at::get_num_threads(), 1);
}

TEST(TorchThreads, OmpNumThreadsIsLeftInForce) {
  const OmpNumThreads asked("2");
  at::set_num_threads(2);  // what libtorch makes of OMP_NUM_THREADS=2 at start
  EXPECT_EQ(UseOneTorchThreadUnlessAsked(), 2);
  EXPECT_EQ(at::get_num_threads(), 2);
}

}  // namespace
}  // namespace rlpos
