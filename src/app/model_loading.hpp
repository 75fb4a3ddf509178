#pragma once
// Reading a model file with its ground-motion records into a built model: what `run`, `modes`
// and later `batch` share. Everything that can be wrong with the input is found here, before
// any output exists.
#include <optional>
#include <string>
#include <vector>

#include "builder/build.hpp"

namespace pound::app {

struct LoadedModel {
  builder::ModelSpec spec;
  builder::BuiltModel built;
};

// `motion_override`: a record path replacing the first excitation's record (or adding a uniform
// x excitation in g when the model has none), as `pound run --motion` does.
LoadedModel load_model(const std::string& path, const std::optional<std::string>& motion_override = {});

}  // namespace pound::app
