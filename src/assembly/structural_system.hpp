#pragma once
// The assembled equations of a Model: lumped mass M (a diagonal), stiffness K of the linear
// elements, no damping matrix unless the model has damping, and the links as a LinkSet. Only the
// free DOFs of the scene are numbered (DofMap).
#include <Eigen/SparseCore>

#include "integrators/second_order_system.hpp"
#include "model/model.hpp"

namespace pound::assembly {

class StructuralSystem final : public SecondOrderSystem {
 public:
  // Throws InputError when a free DOF has no mass (the equations of motion would be singular).
  explicit StructuralSystem(const model::Model& model);

  Index size() const override { return dofs_.size(); }
  void multiply_mass(const Vector& x, Vector& y) const override;
  bool has_damping() const override { return false; }
  void multiply_damping(const Vector& x, Vector& y) const override;
  void multiply_stiffness(const Vector& x, Vector& y) const override;
  bool has_external_force() const override { return has_loads_; }
  void external_force(double time, Vector& force) const override;
  std::unique_ptr<LinearSolver> factor(double c_m, double c_c, double c_k) const override;
  LinkSet& links() override { return links_; }

  const model::DofMap& dofs() const { return dofs_; }
  const Vector* lumped_mass() const override { return &mass_; }
  const Eigen::SparseMatrix<double>& stiffness() const { return stiffness_; }
  // What a link's law may need of the bodies it joins (masses and stiffnesses at its ends).
  contact::LinkContext link_context(const model::Link& link) const;
  // u, v at t = 0 from the model's initial velocities (displacements zero).
  Vector initial_velocity(const model::Model& model) const;

 private:
  model::DofMap dofs_;
  Vector mass_;
  Vector loads_;  // constant nodal forces on the free DOFs
  bool has_loads_ = false;
  Eigen::SparseMatrix<double> stiffness_;
  LinkSet links_;
};

}  // namespace pound::assembly
