#pragma once
// Reading model files (docs/model_format.md) into a builder::ModelSpec. Everything that can be
// checked within the file itself is checked here: JSON syntax, types, required and unknown
// fields, value ranges, enumerations, 2-D-only fields, unit axes and ids repeated within one
// array. References between entries (does node 'b9' exist?) are the builder's to check.
#include <string>

#include "builder/spec.hpp"
#include "io/json_reader.hpp"

namespace pound::io {

// Reads and checks a model file; throws InputError naming the file, the JSON path and what was
// expected.
builder::ModelSpec read_model_file(const std::string& path);

// Same from text; `source` names the file in messages.
builder::ModelSpec parse_model(const std::string& text, const std::string& source);

// The fields of a record entry that say how to read and scale it (format, column, time_step,
// time_column, units, scale), shared by model excitations and batch sets.
void read_record_fields(JsonObject& object, builder::ExcitationSpec& excitation);

}  // namespace pound::io
