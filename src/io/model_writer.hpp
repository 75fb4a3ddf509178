#pragma once
// Writing a builder::ModelSpec back as a model file (docs/model_format.md): what `pound expand`
// prints, so that a user can see and edit what a generator made. parse_model() of the text gives
// back an equal spec for every field the reader reads; fields at their defaults are mostly left
// out, and numbers are printed with enough digits to read back bit for bit.
#include <string>

#include "builder/spec.hpp"

namespace pound::io {

// Pretty-printed JSON, keys in the order of the format description. `source` and the
// `generated_from` bookkeeping of builder::expand() are not part of the format and not written.
std::string model_to_json(const builder::ModelSpec& spec);

}  // namespace pound::io
