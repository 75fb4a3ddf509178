// The law registry: every entry is complete and consistent, and each law's traits say what the
// law object actually does.
#include "links/law_registry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <set>

#include "links/hard_contact.hpp"

namespace pound::links {
namespace {

// Two bodies of 1000 and 3000 on supports of stiffness 1e5.
const LinkContext kContext{1000.0, 3000.0, 1e5, 1e5, false, false};

// The law of `entry` with its example numbers and its default choices.
std::unique_ptr<LinkLaw> make_sample(const LawEntry& entry) {
  LawSpec law{entry.name, entry.example};
  for (const LawChoice& choice : entry.choices) law.choices[choice.name] = choice.values.front();
  return make_law(law, {"test.json", "/links/0/law"})(kContext);
}

TEST(LawRegistry, EveryEntryIsCompleteAndNamesOnlyItsOwnParameters) {
  std::set<std::string> names;
  for (const LawEntry* entry : law_registry()) {
    SCOPED_TRACE(entry->name);
    EXPECT_TRUE(names.insert(entry->name).second) << "duplicate name";
    EXPECT_EQ(find_law(entry->name), entry);
    EXPECT_FALSE(entry->formula.empty());
    EXPECT_FALSE(entry->source.empty());
    EXPECT_TRUE(entry->make);
    for (const LawParameter& p : entry->parameters) {
      EXPECT_FALSE(p.units.empty()) << p.name;
      EXPECT_FALSE(p.meaning.empty()) << p.name;
    }
    for (const LawChoice& c : entry->choices) EXPECT_GE(c.values.size(), 2u) << c.name;
    // Every rule names parameters the law has (a misspelt one would never fire).
    auto known = [&](const std::string& name) { return entry->parameter(name) != nullptr; };
    for (const std::string& name : entry->required) EXPECT_TRUE(known(name)) << name;
    for (const auto& group : entry->exactly_one_of)
      for (const std::string& name : group) EXPECT_TRUE(known(name)) << name;
    for (const auto& rules : {entry->needs, entry->excludes})
      for (const auto& [name, others] : rules) {
        EXPECT_TRUE(known(name)) << name;
        for (const std::string& other : others) EXPECT_TRUE(known(other)) << other;
      }
    // A law with a calibration hook is one that takes a restitution.
    if (entry->calibration) {
      EXPECT_TRUE(entry->calibratable());
    }
  }
  EXPECT_EQ(law_names().size(), law_registry().size());
  EXPECT_EQ(find_law("no_such_law"), nullptr);
  EXPECT_THROW(make_law({"no_such_law"}, {}), std::invalid_argument);
}

TEST(LawRegistry, EveryLawsExampleMakesIt) {
  for (const LawEntry* entry : law_registry()) {
    EXPECT_FALSE(entry->example.empty()) << entry->name;
    EXPECT_EQ(make_sample(*entry)->name(), entry->name);
  }
}

// The role is what the law does: a contact pushes only when it penetrates, a tension link pulls
// only when it opens, a spring acts both ways.
TEST(LawRegistry, TheRoleIsWhatTheLawDoes) {
  for (const LawEntry* entry : law_registry()) {
    SCOPED_TRACE(entry->name);
    const auto law = make_sample(*entry);
    if (entry->traits.constraint) {
      // No force of its own: what the integrator imposes, kept by commit, undone by revert.
      HardContact* hard = law->hard_contact();
      ASSERT_NE(hard, nullptr);
      EXPECT_EQ(hard->set_trial({0.1, 0.1, 0.0}).force, 0.0);
      hard->impose(3.0);
      EXPECT_EQ(hard->set_trial({0.1, 0.1, 0.0}).force, 3.0);
      EXPECT_FALSE(hard->in_contact());
      hard->commit();
      EXPECT_TRUE(hard->in_contact());
      EXPECT_EQ(hard->clone()->set_trial({0.0, 0.0, 0.0}).force, 3.0);
      hard->impose(0.0);
      hard->revert();
      EXPECT_EQ(hard->set_trial({0.0, 0.0, 0.0}).force, 3.0);
      EXPECT_EQ(entry->traits.role, LinkRole::contact);
      continue;
    }
    EXPECT_EQ(law->hard_contact(), nullptr);
    // Closing while pushed in, opening while pulled apart past any slack (a damper acts on the
    // rate).
    const double pushed = law->clone()->set_trial({0.1, 0.1, 0.0}).force;
    const double opened = law->clone()->set_trial({-0.1, -0.1, 0.0}).force;
    switch (entry->traits.role) {
      case LinkRole::contact:
        EXPECT_GT(pushed, 0.0);
        EXPECT_EQ(opened, 0.0);
        break;
      case LinkRole::tension:
        EXPECT_EQ(pushed, 0.0);
        EXPECT_LT(opened, 0.0);
        break;
      case LinkRole::spring:
        EXPECT_GT(pushed, 0.0);
        EXPECT_LT(opened, 0.0);
        break;
    }
  }
}

// Stiff at first touch: the tangent just after contact is that of a deeper contact, not ~0 as
// for a Hertz-type law (whose tangent grows as the square root of the penetration). A law that
// sets its stiffness from the approach velocity knows it only at the impact: not stiff before.
TEST(LawRegistry, StiffAtFirstTouchIsTheLawsTangentAtTouch) {
  for (const LawEntry* entry : law_registry()) {
    if (entry->traits.role != LinkRole::contact) continue;
    const auto law = make_sample(*entry);
    const double touch = law->clone()->set_trial({1e-12, 0.0, 0.0}).stiffness;
    const double deeper = law->clone()->set_trial({1e-4, 0.0, 0.0}).stiffness;
    std::cout << entry->name << ": tangent at touch / at 1e-4 = " << touch / deeper << "\n";
    const bool stiff = touch > 0.5 * deeper && !entry->traits.uses_approach_velocity;
    EXPECT_EQ(entry->traits.stiff_at_first_touch, stiff) << entry->name;
  }
}

// A law that uses the approach velocity answers the same trial differently after approaching at
// 1 than at 2.
TEST(LawRegistry, UsesTheApproachVelocityExactlyWhenItSaysSo) {
  for (const LawEntry* entry : law_registry()) {
    if (entry->traits.role != LinkRole::contact) continue;
    double forces[2];
    for (int k = 0; k < 2; ++k) {
      const auto law = make_sample(*entry);
      law->set_trial({-1e-9, 1.0 + k, 0.0});
      law->commit();
      law->set_trial({1e-6, 1.0 + k, 0.0});
      law->commit();
      forces[k] = law->set_trial({1e-3, 0.5, 0.0}).force;
    }
    EXPECT_EQ(entry->traits.uses_approach_velocity, forces[0] != forces[1]) << entry->name;
  }
}

TEST(LawRegistry, AcceptsAParameterUnlessTheGivenOnesExcludeIt) {
  const LawEntry& kelvin_voigt = *find_law("kelvin_voigt");
  EXPECT_TRUE(kelvin_voigt.accepts("mass", {"kelvin_voigt", {{"restitution", 0.5}}}));
  EXPECT_FALSE(kelvin_voigt.accepts("mass", {"kelvin_voigt", {{"damping", 10.0}}}));
  EXPECT_FALSE(find_law("hertz_damp")->accepts("mass", {"hertz_damp"}));
}

}  // namespace
}  // namespace pound::links
