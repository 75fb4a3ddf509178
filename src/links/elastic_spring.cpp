#include "links/elastic_spring.hpp"

namespace pound::links {

LawResponse ElasticSpring::set_trial(const LinkKinematics& trial) {
  trial_loaded_ = trial.penetration != 0.0;
  return {.force = stiffness_ * trial.penetration, .stiffness = stiffness_};
}

}  // namespace pound::links
