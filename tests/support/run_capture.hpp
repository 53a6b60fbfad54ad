#pragma once
// Runs a shell command and returns its exit status and output (stdout and stderr together):
// the tests that hand their output files to an independent Python reader use it.

#include <cstdio>
#include <string>
#include <utility>

#include <sys/wait.h>

#include <rkpm/core/error.hpp>

namespace rkpm::test {

inline std::pair<int, std::string> run_capture(const std::string& command) {
  std::FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (!pipe) fail("cannot start '{}': the system is out of processes or memory", command);
  std::string output;
  char buffer[4096];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) output.append(buffer, n);
  const int status = ::pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

}  // namespace rkpm::test
