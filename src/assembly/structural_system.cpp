#include "assembly/structural_system.hpp"

#include <fmt/format.h>

#include <Eigen/SparseCholesky>

#include "assembly/banded_ldlt.hpp"
#include "assembly/twisted_tridiagonal.hpp"
#include "core/errors.hpp"

namespace pound::assembly {
namespace {

template <typename Factor>
class FactorSolver final : public LinearSolver {
 public:
  explicit FactorSolver(const Eigen::SparseMatrix<double>& matrix) : factor_(matrix) {}
  void solve(const Vector& rhs, Vector& solution) const override { factor_.solve(rhs, solution); }

 private:
  Factor factor_;
};

// Wide bands (unlucky numbering) go to a general sparse LDL^T with fill-reducing ordering.
class SparseSolver final : public LinearSolver {
 public:
  explicit SparseSolver(const Eigen::SparseMatrix<double>& matrix) : factor_(matrix) {
    if (factor_.info() != Eigen::Success)
      throw std::domain_error("effective matrix is not positive definite");
  }
  void solve(const Vector& rhs, Vector& solution) const override { solution = factor_.solve(rhs); }

 private:
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor_;
};

constexpr const char* kDirection[] = {"x", "y"};

}  // namespace

StructuralSystem::StructuralSystem(const model::Model& model) : dofs_(model) {
  const Index n = dofs_.size();
  const int dpn = dofs_.dofs_per_node();
  mass_ = Vector::Zero(n);
  std::vector<Eigen::Triplet<double>> triplets;

  for (const model::Truss& truss : model.trusses) {
    const double length = model.element_length(truss);
    const auto& a = model.nodes[static_cast<std::size_t>(truss.node_i)].position;
    const auto& b = model.nodes[static_cast<std::size_t>(truss.node_j)].position;
    const double cosines[2] = {(b[0] - a[0]) / length, (b[1] - a[1]) / length};
    const double axial = truss.youngs_modulus * truss.area / length;
    const double half_mass = 0.5 * truss.density * truss.area * length;
    const Index nodes[2] = {truss.node_i, truss.node_j};
    for (int p = 0; p < 2; ++p)
      for (int dp = 0; dp < dpn; ++dp) {
        const Index row = dofs_.equation(nodes[p], dp);
        if (row < 0) continue;
        mass_[row] += half_mass;
        for (int q = 0; q < 2; ++q)
          for (int dq = 0; dq < dpn; ++dq) {
            const Index col = dofs_.equation(nodes[q], dq);
            if (col < 0) continue;
            const double sign = (p == q) ? 1.0 : -1.0;
            triplets.emplace_back(row, col, sign * axial * cosines[dp] * cosines[dq]);
          }
      }
  }
  for (const model::NodalMass& lumped : model.masses)
    for (int d = 0; d < dpn; ++d)
      if (const Index row = dofs_.equation(lumped.node, d); row >= 0) mass_[row] += lumped.mass;

  for (Index node = 0; node < static_cast<Index>(model.nodes.size()); ++node)
    for (int d = 0; d < dpn; ++d)
      if (const Index row = dofs_.equation(node, d); row >= 0 && !(mass_[row] > 0.0))
        throw InputError("", fmt::format("/nodes/{}", node),
                         fmt::format("node '{}' has no mass in direction {} (add a mass, an "
                                     "element with density, or a support)",
                                     model.nodes[static_cast<std::size_t>(node)].id, kDirection[d]));

  loads_ = Vector::Zero(n);
  for (const model::NodalLoad& load : model.loads)
    for (int d = 0; d < dpn; ++d)
      if (const Index row = dofs_.equation(load.node, d); row >= 0) {
        loads_[row] += load.force[static_cast<std::size_t>(d)];
        has_loads_ = has_loads_ || load.force[static_cast<std::size_t>(d)] != 0.0;
      }

  stiffness_.resize(n, n);
  stiffness_.setFromTriplets(triplets.begin(), triplets.end());
  stiffness_.prune(0.0);

  std::vector<LinkSet::Link> links;
  for (const model::Link& link : model.links) {
    // Row of a direction d: +d at node i, -d at node j (fixed DOFs dropped).
    auto row_along = [&](const model::Coordinates& direction) {
      std::vector<LinkSet::Term> row;
      for (int d = 0; d < dpn; ++d) {
        const double component = direction[static_cast<std::size_t>(d)];
        if (component == 0.0) continue;
        if (const Index eq = dofs_.equation(link.node_i, d); eq >= 0) row.push_back({eq, component});
        if (const Index eq = dofs_.equation(link.node_j, d); eq >= 0) row.push_back({eq, -component});
      }
      return row;
    };
    LinkSet::Link entry;
    entry.normal_row = row_along(link.axis);
    entry.gap = link.gap;
    std::unique_ptr<contact::ContactLaw> law = link.make_law(link_context(link));
    if (!link.friction) {
      entry.law = std::move(law);
    } else {
      entry.tangential_row = row_along({-link.axis[1], link.axis[0]});
      // The stick penalty defaults to the normal law's tangent at first touch.
      const auto probe = law->clone();
      const contact::LawResponse touch = probe->set_trial({1e-12, 1e-12, 0.0});
      const model::LinkFriction& f = *link.friction;
      const contact::StickPenalty stick{f.stick_stiffness.value_or(touch.stiffness),
                                        f.stick_damping.value_or(touch.damping),
                                        f.stick_mass.value_or(touch.mass)};
      entry.friction = std::make_unique<contact::CoulombFriction>(std::move(law), f.coefficient, stick);
    }
    links.push_back(std::move(entry));
  }
  links_ = LinkSet(n, std::move(links));
}

contact::LinkContext StructuralSystem::link_context(const model::Link& link) const {
  contact::LinkContext context;
  // Mass and diagonal stiffness of one end along the axis: n^T K_nn n over its free DOFs.
  auto end = [&](Index node, double& mass, double& stiffness, bool& fixed) {
    fixed = true;
    for (int d = 0; d < dofs_.dofs_per_node(); ++d) {
      const double n_d = link.axis[static_cast<std::size_t>(d)];
      const Index row = dofs_.equation(node, d);
      if (n_d == 0.0 || row < 0) continue;
      fixed = false;
      mass = mass_[row];
      for (int e = 0; e < dofs_.dofs_per_node(); ++e)
        if (const Index col = dofs_.equation(node, e); col >= 0)
          stiffness += n_d * link.axis[static_cast<std::size_t>(e)] * stiffness_.coeff(row, col);
    }
  };
  end(link.node_i, context.mass_i, context.stiffness_i, context.fixed_i);
  end(link.node_j, context.mass_j, context.stiffness_j, context.fixed_j);
  return context;
}

void StructuralSystem::multiply_mass(const Vector& x, Vector& y) const {
  y = mass_.cwiseProduct(x);
}

void StructuralSystem::multiply_damping(const Vector&, Vector& y) const {
  y = Vector::Zero(size());
}

void StructuralSystem::multiply_stiffness(const Vector& x, Vector& y) const {
  y.noalias() = stiffness_ * x;
}

void StructuralSystem::external_force(double, Vector& force) const { force = loads_; }

std::unique_ptr<LinearSolver> StructuralSystem::factor(double c_m, double, double c_k) const {
  Eigen::SparseMatrix<double> effective = c_k * stiffness_;
  Eigen::SparseMatrix<double> mass(size(), size());
  mass.reserve(Eigen::VectorXi::Constant(size(), 1));
  for (Index i = 0; i < size(); ++i) mass.insert(i, i) = c_m * mass_[i];
  effective += mass;
  // A band factor costs n b^2 and solves in n b; past a modest band the sparse factor wins.
  const Index bandwidth = BandedLdlt::bandwidth_of(effective);
  if (bandwidth <= 1) return std::make_unique<FactorSolver<TwistedTridiagonal>>(effective);
  if (bandwidth <= 32) return std::make_unique<FactorSolver<BandedLdlt>>(effective);
  return std::make_unique<SparseSolver>(effective);
}

Vector StructuralSystem::initial_velocity(const model::Model& model) const {
  Vector velocity = Vector::Zero(size());
  if (model.initial_velocity.empty()) return velocity;
  for (Index node = 0; node < static_cast<Index>(model.nodes.size()); ++node)
    for (int d = 0; d < dofs_.dofs_per_node(); ++d)
      if (const Index row = dofs_.equation(node, d); row >= 0)
        velocity[row] = model.initial_velocity[static_cast<std::size_t>(node)][static_cast<std::size_t>(d)];
  return velocity;
}

}  // namespace pound::assembly
