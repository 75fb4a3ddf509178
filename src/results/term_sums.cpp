#include "results/term_sums.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "core/packets.hpp"

namespace pound::results {

std::size_t TermSums::add(std::span<const model::DofTerm> terms) {
  if (sums_.size() >= UINT32_MAX - 1) throw std::length_error("more than 2^32 sums to read");
  sums_.emplace_back(terms.begin(), terms.end());
  arranged_ = false;
  return sums_.size() - 1;
}

namespace {
// A sum's terms after the group's last, in order.
template <typename Group>
void append_terms(const std::vector<model::DofTerm>& terms, Group& group) {
  for (const model::DofTerm& term : terms) {
    group.equations.push_back(term.equation);
    group.coefficients.push_back(term.coefficient);
  }
}
}  // namespace

// Sums of two or more terms whose equations two other sums or more share go to batches of four
// (two alone in a packet took more instructions than apart: a column's shear and moment about
// one axis), the rest to the groups by length.
void TermSums::arrange() const {
  for (Group& group : groups_) group = Group{};
  shared_ = Shared{};
  empty_.clear();
  std::map<std::vector<Index>, std::vector<std::uint32_t>> by_equations;
  for (std::size_t s = 0; s < sums_.size(); ++s) {
    if (sums_[s].size() < 2) continue;
    std::vector<Index> equations;
    for (const model::DofTerm& term : sums_[s]) equations.push_back(term.equation);
    by_equations[equations].push_back(static_cast<std::uint32_t>(s));
  }
  std::vector<char> batched(sums_.size(), 0);
  for (const auto& [equations, places] : by_equations) {
    if (places.size() < 3) continue;
    for (std::size_t first = 0; first < places.size(); first += 4) {
      shared_.equations.insert(shared_.equations.end(), equations.begin(), equations.end());
      for (std::size_t k = 0; k < equations.size(); ++k)
        for (std::size_t j = first; j < first + 4; ++j)
          shared_.coefficients.push_back(j < places.size() ? sums_[places[j]][k].coefficient : 0.0);
      // A lane past the list's sums writes its (unused) sum to the batch's first place, which the
      // first lane, stored last, then writes again: no branch per lane.
      for (std::size_t j = first; j < first + 4; ++j) {
        shared_.places.push_back(places[j < places.size() ? j : first]);
        if (j < places.size()) batched[places[j]] = 1;
      }
      if (shared_.equations.size() > UINT32_MAX) throw std::length_error("more than 2^32 terms");
      shared_.starts.push_back(static_cast<std::uint32_t>(shared_.equations.size()));
    }
  }
  std::array<std::vector<std::uint32_t>, kGrouped + 1> by_length;
  for (std::size_t s = 0; s < sums_.size(); ++s) {
    const auto place = static_cast<std::uint32_t>(s);
    if (sums_[s].empty())
      empty_.push_back(place);
    else if (!batched[s])
      by_length[std::min(sums_[s].size(), kGrouped + 1) - 1].push_back(place);
  }
  // The groups of 1 to 4 terms four sums at a time, term k of lane j at 4 k + j of its four,
  // then the rest one after the other.
  for (std::size_t t = 0; t < kGrouped; ++t) {
    Group& group = groups_[t];
    const std::vector<std::uint32_t>& places = by_length[t];
    const std::size_t lanes = places.size() / 4 * 4;
    for (std::size_t first = 0; first < lanes; first += 4)
      for (std::size_t k = 0; k <= t; ++k)
        for (std::size_t j = first; j < first + 4; ++j) {
          group.equations.push_back(sums_[places[j]][k].equation);
          group.coefficients.push_back(sums_[places[j]][k].coefficient);
        }
    for (std::size_t j = lanes; j < places.size(); ++j) append_terms(sums_[places[j]], group);
    group.places = places;
  }
  Group& longer = groups_[kGrouped];
  for (const std::uint32_t place : by_length[kGrouped]) {
    longer.places.push_back(place);
    append_terms(sums_[place], longer);
    if (longer.equations.size() > UINT32_MAX) throw std::length_error("more than 2^32 terms");
    longer.ends.push_back(static_cast<std::uint32_t>(longer.equations.size()));
  }
  arranged_ = true;
}

template <std::size_t Terms, typename Value>
void TermSums::evaluate_group(const Group& group, Value value, double* out) {
  const Index* equations = group.equations.data();
  const double* coefficients = group.coefficients.data();
  const std::uint32_t* places = group.places.data();
  const std::size_t count = group.places.size(), lanes = count / 4 * 4;
  const auto gather = [&](const Index* e) {
    return Packet4{value(e[0]), value(e[1]), value(e[2]), value(e[3])};
  };
  for (std::size_t s = 0; s < lanes; s += 4) {
    Packet4 sums = load_packet(coefficients) * gather(equations);
    for (std::size_t k = 1; k < Terms; ++k)
      sums = multiply_add(load_packet(coefficients + 4 * k), gather(equations + 4 * k), sums);
    for (std::size_t j = 0; j < 4; ++j) out[places[s + j]] = sums[j];
    equations += 4 * Terms;
    coefficients += 4 * Terms;
  }
  for (std::size_t s = lanes; s < count; ++s) {
    double sum = coefficients[0] * value(equations[0]);
    for (std::size_t k = 1; k < Terms; ++k)
      sum = multiply_add(coefficients[k], value(equations[k]), sum);
    out[places[s]] = sum;
    equations += Terms;
    coefficients += Terms;
  }
}

template <typename Value>
void TermSums::evaluate_shared(const Shared& shared, Value value, double* out) {
  const double* coefficients = shared.coefficients.data();
  const std::uint32_t* places = shared.places.data();
  for (std::size_t b = 0; b + 1 < shared.starts.size(); ++b, places += 4) {
    std::uint32_t k = shared.starts[b];
    Packet4 sums = load_packet(coefficients + 4 * k) * broadcast(value(shared.equations[k]));
    for (++k; k < shared.starts[b + 1]; ++k)
      sums = multiply_add(load_packet(coefficients + 4 * k), broadcast(value(shared.equations[k])),
                          sums);
    out[places[3]] = sums[3];
    out[places[2]] = sums[2];
    out[places[1]] = sums[1];
    out[places[0]] = sums[0];
  }
}

template <typename Value>
void TermSums::evaluate_with(Value value, double* out) const {
  if (!arranged_) arrange();
  for (const std::uint32_t place : empty_) out[place] = 0.0;
  evaluate_shared(shared_, value, out);
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
