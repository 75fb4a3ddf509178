#pragma once
// Presentation of rod-impact results: one-line summaries, study tables, JSON documents and CSV
// tables (written by io/).
#include <string>
#include <vector>

#include "io/document.hpp"
#include "io/output.hpp"
#include "verification/restitution.hpp"
#include "verification/rod_impact.hpp"
#include "verification/two_element.hpp"

namespace pound::verification {

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
// Suzuki & Toi's Figs. 7-8 in numbers, on their fixed-end rods (n = 50, dt = h / C0, Newmark):
// alpha0 alone at xi = alpha0 / k = 1, 10, 10^3, and the extended penalty on automatic numbers
// with eta = 0, 1, 10; the gap spring at k-ratio 1 for reference.
std::vector<Study> penalty_study();

std::string format_metrics(const RodImpactMetrics& metrics);
std::string format_two_element(const std::vector<TwoElementResult>& results);
io::Document to_document(const std::vector<TwoElementResult>& results);
std::string format_restitution(const std::vector<RestitutionRow>& rows);
io::Document to_document(const std::vector<RestitutionRow>& rows);
std::string format_study(const Study& study);
io::Document to_document(const std::vector<Study>& studies);

}  // namespace pound::verification
