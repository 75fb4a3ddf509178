#pragma once
// What `pound check` finds before a run, and `pound run` warns about too: the model's size and
// first periods, the stable step of explicit central difference with the contacts open and in
// contact, and for every contact link its stiffness against the elements next to it
// (Kawashima's k-ratio), Suzuki & Toi's automatic penalty numbers and the expected contact
// duration against the time step (Kawashima: dt <= T_contact / 20; for Hertz-type laws the
// closed-form duration of an elastic Hertz impact at an estimated approach velocity). Every setting
// the benchmarks show to give meaningless results is a warning.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "assembly/structural_system.hpp"
#include "builder/build.hpp"
#include "links/extended_penalty.hpp"

namespace pound::verification {

struct LinkCheck {
  std::string id, law;
  bool stiff_at_first_touch = true;  // else its stiffness grows from 0 (Hertz-type)
  bool constraint = false;           // a hard contact: no stiffness at all
  double stiffness = 0.0;            // at first touch
  double adjacent = 0.0;             // of the softer element next to it; 0: bare masses
  double contact_duration = 0.0;     // when the link governs it; 0: not claimed
  std::string no_duration;           // why none is claimed, where a reader would look for one
  // For a Hertz-type law (F = k_h delta^1.5), whose contact shortens as v0^(-1/5): the approach
  // velocity its duration is estimated at, twice the largest peak ground velocity of the
  // excitations or the link's initial closing velocity, whichever is larger; 0: none.
  double approach_velocity = 0.0;
  std::optional<links::ExtendedPenalty::Numbers> automatic;  // with an adjacent stiffness
  std::optional<links::ExtendedPenalty::Numbers> used;       // an extended penalty's own
};

struct ModelCheck {
  Index dofs = 0;
  int dofs_per_node = 0;
  Index links = 0;
  int dimension = 1;  // the scene's, which numbers the directions (model::direction)
  // The free DOFs per direction: the directions the scene moves in (a shear building in a plane
  // has x and, at its column cuts, rotation, but no y).
  std::array<Index, 6> dofs_by_direction{};
  Index tied_dofs = 0;  // DOFs a constraint ties to their master (no equations of their own)
  std::vector<double> periods;  // the first six; none when not asked
  // Central difference's stable step; none without a lumped mass on every DOF.
  std::optional<double> explicit_step_open, explicit_step_contact;
  // The Hertz-type contacts in explicit_step_contact: at their peak penetration for an impact at
  // their approach velocity (some), or without their stiffness (some had no velocity to take).
  bool hertz_at_peak = false, hertz_without_stiffness = false;
  // Why there are no explicit steps: no lumped mass on some DOF, or no stable step at all.
  std::string explicit_unavailable;
  // The longest stable step of the model's implicit method when it has one (linear
  // acceleration: builder::conditional_stable_step), links in contact.
  std::optional<double> implicit_stable_step;
  std::vector<LinkCheck> contacts;
  // How many impacts of a contact's end masses were simulated for the created-energy warning:
  // one for each distinct law spec, context and approach velocity (contact_energy_probe.hpp).
  std::size_t contact_energy_probes = 0;
  std::vector<std::string> warnings;
};

// Warnings when `analysis` takes more than a billion steps (with the wall time that means) or
// more than its step limit allows (the run would stop as failed part way); check_model gives them.
void warn_step_count(const builder::AnalysisSpec& analysis, std::vector<std::string>& warnings);

// The model's checks for `analysis`, its time step settled (builder::settle_time_step: "auto"
// is checked as the step it takes). `with_periods`: the natural periods
// (assembly::natural_periods) and the warning on the step against the sixth; `run` leaves them
// out.
ModelCheck check_model(const builder::BuiltModel& built, const builder::AnalysisSpec& analysis,
                       assembly::StructuralSystem& system, bool with_periods);

}  // namespace pound::verification
