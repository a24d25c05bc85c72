#include "tests/support/command.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace rlpos::testing {

CommandResult RunCommand(const std::string& command_line) {
  char err_path[] = "/tmp/rlpos-test-stderr-XXXXXX";
  const int fd = mkstemp(err_path);
  if (fd < 0)
    throw std::runtime_error("mkstemp failed");
  close(fd);
  CommandResult result;
  FILE* pipe = popen((command_line + " 2>" + err_path).c_str(), "r");
  if (!pipe)
    throw std::runtime_error("popen failed");
  char buffer[4096];
  std::size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0)
    result.out.append(buffer, n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  std::ifstream err(err_path);
  std::stringstream content;
  content << err.rdbuf();
  result.err = content.str();
  std::remove(err_path);
  return result;
}

std::string BuiltBinary(const std::string& name) {
  return std::string(RLPOS_BIN_DIR) + "/" + name;
}

}  // namespace rlpos::testing
