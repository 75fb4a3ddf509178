#include "results/term_sums.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/packets.hpp"

namespace pound::results {

std::size_t TermSums::add(std::span<const model::DofTerm> terms) {
  if (count_ >= UINT32_MAX) throw std::length_error("more than 2^32 sums to read");
  const auto place = static_cast<std::uint32_t>(count_++);
  if (terms.empty()) {
    empty_.push_back(place);
    return place;
  }
  Group& group = groups_[std::min(terms.size(), kGrouped + 1) - 1];
  group.places.push_back(place);
  for (const model::DofTerm& term : terms) {
    group.equations.push_back(term.equation);
    group.coefficients.push_back(term.coefficient);
  }
  if (terms.size() > kGrouped) {
    if (group.equations.size() > UINT32_MAX) throw std::length_error("more than 2^32 terms");
    group.ends.push_back(static_cast<std::uint32_t>(group.equations.size()));
  }
  return place;
}

template <std::size_t Terms, typename Value>
void TermSums::evaluate_group(const Group& group, Value value, double* out) {
  const Index* equations = group.equations.data();
  const double* coefficients = group.coefficients.data();
  for (const std::uint32_t place : group.places) {
    double sum = coefficients[0] * value(equations[0]);
    for (std::size_t k = 1; k < Terms; ++k)
      sum = multiply_add(coefficients[k], value(equations[k]), sum);
    out[place] = sum;
    equations += Terms;
    coefficients += Terms;
  }
}

template <typename Value>
void TermSums::evaluate_with(Value value, double* out) const {
  for (const std::uint32_t place : empty_) out[place] = 0.0;
  evaluate_group<1>(groups_[0], value, out);
  evaluate_group<2>(groups_[1], value, out);
  evaluate_group<3>(groups_[2], value, out);
  evaluate_group<4>(groups_[3], value, out);
  const Group& longer = groups_[kGrouped];
  std::uint32_t k = 0;
  for (std::size_t s = 0; s < longer.places.size(); ++s) {
    double sum = longer.coefficients[k] * value(longer.equations[k]);
    for (++k; k < longer.ends[s]; ++k)
      sum = multiply_add(longer.coefficients[k], value(longer.equations[k]), sum);
    out[longer.places[s]] = sum;
  }
}

void TermSums::evaluate(const Vector& v, double* out) const {
  const double* values = v.data();
  evaluate_with([values](Index e) { return values[e]; }, out);
}

void TermSums::evaluate(const Vector& v, const Vector& w, double* out) const {
  const double *first = v.data(), *second = w.data();
  evaluate_with([first, second](Index e) { return first[e] + second[e]; }, out);
}

}  // namespace pound::results
