#include "results/case_summary.hpp"

namespace pound::results {

const char* status_name(CaseStatus status) {
  switch (status) {
    case CaseStatus::completed:
      return "completed";
    case CaseStatus::failed:
      return "failed";
    case CaseStatus::input_error:
      return "input_error";
  }
  return "";
}

std::optional<CaseStatus> status_from_name(const std::string& name) {
  for (CaseStatus status : {CaseStatus::completed, CaseStatus::failed, CaseStatus::input_error})
    if (name == status_name(status)) return status;
  return std::nullopt;
}

}  // namespace pound::results
