#pragma once
// Natural frequencies and mode shapes of an assembled model as it starts: the linear elements
// plus every link at its initial tangent (structural springs at their stiffness, contact links
// open), undamped. modal_analysis gives every mode: massless DOFs (rotations without rotary
// inertia) are condensed statically first, the rest is a dense generalised eigenproblem
// K x = w^2 M x (Eigen), whose time grows with the cube of the DOFs (about 10 s at 2,000).
// vibration_modes gives the lowest few, past a few hundred DOFs by shift-invert Lanczos on the
// sparse matrices (Spectra), in milliseconds at thousands of DOFs.
#include <stdexcept>
#include <string>
#include <vector>

#include "assembly/structural_system.hpp"

namespace pound::assembly {

class ModalAnalysisError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Modes {
  Vector omega_squared;  // ascending, [1/T^2]; rigid-body modes ~ 0
  Matrix shapes;         // columns, mass-normalised (phi^T M phi = 1), all DOFs
};

// The diagonal of K with every link at its initial tangent, as the modes see it.
Vector stiffness_diagonal_with_links(const StructuralSystem& system);
// A model without a DOF that has mass has no modes (empty). Throws std::length_error above
// `max_dofs` (dense solve), NotPositiveDefinite when the massless DOFs are not held by stiffness
// alone (its equation names one of them), and ModalAnalysisError when the eigen-solver fails
// (matrices not finite, or masses and stiffnesses too far apart in scale) or would (a
// stiffness-to-mass ratio past 1e150).
Modes modal_analysis(const StructuralSystem& system, Index max_dofs = 4000);
// The lowest `count` vibration modes (fewer if the model has fewer), ascending, shapes
// mass-normalised over all DOFs; rigid-body and mechanism modes, which store no strain energy
// (u^T K u round-off of its terms, or w^2 at most 1e-14 of the smallest positive K_ii / M_ii),
// left out.
// Up to 300 DOFs (and up to 4,000 when a quarter of the modes or more, or more than 500, is asked
// for) they are modal_analysis's; otherwise shift-invert Lanczos finds them (Spectra), at most
// 500. Throws as modal_analysis does, but never std::length_error.
Modes vibration_modes(const StructuralSystem& system, int count);
// Past this many DOFs vibration_modes finds at most kMostLanczosModes modes, from a Lanczos basis
// of at most kLanczosBasis modes, rigid-body ones included.
inline constexpr Index kLargestDenseModalDofs = 4000;
inline constexpr int kMostLanczosModes = 500;
inline constexpr Index kLanczosBasis = 4 * kMostLanczosModes;
// Why vibration_modes found `found` modes of the `asked` of a model of `dofs` DOFs,
// `dofs_with_mass` of them with mass: empty when it found them all, else a clause for a user ("the
// model has 2 DOFs with mass, hence 2 modes").
std::string fewer_modes_reason(Index dofs, Index dofs_with_mass, int asked, Index found);
// The first `count` periods 2 pi / w of the vibration modes (rigid-body modes left out).
std::vector<double> natural_periods(const StructuralSystem& system, int count);

}  // namespace pound::assembly
