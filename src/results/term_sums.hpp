#pragma once
// Many sums of coefficient x value over equations (model::DofTerm), read in one pass. The
// monitors and element recorders read hundreds of DOFs a step (a 3-D building's rigid floors
// make most of them two or three terms); a loop per sum cost more in its set-up than in its
// terms, so the sums are kept in groups of equal length, each group's terms in one flat table
// read without a loop per sum, four sums to a packet (core/packets.hpp): sums over the same
// equations in the same order, three or more of them (a 3-D storey's four corner drifts, a
// beam's end shears and moments about one axis), with one value a term for all four lanes; the
// other sums of 1 to 4 terms each lane from its own equations. Every sum is formed as
// model::value_of forms it, the first term's product and then multiply-adds in order (0 with no
// terms), so the values are the same to the bit. The tables are arranged at the first evaluate
// after an add (the owners add all their sums first).
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/types.hpp"
#include "model/dof_term.hpp"

namespace pound::results {

class TermSums {
 public:
  // The place of the sum of `terms` in evaluate's output.
  std::size_t add(std::span<const model::DofTerm> terms);
  std::size_t size() const { return sums_.size(); }
  // out[s] = sum s of the terms over v, for each of the size() sums.
  void evaluate(const Vector& v, double* out) const;
  // The same over v + w, each term's c (v_e + w_e) (absolute accelerations: a + the frame's).
  void evaluate(const Vector& v, const Vector& w, double* out) const;

 private:
  static constexpr std::size_t kGrouped = 4;  // sums of 1 to 4 terms in groups, longer ones apart
  struct Group {
    std::vector<std::uint32_t> places;  // in evaluate's output
    // The sums' terms: of 1 to 4 terms, four sums at a time (term k of the j-th at 4 k + j),
    // then the last one to three one after the other; longer sums one after the other.
    std::vector<Index> equations;
    std::vector<double> coefficients;
    std::vector<std::uint32_t> ends;  // one past each sum's last term (the longer sums only)
  };
  // Batches of up to four sums over the same equations: batch b's equations
  // [starts[b], starts[b + 1]), the coefficient of its term k in lane j at 4 (starts[b] + k) + j,
  // lane j's place at 4 b + j (past the batch's sums, whose coefficients are 0, lane 0's).
  struct Shared {
    std::vector<std::uint32_t> starts{0};
    std::vector<Index> equations;
    std::vector<double> coefficients;
    std::vector<std::uint32_t> places;
  };
  void arrange() const;
  template <typename Value>
  void evaluate_with(Value value, double* out) const;
  template <std::size_t Terms, typename Value>
  static void evaluate_group(const Group& group, Value value, double* out);
  template <typename Value>
  static void evaluate_shared(const Shared& shared, Value value, double* out);

  std::vector<std::vector<model::DofTerm>> sums_;  // as added, sum s at place s
  mutable bool arranged_ = true;
  mutable std::array<Group, kGrouped + 1> groups_;  // [k - 1]: sums of k terms; [kGrouped]: longer
  mutable Shared shared_;
  mutable std::vector<std::uint32_t> empty_;  // places of the sums without terms
};

}  // namespace pound::results
