#pragma once
// Reading batch set files (docs/batch_format.md) into a builder::SetSpec, checked like model
// files: every error names the file, the JSON path and what was expected. Model and record paths
// are relative to the set file; a record entry with a folder and a pattern becomes one record per
// matching file, in name order. The models and records themselves are read per case, so a
// broken record fails its own cases only.
#include <string>

#include "builder/batch_spec.hpp"

namespace pound::io {

builder::SetSpec read_set_file(const std::string& path);

// Same from text; `source` names the file in messages and relative paths start from its folder.
builder::SetSpec parse_set(const std::string& text, const std::string& source);

}  // namespace pound::io
