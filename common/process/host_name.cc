#include "common/process/host_name.h"

#include <unistd.h>

namespace rlpos {

std::string HostName() {
  char host[256] = {0};
  if (gethostname(host, sizeof host - 1) != 0)
    return "localhost";
  return host;
}

}  // namespace rlpos
