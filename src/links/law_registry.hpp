#pragma once
// Every law a link may have, each described once by its class (`entry()`, beside its code, as
// OpenSees keeps a material's parser beside the material): its name in model files, formula,
// units and source (docs/laws.md is generated from them), its parameters and their checks (the
// reader checks a law object against them, the writer writes them back in their order), what it
// is for (its traits) and how it is made. law_registry.cpp lists the entries; nothing else keeps
// a list of law names.
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "links/link_context.hpp"
#include "links/link_law.hpp"

namespace pound::links {

// A law as a model file gives it: its name, numbers and choices (the reader has checked them
// against the law's entry, and filled in every choice's default).
struct LawSpec {
  std::string type;
  std::map<std::string, double> parameters;
  std::map<std::string, std::string> choices;

  std::optional<double> number(const std::string& name) const;
  std::string choice(const std::string& name, const std::string& fallback) const;
  // Equal specs make equal laws in equal contexts (verification's contact probe shares them).
  bool operator==(const LawSpec&) const = default;
};

// Where a law object is in its file, for the errors found only when the law is made.
struct LawSource {
  std::string file;
  std::string path;  // JSON pointer of the law object
};

// Makes a link's law once the assembled model can say what the link joins (masses and
// stiffnesses at its ends, for laws that take their numbers from them). Throws InputError when
// the model cannot give what the law needs.
using LawFactory = std::function<std::unique_ptr<LinkLaw>(const LinkContext&)>;

// What a link is for: a run's summary, a batch row and `pound check` treat them apart.
enum class LinkRole {
  contact,  // pounding: impacts, peak force, penetration
  tension,  // restrainers and hooks: taut, peak tension, opening
  spring,   // structural springs and dampers (bearings, hinges): force both ways
};

struct LawTraits {
  LinkRole role = LinkRole::contact;
  // A finite stiffness at the instant of first touch, known before any impact (Hertz-type laws
  // start from 0; a law calibrated at each impact knows it only then): what a sticking friction
  // penalty can default to, and what a k-ratio can be given for.
  bool stiff_at_first_touch = true;
  // The contact stiffness is a numerical penalty (chosen for the analysis, not a property of the
  // structure), so Kawashima's k-ratio advice applies to it.
  bool penalty = true;
  // The force depends on the approach velocity v0 at first contact (links/impact_onset.hpp).
  bool uses_approach_velocity = false;
  // Not a force law but a constraint the integrator enforces (links/hard_contact.hpp).
  bool constraint = false;
  // An inertia term (dF/d(delta_ddot), the extended penalty's alpha2): its kinetic energy
  // 1/2 alpha2 delta_dot^2 is set at touch, so an engagement's work has no sign to judge by.
  bool inertia = false;
};

struct LawParameter {
  // > 0, >= 0, (0, 1] for a coefficient of restitution, [0, 1), (0, 1], [0, 1]
  enum class Range { positive, non_negative, restitution, fraction, unit, closed_unit };
  std::string name;
  Range range;
  std::string units;            // "F/L", "-": in the model's units
  std::string meaning;          // with the default when there is one
  bool generator_only = false;  // only inside a rod_pair generator (scaled by its elements)
};

struct LawChoice {
  std::string name;
  std::vector<std::string> values;  // the first is the default
  std::string meaning;
};

// How `restitution` becomes a law's damping: the law itself at unit stiffness, effective mass
// and approach velocity (k = m_eff = v0 = 1, where every two-mass impact of the law looks the
// same) with a damping knob, whose value for e is found by running its impact
// (links/restitution_calibration.hpp); and the source's own formula, which approximates it.
struct RestitutionCalibration {
  std::function<std::unique_ptr<LinkLaw>(double damping, const LawSpec& law)> unit_law;
  std::function<double(double restitution)> published;
};

struct LawEntry {
  std::string name;
  std::string formula;
  std::string source;
  std::vector<LawParameter> parameters;
  std::vector<LawChoice> choices;
  std::vector<std::string> required;
  // Groups of which exactly one parameter must be given ("damping" or "restitution").
  std::vector<std::vector<std::string>> exactly_one_of;
  // A parameter that, when given, needs others or rules others out.
  std::map<std::string, std::vector<std::string>> needs;
  std::map<std::string, std::vector<std::string>> excludes;
  LawTraits traits;
  // A typical, valid set of its numbers (SI units, bridge scale), for the docs and the tests.
  std::map<std::string, double> example;
  std::optional<RestitutionCalibration> calibration;
  // The factory of a law object, its parameters already checked by the reader; `where` locates
  // it for errors the combination of numbers or the model reveals.
  std::function<LawFactory(const LawSpec& law, const LawSource& where)> make;

  const LawParameter* parameter(std::string_view name) const;
  // Whether `parameter` may be added to `law` (the law has it, and nothing given excludes it).
  bool accepts(const std::string& parameter, const LawSpec& law) const;
  // Reaches a target coefficient of restitution of a two-mass impact when given one.
  // (A constraint takes e as its impact law instead.)
  bool calibratable() const { return parameter("restitution") != nullptr && !traits.constraint; }
};

// What several laws share: a target restitution, how it becomes damping, and the effective mass
// they calibrate with.
LawParameter restitution_parameter();
LawChoice calibration_choice();
LawParameter effective_mass_parameter();
// m1 m2 / (m1 + m2) of the two ends: the law's own `mass`, or the model's; an InputError at
// where/mass when neither gives a positive one.
double effective_mass(const LawSpec& law, const LawSource& where, const LinkContext& context);

// Every law, in the order of docs/laws.md.
const std::vector<const LawEntry*>& law_registry();
const LawEntry* find_law(std::string_view name);
std::vector<std::string> law_names();

// The factory of the law `law` names (a rod pair's stiffness_ratio already resolved).
LawFactory make_law(const LawSpec& law, const LawSource& where);

}  // namespace pound::links
