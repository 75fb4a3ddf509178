#pragma once
// Presentation of rod-impact results: one-line summaries, study tables, JSON documents and CSV
// tables (written by io/).
#include <string>
#include <vector>

#include "io/document.hpp"
#include "io/output.hpp"
#include "report/rod_impact.hpp"

namespace pound::report {

// The named benchmark cases: "kawashima" (two free rods, each at V0 = 0.1 towards the other),
// "fixed-end" (a rod at 0.1 into an identical one at rest with its far end fixed; Suzuki & Toi)
// and "area-ratio-3" (the same with the striking rod's area three times the struck one's).
// `law` is "gap_spring" (with the stiffness ratio) or "extended_penalty" (automatic numbers,
// `eta` its damping factor).
builder::RodPairSpec rod_impact_case(const std::string& name, int elements, double stiffness_ratio,
                                     const std::string& law = "gap_spring", double eta = 1.0);
std::vector<std::string> rod_impact_law_names();
std::vector<std::string> rod_impact_case_names();

io::Document to_document(const RodImpactMetrics& metrics);
io::Table force_history_table(const RodImpactResult& result);
io::Table profile_table(const RodImpactResult& result);

// Kawashima's three studies (k_I, n, dt) as rows; `label` says what was varied.
struct StudyRow {
  std::string label;
  RodImpactMetrics metrics;
};
struct Study {
  std::string title;
  std::vector<StudyRow> rows;
};
std::vector<Study> kawashima_study();

std::string format_metrics(const RodImpactMetrics& metrics);
std::string format_study(const Study& study);
io::Document to_document(const std::vector<Study>& studies);

}  // namespace pound::report
