#pragma once
// A law's errors as a model file meets them: a model with one link of that law (an object's JSON
// text), read and built as `pound run` does.
#include <fmt/format.h>

#include <optional>
#include <string>

#include "builder/build.hpp"
#include "core/errors.hpp"
#include "io/model_reader.hpp"

namespace pound::testing {

// The InputError the model with this law gives, or none; its link is /links/0.
inline std::optional<InputError> law_model_error(const std::string& law) {
  const std::string model = fmt::format(R"({{
    "nodes": [{{"id": "deck", "x": 0.0}}, {{"id": "pier", "x": 0.0}}],
    "masses": [{{"node": "deck", "mass": 1e5}}],
    "supports": [{{"node": "pier", "fix": ["x"]}}],
    "links": [{{"id": "hinge", "nodes": ["deck", "pier"], "axis": [1], "law": {}}}],
    "analysis": {{"time_step": 0.01, "duration": 1}}
  }})",
                                        law);
  try {
    (void)builder::build(io::parse_model(model, "m.json"));
  } catch (const InputError& error) {
    return error;
  }
  return std::nullopt;
}

}  // namespace pound::testing
