#pragma once
// The assembled equations of a Model: mass M (a diagonal when every element lumps its mass,
// sparse with consistent element masses), stiffness K of the linear elements, Rayleigh damping
// C = a0 M + a1 K only when the model has damping, loads and uniform ground excitation
// -M iota a_g(t), and the links as a LinkSet. Only the free DOFs of the scene are numbered.
#include <Eigen/SparseCore>
#include <limits>
#include <string>
#include <vector>

#include "integrators/second_order_system.hpp"
#include "model/model.hpp"

namespace pound::assembly {

// One per run: its products and external force keep scratch space and the last force computed,
// so one system is not used from two threads at once.
class StructuralSystem final : public integrators::SecondOrderSystem {
 public:
  // Throws InputError when a free DOF has no mass (the equations of motion would be singular).
  explicit StructuralSystem(const model::Model& model);

  Index size() const override { return dofs_.size(); }
  void multiply_mass(const Vector& x, Vector& y) const override;
  const Rayleigh* rayleigh() const override;
  bool has_damping() const override {
    return damping_matrix_.size() > 0 || damping_.mass_coefficient != 0.0 ||
           damping_.stiffness_coefficient != 0.0;
  }
  void multiply_damping(const Vector& x, Vector& y) const override;
  void multiply_stiffness(const Vector& x, Vector& y) const override;
  // By blocks of rows when K is banded (the rows of a block need x only up to b past it).
  void multiply_stiffness_by_blocks(Vector& x, Vector& y, const integrators::BlockFunction& make,
                                    const integrators::BlockFunction& use) const override;
  bool has_external_force() const override {
    return has_loads_ || !excitations_.empty() || !moving_supports_.empty();
  }
  bool has_link_motion() const override { return has_link_motion_; }
  void link_motion(double time, Vector& offset, Vector& rate, Vector& acceleration) const override;
  void external_force(double time, Vector& force) const override;
  std::unique_ptr<integrators::LinearSolver> factor(double c_m, double c_c,
                                                    double c_k) const override;
  std::unique_ptr<integrators::LinearSolver> factor_with_links(
      double c_m, double c_c, double c_k, const Vector& link_stiffness) const override;
  integrators::LinkSet& links() override { return links_; }
  const integrators::LinkSet& links() const { return links_; }
  // The model's id of link k (LinkSet's order), for messages.
  const std::string& link_id(Index link) const { return link_ids_[static_cast<std::size_t>(link)]; }

  const model::DofMap& dofs() const { return dofs_; }
  const Vector* lumped_mass() const override;
  Eigen::SparseMatrix<double> mass_matrix() const;
  const model::RayleighDamping& damping() const { return damping_; }
  // K: the elements' stiffness, with their geometric stiffness under gravity when the model
  // asks for P-Delta.
  const Eigen::SparseMatrix<double>& stiffness() const { return stiffness_; }
  // The elements' own (first-order) stiffness, which Rayleigh damping a1 K stays proportional to.
  const Eigen::SparseMatrix<double>& elastic_stiffness() const {
    return elastic_stiffness_.size() > 0 ? elastic_stiffness_ : stiffness_;
  }
  // What a link's law may need of the bodies it joins (masses and stiffnesses at its ends).
  links::LinkContext link_context(const model::Link& link) const;
  // u, v at t = 0 from the model's initial velocities (displacements zero).
  Vector initial_velocity(const model::Model& model) const;
  // u is measured from the ground's motion (u = u_abs - iota u_g for a uniform excitation, the
  // quasi-static R u_s removed for moving supports): the acceleration of that frame at each
  // free DOF, sum iota a_g(t) + sum r a_s(t), so that a + frame is the absolute acceleration:
  // a sum of shapes (iota, r) times scales (a_g, a_s), the scales at `time` in the shapes' order.
  std::vector<Vector> frame_shapes() const;
  // Whether uniform excitation k loads any DOF (M iota not all zero): along a direction in which
  // every DOF with mass is held it loads none, and the structure does not respond to it.
  bool excitation_loads(std::size_t k) const { return excitations_.at(k).inertia.any(); }
  void frame_scales(double time, std::vector<double>& scales) const;
  // The absolute acceleration of a supported DOF (node, direction 0 = x, 1 = y): the ground's
  // along the excitations' directions, and a moving support's own record.
  double support_acceleration(Index node, int direction, double time) const;
  // The moving supports' quasi-static part of the displacements, which u leaves out
  // (u_total = u + sum r_k u_s,k(t)): each moving support's influence r_k on the free DOFs, its
  // node's share of u_s,k along a direction (its record's direction there; 0 for another node or
  // a rotation, as the ground does not turn), and the supports' displacements at a time.
  std::size_t moving_support_count() const { return moving_supports_.size(); }
  const Vector& moving_support_influence(std::size_t k) const {
    return moving_supports_.at(k).influence;
  }
  double moving_support_share(std::size_t k, Index node, int direction) const;
  void moving_support_displacements(double time, std::vector<double>& displacements) const;

