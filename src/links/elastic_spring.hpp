#pragma once
// Linear elastic structural spring: an elastomeric bearing, an elastic abutment or shear spring
// used as a link with gap 0. It acts in both directions:
//
//   F = k delta   (delta = (u_i - u_j) . n - gap; F > 0 compression, F < 0 tension)
//
// Units: k [F/L], delta [L], F [F]. No history; commit/revert only move the loaded flag. Source:
// the linear bearing/abutment spring of Caltrans SDC and of OpenSees' Elastic uniaxial material.
#include "links/link_law.hpp"

namespace pound::links {

class ElasticSpring final : public LinkLaw {
 public:
  explicit ElasticSpring(double stiffness) : stiffness_(stiffness) {}

  std::string name() const override { return "elastic_spring"; }
  // Its registry entry: parameters, traits, factory (links/law_registry.hpp).
  static const LawEntry& entry();
  std::unique_ptr<LinkLaw> clone() const override { return std::make_unique<ElasticSpring>(*this); }
  LawResponse set_trial(const LinkKinematics& trial) override;
  void commit() override { committed_loaded_ = trial_loaded_; }
  void revert() override { trial_loaded_ = committed_loaded_; }
  // A spring is always attached; "in contact" means it carries a force (delta != 0).
  bool in_contact() const override { return committed_loaded_; }

  double stiffness() const { return stiffness_; }

 private:
  double stiffness_;
  bool trial_loaded_ = false, committed_loaded_ = false;
};

}  // namespace pound::links
