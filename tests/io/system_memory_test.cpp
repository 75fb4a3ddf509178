// The memory bound pound checks models against: on Linux it exists, and it is never more than
// the MemAvailable the kernel reports (read here independently, in kB, before and after).
#include "io/system_memory.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>

namespace pound::io {
namespace {

std::size_t mem_available_bytes() {
  std::ifstream meminfo("/proc/meminfo");
  for (std::string line; std::getline(meminfo, line);)
    if (line.rfind("MemAvailable:", 0) == 0) return std::stoull(line.substr(13)) * 1024;
  return 0;
}

TEST(SystemMemory, IsAtMostWhatTheKernelSaysIsAvailable) {
  const std::size_t before = mem_available_bytes();
  const std::optional<std::size_t> available = available_memory_bytes();
  const std::size_t after = mem_available_bytes();
  if (before == 0) GTEST_SKIP() << "no MemAvailable in /proc/meminfo";
  ASSERT_TRUE(available.has_value());
  EXPECT_GT(*available, 0u);
  const std::size_t slack = 64u << 20;  // MemAvailable moves while other processes run
  EXPECT_LE(*available, std::max(before, after) + slack);
}

}  // namespace
}  // namespace pound::io
