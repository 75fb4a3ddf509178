#include "links/coupled_shear.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <utility>

#include "links/bilinear_spring.hpp"
#include "links/bouc_wen.hpp"
#include "links/elastic_spring.hpp"
#include "links/law_registry.hpp"

namespace pound::links {

std::optional<ShearNumbers> CoupledShear::numbers_of(const LinkLaw& law) {
  if (const auto* bilinear = dynamic_cast<const BilinearSpring*>(&law))
    return ShearNumbers{bilinear->stiffness(), bilinear->yield_force(),
                        bilinear->hardening_ratio()};
  if (const auto* smooth = dynamic_cast<const BoucWen*>(&law)) {
    const BoucWen::Parameters& p = smooth->parameters();
    return ShearNumbers{p.stiffness, p.stiffness * *smooth->yield_deformation(), p.hardening_ratio,
                        SmoothShape{p.sharpness, p.beta, p.gamma, p.amplitude}};
  }
  if (const auto* elastic = dynamic_cast<const ElasticSpring*>(&law))
    return ShearNumbers{elastic->stiffness(), std::numeric_limits<double>::infinity(), 0.0};
  return std::nullopt;
}

std::optional<ShearNumbers> CoupledShear::numbers_of(const LawSpec& law, const LawSource& where) {
  if (!find_law(law.type)) return std::nullopt;
  return numbers_of(*make_law(law, where)(LinkContext{}));
}

std::optional<std::string> CoupledShear::mismatch(const ShearNumbers& first,
                                                  const ShearNumbers& second) {
  if (first.yields() != second.yields()) return "one direction yields and the other does not";
  if (first.hardening_ratio != second.hardening_ratio)
    return fmt::format("the two directions harden by one ratio b (here {:g} and {:g})",
                       first.hardening_ratio, second.hardening_ratio);
  if (first.smooth.has_value() != second.smooth.has_value())
    return "both directions are bouc_wen laws, or neither is";
  if (!first.smooth) return std::nullopt;
  const SmoothShape &one = *first.smooth, &two = *second.smooth;
  if (one.sharpness != two.sharpness || one.amplitude != two.amplitude)
    return fmt::format(
        "the two directions have one sharpness n and one amplitude A (here n {:g} "
        "and {:g}, A {:g} and {:g})",
        one.sharpness, two.sharpness, one.amplitude, two.amplitude);
  const double share_one = one.beta / (one.beta + one.gamma);
  const double share_two = two.beta / (two.beta + two.gamma);
  if (std::abs(share_one - share_two) > 1e-12)
    return fmt::format(
        "the two directions have one loop shape, beta / (beta + gamma) (here {:g} "
        "and {:g}; their z_max may differ)",
        share_one, share_two);
  return std::nullopt;
}

CoupledShear::CoupledShear(std::unique_ptr<LinkLaw> normal, ShearDirections numbers, int tangents)
    : normal_(std::move(normal)),
      numbers_(numbers),
      hysteresis_(make_plane_hysteresis(numbers[0], tangents)),
      tangents_(tangents) {
  // Equal directions scale by exactly 1 (the circular law to the bit).
  for (std::size_t a = 1; a < static_cast<std::size_t>(tangents_); ++a) {
    if (numbers[a] == numbers[0]) continue;
    force_scale_[a] = numbers[0].yields() ? numbers[a].yield_force / numbers[0].yield_force : 1.0;
    deformation_scale_[a] = numbers[a].stiffness / numbers[0].stiffness / force_scale_[a];
  }
}

CoupledShear::CoupledShear(const CoupledShear& other)
    : normal_(other.normal_->clone()),
      numbers_(other.numbers_),
      hysteresis_(other.hysteresis_->clone()),
      tangents_(other.tangents_),
      deformation_scale_(other.deformation_scale_),
      force_scale_(other.force_scale_),
      damping_(other.damping_),
      dashpot_(other.dashpot_),
      trial_tangent_(other.trial_tangent_),
      trial_viscous_(other.committed_viscous_),
      committed_viscous_(other.committed_viscous_),
      trial_slide_(other.committed_slide_),
      committed_slide_(other.committed_slide_),
      trial_viscous_work_(other.committed_viscous_work_),
      committed_viscous_work_(other.committed_viscous_work_),
      started_(other.started_) {}

FrictionResponse CoupledShear::set_trial(const LinkKinematics& normal,
                                         std::span<const LinkKinematics> tangential) {
  FrictionResponse out;
  out.normal = normal_->set_trial(normal);
  Tangential deformation{};
  for (std::size_t a = 0; a < static_cast<std::size_t>(tangents_); ++a)
    deformation[a] = tangential[a].penetration * deformation_scale_[a];
  const PlaneResponse plane = hysteresis_->set_trial(deformation);
  for (std::size_t a = 0; a < static_cast<std::size_t>(tangents_); ++a) {
    out.tangential_force[a] = plane.force[a];
    for (std::size_t b = 0; b < static_cast<std::size_t>(tangents_); ++b)
      out.tangential_on_slip[a][b].stiffness = plane.tangent[a][b];
  }
  to_own_units(out);
  if (damping_) add_damping(tangential, out);
  return out;
}

void CoupledShear::set_damping(const ShearDamping& damping) {
  damping_ = damping;
  for (std::size_t a = 0; a < static_cast<std::size_t>(tangents_); ++a)
    dashpot_[a][a] = damping.stiffness_coefficient * numbers_[a].initial_stiffness();
}

void CoupledShear::add_damping(std::span<const LinkKinematics> tangential, FrictionResponse& out) {
  const auto n = static_cast<std::size_t>(tangents_);
  if (!started_) {  // a link may start deformed
    for (std::size_t a = 0; a < n; ++a) committed_slide_[a] = tangential[a].penetration;
    started_ = true;
  }
  trial_viscous_work_ = committed_viscous_work_;
  for (std::size_t a = 0; a < n; ++a) {
    trial_viscous_[a] = 0.0;
    for (std::size_t b = 0; b < n; ++b) {
      trial_tangent_[a][b] = out.tangential_on_slip[a][b].stiffness;
      trial_viscous_[a] += dashpot_[a][b] * tangential[b].penetration_rate;
      out.tangential_on_slip[a][b].damping += dashpot_[a][b];
    }
    trial_slide_[a] = tangential[a].penetration;
    out.tangential_force[a] += trial_viscous_[a];
    trial_viscous_work_ +=
        0.5 * (trial_viscous_[a] + committed_viscous_[a]) * (trial_slide_[a] - committed_slide_[a]);
  }
}

void CoupledShear::to_own_units(FrictionResponse& out) const {
  for (std::size_t a = 0; a < static_cast<std::size_t>(tangents_); ++a) {
    out.tangential_force[a] *= force_scale_[a];
    for (std::size_t b = 0; b < static_cast<std::size_t>(tangents_); ++b)
      out.tangential_on_slip[a][b].stiffness *= force_scale_[a] * deformation_scale_[b];
  }
}

Tangential CoupledShear::plastic_deformation() const {
  Tangential plastic = hysteresis_->plastic_deformation();
  for (std::size_t a = 0; a < static_cast<std::size_t>(tangents_); ++a)
    plastic[a] /= deformation_scale_[a];
  return plastic;
}

void CoupledShear::commit() {
  normal_->commit();
  hysteresis_->commit();
  if (!damping_) return;
  committed_viscous_ = trial_viscous_;
  committed_slide_ = trial_slide_;
  committed_viscous_work_ = trial_viscous_work_;
  if (damping_->stiffness == DampingStiffness::committed)
    for (std::size_t a = 0; a < static_cast<std::size_t>(tangents_); ++a)
      for (std::size_t b = 0; b < static_cast<std::size_t>(tangents_); ++b)
        dashpot_[a][b] = damping_->stiffness_coefficient * trial_tangent_[a][b];
}

void CoupledShear::revert() {
  normal_->revert();
  hysteresis_->revert();
  trial_viscous_ = committed_viscous_;
  trial_slide_ = committed_slide_;
  trial_viscous_work_ = committed_viscous_work_;
}

}  // namespace pound::links
