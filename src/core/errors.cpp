#include "core/errors.hpp"

#include <fmt/format.h>

namespace pound {
namespace {
std::string locate(const std::string& file, const std::string& where, const std::string& what) {
  std::string text;
  if (!file.empty()) text += file + ": ";
  if (!where.empty()) text += where + ": ";
  return text + what;
}
}  // namespace

InputError::InputError(std::string file, std::string where, std::string what)
    : std::runtime_error(locate(file, where, what)),
      file_(std::move(file)),
      where_(std::move(where)),
      reason_(std::move(what)) {}

InputError InputError::in_file(const std::string& file) const {
  return InputError(file, where_, reason_);
}

SolveError::SolveError(double time, std::string reason)
    : std::runtime_error(fmt::format("analysis failed at t = {:.6g}: {}", time, reason)),
      time_(time),
      reason_(std::move(reason)) {}

}  // namespace pound
