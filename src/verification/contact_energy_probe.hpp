#pragma once
// Whether a contact link's law, the run's integrator and its time step together create energy in
// an impact, before the run: the link's two end masses alone (a fixed end rigid) close at the
// approach velocity the check assumes, with first touch at several phases inside a step, and
// each impact's created energy (LinkSummary::created_energy: what the link gave back beyond what
// it took) is taken over the approach kinetic energy 1/2 m_eff v^2. A penalty contact that starts
// or ends inside a step can give back more than it took; the run measures the same thing on the
// whole model (RunSummary::contact_created_energy).
#include <optional>

#include "builder/spec.hpp"
#include "links/link_context.hpp"
#include "links/link_law.hpp"

namespace pound::verification {

struct ContactEnergyProbe {
  double created_fraction = 0.0;  // the largest over the phases, of 1/2 m_eff v^2
  double contact_duration = 0.0;  // of the bare masses, the probe's estimate [T]
};

// None when the probe does not apply: no approach velocity or step, a massless free end, a law
// with no stiffness at contact, or a contact resolved by more than 20,000 steps (which creates
// nothing worth a warning).
std::optional<ContactEnergyProbe> probe_contact_energy(const links::LinkLaw& law,
                                                       const links::LinkContext& context,
                                                       const builder::AnalysisSpec& analysis,
                                                       double approach_velocity);

}  // namespace pound::verification
