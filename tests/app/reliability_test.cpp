// Every input ends in a clear answer (issue 14): the reproducers of the mutation sweep that
// crashed, aborted or "completed" with overflowed numbers, each now refused before the run
// (exit 2, file and JSON path, nothing written) or failed loudly (exit 3, when and why).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>
#include <vector>

#include "support/process.hpp"

namespace pound::testing {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

class Reliability : public PoundProcess {
 protected:
  // A bundled model with its records named by absolute path, so it runs from the test folder.
  static json bundled(const std::string& name) {
    json model = json::parse(read_text(fs::path(POUND_SOURCE_DIR) / "models" / (name + ".json")));
    if (!model.contains("excitations")) return model;
    for (json& excitation : model["excitations"])
      if (excitation.contains("record"))
        excitation["record"] =
            (fs::path(POUND_SOURCE_DIR) / "models" / excitation["record"].get<std::string>())
                .lexically_normal()
                .string();
    return model;
  }
  std::string write(const std::string& name, const json& model) const {
    std::ofstream(path(name)) << model.dump();
    return path(name).string();
  }
  // `pound <command> model`, expected refused: exit 2, the file and `where` named, no output.
  void expect_refused(const std::string& command, const std::string& model,
                      const std::vector<std::string>& parts) const {
    std::vector<std::string> arguments{command, model};
    if (command == "run") arguments.insert(arguments.end(), {"--out", path("out").string()});
    const Outcome outcome = pound(arguments);
    EXPECT_EQ(outcome.exit_code, 2) << command << ": " << outcome.err;
    EXPECT_TRUE(contains(outcome.err, "error: " + model + ": ")) << outcome.err;
    for (const std::string& part : parts) EXPECT_TRUE(contains(outcome.err, part)) << outcome.err;
    EXPECT_FALSE(fs::exists(path("out"))) << command;
  }
  // Each (model, where, what) written to a file and refused by both run and check.
  void expect_each_refused(
      const std::vector<std::tuple<json, std::string, std::string>>& refusals) const {
    for (const auto& [model, where, what] : refusals) {
      const std::string file = write("refused.json", model);
      for (const char* command : {"run", "check"}) expect_refused(command, file, {where, what});
    }
  }
  // `pound run model` expected to fail loudly: exit 3, the reason, a summary saying "failed".
  Outcome expect_failed(const std::string& model, const std::string& reason) const {
    const Outcome outcome = pound({"run", model, "--out", path("out").string(), "--quiet"});
    EXPECT_EQ(outcome.exit_code, 3) << outcome.err;
    EXPECT_TRUE(contains(outcome.err, "analysis failed at t = ")) << outcome.err;
    EXPECT_TRUE(contains(outcome.err, reason)) << outcome.err;
    const json summary = json::parse(read_text(path("out/summary.json")));
    EXPECT_EQ(summary["status"], "failed");
    return outcome;
  }
};

// A block launched on a floor from a static start (its weight settled first) was refused as
// "the initial loads ask more of friction than it holds" once its stick dashpot's c_t v0 passed
// mu N: the first step's trial had committed the friction with the launch velocity before the
// run's static solve. It slides and stops as without the static start, at v0^2 / (2 mu g).
TEST_F(Reliability, ALaunchedBlockStartsFromItsStaticState) {
  json model = bundled("block_on_floor");
  model["analysis"]["initial_state"] = "static";
  const Outcome outcome =
      pound({"run", write("launched.json", model), "--out", path("out").string(), "--quiet"});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const std::string csv = read_text(path("out/block.csv"));
  const std::string last = csv.substr(csv.rfind('\n', csv.size() - 2) + 1);
  const double stop = std::stod(last.substr(last.find(',') + 1));
  const double expected = 2.0 * 2.0 / (2 * 0.5 * 9.81);
  std::printf("launched from its static state: stops at %.6f m against v0^2/(2 mu g) = %.6f m\n",
              stop, expected);
  EXPECT_NEAR(stop / expected, 1.0, 1e-4);
}

// No DOFs with modal damping segfaulted in run, check and modes.
TEST_F(Reliability, ModalDampingWithoutModesIsRefused) {
  const std::string model = write("empty.json", json::parse(R"({"dimension": 1,
      "damping": {"ratio": 0.05, "modes": [1, 3]},
      "analysis": {"time_step": 0.01, "duration": 1.0}})"));
  for (const char* command : {"run", "check", "modes"})
    expect_refused(command, model, {"/damping/modes", "the model has 0 vibration modes"});
}

// Modal damping asking for a mode that was dropped as rigid-body motion said only "mode 2 asked
// for, the model has 1 vibration modes"; it now says why the other is not a vibration mode.
TEST_F(Reliability, ModalDampingNamesTheModesThatStoreNoStrainEnergy) {
  json model = bundled("two_sdof_girders");
  model["elements"].erase(1);  // girder_2 stands on nothing: a mass free to move as a whole
  model["masses"][0].erase("mass_damping");
  model["masses"][1].erase("mass_damping");
  model["damping"] = {{"ratio", 0.05}, {"modes", {1, 2}}};
  const std::string file = write("free_girder.json", model);
  for (const char* command : {"run", "check"})
    expect_refused(command, file,
                   {"/damping/modes", "the model has 1 vibration mode:",
                    "1 of the model's 2 modes (one per DOF with mass) stores no strain energy"});
}

// A spring law across a gap pulled with k x gap at rest: a yielding shear key 5 cm from the deck
// carried -100 kN at t = 0, the generator's keys -2 MN each, and a spring as the buildings'
// pounding law failed the run blaming the time step (audit 70). Each is refused where it is
// written, with the laws that fit; a generator's law at its own path, not the generator's.
TEST_F(Reliability, ALawInTheWrongRoleIsRefusedWhereItIsWritten) {
  const json spring = {
      {"type", "elastic_perfectly_plastic"}, {"stiffness", 1e8}, {"yield_force", 1e5}};
  json girders = bundled("two_sdof_girders");
  girders["links"][0]["law"] = spring;
  json bridge = bundled("three_span_bridge");
  bridge["generators"][0]["joint"]["law"] = spring;
  json restrainer = bundled("three_span_bridge");
  restrainer["generators"][0]["joint"]["restrainer"] = {{"type", "gap_spring"}, {"stiffness", 1e8}};
  json backfill = bundled("three_span_bridge");
  backfill["generators"][0]["backfill"] = {{"type", "elastic_spring"}, {"stiffness", 5e8}};
  json buildings = bundled("adjacent_buildings");
  buildings["generators"][0]["law"] = {{"type", "elastic_spring"}, {"stiffness", 1e8}};
  expect_each_refused(
      {{girders, "/links/0/gap", "a spring pulling with k x gap"},
       {bridge, "/generators/0/joint/law/type", "needs a compression-only contact law"},
       {restrainer, "/generators/0/joint/restrainer/type", "pushes, not pulls"},
       {backfill, "/generators/0/backfill/type", "would pull with k x gap"},
       {buildings, "/generators/0/law/type", "hertz_damp, jankowski"}});
}

// A field given where it does not apply was "unknown field", which sends a reader looking for a
// typo: backwall_mass without backfill (documented "required", with backfill) now says where it
// applies. A hard contact where a floor strikes the other building's column between its floors (no
// mass there for its impulse) was refused at /analysis/integrator, naming a generated node; now at
// the generator's law (audit 70).
TEST_F(Reliability, AFieldOrLawThatDoesNotApplyIsRefusedSayingWhy) {
  json bridge = bundled("three_span_bridge");
  bridge["generators"][0].erase("backfill");
  json buildings = bundled("adjacent_buildings");
  buildings["generators"][0]["law"] = {{"type", "hard_contact"}, {"restitution", 0.5}};
  expect_each_refused({{bridge, "/generators/0/backwall_mass",
                        "unknown field here: it applies only where the docs say (with backfill)"},
                       {buildings, "/generators/0/law",
                        "at 3 a floor strikes the left building's column between its floors"}});
}

// Central difference's "auto" step cannot see a Hertz-type contact (no stiffness until it
// touches): it took 1.7 s steps through impacts and completed with a force 2,400 x the exact one.
// A hard contact's impulse needs Newmark's beta >= 1/4: under linear acceleration a block sank
// through its floor. A relative Newton tolerance of 1 passed bodies through each other. Each is
// refused at its path (audit 70).
TEST_F(Reliability, IntegratorSettingsThatCannotResolveTheContactsAreRefused) {
  json hertz = bundled("two_sdof_girders");
  hertz["links"][0]["law"] = {{"type", "hertz_damp"}, {"stiffness", 4e10}, {"restitution", 0.65}};
  hertz["analysis"] = {{"integrator", "central_difference"}};
  json linear = bundled("two_girders_hard_contact");
  linear["analysis"]["integrator"] = "newmark_linear_acceleration";
  json loose = bundled("two_sdof_girders");
  loose["analysis"]["convergence"] = {{"relative_tolerance", 1.0}};
  expect_each_refused({{hertz, "/analysis/time_step", "no stiffness until it touches"},
                       {linear, "/analysis/integrator", "(beta = 0.1667 < 1/4) cannot impose"},
                       {loose, "/analysis/convergence/relative_tolerance", "must be < 0.1"}});
}

// Masses of 1e300 (m1 m2 overflows) or 1e-300 (underflows) were refused as "both ends fixed or
// massless", which they are not; storey_damping on a building without yielding storeys was taken
// silently (it damps only yielding storeys' links). Each now says what it is (audit 70).
TEST_F(Reliability, MassesAndStoreyDampingThatMeanNothingSayWhy) {
  json heavy = bundled("two_sdof_girders");
  json light = heavy;
  for (json& mass : heavy["masses"]) mass["mass"] = 1e300;
  for (json& mass : light["masses"]) mass["mass"] = 1e-300;
  json elastic = bundled("adjacent_buildings");
  elastic["generators"][0]["left"]["storey_damping"] = "committed";
  expect_each_refused({{heavy, "/links/0/law/mass", "overflows: masses far beyond physical ones"},
                       {light, "/links/0/law/mass", "or masses so small that m1 m2 underflows"},
                       {elastic, "/generators/0/left/storey_damping", "with a yielding storey"}});
}

// The bundled bridge without its girders' extra mass: a deck without mass. It aborted in run
// ("not positive definite at equation 24") while check passed; then both named a girder node as
// a mechanism without mass; now the generator refuses the massless deck at its girder. A node
// without mass that only links hold, on a part no element joins to a support, is still such a
// mechanism, refused naming its node.
TEST_F(Reliability, MasslessMechanismIsFoundBeforeTheRunNamingItsNode) {
  json model = bundled("three_span_bridge");
  model["generators"][0]["girder"].erase("extra_mass");
  const std::string file = write("no_extra_mass.json", model);
  for (const char* command : {"run", "check"})
    expect_refused(command, file, {"/generators/0/girder: the girders have no mass"});
  // A girder and its tip (a truss between them) without mass, against the abutment through the
  // contact alone: no element or spring holds the part.
  json loose = bundled("girder_abutment_sdof");
  loose["masses"] = json::array();
  loose.erase("initial_velocities");
  loose["nodes"].push_back(json::parse(R"({"id": "tip", "x": 5.0})"));
  loose["elements"][0]["nodes"] = json::parse(R"(["tip", "girder"])");
  const std::string loose_file = write("loose.json", loose);
  for (const char* command : {"run", "check"})
    expect_refused(command, loose_file, {"fails at node 'tip'", "a mechanism without mass"});
}

// Piers of density 0 (girder_bridge's default) on plastic hinges, without gravity: their tops are
// static DOFs the hinges and bearings hold. The run was refused as "a mechanism without mass"
// (Newmark checked the matrix without its links); it now runs, and its pier drifts are those of
// nearly massless piers (density 0.01: within 3e-4, the response being chaotic after impacts).
// The tops' step-by-step accelerations are no accelerations: not reported (a massless elastic
// pier's read 13.95 m/s^2 against 4.68 with its mass).
TEST_F(Reliability, MasslessPiersOnHingesRunAsStaticDofs) {
  std::map<double, json> piers;
  for (const double density : {0.0, 0.01}) {
    json model = bundled("three_span_bridge_takeda");
    model.erase("gravity");
    model.erase("recorders");
    model["generators"][0]["pier"]["density"] = density;
    const std::string file = write("massless_piers.json", model);
    const Outcome outcome = pound({"run", file, "--out", path("out").string(), "--quiet"});
    ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
    piers[density] = json::parse(read_text(path("out/summary.json")))["piers"];
    fs::remove_all(path("out"));
  }
  ASSERT_EQ(piers[0.0].size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    const json &massless = piers[0.0][k], &light = piers[0.01][k];
    const double drift = massless["peak_drift"].get<double>();
    const double difference = drift / light["peak_drift"].get<double>() - 1.0;
    std::cout << massless["id"] << ": peak drift " << drift << " m, against density 0.01 "
              << difference << ", ductility " << massless["ductility"] << "\n";
    EXPECT_LT(std::abs(difference), 1e-3);
    EXPECT_GT(massless["ductility"].get<double>(), 1.0);
    EXPECT_TRUE(massless["top_without_mass"].get<bool>());
    EXPECT_FALSE(massless.contains("peak_absolute_acceleration"));
    EXPECT_FALSE(light.contains("top_without_mass"));
    EXPECT_TRUE(light.contains("peak_absolute_acceleration"));
  }
}

// A storey mass of 5e-324 (a denormal) aborted with "pivot -nan"; 1e-300 aborted check and
// modes in the modal analysis.
TEST_F(Reliability, DenormalAndTinyMassesEndInAClearAnswer) {
  for (const double mass : {5e-324, 1e-300}) {
    json model = bundled("adjacent_buildings");
    model["generators"][0]["right"]["storeys"][4]["mass"] = mass;
    const std::string file = write("tiny_mass.json", model);
    for (const char* command : {"run", "check", "modes"}) {
      std::vector<std::string> arguments{command, file};
      if (std::string(command) == "run")
        arguments.insert(arguments.end(), {"--out", path("out").string(), "--quiet"});
      const Outcome outcome = pound(arguments);
      std::cout << "mass " << mass << ", " << command << ": exit " << outcome.exit_code << "\n";
      EXPECT_TRUE(outcome.exit_code == 0 || outcome.exit_code == 2 || outcome.exit_code == 3)
          << command << " " << outcome.exit_code << ": " << outcome.err;
      if (outcome.exit_code != 0) {
        EXPECT_TRUE(contains(outcome.err, "error: ")) << outcome.err;
      }
      fs::remove_all(path("out"));
    }
  }
}

// E, A or I of 1e308 overflow an element's matrices: refused naming the element.
TEST_F(Reliability, AnElementWhoseMatricesOverflowIsRefusedByName) {
  json model = bundled("two_sdof_girders");
  model["materials"][0]["youngs_modulus"] = 1e308;
  model["elements"][0]["area"] = 10.0;
  expect_refused("run", write("overflow.json", model),
                 {"/elements/0: element 'pier_1': its stiffness or mass is not finite"});
}

// Link stiffness 1e20: the girder flew 1e10 m and the run "completed", because the links' negative
// work cancelled the energy residual. Now the links' created energy stops it.
TEST_F(Reliability, EnergyCreatedThroughALinkStopsTheRun) {
  json model = bundled("two_sdof_girders");
  model["links"][0]["law"]["stiffness"] = 1e20;
  expect_failed(write("stiff.json", model), "the links have given the structure");
}

// A load of 1e300 overflowed the energy input, written as null in a "completed" summary.
TEST_F(Reliability, ANonFiniteResultFailsTheRun) {
  json model = bundled("block_on_floor");
  model["loads"] = json::parse(R"([{"node": "block", "x": 1e300, "y": 0}])");
  expect_failed(write("load.json", model), "a result is not finite");
}

// The exact rod solution's own limits (a gap of 1e308, a modulus of 5e-324) crashed after the
// analysis, losing its results: the run now keeps them, with a warning.
TEST_F(Reliability, RodPairBeyondTheExactSolutionKeepsItsResults) {
  for (const auto& [pointer, value] :
       std::vector<std::pair<std::string, double>>{{"/generators/0/gap", 1e308},
                                                   {"/generators/0/right/youngs_modulus", 5e-324},
                                                   {"/generators/0/right/length", 1e300}}) {
    json model = bundled("rod_impact");
    model[json::json_pointer(pointer)] = value;
    const Outcome outcome =
        pound({"run", write("rod.json", model), "--out", path("out").string(), "--quiet"});
    std::cout << pointer << " = " << value << ": exit " << outcome.exit_code << "\n";
    EXPECT_TRUE(outcome.exit_code == 0 || outcome.exit_code == 2 || outcome.exit_code == 3)
        << outcome.err;
    if (outcome.exit_code == 0) {
      EXPECT_TRUE(fs::exists(path("out/summary.json")));
      EXPECT_TRUE(contains(outcome.err, "the exact solution of the rod pair could not be computed"))
          << outcome.err;
    }
    fs::remove_all(path("out"));
  }
}

// Two initial velocities for one node (the last won) and repeated monitor ids are refused.
TEST_F(Reliability, RepeatedInitialVelocitiesAndMonitorIdsAreRefused) {
  json model = bundled("two_girders_joint");
  model["initial_velocities"].push_back(model["initial_velocities"][0]);
  expect_refused("run", write("velocities.json", model),
                 {"/initial_velocities/2/node: node 'girder_1' already has an initial velocity "
                  "(at /initial_velocities/0)"});
  json monitored = bundled("two_sdof_girders");
  monitored["monitors"]["joints"].push_back(monitored["monitors"]["joints"][0]);
  expect_refused("run", write("monitors.json", monitored),
                 {"/monitors/joints/1", "duplicate joint monitor id 'joint'"});
}

// The verify benchmarks skipped the memory check that run applies: 10^8 elements per rod (2e8
// DOFs, ~400 GB) and 10^6 elements across the 2-D strips are refused before allocating.
TEST_F(Reliability, VerifyRefusesMeshesBeyondTheMemory) {
  const Outcome rods = pound({"verify", "rod-impact", "--n", "100000000"});
  EXPECT_EQ(rods.exit_code, 1) << rods.err;
  EXPECT_TRUE(contains(rods.err, "--n 100000000: the rods would need about")) << rods.err;
  const Outcome strips = pound({"verify", "rod-impact-2d", "--n-across", "1000000"});
  EXPECT_EQ(strips.exit_code, 1) << strips.err;
  EXPECT_TRUE(contains(strips.err, "--n-across 1000000: the strips would need about"))
      << strips.err;
}

// A storey stiffness of 1e-300 aborted; it now runs, and its 100 % drift is called meaningless.
TEST_F(Reliability, AVanishingStoreyStiffnessWarnsThatItsDriftIsMeaningless) {
  json model = bundled("adjacent_buildings");
  model["generators"][0]["left"]["storeys"][2]["stiffness"] = 1e-300;
  const Outcome outcome =
      pound({"run", write("soft.json", model), "--out", path("out").string(), "--quiet"});
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_TRUE(contains(outcome.err, "storey pair.left.s3: drift ratio")) << outcome.err;
  EXPECT_TRUE(contains(outcome.err, "the result is meaningless there")) << outcome.err;
}

// Central difference's "auto" step with a density of 1e-300 reached the integrator as infinite
// (the power iteration's vector overflowed to zero): it is now the tiny limit it is, refused as
// too many steps.
TEST_F(Reliability, AnExplicitStepFromAnOverflowingFrequencyIsRefused) {
  json model = bundled("rod_impact");
  model["analysis"]["integrator"] = "central_difference";
  model["analysis"]["time_step"] = "auto";
  model["generators"][0]["left"]["density"] = 1e-300;
  expect_refused("run", write("light.json", model), {"/analysis/time_step", "steps, more than"});
}

// A record value of 1.7e308 g overflowed every spectral value to inf under exit 0.
TEST_F(Reliability, ARecordValueThatOverflowsIsRefused) {
  std::ofstream(path("big.txt")) << "0.01\n0.5\n1.7e308\n0.2\n";
  const Outcome outcome = pound({"spectrum", path("big.txt").string(), "--dt", "0.01"});
  EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
  EXPECT_TRUE(contains(outcome.err, "big.txt: sample 3 overflows the number range")) << outcome.err;
}

// An Sa target at a period of 1e-300 s aborted (w^2 overflowed): an oscillator that much faster
// than the sampling is rigid, so its Sa is the PGA and the record scales as to that PGA.
TEST_F(Reliability, AnSaTargetAtAVanishingPeriodScalesAsThePga) {
  json model = bundled("two_sdof_girders");
  model["excitations"][0]["scale"] = json::parse(R"({"sa": 0.5, "period": 1e-300})");
  const Outcome sa = pound({"run", write("sa.json", model), "--out", path("sa").string(), "-q"});
  model["excitations"][0]["scale"] = json::parse(R"({"pga": 0.5})");
  const Outcome pga = pound({"run", write("pga.json", model), "--out", path("pga").string(), "-q"});
  ASSERT_EQ(sa.exit_code, 0) << sa.err;
  ASSERT_EQ(pga.exit_code, 0) << pga.err;
  EXPECT_EQ(read_text(path("sa/joint.csv")), read_text(path("pga/joint.csv")));
}

}  // namespace
}  // namespace pound::testing
