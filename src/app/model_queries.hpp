#pragma once
// What `pound check` and `pound modes` find in a loaded model, as documents and text, for the
// commands and the Python module alike. Nothing here prints or writes.
#include <string>

#include "app/model_loading.hpp"
#include "core/table.hpp"
#include "io/document.hpp"
#include "verification/model_check.hpp"

namespace pound::app {

// The checks before a run (`pound check`): the findings and their document (`--json`). Throws
// InputError, naming `model_path`, where the model cannot start or its numbers overflow.
struct ModelFindings {
  verification::ModelCheck check;
  io::Document document;
  builder::AnalysisSpec analysis;  // with its step settled, as the run will take it
  UnitNames units;
};
ModelFindings check_findings(const LoadedModel& loaded, const std::string& model_path);

// The first `count` modes (`pound modes`): the document (`--json`), the shapes (`--shapes`, a
// row per free DOF, a column per mode) and the table printed.
struct ModalFindings {
  io::Document document;
  Table shapes;
  std::string text;
};
ModalFindings modal_findings(const LoadedModel& loaded, const std::string& model_path, int count);

}  // namespace pound::app
