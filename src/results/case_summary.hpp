#pragma once
// The pounding summary of one analysis in a batch: one row of batch_summary.csv (the response
// quantities among its members are listed in results/batch_quantities.hpp). Quantities a model
// does not have (no joints, no storeys) are absent rather than zero, so statistics never mix
// "no joint" with "a joint that did not open".
#include <optional>
#include <string>

namespace pound::results {

// How a case ended: completed; failed (the analysis stopped: results up to then); input_error (the
// model or record was refused, nothing ran).
enum class CaseStatus { completed, failed, input_error };
const char* status_name(CaseStatus status);
// The status a batch_summary.csv cell names; none for another word.
std::optional<CaseStatus> status_from_name(const std::string& name);

struct CaseSummary {
  std::string name;    // the case folder under the batch's output, "<model>/<record>/x<scale>"
  std::string model;   // model id
  std::string record;  // record id
  double scale = 1.0;  // the IDA factor on top of the record's own scale
  CaseStatus status = CaseStatus::completed;
  std::string reason;  // why it failed, empty when completed

  std::optional<double> pga_g;      // peak of the record as applied [g]
  std::optional<double> intensity;  // the set's intensity measure of the record as applied [g]
  std::optional<double> end_time;   // how far the analysis got [T]
  std::optional<double> steps;
  // Over the contact links (every law but springs, restrainers and hooks): engagements, and the
  // largest compression with the link that carried it.
  std::optional<double> impacts;
  std::optional<double> max_pounding_force;
  std::string max_pounding_link;
  // Over restrainers and hooks: the largest tension and its link.
  std::optional<double> max_restrainer_force;
  std::string max_restrainer_link;
  // Over the joint monitors: widest opening, largest movement on a seat, the least margin left
  // on a seat and whether any girder came off its seat.
  std::optional<double> max_joint_opening;
  std::optional<double> max_seat_movement;
  std::optional<double> min_unseating_margin;
  std::optional<bool> unseated;
  // Over the storey and pier monitors: largest drift ratio, ductility demand and residual drift.
  std::optional<double> max_drift_ratio;
  std::optional<double> max_ductility;
  std::optional<double> max_residual_drift_ratio;  // |residual drift| over height, at the end
  std::optional<double> energy_balance_error;      // worst over the run
  // Absolute accelerations along x (a drift monitor's own direction): the largest at a drift
  // monitor's top (floors, pier tops) and at a joint monitor's girder end (the deck) [L/T^2].
  std::optional<double> max_top_acceleration;
  std::optional<double> max_deck_acceleration;
  // How many warnings the run's results gave (summary.json's "warnings": a drift past 10 % or a
  // collapse, a girder off its seat, energy created by contacts...): a completed case with some is
  // not a plain result.
  std::optional<double> warnings;
  std::optional<double> run_time_s;  // of the solve; the one column that varies run to run
};

}  // namespace pound::results
