#pragma once
// The seam between integrators and whatever they integrate (after Chrono's
// (c_a M + c_v C + c_x K) Delta = R): a linear part M u'' + C u' + K u = f_ext(t), factored by
// the system for any coefficients, plus a LinkSet whose forces B^T F(B u - gap, ...) are the
// only nonlinearity. Integrators see nothing else, so they are tested on a one-DOF oscillator.
#include <concepts>
#include <memory>
#include <optional>
#include <type_traits>

#include "core/types.hpp"
#include "integrators/link_set.hpp"

namespace pound::integrators {

// A factored matrix of the linear part.
class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  virtual void solve(const Vector& rhs, Vector& solution) const = 0;
};

// A non-owning reference to a callable taking a range [first, last) of equations: unlike
// std::function it never allocates, so a time step can pass lambdas for free.
class BlockFunction {
 public:
  template <typename Function>
  requires(!std::same_as<std::remove_cvref_t<Function>, BlockFunction>)
      BlockFunction(const Function& function)  // implicit, as std::function's
      : object_(&function), call_([](const void* object, Index first, Index last) {
          (*static_cast<const Function*>(object))(first, last);
        }) {}
  void operator()(Index first, Index last) const { call_(object_, first, last); }

 private:
  const void* object_;
  void (*call_)(const void*, Index, Index);
};

class SecondOrderSystem {
 public:
  virtual ~SecondOrderSystem() = default;

  virtual Index size() const = 0;
  virtual void multiply_mass(const Vector& x, Vector& y) const = 0;  // y = M x
  // The diagonal of M when M is diagonal (lumped), so integrators can fuse their vector
  // updates into one pass; nullptr otherwise.
  virtual const Vector* lumped_mass() const { return nullptr; }
  virtual bool has_damping() const = 0;
  virtual void multiply_damping(const Vector& x, Vector& y) const = 0;  // y = C x
  // C = diag(a0) M + diag(a1) K with the M and K of the products here, by DOF, where neither M
  // nor K couples two DOFs of different coefficients: Rayleigh damping a0 M + a1 K (every
  // coefficient the same), or each structure of a scene damped with its own a0 and a1 (two
  // buildings that only their links join). C x then follows from products already made (none of
  // K when every a1 is 0); none otherwise (a C that must be assembled, or no damping).
  struct Rayleigh {
    Vector mass_coefficient, stiffness_coefficient;  // a0 [1/T] and a1 [T] of each DOF
    bool stiffness = false;                          // some a1 is not 0
  };
  virtual const Rayleigh* rayleigh() const { return nullptr; }
  virtual void multiply_stiffness(const Vector& x, Vector& y) const = 0;  // y = K x
  // y = K x with x made on the way, so that a step's vector passes can share one trip through
  // the cache: make(first, last) writes x[first, last) and is called in order, before any entry
  // of y that needs them; use(first, last) is called in order once y[first, last) is final.
  // x has size() entries on entry. By default x is made whole, multiplied, then used whole.
  virtual void multiply_stiffness_by_blocks(Vector& x, Vector& y, const BlockFunction& make,
                                            const BlockFunction& use) const {
    make(0, size());
    multiply_stiffness(x, y);
    use(0, size());
  }
  virtual bool has_external_force() const = 0;
  virtual void external_force(double time, Vector& force) const = 0;  // f_ext(t)

  // Factors c_m M + c_c C + c_k K (every coefficient >= 0, the result positive definite).
  virtual std::unique_ptr<LinearSolver> factor(double c_m, double c_c, double c_k) const = 0;
  // Factors c_m M + c_c C + c_k K + B^T diag(link_stiffness) B with the links' B: stiffnesses
  // of link rows that an implicit integrator folds into the linear part, so that a link that
  // stays on a linear branch needs no Newton iteration. nullptr when the system cannot (the
  // default; the integrator then iterates on every link row).
  virtual std::unique_ptr<LinearSolver> factor_with_links(double /*c_m*/, double /*c_c*/,
                                                          double /*c_k*/,
                                                          const Vector& /*link_stiffness*/) const {
    return nullptr;
  }

  virtual LinkSet& links() = 0;

  // Links attached to supports that move differently from the rest (multi-support excitation)
  // see a prescribed part of their deformation: delta = B u - gap + s(t), with rates
  // B v + s'(t) and B a + s''(t). None unless the system says so.
  virtual bool has_link_motion() const { return false; }
  virtual void link_motion(double /*time*/, Vector& offset, Vector& rate,
                           Vector& acceleration) const {
    offset.setZero(links().size());
    rate.setZero(links().size());
    acceleration.setZero(links().size());
  }
  const LinkSet& links() const { return const_cast<SecondOrderSystem*>(this)->links(); }
};

}  // namespace pound::integrators
