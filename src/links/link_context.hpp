#pragma once
// What a law may need to know about the two bodies a link joins, measured on the assembled
// model along the link axis: the lumped mass and the diagonal stiffness at each end node
// (Suzuki & Toi use the diagonal entries of the global M and K at the contact DOFs). A fixed
// end is rigid: its mass and stiffness enter the formulas as 0 and the effective mass is the
// other end's.
namespace pound::links {

struct LinkContext {
  double mass_i = 0.0;       // [M]
  double mass_j = 0.0;       // [M]
  double stiffness_i = 0.0;  // [F/L]
  double stiffness_j = 0.0;  // [F/L]
  bool fixed_i = false;
  bool fixed_j = false;

  // m1 m2 / (m1 + m2) of the two free ends; the free end's mass against a rigid one.
  double effective_mass() const {
    if (fixed_i) return mass_j;
    if (fixed_j) return mass_i;
    return mass_i * mass_j / (mass_i + mass_j);
  }
  bool operator==(const LinkContext&) const = default;
};

}  // namespace pound::links
