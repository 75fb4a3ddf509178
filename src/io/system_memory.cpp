#include "io/system_memory.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <string>

namespace pound::io {
namespace {

std::optional<std::size_t> mem_available() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::size_t kilobytes = 0;
  std::string unit;
  while (meminfo >> key >> kilobytes >> unit)
    if (key == "MemAvailable:") return kilobytes * 1024;
  return std::nullopt;
}

// cgroup v2: memory.max ("max" when unlimited) less memory.current.
std::optional<std::size_t> cgroup_room() {
  std::ifstream max_file("/sys/fs/cgroup/memory.max"),
      current_file("/sys/fs/cgroup/memory.current");
  std::string max_text;
  std::size_t current = 0;
  if (!(max_file >> max_text) || max_text == "max" || !(current_file >> current))
    return std::nullopt;
  try {
    const std::size_t max = std::stoull(max_text);
    return max > current ? max - current : 0;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// ulimit -v, less the address space already mapped.
std::optional<std::size_t> address_space_room() {
  rlimit limit{};
  if (::getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return std::nullopt;
  std::size_t mapped_pages = 0;
  std::ifstream("/proc/self/statm") >> mapped_pages;
  const std::size_t mapped = mapped_pages * static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
  const auto cap = static_cast<std::size_t>(limit.rlim_cur);
  return cap > mapped ? cap - mapped : 0;
}

}  // namespace

std::optional<std::size_t> available_memory_bytes() {
  std::optional<std::size_t> least;
  for (const std::optional<std::size_t>& bound :
       {mem_available(), cgroup_room(), address_space_room()})
    if (bound) least = least ? std::min(*least, *bound) : *bound;
  return least;
}

}  // namespace pound::io
