#include "links/plane_bilinear.hpp"

#include <cmath>

#include "links/plane_bouc_wen.hpp"

namespace pound::links {

std::unique_ptr<PlaneHysteresis> make_plane_hysteresis(const ShearNumbers& numbers, int tangents) {
  if (numbers.smooth) return std::make_unique<PlaneBoucWen>(numbers, tangents);
  return std::make_unique<PlaneBilinear>(numbers, tangents);
}

PlaneBilinear::PlaneBilinear(const ShearNumbers& numbers, int tangents)
    : numbers_(numbers),
      hardening_modulus_(numbers.hardening_ratio * numbers.stiffness /
                         (1.0 - numbers.hardening_ratio)),
      tangents_(tangents) {}

std::unique_ptr<PlaneHysteresis> PlaneBilinear::clone() const {
  auto copy = std::make_unique<PlaneBilinear>(*this);
  copy->trial_plastic_ = committed_plastic_;
  return copy;
}

PlaneResponse PlaneBilinear::set_trial(const Tangential& deformation) {
  PlaneResponse out;
  trial_plastic_ = committed_plastic_;
  Tangential relative{};
  const double length = elastic_trial(deformation, relative, out);
  if (length > numbers_.yield_force) return_to_circle(relative, length, out);
  return out;
}

double PlaneBilinear::elastic_trial(const Tangential& deformation, Tangential& relative,
                                    PlaneResponse& out) const {
  const double k = numbers_.stiffness;
  double length = 0.0;
  for (std::size_t a = 0; a < static_cast<std::size_t>(tangents_); ++a) {
    out.force[a] = k * (deformation[a] - committed_plastic_[a]);
    relative[a] = out.force[a] - hardening_modulus_ * committed_plastic_[a];
    length += relative[a] * relative[a];
    out.tangent[a][a] = k;
  }
  return std::sqrt(length);
}

void PlaneBilinear::return_to_circle(const Tangential& relative, double length,
                                     PlaneResponse& out) {
  const double k = numbers_.stiffness, hardening = hardening_modulus_;
  const auto n = static_cast<std::size_t>(tangents_);
  const double plastic_step = (length - numbers_.yield_force) / (k + hardening);
  for (std::size_t a = 0; a < n; ++a) {
    const double step =
        n == 1 ? std::copysign(plastic_step, relative[a]) : plastic_step * relative[a] / length;
    trial_plastic_[a] += step;
    out.force[a] -= k * step;
  }
  if (n == 1) {  // BilinearSpring's slope, b k, as that law computes it
    out.tangent[0][0] = numbers_.hardening_ratio * k;
    return;
  }
  const double along = k * k / (k + hardening), across = k * k * plastic_step / length;
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b) {
      const double e_ab = relative[a] * relative[b] / (length * length);
      out.tangent[a][b] = (a == b ? k - across : 0.0) - (along - across) * e_ab;
    }
}

}  // namespace pound::links