 private:
  model::DofMap dofs_;
  Vector mass_;                              // lumped part (all of M without consistent masses)
  Eigen::SparseMatrix<double> mass_matrix_;  // all of M, only with consistent masses
  model::RayleighDamping damping_;
  Eigen::SparseMatrix<double> damping_matrix_;  // assembled C, only when elements damp on their own
  // The same by rows for C x: each entry of y one sum in registers, the terms in the same order
  // as by columns (a sixth fewer instructions than the columns' scatter on the 3-D buildings).
  Eigen::SparseMatrix<double, Eigen::RowMajor> damping_rows_;
  // C as diag(a0) M + diag(a1) K where it is (Rayleigh damping, or each structure's own), for
  // its products: none with P-Delta (a1 times the first-order K) or where an equation has two.
  std::optional<Rayleigh> rayleigh_;
  // From the model's a0, a1 or, with `own` damping, the elements' by equation (`by_dof`: one of
  // each on every equation; NaN where none).
  void set_rayleigh(bool own, bool by_dof, const Vector& mass_coefficient,
                    const Vector& stiffness_coefficient);
  mutable Vector damping_work_;  // K x of multiply_damping
  Vector loads_;                 // constant nodal forces on the free DOFs
  bool has_loads_ = false;
  struct Excitation {
    model::GroundMotion motion;
    Vector inertia;    // M iota
    Vector influence;  // iota
    model::Coordinates direction;
  };
  std::vector<Excitation> excitations_;
  struct MovingSupport {
    model::GroundKinematics kinematics;  // the record at this support, delayed
    Vector inertia;                      // M r
    Vector link_coefficients;            // d(delta) / d(u_support) of every link row
    Vector static_load;                  // -(K_ff r + K_fs): zero when r is K_ff's own
    Vector influence;                    // r
    Index node = -1;                     // the support
    model::Coordinates direction;
  };
  std::vector<MovingSupport> moving_supports_;
  Vector surface_rate_;  // d(delta)/dt of each link row from its moving j side (belts)
  // Whether the belts or the supports' motion move any link row, found once (asked every step).
  bool find_link_motion() const;
  bool has_link_motion_ = false;
  Eigen::SparseMatrix<double> stiffness_;
  Eigen::SparseMatrix<double> elastic_stiffness_;              // only with P-Delta: K without it
  Eigen::SparseMatrix<double, Eigen::RowMajor> elastic_rows_;  // the same by rows, for C x
  void add_geometric_stiffness(const model::Model& model, model::GeometricStiffness kind);
  // The same for K x, a large part of an explicit step. A band at least half full (chains
  // numbered in node order) is kept by diagonals, column b + k holding K(i, i + k): the product
  // is unit-stride and vectorises (by rows, K x took 2.7 us of a 5.0 us central-difference step
  // on the fine rod mesh); so is a band at least a quarter full (the bridge's b = 5 band: its
  // products a third faster than by rows). Otherwise by rows: each entry of y one dot product.
  Matrix stiffness_band_;
  Index stiffness_bandwidth_ = -1;    // -1: K is kept by rows
  bool stiffness_symmetric_ = false;  // tridiagonal with K(i, i - 1) = K(i - 1, i)
  void multiply_band(const Vector& x, Vector& y, Index first, Index last) const;  // y[first, last)
  mutable Vector padded_input_;  // of multiply_band
  void compute_external_force(double time, Vector& force) const;
  // The last external force computed and its time: a step asks for f(t_{n+1}) twice (the
  // integrator and the energy balance).
  mutable Vector last_external_force_;
  mutable double last_external_time_ = std::numeric_limits<double>::quiet_NaN();
  mutable std::vector<double> last_scales_;  // frame_scales at last_external_time_
  mutable Vector frame_force_;               // frame_scales' external force, on a cache miss
  Eigen::SparseMatrix<double, Eigen::RowMajor> stiffness_rows_;
  // Keeps stiffness_ for K x: by diagonals or by rows, as above.
  void store_stiffness_for_products();
  // c_m M + c_c C + c_k K, and its factors (banded, tridiagonal or sparse by its band).
  Eigen::SparseMatrix<double> effective_matrix(double c_m, double c_c, double c_k) const;
  static std::unique_ptr<integrators::LinearSolver> factor_matrix(
      Eigen::SparseMatrix<double> effective);
  integrators::LinkSet links_;
  std::vector<std::string> link_ids_;
};

}  // namespace pound::assembly
