#include "io/output_paths.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <system_error>

#include "core/errors.hpp"

namespace pound::io {
namespace {

namespace fs = std::filesystem;

// The path with symlinks of its existing part resolved and "." and ".." folded.
fs::path resolved(const std::string& path) {
  std::error_code error;
  fs::path result = fs::weakly_canonical(fs::absolute(path, error), error);
  return error ? fs::absolute(path).lexically_normal() : result;
}

bool same_file(const std::string& a, const std::string& b) {
  std::error_code error;
  if (fs::exists(a, error) && fs::exists(b, error)) {
    const bool equivalent = fs::equivalent(a, b, error);
    if (!error) return equivalent;
  }
  return resolved(a) == resolved(b);
}

}  // namespace

std::string resolved_path(const std::string& path) { return resolved(path).string(); }

void check_outputs_apart(const std::vector<NamedPath>& inputs,
                         const std::vector<NamedPath>& outputs) {
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    const NamedPath& output = outputs[k];
    for (const NamedPath& input : inputs)
      if (same_file(output.path, input.path))
        throw InputError(output.in_file, output.named_by,
                         fmt::format("the output '{}' would overwrite the input '{}' ({}): "
                                     "choose another name",
                                     output.path, input.path, input.named_by));
    for (std::size_t j = 0; j < k; ++j)
      if (same_file(output.path, outputs[j].path))
        throw InputError(output.in_file, output.named_by,
                         fmt::format("the output '{}' is also the output of {}: choose another "
                                     "name",
                                     output.path, outputs[j].named_by));
  }
}

std::string folder_named_after(const std::string& parent, const std::string& input,
                               const std::string& option) {
  const std::string stem = fs::path(input).stem().string();
  if (stem.empty() || stem.starts_with('.'))
    throw InputError("", option,
                     fmt::format("no output folder can be named after '{}' (its name without "
                                 "extension is '{}'): give {}",
                                 input, stem, option));
  return (fs::path(parent) / stem).string();
}

}  // namespace pound::io
