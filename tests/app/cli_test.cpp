// The `pound` program as a user runs it: exit codes, messages, and the files it writes (or does
// not write). Each test runs the real binary with its output captured in a fresh temporary folder.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "io/ground_motion_reader.hpp"
#include "links/restitution.hpp"
#include "support/process.hpp"
#include "support/shared_records.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kRodModel = POUND_SOURCE_DIR "/models/rod_impact.json";
const std::string kGirderModel = POUND_SOURCE_DIR "/models/girder_abutment_sdof.json";

// A small valid model; the bad-input cases change one thing in it (RFC 6902 patch).
constexpr const char* kModel = R"({
  "dimension": 1,
  "nodes": [{"id": "ground", "x": 0.0}, {"id": "girder", "x": 10.0},
            {"id": "abutment", "x": 10.0}],
  "materials": [{"id": "bearing", "youngs_modulus": 2.0e6, "density": 0.0}],
  "elements": [{"id": "bearing", "type": "truss", "nodes": ["ground", "girder"],
                "material": "bearing", "area": 0.05}],
  "masses": [{"node": "girder", "mass": 500.0}],
  "supports": [{"node": "ground", "fix": ["x"]}, {"node": "abutment", "fix": ["x"]}],
  "initial_velocities": [{"node": "girder", "x": 0.5}],
  "links": [{"id": "joint", "nodes": ["girder", "abutment"], "axis": [1], "gap": 0.02,
             "law": {"type": "gap_spring", "stiffness": 1.0e6}}],
  "analysis": {"time_step": 0.001, "duration": 0.1}
})";

std::vector<std::string> read_lines(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// First comma-separated field of a CSV data line, as a number.
double first_field(const std::string& line) { return std::stod(line.substr(0, line.find(','))); }

using pound::testing::Outcome;
using pound::testing::read_text;

class Cli : public pound::testing::PoundProcess {
 protected:
  // Writes kModel with `json_patch` applied; returns the file's path.
  std::string write_model(const std::string& name, const std::string& json_patch) const {
    const fs::path file = path(name);
    std::ofstream(file) << json::parse(kModel).patch(json::parse(json_patch)).dump(2);
    return file.string();
  }

  // `pound run` on a model that must be refused: exit 2, nothing written.
  Outcome run_refused(const std::string& model) const {
    const fs::path out = path("out");
    const Outcome outcome = pound({"run", model, "--out", out.string()});
    EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
    EXPECT_NE(outcome.err.find(model), std::string::npos) << outcome.err;
    EXPECT_FALSE(fs::exists(out)) << "output folder created for an invalid model";
    std::cout << "stderr: " << outcome.err;
    return outcome;
  }
};

using pound::testing::contains;

TEST_F(Cli, HelpListsTheCommands) {
  const Outcome outcome = pound({"--help"});
  EXPECT_EQ(outcome.exit_code, 0);
  EXPECT_TRUE(contains(outcome.out, "run MODEL.json")) << outcome.out;
  EXPECT_TRUE(contains(outcome.out, "verify rod-impact")) << outcome.out;
}

TEST_F(Cli, NoArgumentsIsAUsageError) {
  const Outcome outcome = pound({});
  EXPECT_EQ(outcome.exit_code, 1);
  EXPECT_TRUE(contains(outcome.err, "usage")) << outcome.err;
}

TEST_F(Cli, UnknownCommandIsAUsageError) {
  const Outcome outcome = pound({"frobnicate"});
  EXPECT_EQ(outcome.exit_code, 1);
  EXPECT_TRUE(contains(outcome.err, "unknown command 'frobnicate'")) << outcome.err;
}

TEST_F(Cli, RunHelpShowsItsOptions) {
  const Outcome outcome = pound({"run", "--help"});
  EXPECT_EQ(outcome.exit_code, 0);
  for (const char* option : {"--out", "--max-steps", "--quiet"})
    EXPECT_TRUE(contains(outcome.out, option)) << option << " missing from\n" << outcome.out;
}

TEST_F(Cli, VerifyHelpShowsItsOptions) {
  const Outcome outcome = pound({"verify", "--help"});
  EXPECT_EQ(outcome.exit_code, 0);
  for (const char* option : {"--json", "--n", "--k-ratio", "--dt-ratio", "--courant", "--case",
                             "--csv", "--profiles-csv", "--study"})
    EXPECT_TRUE(contains(outcome.out, option)) << option << " missing from\n" << outcome.out;
}

// HHT at alpha = -1/3 damps a 1.4 s oscillator stepped at 0.05 s (omega dt = 0.22) by design,
// which the energy balance counts as an error (4.9e-2 of the run's largest term): the warning
// says so instead of blaming a contact or a step; the trapezoidal rule's run of the same model
// balances, and gives no such warning. (HHT at its default alpha on the bundled bridge balances
// to 8.6e-5 of the run's largest term; measured against the terms of its first steps it read
// 1 % or more, and warned.)
TEST_F(Cli, BalanceWarningOfADissipativeMethodSaysTheMethodDampsByDesign) {
  json model =
      json::parse(read_text(fs::path(POUND_SOURCE_DIR) / "models" / "girder_abutment_sdof.json"));
  model["links"] = json::array();
  model.erase("recorders");
  model.erase("initial_velocities");
  model["damping"] = {{"ratio", 0.05}, {"periods", {1.405, 0.5}}};
  model["excitations"] = {
      {{"record", std::string(POUND_SOURCE_DIR) + "/ground_motions/synthetic_firm_01.AT2"}}};
  const std::vector<std::pair<std::string, json>> integrators{
      {"hht", {{"type", "hht"}, {"alpha", -1.0 / 3.0}}},
      {"newmark_average_acceleration", "newmark_average_acceleration"}};
  for (const auto& [name, integrator] : integrators) {
    model["analysis"] = {{"integrator", integrator}, {"time_step", 0.05}};
    const fs::path file = path(name + ".json");
    std::ofstream(file) << model.dump(2);
    const fs::path out = path(name + ".out");
    const Outcome outcome = pound({"run", file.string(), "--out", out.string(), "--quiet"});
    ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
    const double error =
        json::parse(read_text(out / "summary.json"))["energy"]["worst_balance_error"].get<double>();
    std::cout << name << ": worst balance error " << error << "\n";
    if (name == "hht") {
      EXPECT_GT(error, 0.01);
      EXPECT_TRUE(contains(outcome.err, "damps the highest modes by design")) << outcome.err;
      EXPECT_FALSE(contains(outcome.err, "was not resolved (reduce")) << outcome.err;
    } else {
      EXPECT_LT(error, 1e-9);
      EXPECT_FALSE(contains(outcome.err, "energy balance error reached")) << outcome.err;
    }
  }
}

// Hard contacts under Newmark in a generated bridge and between two SDOF girders: the energy
// balance closes to round-off (the contact's force is its step's impulse, and the balance takes
// it so), no contact creates energy, and the girders pound as often as under central difference.
TEST_F(Cli, HardContactUnderNewmarkBalancesEnergy) {
  json girders = json::parse(
      read_text(fs::path(POUND_SOURCE_DIR) / "models" / "two_girders_hard_contact.json"));
  girders["analysis"]["integrator"] = "newmark_average_acceleration";
  girders["analysis"]["time_step"] = 0.005;
  for (json& excitation : girders["excitations"])  // relative to models/, the file moves
    excitation["record"] =
        (fs::path(POUND_SOURCE_DIR) / "models" / excitation["record"].get<std::string>())
            .lexically_normal()
            .string();
  const fs::path girders_file = path("girders.json");
  std::ofstream(girders_file) << girders.dump(2);
  for (const fs::path& model :
       {fs::path(POUND_SOURCE_DIR) / "models" / "three_span_bridge_hard_contact.json",
        girders_file}) {
    const fs::path out = path(model.stem().string() + ".out");
    const Outcome outcome = pound({"run", model.string(), "--out", out.string()});
    ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
    const json summary = json::parse(read_text(out / "summary.json"));
    const json& energy = summary["energy"];
    std::cout << model.filename() << ": balance error " << energy["balance_error"]
              << ", created by contacts " << energy["contact_created"] << " of input "
              << energy["input"] << "\n";
    EXPECT_LT(energy["worst_balance_error"].get<double>(), 1e-9);
    EXPECT_LT(energy["contact_created_fraction"].get<double>(), 1e-4);
    int impacts = 0;
    for (const json& link : summary["links"])
      if (link["role"] == "contact") impacts += link["impacts"].get<int>();
    EXPECT_GT(impacts, 10);
  }
}

// The block's x displacement in the last row of its node history (time, x, ...).
double last_block_position(const fs::path& history_file) {
  const std::string history = read_text(history_file);
  const std::string last = history.substr(history.rfind('\n', history.size() - 2) + 1);
  return std::stod(last.substr(last.find(',') + 1));
}

// The bundled block on a rough floor with a hard contact in place of its penalty: under the
// explicit and an implicit integrator it stops at v^2 / (2 mu g) and its contact's work is the
// kinetic energy it had (central difference's takes the start's friction force over the first
// half step, where it acts: 20 J to 5e-12; by the trapezoidal rule it was F v dt / 2 short).
TEST_F(Cli, HardContactWithFrictionStopsABlockWhereMuGSays) {
  json block =
      json::parse(read_text(fs::path(POUND_SOURCE_DIR) / "models" / "block_on_floor.json"));
  block["links"][0]["law"] = {{"type", "hard_contact"}, {"restitution", 0.0}};
  const double stop = 2.0 * 2.0 / (2.0 * 0.5 * 9.81);
  for (const std::string integrator : {"central_difference", "newmark_average_acceleration"}) {
    block["analysis"]["integrator"] = integrator;
    const fs::path model = path(integrator + ".json"), out = path(integrator + ".out");
    std::ofstream(model) << block.dump(2);
    const Outcome outcome = pound({"run", model.string(), "--out", out.string()});
    ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
    const json summary = json::parse(read_text(out / "summary.json"));
    const json& energy = summary["energy"];
    const double position = last_block_position(out / "block.csv");
    std::cout << integrator << ": stopped at " << position << " (exact " << stop
              << "), contact work " << energy["links"] << " of 20, balance error "
              << energy["balance_error"] << "\n";
    EXPECT_NEAR(position, stop, 1e-7);
    EXPECT_NEAR(energy["links"].get<double>(), 20.0,
                integrator == "central_difference" ? 1e-9 : 1e-6);
    EXPECT_LT(energy["worst_balance_error"].get<double>(), 1e-3);
    EXPECT_LT(energy["contact_created_fraction"].get<double>(), 1e-6);
  }
}

// Bodies that touch at t = 0 and approach strike at once. Under central difference the contact's
// force at the start acts over the first half step: it is an impact (it counted none, with impulse
// and work 0, as a trial of the first step on the run's system had left the contact holding), and
// its work is F_0 (dt delta_dot_0 + d(delta)) / 4, what the impulse took from the kinetic energy
// (the trapezoidal rule gave -1.5 J for the block's +0.75 and stopped the run as created energy).
// Against the rigid-body impulse solution: a 2 kg block at 1 m/s on a wall, e = 0.5 (impulse
// m (1 + e) v = 3 N s, loss (1 - e^2) m v^2 / 2 = 0.75 J), and three 1 kg masses touching, the
// first at 1 m/s, e = 1 (the simultaneous solution: impulses 4/3 and 2/3 N s, no loss).
// `count` masses of `mass` on a line 1 apart, the first at 1 m/s toward the others.
json moving_masses(int count, double mass, const std::string& integrator) {
  json model = {{"dimension", 1},
                {"nodes", json::array()},
                {"masses", json::array()},
                {"supports", json::array()},
                {"links", json::array()},
                {"initial_velocities", {{{"node", "m0"}, {"x", 1.0}}}},
                {"analysis", {{"integrator", integrator}, {"time_step", 1e-3}, {"duration", 0.2}}}};
  for (int k = 0; k < count; ++k) {
    model["nodes"].push_back({{"id", fmt::format("m{}", k)}, {"x", k}});
    model["masses"].push_back({{"node", fmt::format("m{}", k)}, {"mass", mass}});
  }
  return model;
}

// Masses of 100 and 200 t, the first at 1 m/s, `gap` apart, on an undamped extended penalty
// (alpha0 = 1e9 N/m, `alpha2`), over 0.05 s at dt = 1e-5 s.
json penalty_pair(const std::string& integrator, double alpha2, double gap) {
  json pair = moving_masses(2, 1e5, integrator);
  pair["masses"][1]["mass"] = 2e5;
  pair["analysis"]["time_step"] = 1e-5;
  pair["analysis"]["duration"] = 0.05;
  pair["links"] = {
      {{"id", "c"},
       {"nodes", {"m0", "m1"}},
       {"gap", gap},
       {"law",
        {{"type", "extended_penalty"}, {"alpha0", 1e9}, {"alpha1", 0.0}, {"alpha2", alpha2}}}}};
  return pair;
}

// A hard contact c<i> between masses i and j.
json hard_contact_between(int i, int j, double restitution, double gap = 0.0) {
  return json{{"id", fmt::format("c{}", i)},
              {"nodes", {fmt::format("m{}", i), fmt::format("m{}", j)}},
              {"gap", gap},
              {"law", {{"type", "hard_contact"}, {"restitution", restitution}}}};
}

TEST_F(Cli, AHardContactStrikingAtTheStartIsAnImpactWithItsImpulseAndLoss) {
  json wall = moving_masses(2, 2.0, "central_difference");
  wall["masses"].erase(1);
  wall["supports"].push_back({{"node", "m1"}, {"fix", {"x"}}});
  wall["links"].push_back(hard_contact_between(0, 1, 0.5));
  json chain = moving_masses(3, 1.0, "central_difference");
  chain["links"] = {hard_contact_between(0, 1, 1.0), hard_contact_between(1, 2, 1.0)};
  for (const auto& [name, model, impulses, loss] :
       std::vector<std::tuple<std::string, json, std::vector<double>, double>>{
           {"wall", wall, {3.0}, 0.75}, {"chain", chain, {4.0 / 3.0, 2.0 / 3.0}, 0.0}}) {
    const fs::path file = path(name + ".json"), out = path(name + ".out");
    std::ofstream(file) << model.dump(2);
    const Outcome outcome = pound({"run", file.string(), "--out", out.string()});
    ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
    const json summary = json::parse(read_text(out / "summary.json"));
    double worst = 0.0, work = 0.0;
    for (std::size_t k = 0; k < impulses.size(); ++k) {
      const json& link = summary["links"][k];
      EXPECT_EQ(link["impacts"], 1) << name;
      worst = std::max(worst, std::abs(link["impulse"].get<double>() - impulses[k]));
      work += link["work"].get<double>();
    }
    std::cout << fmt::format(
        "{} struck at t = 0: impulses off by {:.1e} N s, contact work {:.12f} J against {} J, "
        "balance error {:.1e}\n",
        name, worst, work, loss, summary["energy"]["worst_balance_error"].get<double>());
    EXPECT_LT(worst, 1e-12);
    EXPECT_NEAR(work, loss, 1e-12);
    EXPECT_NEAR(summary["energy"]["links"].get<double>(), loss, 1e-12);
    EXPECT_LT(summary["energy"]["worst_balance_error"].get<double>(), 1e-12);
    EXPECT_FALSE(contains(outcome.err, "warning")) << outcome.err;
  }
}

// Three 1 kg masses 10 and 1 mm apart, the first at 1 m/s, plastic impacts (e = 0) under Newmark:
// the first pair closes, then strikes the third, then the first catches the pair it pushed (a
// second force on both contacts), and all three move on at 1/3 m/s. Riding together, the contacts
// were pressed by round-off (1e-10 N now and then) and counted 29 and 40 impacts; a contact past
// its bound by no more than its round-off now carries no force.
TEST_F(Cli, BodiesRidingTogetherAfterAPlasticImpactAreNotImpactsAgain) {
  json chain = moving_masses(3, 1.0, "newmark_average_acceleration");
  chain["analysis"]["time_step"] = 1e-4;
  chain["analysis"]["duration"] = 0.1;
  chain["links"] = {hard_contact_between(0, 1, 0.0, 0.01), hard_contact_between(1, 2, 0.0, 0.001)};
  const fs::path file = path("chain.json"), out = path("chain.out");
  std::ofstream(file) << chain.dump(2);
  const Outcome outcome = pound({"run", file.string(), "--out", out.string()});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const json summary = json::parse(read_text(out / "summary.json"));
  const int first = summary["links"][0]["impacts"], second = summary["links"][1]["impacts"];
  const double impulse = summary["links"][0]["impulse"];
  std::cout << fmt::format(
      "plastic chain under Newmark: impacts {} and {}, first impulse {:.15f}"
      " N s (2/3), kinetic energy {:.15f} J (1/6)\n",
      first, second, impulse, summary["energy"]["kinetic"].get<double>());
  EXPECT_EQ(first, 2);
  EXPECT_EQ(second, 2);
  EXPECT_NEAR(impulse, 2.0 / 3.0, 1e-9);  // Newmark's hard contacts balance to ~1e-11
  EXPECT_NEAR(summary["energy"]["kinetic"].get<double>(), 1.0 / 6.0, 1e-9);
}

// Two 1 kg masses, the first at 1 m/s, a hard contact 10 mm apart, under the dissipative implicit
// integrators: the impulse turns the rate from w- to w+ = -e w-, and its work is the impulse times
// their mean, (1 - e^2) m v^2 / 4. By the rectangle rule F d(delta) (exact only where d(delta) is
// dt times the mean rate: the trapezoidal rule) an elastic impact under HHT read -1.8 J of 81 and
// was called a penalty contact creating energy.
TEST_F(Cli, AHardContactsImpulseUnderHhtAndGeneralizedAlphaTakesItsExactWork) {
  for (const std::string integrator : {"hht", "generalized_alpha"})
    for (const double restitution : {1.0, 0.5}) {
      json pair = moving_masses(2, 1.0, integrator);
      pair["links"] = {hard_contact_between(0, 1, restitution, 0.01)};
      const std::string name = fmt::format("{}_{}", integrator, restitution);
      const fs::path file = path(name + ".json"), out = path(name + ".out");
      std::ofstream(file) << pair.dump(2);
      const Outcome outcome = pound({"run", file.string(), "--out", out.string()});
      ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
      const json summary = json::parse(read_text(out / "summary.json"));
      const double work = summary["links"][0]["work"],
                   loss = (1.0 - restitution * restitution) / 4.0;
      std::cout << fmt::format(
          "{} at e = {}: contact work {:.3e} J against {} J, balance error "
          "{:.1e}\n",
          integrator, restitution, work, loss,
          summary["energy"]["worst_balance_error"].get<double>());
      EXPECT_NEAR(work, loss, 1e-12);
      EXPECT_NEAR(summary["energy"]["links"].get<double>(), loss, 1e-12);
      EXPECT_LT(summary["energy"]["worst_balance_error"].get<double>(), 1e-10);
      EXPECT_FALSE(contains(outcome.err, "warning")) << outcome.err;
    }
}

// An extended penalty with a mass alpha2 between bare masses, under Newmark: its law force is
// alpha2 c_m (delta - delta~) + alpha0 delta, terms of 6e10 N cancelling to 3e4 N, so its
// round-off is 1e-5 N, above the tolerance on the force; Newton swung by that much to its 25th
// iteration and the run failed from alpha2 = 0.45 m_eff on. The iteration now stops where its
// correction is below the laws' terms' round-off: undamped, the pair parts with its energy.
TEST_F(Cli, AnExtendedPenaltysMassBetweenBareMassesConvergesUnderNewmark) {
  for (const double alpha2 : {3e4, 1e5}) {
    json pair = penalty_pair("newmark_average_acceleration", alpha2, 0.01);
    pair["analysis"]["duration"] = 0.06;
    const fs::path file = path("penalty.json"), out = path("penalty.out");
    std::ofstream(file) << pair.dump(2);
    const Outcome outcome = pound({"run", file.string(), "--out", out.string()});
    ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
    const json summary = json::parse(read_text(out / "summary.json"));
    const double kinetic = summary["energy"]["kinetic"];
    std::cout << fmt::format(
        "extended penalty, alpha2 = {:.2f} m_eff: kinetic energy after "
        "{:.9f} of 50,000 J\n",
        alpha2 / (1e5 * 2e5 / 3e5), kinetic / 5e4);
    EXPECT_EQ(summary["links"][0]["impacts"], 1);
    EXPECT_NEAR(kinetic, 5e4, 1e-6 * 5e4);
  }
}

// The round-off stop above is no licence for a residual the size of the load: a 1,000 t mass on a
// bilinear spring of k = 1e50 (yield 5e5 N) or a damper with a linear_velocity of 1e-300 has
// tangents that make any correction vanish against the laws' terms, and the runs completed with
// the mass carried rigidly (3.9e6 N through a spring that yields at 5e5; unbalanced 3.4e6 N).
// They now fail (exit 3), saying Newton did not converge; at k = 1e12 the spring still yields at
// its force.
TEST_F(Cli, ARoundOffStopNeverAcceptsAResidualOfTheLoad) {
  const auto run_with = [&](const json& law) {
    json model = {{"dimension", 1},
                  {"nodes", {{{"id", "g"}, {"x", 0}}, {{"id", "m"}, {"x", 1}}}},
                  {"masses", {{{"node", "m"}, {"mass", 1e6}}}},
                  {"supports", {{{"node", "g"}, {"fix", {"x"}}}}},
                  {"links", {{{"id", "L"}, {"nodes", {"m", "g"}}, {"axis", {-1}}, {"law", law}}}},
                  {"excitations",
                   {{{"record", POUND_SOURCE_DIR "/ground_motions/synthetic_soft_01.AT2"},
                     {"units", "g"},
                     {"scale", {{"pga", 0.4}}}}}},
                  {"analysis", {{"time_step", 0.002}, {"duration", 3.0}}}};
    const fs::path file = path("stiff.json"), out = path("stiff.out");
    fs::remove_all(out);
    std::ofstream(file) << model.dump(2);
    return std::pair{pound({"run", file.string(), "--out", out.string()}), out};
  };
  const auto spring = [](double stiffness) {
    return json{{"type", "bilinear_spring"},
                {"stiffness", stiffness},
                {"yield_force", 5e5},
                {"hardening_ratio", 0}};
  };
  for (const json& law : {spring(1e50), json{{"type", "viscous_damper"},
                                             {"coefficient", 1e6},
                                             {"exponent", 0.05},
                                             {"linear_velocity", 1e-300}}}) {
    const auto [outcome, out] = run_with(law);
    std::cout << law.dump() << ": exit " << outcome.exit_code << "\n";
    EXPECT_EQ(outcome.exit_code, 3) << outcome.err;
    EXPECT_TRUE(contains(outcome.err, "Newton did not converge")) << outcome.err;
  }
  const auto [outcome, out] = run_with(spring(1e12));
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const json summary = json::parse(read_text(out / "summary.json"));
  const double peak = summary["links"][0]["peak_force"];
  std::cout << "k = 1e12: peak force " << peak << " (yield 5e5), unbalanced "
            << summary["max_unbalanced_force"] << "\n";
  EXPECT_LT(peak, 5e5 * (1.0 + 1e-9));
}

// The extended penalty with its automatic numbers between lumped girders (models/
// two_girders_joint.json): alpha2 = alpha0 (m1 + m2) / (k1 + k2) is 2,800 times the girders'
// effective mass, for meshed bodies only. check warns of it; the run, whose steps at a release
// were accepted with a residual of 3.8e5 N against no force at all (3 "impacts", 0.107 m of
// penetration), now fails saying Newton did not converge.
TEST_F(Cli, AnAutomaticPenaltyMassBetweenLumpedGirdersIsWarnedOf) {
  json girders =
      json::parse(read_text(fs::path(POUND_SOURCE_DIR) / "models" / "two_girders_joint.json"));
  for (json& link : girders["links"])
    if (link["id"] == "joint") link["law"] = {{"type", "extended_penalty"}};
  const fs::path file = path("penalty_girders.json");
  std::ofstream(file) << girders.dump();
  const Outcome checked = pound({"check", file.string()});
  EXPECT_TRUE(contains(checked.out,
                       "link joint: its extended penalty's mass alpha2 = 4.333e+08 "
                       "is 2.82e+03 times its end masses' effective mass"))
      << checked.out;
  const Outcome ran = pound({"run", file.string(), "--out", path("penalty_girders").string()});
  EXPECT_EQ(ran.exit_code, 3) << ran.err;
  EXPECT_TRUE(contains(ran.err, "Newton did not converge")) << ran.err;
}

// Central difference's stable step holds what the links' own modes need: a friction pendulum's
// stick spring (k_t = 1e10 on 100 t: 2 / sqrt(k_t / m) = 6.32 ms; "auto" took 16 ms, from the
// normal stiffness alone, and the block came to rest 57 % short), and a damper's decay, m / c
// (a damper alone was "no stable limit", and beside a spring 2 m / c, where the velocity changes
// sign at every step). A linear dashpot is warned of where central difference does not resolve
// its decay.
TEST_F(Cli, CentralDifferencesStepHoldsStickSpringsAndDampers) {
  const auto check_json = [&](const json& model) {
    const fs::path file = path("cd.json");
    std::ofstream(file) << model.dump(2);
    const Outcome outcome = pound({"check", "--json", file.string()});
    EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
    return json::parse(outcome.out);
  };
  json pendulum = {
      {"dimension", 2},
      {"nodes", {{{"id", "block"}, {"x", 0}, {"y", 0}}, {{"id", "seat"}, {"x", 0}, {"y", 0}}}},
      {"masses", {{{"node", "block"}, {"mass", 1e5}}}},
      {"supports", {{{"node", "seat"}, {"fix", {"x", "y"}}}}},
      {"loads", {{{"node", "block"}, {"y", -981000.0}}}},
      {"initial_velocities", {{{"node", "block"}, {"x", 0.5}}}},
      {"links",
       {{{"id", "b"},
         {"nodes", {"block", "seat"}},
         {"axis", {0, -1}},
         {"law", {{"type", "gap_spring"}, {"stiffness", 1e9}}},
         {"friction", {{"coefficient", 0.06}, {"radius", 2.24}, {"stick_stiffness", 1e10}}}}}},
      {"recorders", {{{"type", "node"}, {"nodes", {"block"}}, {"file", "block.csv"}}}},
      {"analysis",
       {{"duration", 15.0}, {"initial_state", "static"}, {"integrator", "central_difference"}}}};
  const double stick_limit = 2.0 / std::sqrt(1e10 / 1e5);
  const double stable = check_json(pendulum)["explicit_stable_step_contact"];
  std::cout << "pendulum: stable step " << stable << ", the stick spring's " << stick_limit << "\n";
  EXPECT_LE(stable, stick_limit * (1.0 + 1e-9));
  const auto rest = [&](const std::string& name) {
    const fs::path file = path(name + ".json"), out = path(name + ".out");
    std::ofstream(file) << pendulum.dump(2);
    const Outcome outcome = pound({"run", file.string(), "--out", out.string()});
    EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
    return last_block_position(out / "block.csv");
  };
  const double explicit_rest = rest("explicit");
  pendulum["analysis"]["integrator"] = "newmark_average_acceleration";
  pendulum["analysis"]["time_step"] = 1e-3;
  const double implicit_rest = rest("implicit");
  std::cout << "comes to rest at " << explicit_rest << " (auto step), " << implicit_rest
            << " (Newmark, 1 ms)\n";
  EXPECT_NEAR(explicit_rest, implicit_rest, 5e-3 * implicit_rest);

  json damped = {{"dimension", 1},
                 {"nodes", {{{"id", "g"}, {"x", 0}}, {{"id", "m"}, {"x", 1}}}},
                 {"masses", {{{"node", "m"}, {"mass", 1e6}}}},
                 {"supports", {{{"node", "g"}, {"fix", {"x"}}}}},
                 {"initial_velocities", {{{"node", "m"}, {"x", 0.5}}}},
                 {"links",
                  {{{"id", "spring"},
                    {"nodes", {"m", "g"}},
                    {"axis", {-1}},
                    {"law", {{"type", "elastic_spring"}, {"stiffness", 1e7}}}},
                   {{"id", "damper"},
                    {"nodes", {"m", "g"}},
                    {"axis", {-1}},
                    {"law", {{"type", "viscous_damper"}, {"coefficient", 1e8}}}}}},
                 {"analysis", {{"integrator", "central_difference"}, {"duration", 1.0}}}};
  const json linear = check_json(damped);
  EXPECT_EQ(linear["units"]["time"], "s");  // check --json names its units too
  std::cout << "spring and damper: stable step " << linear["explicit_stable_step_contact"]
            << " (m / c = 0.01)\n";
  EXPECT_NEAR(linear["explicit_stable_step_contact"].get<double>(), 0.01, 1e-12);
  ASSERT_EQ(linear["warnings"].size(), 1u) << linear["warnings"];
  const std::string warning = linear["warnings"][0]["warning"];
  EXPECT_TRUE(contains(warning, "link damper: its dashpot (c = 1e+08)") &&
              contains(warning, "off by about dt / (2 tau) = 40 %"))
      << warning;
  damped["links"].erase(0);
  damped["links"][0]["law"] = {{"type", "viscous_damper"},
                               {"coefficient", 1e6},
                               {"exponent", 0.05},
                               {"linear_velocity", 1e-3}};
  const json alone = check_json(damped);
  // Its tangent below the linear velocity: c v_l^(alpha - 1); m / that = 1e-3^0.95.
  std::cout << "a damper alone: stable step " << alone["explicit_stable_step_contact"] << "\n";
  EXPECT_NEAR(alone["explicit_stable_step_contact"].get<double>(), std::pow(1e-3, 0.95), 1e-12);
}

// The same block started at rest from the static state ("initial_state": "static", which a hard
// contact used to refuse): the contact holds its weight from t = 0 and the block stays where it
// is, with every energy term at round-off and no warning (their 1e-21 J is not "100 %" of
// anything); pushed sideways below mu W it still stays.
TEST_F(Cli, ABlockOnAHardContactStartsFromItsStaticStateAndStaysAtRest) {
  json block =
      json::parse(read_text(fs::path(POUND_SOURCE_DIR) / "models" / "block_on_floor.json"));
  block["links"][0]["law"] = {{"type", "hard_contact"}, {"restitution", 0.0}};
  block["analysis"]["initial_state"] = "static";
  block["initial_velocities"] = json::array();
  block["loads"][0]["x"] = 30.0;  // < mu W = 49.05
  for (const std::string integrator : {"central_difference", "newmark_average_acceleration"}) {
    block["analysis"]["integrator"] = integrator;
    const fs::path model = path(integrator + ".json"), out = path(integrator + ".out");
    std::ofstream(model) << block.dump(2);
    const Outcome outcome = pound({"run", model.string(), "--out", out.string()});
    ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
    EXPECT_FALSE(contains(outcome.err, "warning")) << outcome.err;
    const json summary = json::parse(read_text(out / "summary.json"));
    const double position = last_block_position(out / "block.csv");
    const double peak = summary["links"][0]["peak_force"].get<double>();
    std::cout << integrator << ": at rest, moved " << position << ", contact peak force " << peak
              << " (weight 98.1), created fraction "
              << summary["energy"]["contact_created_fraction"] << "\n";
    EXPECT_LT(std::abs(position), 1e-12);
    EXPECT_NEAR(peak, 98.1, 1e-9);
  }
}

// The study picks its rod cases by name; a name it does not know is a usage error listing them.
TEST_F(Cli, StudyTakesItsCasesByName) {
  const Outcome wrong = pound({"study", "rod-impact", "--cases", "kawashima,wall"});
  EXPECT_EQ(wrong.exit_code, 1);
  EXPECT_TRUE(contains(wrong.err, "--cases: 'wall' is not a rod-impact case")) << wrong.err;
  EXPECT_TRUE(contains(wrong.err, "rigid-wall")) << wrong.err;
  const Outcome help = pound({"study", "--help"});
  EXPECT_TRUE(contains(help.out, "--cases")) << help.out;
}

// The bar against a rigid wall, run as a model: the run compares it with the exact solution.
TEST_F(Cli, BarAgainstARigidWallRunsAgainstItsExactSolution) {
  const fs::path out = path("out");
  const Outcome outcome =
      pound({"run", POUND_SOURCE_DIR "/models/bar_rigid_wall.json", "--out", out.string()});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  std::cout << outcome.out;
  EXPECT_TRUE(contains(outcome.out, "against the exact solution: force_l2_error")) << outcome.out;
  const json summary = json::parse(read_text(out / "summary.json"));
  std::cout << summary["verification"].dump() << "\n";
  ASSERT_TRUE(summary.contains("verification")) << summary.dump(2).substr(0, 2000);
  EXPECT_LT(summary["verification"]["force_l2_error"].get<double>(), 0.04);
  EXPECT_LT(std::abs(summary["verification"]["duration_error"].get<double>()), 0.005);
  EXPECT_LT(std::abs(summary["verification"]["separation_velocity_error"].get<double>()), 0.005);
  // The bar's own kinetic and strain energy at the end, of its initial 1/2 m V0^2.
  EXPECT_GT(summary["verification"]["energy_ratio"].get<double>(), 0.99);
  EXPECT_LE(summary["verification"]["energy_ratio"].get<double>(), 1.001);
}

TEST_F(Cli, VerifyJsonPrintsOneObjectWithTheMetrics) {
  const Outcome outcome = pound({"verify", "rod-impact", "--json"});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const json metrics = json::parse(outcome.out);  // throws on anything but one JSON value
  ASSERT_TRUE(metrics.is_object());
  for (const char* key :
       {"force_l2_error", "duration_error", "separation_velocity_error", "peak_force_ratio",
        "max_penetration", "min_force", "run_time_s", "steps", "newton_iterations"}) {
    ASSERT_TRUE(metrics.contains(key)) << key;
    EXPECT_TRUE(metrics[key].is_number()) << key;
  }
  EXPECT_GT(metrics["steps"].get<long>(), 0);
  std::cout << "force_l2_error " << metrics["force_l2_error"] << ", steps " << metrics["steps"]
            << "\n";
}

TEST_F(Cli, VerifyCsvHasOneRowPerStepAndTheInitialState) {
  const fs::path csv = path("force.csv");
  const Outcome outcome = pound({"verify", "rod-impact", "--json", "--csv", csv.string()});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const long steps = json::parse(outcome.out)["steps"].get<long>();
  const std::vector<std::string> lines = read_lines(csv);
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines.front(), "time,force,exact_force,penetration");
  EXPECT_EQ(static_cast<long>(lines.size()) - 1, steps + 1);
  EXPECT_EQ(first_field(lines[1]), 0.0);
}

TEST_F(Cli, VerifyProfilesCsvHasTheFourInstants) {
  const fs::path csv = path("profiles.csv");
  const Outcome outcome = pound({"verify", "rod-impact", "--profiles-csv", csv.string()});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const std::vector<std::string> lines = read_lines(csv);
  ASSERT_GT(lines.size(), 1u);
  EXPECT_TRUE(lines.front().starts_with("time_over_T,")) << lines.front();
  std::set<double> instants;
  for (std::size_t k = 1; k < lines.size(); ++k) instants.insert(first_field(lines[k]));
  EXPECT_EQ(instants, (std::set<double>{0.0, 0.25, 0.5, 0.75}));
}

TEST_F(Cli, RunRodImpactMatchesVerify) {
  const fs::path out = path("out");
  const Outcome run = pound({"run", kRodModel, "--out", out.string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(fs::exists(out / "link_force.csv"));
  const json summary = json::parse(read_text(out / "summary.json"));
  EXPECT_EQ(summary["status"], "completed");
  ASSERT_TRUE(summary.contains("verification")) << summary.dump(2);

  const Outcome verify = pound({"verify", "rod-impact", "--n", "100", "--courant", "1", "--json"});
  ASSERT_EQ(verify.exit_code, 0) << verify.err;
  const double from_run = summary["verification"]["force_l2_error"].get<double>();
  const double from_verify = json::parse(verify.out)["force_l2_error"].get<double>();
  const double relative = std::abs(from_run - from_verify) / std::abs(from_verify);
  std::cout << "force_l2_error run " << from_run << ", verify " << from_verify
            << ", relative difference " << relative << "\n";
  EXPECT_LE(relative, 1e-12);
  EXPECT_EQ(summary["verification"]["steps"], json::parse(verify.out)["steps"]);
}

TEST_F(Cli, RunGirderWritesItsRecorders) {
  const fs::path out = path("out");
  const Outcome outcome = pound({"run", kGirderModel, "--out", out.string(), "--quiet"});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_TRUE(outcome.out.empty()) << outcome.out;
  const std::vector<std::string> joint = read_lines(out / "joint.csv");
  const std::vector<std::string> girder = read_lines(out / "girder.csv");
  ASSERT_FALSE(joint.empty());
  ASSERT_FALSE(girder.empty());
  // Issue 16 item 5: headers name the units (the model's kg m s: forces in N).
  EXPECT_EQ(joint.front(), "time [s],joint.force [N],joint.penetration [m]");
  EXPECT_EQ(girder.front(),
            "time [s],girder.u_x [m],girder.v_x [m/s],girder.a_rel_x [m/s^2],girder.a_abs_x "
            "[m/s^2]");
  const json summary = json::parse(read_text(out / "summary.json"));
  EXPECT_EQ(summary["status"], "completed");
  EXPECT_FALSE(summary.contains("verification"));
  EXPECT_EQ(joint.size(), static_cast<std::size_t>(summary["steps"].get<long>()) + 2);
}

TEST_F(Cli, NegativeGapIsRefusedWithItsPath) {
  const Outcome outcome = run_refused(write_model(
      "negative_gap.json", R"([{"op": "replace", "path": "/links/0/gap", "value": -0.01}])"));
  EXPECT_TRUE(contains(outcome.err, "/links/0/gap")) << outcome.err;
}

TEST_F(Cli, DanglingNodeIsRefusedWithItsPath) {
  const Outcome outcome = run_refused(write_model(
      "dangling.json", R"([{"op": "replace", "path": "/links/0/nodes/1", "value": "b9"}])"));
  EXPECT_TRUE(contains(outcome.err, "/links/0/nodes/1")) << outcome.err;
  EXPECT_TRUE(contains(outcome.err, "does not exist")) << outcome.err;
}

TEST_F(Cli, MalformedJsonIsRefusedWithLineAndColumn) {
  const fs::path model = path("malformed.json");
  std::ofstream(model) << "{\n  \"dimension\": 1,,\n}\n";
  const Outcome outcome = run_refused(model.string());
  EXPECT_TRUE(contains(outcome.err, "line 2")) << outcome.err;
  EXPECT_TRUE(contains(outcome.err, "column")) << outcome.err;
}

TEST_F(Cli, MissingModelFileIsRefused) { run_refused(path("no_such_model.json").string()); }

TEST_F(Cli, StepLimitFailsAndKeepsTheHistorySoFar) {
  const fs::path out = path("out");
  const Outcome outcome = pound({"run", kRodModel, "--out", out.string(), "--max-steps", "10"});
  EXPECT_EQ(outcome.exit_code, 3);
  EXPECT_TRUE(contains(outcome.err, "step limit")) << outcome.err;
  const json summary = json::parse(read_text(out / "summary.json"));
  EXPECT_EQ(summary["status"], "failed");
  EXPECT_EQ(summary["steps"], 10);
  EXPECT_TRUE(contains(summary["failure"].get<std::string>(), "step limit"));
  EXPECT_FALSE(summary.contains("verification"));  // no metrics for a partial run
  const std::vector<std::string> lines = read_lines(out / "link_force.csv");
  EXPECT_EQ(lines.size(), 1u + 11u);  // header, the initial state, 10 steps
}

// A run of more than a billion steps (here 2e9: a duration mistyped by powers of ten) says so,
// with the time that means, before it starts (once, not again after the run), and check says it.
TEST_F(Cli, ARunOfBillionsOfStepsIsWarnedOfBeforeItStarts) {
  const std::string model =
      write_model("long.json", R"([{"op": "replace", "path": "/analysis/duration", "value": 2e6},
                       {"op": "add", "path": "/recorders", "value": []}])");
  const Outcome run =
      pound({"run", model, "--out", path("out").string(), "--max-steps", "5", "--quiet"});
  EXPECT_EQ(run.exit_code, 3) << run.err;
  const std::string warning =
      "warning: the analysis takes 2e+09 steps (a duration of 2e+06 over a time step of 0.001): at "
      "a microsecond a step, a plane bridge of 60 DOFs, that is about 33 minutes";
  const std::size_t at = run.err.find(warning);
  ASSERT_NE(at, std::string::npos) << run.err;
  EXPECT_EQ(run.err.find(warning, at + 1), std::string::npos) << "printed twice:\n" << run.err;
  const std::size_t stop = run.err.find("step limit of 5 steps");
  ASSERT_NE(stop, std::string::npos) << run.err;
  EXPECT_LT(at, stop) << run.err;
  // With copies, once too: the copies' warnings are the unperturbed run's.
  const Outcome copies = pound({"run", model, "--out", path("copies").string(), "--max-steps", "5",
                                "--ensemble", "2", "--quiet"});
  EXPECT_EQ(copies.exit_code, 3) << copies.err;
  const std::size_t first = copies.err.find(warning);
  ASSERT_NE(first, std::string::npos) << copies.err;
  EXPECT_EQ(copies.err.find(warning, first + 1), std::string::npos) << copies.err;
  const Outcome check = pound({"check", model});
  EXPECT_EQ(check.exit_code, 0) << check.err;
  EXPECT_TRUE(contains(check.out + check.err, "2e+09 steps")) << check.out << check.err;
  std::cout << "stderr: " << run.err;
}

// The lines of `text` that start with `prefix`.
std::vector<std::string> lines_starting(const std::string& text, const std::string& prefix) {
  std::vector<std::string> found;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(prefix, 0) == 0) found.push_back(line);
  return found;
}

// "t = T of ..." in a progress line: T.
double progress_time(const std::string& line) {
  const std::size_t at = line.find("t = ");
  return at == std::string::npos ? NAN : std::stod(line.substr(at + 4));
}

TEST_F(Cli, ProgressForALogComesEverySoManySecondsAndLeavesTheResultsAlone) {
  // --progress 1e-9: a line every kProgressStride (64) steps of the girders' 15,000.
  const std::string model = POUND_SOURCE_DIR "/models/two_sdof_girders.json";
  const Outcome plain = pound({"run", model, "--out", path("plain").string()});
  const Outcome logged =
      pound({"run", model, "--out", path("logged").string(), "--progress", "1e-9"});
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  ASSERT_EQ(logged.exit_code, 0) << logged.err;
  const std::vector<std::string> lines = lines_starting(logged.err, "progress: t = ");
  ASSERT_GE(lines.size(), 200u) << logged.err.substr(0, 500);
  EXPECT_LE(lines.size(), 15000u / 64);
  EXPECT_TRUE(lines_starting(plain.err, "progress").empty()) << "not a terminal: " << plain.err;
  double previous = 0.0;
  for (const std::string& line : lines) {
    EXPECT_GT(progress_time(line), previous) << line;
    previous = progress_time(line);
    EXPECT_TRUE(contains(line, " of 30 s (")) << line;
    EXPECT_TRUE(contains(line, "elapsed")) << line;
  }
  EXPECT_EQ(read_text(path("plain") / "joint.csv"), read_text(path("logged") / "joint.csv"));
  EXPECT_EQ(plain.out.substr(plain.out.find('\n')), logged.out.substr(logged.out.find('\n')))
      << "the report after the headline (whose run time and folder differ)";
  std::cout << "first and last: " << lines.front() << "\n  " << lines.back() << "\n";

  // The copies of an ensemble report as each is done, after the unperturbed run's lines.
  const Outcome copies = pound(
      {"run", model, "--out", path("copies").string(), "--ensemble", "3", "--progress", "1e-9"});
  ASSERT_EQ(copies.exit_code, 0) << copies.err;
  EXPECT_GE(lines_starting(copies.err, "progress: unperturbed run, t = ").size(), 200u);
  const std::vector<std::string> done = lines_starting(copies.err, "progress: ");
  EXPECT_TRUE(contains(done.back(), "3 of 3 copies done")) << done.back();
  std::cout << "ensemble's last: " << done.back() << "\n";

  // --quiet: nothing but errors.
  const Outcome quiet = pound({"run", model, "--out", path("quiet").string(), "--quiet"});
  EXPECT_EQ(quiet.exit_code, 0) << quiet.err;
  EXPECT_EQ(quiet.out + quiet.err, "");
}

TEST_F(Cli, ProgressIntervalMustBeAPositiveNumberOfSeconds) {
  for (const char* bad : {"0", "-1", "nan", "inf", "soon"}) {
    const Outcome outcome =
        pound({"run", kGirderModel, "--out", path("out").string(), "--progress", bad});
    EXPECT_EQ(outcome.exit_code, 1) << bad << ": " << outcome.err;
    EXPECT_TRUE(contains(outcome.err, "--progress")) << bad << ": " << outcome.err;
    EXPECT_FALSE(fs::exists(path("out"))) << bad;
    std::cout << bad << ": " << outcome.err;
  }
  const Outcome both =
      pound({"run", kGirderModel, "--out", path("out").string(), "--progress", "1", "--quiet"});
  EXPECT_EQ(both.exit_code, 1) << both.err;
  EXPECT_TRUE(contains(both.err, "--quiet")) << both.err;
  EXPECT_FALSE(fs::exists(path("out")));
}

// `pound check` says how the run will step (the integrator, the step and the rule that chose it,
// the duration, the steps), and the run takes the steps it said: a step given, one set by
// "auto", a duration that is the record's, and a quotient a few ulps above a whole number
// (0.004 / 1e-6).
TEST_F(Cli, CheckSaysHowTheRunWillStepAndTheRunTakesThoseSteps) {
  const std::string bridge = POUND_SOURCE_DIR "/models/three_span_bridge.json";
  const Outcome text = pound({"check", bridge});
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_TRUE(contains(text.out,
                       "  analysis: newmark_average_acceleration, time step 0.0015 s, "
                       "over 25 s (the records' length): 16667 steps\n"))
      << text.out;
  // Times and velocities in the model's units, as `pound run` gives them.
  EXPECT_TRUE(contains(text.out, "  periods: 1.067 0.8857 0.8784 0.5906 0.3333 0.3333 s\n"))
      << text.out;
  EXPECT_TRUE(contains(text.out, "stiffness 5e+08; contact lasts ~0.03142 s\n")) << text.out;
  // Where no contact duration is claimed, why: the joints' Hertz links stay softer at their peak
  // than the girders beside them; a mid-storey contact of the buildings has a massless end.
  EXPECT_TRUE(contains(text.out,
                       "link bridge.joint1 (hertz_damp): stiffness grows with "
                       "penetration; no contact duration claimed: its peak stiffness "
                       "at an approach velocity of 0.611 (1.137e+09) is not 10 x"))
      << text.out;
  const Outcome buildings = pound({"check", POUND_SOURCE_DIR "/models/adjacent_buildings.json"});
  EXPECT_TRUE(contains(buildings.out,
                       "no contact duration claimed: an end carries no lumped "
                       "mass of its own"))
      << buildings.out;
  for (const char* name : {"three_span_bridge", "block_on_belt_hard_contact", "rod_impact_2d",
                           "girder_abutment_sdof", "bar_rigid_wall"}) {
    const std::string model = POUND_SOURCE_DIR "/models/" + std::string(name) + ".json";
    const Outcome check = pound({"check", model, "--json"});
    ASSERT_EQ(check.exit_code, 0) << check.err;
    const json analysis = json::parse(check.out)["analysis"];
    const fs::path out = path(name);
    const Outcome run = pound({"run", model, "--out", out.string(), "--quiet"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const json summary = json::parse(read_text(out / "summary.json"));
    EXPECT_EQ(summary["step_cuts"], 0) << name;
    EXPECT_EQ(analysis["steps"], summary["steps"]) << name << ": " << analysis.dump();
    EXPECT_EQ(analysis["time_step"], summary["time_step"]) << name;
    EXPECT_EQ(analysis["duration"], summary["duration"]) << name;
    std::cout << name << ": " << analysis.dump() << "\n";
  }
  const json automatic = json::parse(
      pound({"check", POUND_SOURCE_DIR "/models/rod_impact_2d.json", "--json"}).out)["analysis"];
  EXPECT_EQ(automatic["time_step_rule"], "auto");
  EXPECT_EQ(automatic["time_step"].get<double>(),
            automatic["safety_factor"].get<double>() * automatic["stable_time_step"].get<double>());
}

// An adaptive run's steps as a range (its longest and shortest step), the method's parameters
// where it is no preset, and a step limit the run would reach is warned of, by check and run.
TEST_F(Cli, CheckGivesAnAdaptiveRunsStepsAndWarnsOfAStepLimitItWouldReach) {
  const std::string adaptive =
      write_model("adaptive.json", R"([{"op": "replace", "path": "/analysis",
      "value": {"integrator": {"type": "hht", "alpha": -0.1}, "time_step": 0.001, "duration": 0.1,
                "adaptive": {"min_time_step": 1e-5, "max_time_step": 0.004}, "max_steps": 20}}])");
  const Outcome check = pound({"check", adaptive});
  ASSERT_EQ(check.exit_code, 0) << check.err;
  EXPECT_TRUE(contains(check.out,
                       "  analysis: hht (alpha -0.1), adaptive time steps from 0.001 s at "
                       "first, between 1.563e-05 s and 0.004 s (tolerance 1e-05), over "
                       "0.1 s: 25 to 6400 steps\n"))
      << check.out;
  const std::string limit = "the analysis takes at least 25 steps and the step limit is 20";
  EXPECT_TRUE(contains(check.out, limit + " (\"max_steps\", or pound run --max-steps): the run "
                                          "stops as failed at t = 0.08 of 0.1 at the latest"))
      << check.out;
  const json analysis = json::parse(pound({"check", adaptive, "--json"}).out)["analysis"];
  EXPECT_EQ(analysis["time_step_rule"], "adaptive");
  EXPECT_EQ(analysis["steps_at_least"], 25);
  // Steps are 0.001 x 2^k: the shortest not below 1e-5 is 0.001 / 64.
  EXPECT_EQ(analysis["adaptive_min_time_step"], 0.001 / 64.0);
  EXPECT_EQ(analysis["steps_at_most"], 6400);
  EXPECT_EQ(analysis["max_steps"], 20);
  EXPECT_FALSE(analysis.contains("steps"));
  EXPECT_EQ(analysis["integrator_parameters"]["alpha"], -0.1);
  const Outcome run = pound({"run", adaptive, "--out", path("out").string(), "--quiet"});
  EXPECT_EQ(run.exit_code, 3) << run.err;
  EXPECT_TRUE(contains(run.err, limit)) << run.err;
  const Outcome fixed = pound({"check", kGirderModel, "--json"});
  EXPECT_FALSE(contains(fixed.out, "step limit")) << fixed.out;
  std::cout << check.out;
}

// An adaptive run shortens its steps where a contact needs them: the 20-steps-per-contact rule is
// asked of its shortest step, not its first (the bundled adaptive girders start at 2 ms against a
// 30 ms contact, and take 0.5 ms steps in it).
TEST_F(Cli, AnAdaptiveRunsContactsAreCheckedAgainstItsShortestStep) {
  const std::string adaptive = POUND_SOURCE_DIR "/models/two_girders_joint_adaptive.json";
  const Outcome check = pound({"check", adaptive});
  ASSERT_EQ(check.exit_code, 0) << check.err;
  EXPECT_TRUE(contains(check.out, "no warnings")) << check.out;
  json fixed = json::parse(read_text(adaptive));
  fixed["analysis"].erase("adaptive");
  std::ofstream(path("fixed.json")) << fixed.dump();
  const Outcome coarse = pound({"check", path("fixed.json").string()});
  EXPECT_TRUE(contains(coarse.out, "link joint: the time step 0.002 gives fewer than 20 steps"))
      << coarse.out;
  fixed["analysis"]["adaptive"] = {{"min_time_step", 0.002}};
  std::ofstream(path("fixed.json")) << fixed.dump();
  const Outcome floor = pound({"check", path("fixed.json").string()});
  EXPECT_TRUE(contains(floor.out, "link joint: the shortest adaptive step 0.002 gives fewer"))
      << floor.out;
}

// An adaptive run steps on time_step x 2^k: a shortest step above the first one, or bounds with no
// such step between them, are refused (a min_time_step of 0.003 over a step of 0.002 left check
// and run cutting a step of 0.004 for ever, snapped back to it each time).
TEST_F(Cli, AdaptiveBoundsWithoutAStepOfTheGridBetweenThemAreRefused) {
  const auto refused = [&](const std::string& adaptive, const std::string& where) {
    const std::string model = write_model("bounds.json", R"([{"op": "replace", "path": "/analysis",
        "value": {"time_step": 0.002, "duration": 0.1, "adaptive": )" +
                                                             adaptive + "}}]");
    for (const Outcome& outcome :
         {pound({"check", model}), pound({"run", model, "--out", path("out").string()})}) {
      EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
      EXPECT_TRUE(contains(outcome.err, model + ": " + where)) << outcome.err;
      std::cout << outcome.err;
    }
    EXPECT_FALSE(fs::exists(path("out")));
  };
  refused(R"({"min_time_step": 0.003})", "/analysis/adaptive/min_time_step");
  refused(R"({"min_time_step": 0.0011, "max_time_step": 0.0015})", "/analysis/adaptive");
  const std::string fine = write_model("fine.json", R"([{"op": "replace", "path": "/analysis",
      "value": {"time_step": 0.002, "duration": 0.1, "adaptive": {"min_time_step": 0.0011}}}])");
  EXPECT_EQ(pound({"check", fine}).exit_code, 0);
  // Extreme bounds are steps of the grid too: 0.002 x 2^1032 is finite where 1e308 / 0.002 is
  // not, and a longest step past the duration still takes a step.
  const std::string wide = write_model("wide.json", R"([{"op": "replace", "path": "/analysis",
      "value": {"time_step": 0.002, "duration": 0.1,
                "adaptive": {"min_time_step": 1e-300, "max_time_step": 1e308}}}])");
  const Outcome extreme = pound({"check", wide, "--json"});
  ASSERT_EQ(extreme.exit_code, 0) << extreme.err;
  const json analysis = json::parse(extreme.out)["analysis"];
  EXPECT_EQ(analysis["adaptive_max_time_step"], std::ldexp(0.002, 1032));
  EXPECT_EQ(analysis["steps_at_least"], 1);
  EXPECT_EQ(pound({"run", wide, "--out", path("wide").string(), "--quiet"}).exit_code, 0);
}

// With "time_step": "auto" the step is settled after the model's check: `pound check` warns of
// the step count once it has settled it, as `pound run` does.
TEST_F(Cli, CheckWarnsOfBillionsOfAutomaticSteps) {
  const std::string long_run = write_model("auto.json", R"([{"op": "replace", "path": "/analysis",
                        "value": {"integrator": "central_difference", "time_step": "auto",
                                  "duration": 1e8}},
                       {"op": "add", "path": "/recorders", "value": []}])");
  const Outcome check = pound({"check", long_run});
  EXPECT_EQ(check.exit_code, 0) << check.err;
  const std::string warning = "steps (a duration of 1e+08 over a time step of ";
  const std::size_t at = check.out.find(warning);
  ASSERT_NE(at, std::string::npos) << check.out;
  EXPECT_EQ(check.out.find(warning, at + 1), std::string::npos) << "twice:\n" << check.out;
  const Outcome run =
      pound({"run", long_run, "--out", path("out").string(), "--max-steps", "3", "--quiet"});
  EXPECT_EQ(run.exit_code, 3) << run.err;
  EXPECT_TRUE(contains(run.err, warning)) << run.err;
  const std::string short_run = write_model("short.json", R"([{"op": "replace", "path": "/analysis",
                         "value": {"integrator": "central_difference", "time_step": "auto",
                                   "duration": 0.1}}])");
  const Outcome quiet = pound({"check", short_run});
  EXPECT_FALSE(contains(quiet.out, "steps (a duration")) << quiet.out;
  std::cout << check.out;
}

TEST_F(Cli, TimeLimitFailsAndKeepsTheHistorySoFar) {
  const fs::path out = path("out");
  // A 1 ms budget cannot finish the bridge's 16,667 steps (0.15 s here) on any machine.
  const Outcome outcome = pound({"run", POUND_SOURCE_DIR "/models/three_span_bridge.json", "--out",
                                 out.string(), "--time-limit", "0.001", "--quiet"});
  EXPECT_EQ(outcome.exit_code, 3);
  EXPECT_TRUE(contains(outcome.err, "time limit of 0.001 s")) << outcome.err;
  const json summary = json::parse(read_text(out / "summary.json"));
  EXPECT_EQ(summary["status"], "failed");
  EXPECT_TRUE(contains(summary["failure"].get<std::string>(), "time limit"));
  std::cout << "stderr: " << outcome.err;
}

TEST_F(Cli, BadTimeLimitIsAUsageError) {
  for (const char* limit : {"-1", "nan", "soon"}) {
    const Outcome outcome =
        pound({"run", kRodModel, "--out", path("out").string(), "--time-limit", limit});
    EXPECT_EQ(outcome.exit_code, 1) << limit << ": " << outcome.err;
    EXPECT_TRUE(contains(outcome.err, "time-limit")) << outcome.err;
    EXPECT_FALSE(fs::exists(path("out")));
  }
}

TEST_F(Cli, UnwritableOutputFolderIsAnOutputError) {
  const std::string out = "/proc/pound_test_out";
  const Outcome outcome = pound({"run", kRodModel, "--out", out, "--quiet"});
  EXPECT_EQ(outcome.exit_code, 4);
  EXPECT_TRUE(contains(outcome.err, out)) << outcome.err;
  std::cout << "stderr: " << outcome.err;
}

}  // namespace

namespace {

// Every bundled example runs to completion and writes its summary.
TEST_F(Cli, EveryBundledModelRuns) {
  int models = 0;
  for (const fs::directory_entry& entry :
       fs::directory_iterator(fs::path(POUND_SOURCE_DIR) / "models")) {
    if (entry.path().extension() != ".json") continue;
    ++models;
    const fs::path out = path(entry.path().stem().string());
    const Outcome outcome = pound({"run", entry.path().string(), "--out", out.string(), "--quiet"});
    EXPECT_EQ(outcome.exit_code, 0) << entry.path() << "\n" << outcome.err;
    const json summary = json::parse(read_text(out / "summary.json"));
    EXPECT_EQ(summary["status"], "completed") << entry.path();
    // Every example keeps its energy balance within 1 % of the largest term, all the way, and
    // its contacts create less than 1 % of what was put in (a hard contact none).
    EXPECT_LT(summary["energy"]["worst_balance_error"].get<double>(), 0.01) << entry.path();
    EXPECT_LT(summary["energy"]["contact_created_fraction"].get<double>(), 0.01) << entry.path();
    if (entry.path().stem() == "two_girders_hard_contact") {
      EXPECT_EQ(summary["energy"]["contact_created"].get<double>(), 0.0);
      EXPECT_EQ(summary["links"][0]["peak_penetration"].get<double>(), 0.0);
      EXPECT_GT(summary["links"][0]["impacts"].get<int>(), 0);
      // Its girders' peak accelerations hold the impulses over one step: said so.
      EXPECT_TRUE(contains(summary["warnings"].dump(), "struck under central difference"))
          << summary["warnings"].dump();
    }
  }
  EXPECT_GE(models, 4);
}

TEST_F(Cli, VerifyTwoElementAndRestitutionPass) {
  const Outcome two_element = pound({"verify", "two-element", "--json"});
  ASSERT_EQ(two_element.exit_code, 0) << two_element.err;
  EXPECT_LE(json::parse(two_element.out)["max_relative_error"].get<double>(), 1e-10);
  const Outcome restitution = pound({"verify", "restitution"});
  EXPECT_EQ(restitution.exit_code, 0) << restitution.out << restitution.err;
  EXPECT_TRUE(contains(restitution.out, "bilinear_impact"));
}

// A generator's refusal names the file in every command: `pound expand` printed the JSON path
// alone for a building whose floor masses overflow its modes (tools/mutate.py found it).
TEST_F(Cli, AGeneratorsRefusalNamesTheFileInEveryCommand) {
  const std::string model = POUND_SOURCE_DIR
      "/tests/corpus/bad_inputs/155_floor_mass_beyond_double_precision_with_damping.json";
  const fs::path never = path("never");
  for (const std::string command : {"expand", "run", "check", "modes"}) {
    const Outcome refused = command == "expand" || command == "run"
                                ? pound({command, model, "--out", never.string()})
                                : pound({command, model});
    EXPECT_EQ(refused.exit_code, 2) << command << ": " << refused.err;
    EXPECT_TRUE(contains(refused.err, "error: " + model + ": /generators/0/right/damping_ratio: "))
        << command << ": " << refused.err;
  }
  EXPECT_FALSE(fs::exists(never));
}

// --periods 5e9 would run the block on its belt for years (tools/mutate.py --options found it as a
// hang): the run length is bounded, and the bound named.
TEST_F(Cli, VerifyBlockBeltRefusesARunOfYears) {
  for (const std::string periods : {"5e9", "1001", "0", "-1"}) {
    const Outcome refused =
        pound({"verify", "block-belt", "--model", POUND_SOURCE_DIR "/models/block_on_belt.json",
               "--speeds", "1", "--periods", periods});
    EXPECT_EQ(refused.exit_code, 1) << periods << ": " << refused.err;
    EXPECT_TRUE(contains(refused.err, "--periods must be in (0, 1000]")) << refused.err;
  }
}

}  // namespace

namespace {

// A massless contact point is fine for implicit methods (a static equation) and refused for
// central difference, which divides by each DOF's mass, naming the node.
TEST_F(Cli, ExplicitMethodRefusesAMasslessNodeByName) {
  // The bearing's far end becomes a massless pad between the girder and the abutment.
  const std::string patch = R"([
    {"op": "add", "path": "/nodes/-", "value": {"id": "pad", "x": 10.5}},
    {"op": "replace", "path": "/nodes/2/x", "value": 10.5},
    {"op": "add", "path": "/elements/-", "value": {"id": "pad_spring", "type": "truss",
      "nodes": ["girder", "pad"], "material": "bearing", "area": 0.05}},
    {"op": "replace", "path": "/links/0/nodes", "value": ["pad", "abutment"]}])";
  const std::string implicit_model = write_model("implicit.json", patch);
  const Outcome implicit_run =
      pound({"run", implicit_model, "--out", path("implicit").string(), "--quiet"});
  EXPECT_EQ(implicit_run.exit_code, 0) << implicit_run.err;

  const std::string explicit_model = write_model(
      "explicit.json",
      patch.substr(0, patch.size() - 1) +
          R"(, {"op": "add", "path": "/analysis/integrator", "value": "central_difference"}])");
  const Outcome refused = run_refused(explicit_model);
  EXPECT_TRUE(contains(refused.err, "/analysis/integrator")) << refused.err;
  EXPECT_TRUE(contains(refused.err, "node 'pad' has none in direction x")) << refused.err;
}

// Central difference above its stable step is refused before the run, naming the limit;
// "auto" takes a safe fraction of it.
TEST_F(Cli, ExplicitStepAboveTheStableLimitIsRefused) {
  json model = json::parse(read_text(fs::path(POUND_SOURCE_DIR) / "models" / "rod_impact.json"));
  model["analysis"]["integrator"] = "central_difference";
  const fs::path file = path("explicit.json");
  std::ofstream(file) << model.dump();
  const Outcome refused = run_refused(file.string());
  EXPECT_TRUE(contains(refused.err, "/analysis/time_step")) << refused.err;
  EXPECT_TRUE(contains(refused.err, "above the stable limit")) << refused.err;
  const fs::path out = path("out");
  model["analysis"]["time_step"] = "auto";
  std::ofstream(file) << model.dump();
  const Outcome ran = pound({"run", file.string(), "--out", out.string(), "--quiet"});
  EXPECT_EQ(ran.exit_code, 0) << ran.err;
  const json summary = json::parse(read_text(out / "summary.json"));
  EXPECT_EQ(summary["integrator"], "central_difference");
  EXPECT_LT(summary["verification"]["duration_error"].get<double>(), 0.05);
}

// Linear acceleration is stable only below omega dt = 2 sqrt(3): a step past it (links in contact)
// is refused before the run as central difference's is, naming the limit, and check shows it. The
// bundled girder on its bearing (k = E A / L = 1e4) against its abutment (gap spring 1e6), 500 kg:
// omega = sqrt(1.01e6 / 500), the limit 2 sqrt(3) / omega = 0.07708. (Audit 70: a 1e10 contact at
// 0.001 s ran and failed at t = 0.042 with energy made by the links; check did not know the
// method's limit.)
TEST_F(Cli, LinearAccelerationStepAboveItsStableLimitIsRefused) {
  json model =
      json::parse(read_text(fs::path(POUND_SOURCE_DIR) / "models" / "girder_abutment_sdof.json"));
  model.erase("recorders");
  const double limit = 2.0 * std::sqrt(3.0) / std::sqrt((1e4 + 1e6) / 500.0);
  model["analysis"]["integrator"] = "newmark_linear_acceleration";
  model["analysis"]["time_step"] = 1.01 * limit;
  const fs::path file = path("linear_acceleration.json");
  std::ofstream(file) << model.dump();
  const Outcome refused = run_refused(file.string());
  EXPECT_TRUE(contains(refused.err, "/analysis/time_step")) << refused.err;
  EXPECT_TRUE(contains(refused.err, fmt::format("above the stable limit {:.6g} of "
                                                "newmark_linear_acceleration",
                                                limit)))
      << refused.err;
  // An adaptive run whose longest step passes it: the adaptive settings are named.
  model["analysis"]["time_step"] = 0.5 * limit;
  model["analysis"]["adaptive"] = {{"max_time_step", 2.5 * limit}};  // steps of 2 x the limit
  std::ofstream(file) << model.dump();
  EXPECT_TRUE(
      contains(run_refused(file.string()).err, "/analysis/adaptive: the longest adaptive step"));
  model["analysis"].erase("adaptive");
  const fs::path out = path("out");
  // Below it: the contact (pi / omega = 0.07 long) wants ten steps or so to be resolved.
  model["analysis"]["time_step"] = 0.1 * limit;
  std::ofstream(file) << model.dump();
  const Outcome checked = pound({"check", file.string(), "--json"});
  EXPECT_EQ(checked.exit_code, 0) << checked.err;
  const double reported = json::parse(checked.out)["implicit_stable_step"].get<double>();
  std::cout << "linear acceleration's stable step " << reported << ", closed form " << limit
            << ", relative difference " << reported / limit - 1.0 << "\n";
  EXPECT_NEAR(reported, limit, 1e-9 * limit);
  const Outcome ran = pound({"run", file.string(), "--out", out.string(), "--quiet"});
  EXPECT_EQ(ran.exit_code, 0) << ran.err;
}

// An explicit integrator given no step takes its stable one ("auto") and says so, in the run's
// report and in summary.json; an implicit one still needs a number.
TEST_F(Cli, ExplicitMethodWithoutAStepTakesTheStableOneAndSaysSo) {
  json model = json::parse(read_text(fs::path(POUND_SOURCE_DIR) / "models" / "rod_impact.json"));
  model["analysis"].erase("time_step");
  const fs::path file = path("no_step.json");
  std::ofstream(file) << model.dump();
  const Outcome refused = pound({"run", file.string(), "--out", path("implicit").string()});
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_TRUE(contains(refused.err, "/analysis/time_step")) << refused.err;
  EXPECT_FALSE(fs::exists(path("implicit")));

  model["analysis"]["integrator"] = "central_difference";
  std::ofstream(file) << model.dump();
  const fs::path out = path("out");
  const Outcome ran = pound({"run", file.string(), "--out", out.string()});
  ASSERT_EQ(ran.exit_code, 0) << ran.err;
  EXPECT_TRUE(contains(ran.out, "0.8 x the stable step")) << ran.out;
  EXPECT_TRUE(contains(ran.out, "no \"time_step\" given")) << ran.out;
  const json summary = json::parse(read_text(out / "summary.json"));
  const double stable = summary["stable_time_step"].get<double>();
  std::printf("time step %.6g = %.6g x stable step %.6g\n", summary["time_step"].get<double>(),
              summary["time_step"].get<double>() / stable, stable);
  EXPECT_NEAR(summary["time_step"].get<double>(), 0.8 * stable, 1e-15 * stable);
  EXPECT_EQ(summary["time_step_rule"], "auto");
  EXPECT_EQ(summary["time_step_defaulted"], true);
  // pound check's "analysis" in the same words.
  const json check = json::parse(pound({"check", file.string(), "--json"}).out)["analysis"];
  EXPECT_EQ(check["time_step_rule"], "auto");
  EXPECT_EQ(check["time_step_defaulted"], true);
  EXPECT_EQ(check["time_step"], summary["time_step"]);
  EXPECT_LT(summary["verification"]["duration_error"].get<double>(), 0.05);
}

// "auto" goes no further than the record's own step, whose samples it would step over.
TEST_F(Cli, AutomaticExplicitStepStaysWithinTheRecordStep) {
  json model =
      json::parse(read_text(fs::path(POUND_SOURCE_DIR) / "models" / "two_sdof_girders.json"));
  model["analysis"] = {{"integrator", "central_difference"}};
  model["excitations"][0]["record"] =
      (fs::path(POUND_SOURCE_DIR) / "ground_motions" / "synthetic_firm_02.AT2").string();
  const fs::path file = path("girders.json");
  std::ofstream(file) << model.dump();
  const fs::path out = path("out");
  const Outcome ran = pound({"run", file.string(), "--out", out.string()});
  ASSERT_EQ(ran.exit_code, 0) << ran.err;
  EXPECT_TRUE(contains(ran.out, "the record's step")) << ran.out;
  const json summary = json::parse(read_text(out / "summary.json"));
  std::printf("0.8 x stable step %.4g, record step 0.01, time step %.4g\n",
              0.8 * summary["stable_time_step"].get<double>(), summary["time_step"].get<double>());
  EXPECT_GT(0.8 * summary["stable_time_step"].get<double>(), 0.01);
  EXPECT_EQ(summary["time_step"].get<double>(), 0.01);
  EXPECT_EQ(summary["time_step_rule"], "auto_record_step");
  const json check = json::parse(pound({"check", file.string(), "--json"}).out)["analysis"];
  EXPECT_EQ(check["time_step_rule"], "auto_record_step");
  EXPECT_EQ(check["time_step"], summary["time_step"]);
  EXPECT_EQ(check["steps"], summary["steps"]);
}

// The energy a contact creates: two free masses closing through an elastic gap spring whose
// contact starts and ends inside steps. Newmark's trapezoidal rule balances energy exactly, so
// what the link gave back beyond what it took is exactly the kinetic energy the pair gained.
// Above 1 % of the energy put in the run warns; at a step that happens to lose energy, nothing.
TEST_F(Cli, EnergyCreatedByAContactIsTheKineticEnergyGainedAndWarnedAbove1Percent) {
  const auto run_at = [&](double time_step) {
    const json model = {
        {"dimension", 1},
        {"nodes", {{{"id", "a"}, {"x", 0.0}}, {{"id", "b"}, {"x", 0.0}}}},
        {"masses", {{{"node", "a"}, {"mass", 1.0}}, {{"node", "b"}, {"mass", 2.0}}}},
        {"initial_velocities", {{{"node", "a"}, {"x", 1.0}}, {{"node", "b"}, {"x", -0.5}}}},
        {"links",
         {{{"id", "c"},
           {"nodes", {"a", "b"}},
           {"axis", {1}},
           {"gap", 0.00123},
           {"law", {{"type", "gap_spring"}, {"stiffness", 1e4}}}}}},
        {"analysis",
         {{"integrator", "newmark_average_acceleration"},
          {"time_step", time_step},
          {"duration", 0.1}}}};
    const fs::path file = path("pair.json"), out = path(fmt::format("out_{}", time_step));
    std::ofstream(file) << model.dump();
    const Outcome ran = pound({"run", file.string(), "--out", out.string()});
    EXPECT_EQ(ran.exit_code, 0) << ran.err;
    // `pound check` probes the same impact beforehand.
    const Outcome checked = pound({"check", file.string()});
    return std::pair{json::parse(read_text(out / "summary.json")), ran.err + checked.out};
  };
  const auto [gaining, gaining_err] = run_at(0.0047);
  const json& e = gaining["energy"];
  const double gained = e["kinetic"].get<double>() - e["initial"].get<double>();
  const double created = e["contact_created"].get<double>();
  std::printf("dt 0.0047: kinetic energy gained %.10g, contact created %.10g (%.3f %% of %.3g)\n",
              gained, created, 100.0 * e["contact_created_fraction"].get<double>(),
              e["initial"].get<double>());
  EXPECT_GT(gained, 0.01 * e["initial"].get<double>());
  EXPECT_NEAR(created, gained, 1e-9 * gained);
  EXPECT_EQ(gaining["links"][0]["created_energy"].get<double>(), created);
  EXPECT_TRUE(contains(gaining_err, "contact links created")) << gaining_err;
  EXPECT_TRUE(contains(gaining_err, "creates up to")) << gaining_err;

  const auto [losing, losing_err] = run_at(0.0021);
  std::printf("dt 0.0021: kinetic energy gained %.4g, contact created %.4g\n",
              losing["energy"]["kinetic"].get<double>() - losing["energy"]["initial"].get<double>(),
              losing["energy"]["contact_created"].get<double>());
  EXPECT_EQ(losing["energy"]["contact_created"].get<double>(), 0.0);
  EXPECT_FALSE(contains(losing_err, "contact links created")) << losing_err;
  EXPECT_FALSE(contains(losing_err, "creates up to")) << losing_err;
}

// `verify rod-impact` with an explicit integrator and no step option runs at the stable step.
TEST_F(Cli, VerifyExplicitWithoutAStepTakesTheStableOne) {
  const Outcome ran = pound({"verify", "rod-impact", "--integrator", "central_difference", "--n",
                             "1000", "--duration-ratio", "1.5"});
  ASSERT_EQ(ran.exit_code, 0) << ran.err;
  EXPECT_TRUE(contains(ran.out, "0.8 x the stable step: no --dt-ratio or --courant given"))
      << ran.out;
  const Outcome refused = pound({"verify", "rod-impact", "--integrator", "central_difference",
                                 "--n", "1000", "--dt-ratio", "0.01"});
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_TRUE(contains(refused.err, "above the stable limit")) << refused.err;
}

// A step longer than the whole run computes nothing; its metrics read as a perfect result (the
// energy kept, the rods' velocities exact), so it is refused, naming the option. Kawashima's
// case: contact from t = 0 for 0.6325, run 3 x that, 1.897; dt = 3.2 x 0.6325 = 2.02.
// Far too many steps ran out of memory (exit 3), a stiffness past round-off let the rods pass
// through each other, and a Newton test of 1 took the contact force for round-off (audit 70): each
// is refused as a usage error naming its option.
TEST_F(Cli, VerifyRefusesOptionsThatMakeTheRunMeaningless) {
  for (const auto& [option, value, words] :
       std::vector<std::tuple<std::string, std::string, std::string>>{
           {"--dt-ratio", "1e-12", "would take 3e+12 steps"},
           {"--courant", "1e-9", "steps over the run"},
           {"--k-ratio", "1e200", "--k-ratio must be <= 1e12"},
           {"--tolerance", "1", "--tolerance must be in (0, 0.1)"}}) {
    const Outcome refused = pound({"verify", "rod-impact", option, value});
    EXPECT_EQ(refused.exit_code, 1) << refused.err;
    EXPECT_TRUE(contains(refused.err, option)) << refused.err;
    EXPECT_TRUE(contains(refused.err, words)) << refused.err;
  }
}

TEST_F(Cli, VerifyRefusesAStepLongerThanTheRun) {
  for (const std::vector<std::string>& option : {std::vector<std::string>{"--dt-ratio", "3.2"},
                                                 {"--dt-ratio", "1e308"},
                                                 {"--courant", "1e308"}}) {
    std::vector<std::string> arguments{"verify", "rod-impact"};
    arguments.insert(arguments.end(), option.begin(), option.end());
    const Outcome refused = pound(arguments);
    EXPECT_EQ(refused.exit_code, 1) << refused.err;
    EXPECT_TRUE(contains(refused.err, option[0] + ": the time step")) << refused.err;
    EXPECT_TRUE(contains(refused.err, "longer than the whole run (1.897")) << refused.err;
    EXPECT_TRUE(refused.out.empty()) << refused.out;
  }
  // An option the benchmark, law or integrator does not read would be ignored, and the results
  // taken for what it asked: refused, naming it (its default, or its own benchmark, runs).
  for (const auto& [arguments, words] :
       std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"verify", "rod-impact", "--alpha", "-0.05"},
            "--alpha is not a parameter of newmark_average_acceleration (give --integrator hht)"},
           {{"verify", "rod-impact", "--integrator", "hht", "--rho-inf", "0.5"},
            "--rho-inf is not a parameter of hht (give --integrator generalized_alpha)"},
           {{"verify", "rod-impact", "--eta", "2"}, "the law gap_spring has none"},
           {{"verify", "two-element", "--n", "50"},
            "--n is not an option of the two-element benchmark"},
           {{"verify", "rod-impact", "--study", "kawashima", "--k-ratio", "2"},
            "--k-ratio does not apply to --study"},
           // Two ways of giving the step: one of them would be ignored.
           {{"verify", "rod-impact", "--courant", "0.5", "--dt-ratio", "0.02"},
            "--courant and --dt-ratio both give the time step"}}) {
    const Outcome refused = pound(arguments);
    EXPECT_EQ(refused.exit_code, 1) << refused.err;
    EXPECT_TRUE(contains(refused.err, words)) << refused.err;
  }
  const Outcome hht = pound({"verify", "rod-impact", "--integrator", "hht", "--alpha", "-0.05"});
  EXPECT_EQ(hht.exit_code, 0) << hht.err;
  const Outcome penalty =
      pound({"verify", "rod-impact", "--law", "extended_penalty", "--eta", "0.5", "--n", "20"});
  EXPECT_EQ(penalty.exit_code, 0) << penalty.err;
  // Just shorter than the run: one step, computed and reported (as bad as it is).
  const Outcome coarse = pound({"verify", "rod-impact", "--dt-ratio", "2.9", "--json"});
  ASSERT_EQ(coarse.exit_code, 0) << coarse.err;
  EXPECT_GE(json::parse(coarse.out)["steps"].get<int>(), 1) << coarse.out;
}

}  // namespace

namespace {

// Central difference's stable step in contact with a Hertz contact (no stiffness at first touch)
// is taken at its elastic impact's peak penetration, for an impact at its approach velocity:
// two bare masses (1,000 and 500 kg) closing at 1 m/s on k_h = 1e9 N/m^1.5 give
// 2 / sqrt(1.5 k_h sqrt(delta_max) / m_eff) with delta_max = (5 m_eff v^2 / (4 k_h))^(2/5), the
// same in mm, ms and kN. At first touch it was 1e-12 of a unit deep: 1.574 s in metres, 8,853 ms
// in millimetres, for an impact that lasts milliseconds.
TEST_F(Cli, CheckTakesAHertzContactsStableStepAtItsPeakPenetration) {
  const double mass_eff = 1000.0 * 500.0 / 1500.0, stiffness = 1e9;
  const double peak = std::pow(5.0 * mass_eff / (4.0 * stiffness), 0.4);
  const double exact = 2.0 / std::sqrt(1.5 * stiffness * std::sqrt(peak) / mass_eff);
  for (const bool millimetres : {false, true}) {
    json pair = moving_masses(2, 1000.0, "central_difference");
    pair["masses"][1]["mass"] = 500.0;
    pair["analysis"]["time_step"] = millimetres ? 1e-2 : 1e-5;
    pair["analysis"]["duration"] = millimetres ? 50.0 : 0.05;
    pair["nodes"][1]["x"] = millimetres ? 1000.0 : 1.0;
    // kN / mm^1.5 = 1e3 N / (1e-3 m)^1.5: k_h / 31,622.8
    pair["links"] = {
        {{"id", "c"},
         {"nodes", {"m0", "m1"}},
         {"law",
          {{"type", "hertz"},
           {"stiffness", millimetres ? stiffness / 1e3 / std::pow(1e3, 1.5) : stiffness}}}}};
    if (millimetres) pair["units"] = {{"length", "mm"}, {"time", "ms"}, {"mass", "kg"}};
    const fs::path file = path(millimetres ? "mm.json" : "m.json");
    std::ofstream(file) << pair.dump(2);
    const Outcome check = pound({"check", file.string(), "--json"});
    ASSERT_EQ(check.exit_code, 0) << check.err << check.out;
    const double step = json::parse(check.out)["explicit_stable_step_contact"].get<double>() /
                        (millimetres ? 1e3 : 1.0);
    std::cout << fmt::format(
        "Hertz pair, {}: explicit stable step in contact {:.6e} s, exact "
        "{:.6e} s\n",
        millimetres ? "mm, ms, kN" : "m, s, N", step, exact);
    EXPECT_NEAR(step / exact, 1.0, 1e-9);
    EXPECT_TRUE(contains(pound({"check", file.string()}).out, "at their peak penetration"));
  }
}

// The extended penalty with its default dashpot, alpha1 = 2 sqrt(alpha0 alpha2) (eta = 1), between
// bare masses under Newmark: its alpha1 v at touch can push the pair back past delta = 0 within
// the step, and the first-touch rule (in contact only while penetrating) then had no solution:
// Newton failed at every first touch. Held once touched within the step, the impact is the pair's
// linear one, (m_eff + alpha2) d'' + alpha1 d' + alpha0 d = 0 from d = 0, d' = v until
// alpha0 d + alpha1 d' = 0 (the force's zero): its impulse m_eff (v - d'_end).
TEST_F(Cli, AnExtendedPenaltysDefaultDashpotStrikesUnderNewmark) {
  json pair = penalty_pair("newmark_average_acceleration", 1e4, 0.01);
  pair["links"][0]["law"].erase("alpha1");
  const fs::path file = path("damped.json"), out = path("damped.out");
  std::ofstream(file) << pair.dump(2);
  const Outcome outcome = pound({"run", file.string(), "--out", out.string()});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const double mass = 1e5 * 2e5 / 3e5 + 1e4, alpha0 = 1e9, alpha1 = 2.0 * std::sqrt(alpha0 * 1e4);
  const double omega = std::sqrt(alpha0 / mass), zeta = alpha1 / (2.0 * std::sqrt(alpha0 * mass));
  const double damped = omega * std::sqrt(1.0 - zeta * zeta);
  const auto rate = [&](double t) {
    return std::exp(-zeta * omega * t) *
           (std::cos(damped * t) - zeta * omega / damped * std::sin(damped * t));
  };
  const auto force = [&](double t) {  // alpha0 d + alpha1 d', v = 1
    return alpha0 * std::exp(-zeta * omega * t) * std::sin(damped * t) / damped + alpha1 * rate(t);
  };
  double low = 0.5 * std::numbers::pi / damped, high = 2.0 * std::numbers::pi / damped;
  for (int k = 0; k < 200; ++k) (force(0.5 * (low + high)) > 0.0 ? low : high) = 0.5 * (low + high);
  const double exact = 1e5 * 2e5 / 3e5 * (1.0 - rate(low));
  const double impulse = json::parse(read_text(out / "summary.json"))["links"][0]["impulse"];
  std::cout << fmt::format(
      "default extended penalty under Newmark: impulse {:.1f} N s, the "
      "linear impact's {:.1f} (error {:.1e})\n",
      impulse, exact, impulse / exact - 1.0);
  EXPECT_NEAR(impulse / exact, 1.0, 1e-3);  // dt = 1e-5 s against a 23 ms contact
}

// An extended penalty's mass alpha2 moves with the pair it joins: between bare masses a contact
// lasts half a period of m_eff + alpha2 on alpha0 (check claimed pi sqrt(m_eff / alpha0), 0.026 s
// for a 0.103 s contact at alpha2 = 15 m_eff).
TEST_F(Cli, CheckCountsTheExtendedPenaltysMassInTheContactsDuration) {
  const json pair = penalty_pair("central_difference", 1e6, 0.0);
  const fs::path file = path("penalty.json");
  std::ofstream(file) << pair.dump(2);
  const Outcome check = pound({"check", file.string(), "--json"});
  ASSERT_EQ(check.exit_code, 0) << check.err << check.out;
  const double duration = json::parse(check.out)["links"][0]["contact_duration"].get<double>();
  const double exact = std::numbers::pi * std::sqrt((1e5 * 2e5 / 3e5 + 1e6) / 1e9);
  std::cout << fmt::format(
      "extended penalty, alpha2 = 15 m_eff: contact lasts {:.6f} s, "
      "pi sqrt((m_eff + alpha2) / alpha0) = {:.6f} s\n",
      duration, exact);
  EXPECT_NEAR(duration, exact, 1e-12 * exact);
}

// `pound check` finds what the benchmarks show to be meaningless, and is quiet otherwise.
TEST_F(Cli, CheckWarnsAboutMeaninglessSettingsOnly) {
  for (const char* model : {"rod_impact.json", "three_span_bridge.json", "two_sdof_girders.json"}) {
    const Outcome quiet =
        pound({"check", (fs::path(POUND_SOURCE_DIR) / "models" / model).string(), "--strict"});
    EXPECT_EQ(quiet.exit_code, 0) << model << "\n" << quiet.out;
    EXPECT_TRUE(contains(quiet.out, "no warnings")) << quiet.out;
  }
  // A stiff link (k-ratio 1800) between lumped girders on massless piers, and a step of half the
  // contact: the step is meaningless; the k-ratio is the contact's against the structure, as a
  // girder joint's is by design (Kawashima's advice is for meshed bodies, below).
  json model =
      json::parse(read_text(fs::path(POUND_SOURCE_DIR) / "models" / "two_sdof_girders.json"));
  model["links"][0]["law"]["stiffness"] = 1e10;
  model["analysis"]["time_step"] = 0.02;
  model["excitations"][0]["record"] =
      (fs::path(POUND_SOURCE_DIR) / "ground_motions" / "synthetic_firm_02.AT2").string();
  const fs::path file = path("stiff.json");
  std::ofstream(file) << model.dump();
  const Outcome warned = pound({"check", file.string(), "--strict", "--json"});
  EXPECT_EQ(warned.exit_code, 1) << warned.err;
  const json findings = json::parse(warned.out);
  std::string all;
  for (const json& w : findings["warnings"]) all += w["warning"].get<std::string>() + "\n";
  EXPECT_FALSE(contains(all, "k-ratio")) << all;
  EXPECT_TRUE(contains(all, "meaningless")) << all;
  EXPECT_GT(findings["explicit_stable_step_open"].get<double>(),
            findings["explicit_stable_step_contact"].get<double>());
  // `pound run` gives the same warnings, printed and in summary.json.
  const Outcome run = pound({"run", file.string(), "--out", path("stiff").string(), "--quiet"});
  EXPECT_TRUE(contains(run.err, "warning: link joint: the time step")) << run.err;
  const json summary = json::parse(read_text(path("stiff") / "summary.json"));
  std::string ran;
  for (const json& w : summary["warnings"]) ran += w["warning"].get<std::string>() + "\n";
  EXPECT_TRUE(contains(ran, all)) << ran;
  // Piers with a little mass of their own (1 m of a 0.0015 m^2 strip at steel's density: 12 kg
  // beside girders of 200 and 400 t, the stiffness unchanged) leave the girders lumped: no k-ratio
  // warning (they made the joint "meshed" and warned).
  json massive = model;
  massive["materials"][0]["density"] = 7850.0;
  massive["materials"][1]["density"] = 7850.0;
  massive["elements"][0]["area"] = 0.0015;
  massive["materials"][0]["youngs_modulus"] = 4.386e7 / 0.0015;
  massive["elements"][1]["area"] = 0.0015;
  massive["materials"][1]["youngs_modulus"] = 5.483e6 / 0.0015;
  std::ofstream(path("massive.json")) << massive.dump();
  const json lumped = json::parse(pound({"check", path("massive.json").string(), "--json"}).out);
  std::string lumped_warnings;
  for (const json& w : lumped["warnings"])
    lumped_warnings += w["warning"].get<std::string>() + "\n";
  EXPECT_FALSE(contains(lumped_warnings, "k-ratio")) << lumped_warnings;
  // Kawashima's stiff link between meshed rods (k-ratio 1000): it rings inside the contact.
  json rods = json::parse(read_text(fs::path(POUND_SOURCE_DIR) / "models" / "rod_impact.json"));
  rods["generators"][0]["law"]["stiffness_ratio"] = 1000.0;
  std::ofstream(path("stiff_rods.json")) << rods.dump();
  const Outcome rung = pound({"check", path("stiff_rods.json").string(), "--strict"});
  EXPECT_EQ(rung.exit_code, 1) << rung.err;
  EXPECT_TRUE(contains(rung.out, "k-ratio 1e+03: a link this stiff")) << rung.out;
  // A link far softer than the piers (N/m typed for kN/m) lets the lumped girders pass through
  // each other: warned of, meshed or not.
  model["links"][0]["law"]["stiffness"] = 5e5;
  model["analysis"]["time_step"] = 0.002;
  std::ofstream(path("soft.json")) << model.dump();
  const Outcome soft = pound({"check", path("soft.json").string(), "--strict"});
  EXPECT_EQ(soft.exit_code, 1) << soft.err;
  EXPECT_TRUE(contains(soft.out, "a link this soft")) << soft.out;
}

// ---- Issue 16 item 6: a run says which records it applied, how scaled ----

// A columns file of the bundled record's first 500 values in m/s^2 (0.02 s), time in column 1.
std::string columns_record(const fs::path& file) {
  std::ifstream at2(fs::path(POUND_SOURCE_DIR) / "ground_motions" / "synthetic_firm_01.AT2");
  std::string line, text = "# time [s], acceleration [m/s2]\n";
  for (int k = 0; k < 4; ++k) std::getline(at2, line);  // the AT2 header
  int sample = 0;
  for (double value; sample < 500 && at2 >> value; ++sample)
    text += fmt::format("{}, {}\n", 0.01 * sample, 9.80665 * value);
  std::ofstream(file) << text;
  return text;
}

TEST_F(Cli, SummaryRecordsEachExcitationsFileHashScalingAndPga) {
  const fs::path record = path("motion.txt");
  const std::string bytes = columns_record(record);
  const Outcome outcome =
      pound({"run", POUND_SOURCE_DIR "/models/two_sdof_girders.json", "--motion", record.string(),
             "--time-column", "--units", "m/s2", "--pga", "0.25", "--out", path("out").string()});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const json summary = json::parse(read_text(path("out") / "summary.json"));
  ASSERT_EQ(summary["excitations"].size(), 1u);
  const json& e = summary["excitations"][0];
  EXPECT_EQ(e["record"], record.string());
  EXPECT_EQ(e["sha1"], pound::io::sha1_hex(bytes));
  EXPECT_EQ(e["format"], "columns");
  EXPECT_EQ(e["units"], "m/s2");
  EXPECT_EQ(e["points"], 500);
  EXPECT_NEAR(e["dt"].get<double>(), 0.01, 1e-15);
  EXPECT_EQ(e["scaling"], json({{"target_pga_g", 0.25}}));
  EXPECT_NEAR(e["pga_g"].get<double>(), 0.25, 1e-15);
  EXPECT_EQ(e["replaced_by"], "--motion");
  // The model's title names its own record: what ran is said instead, the title kept aside.
  EXPECT_EQ(summary["title"], "two_sdof_girders under motion.txt (record replaced by --motion)");
  EXPECT_EQ(summary["model_title"], json::parse(read_text(fs::path(POUND_SOURCE_DIR) / "models" /
                                                          "two_sdof_girders.json"))["title"]);
  EXPECT_TRUE(contains(outcome.out, "record " + record.string() + " (sha1 " +
                                        pound::io::sha1_hex(bytes).substr(0, 12) +
                                        "): scale factor"))
      << outcome.out;
}

TEST_F(Cli, ModelRunsRecordTheirOwnExcitationsAsTheModelScalesThem) {
  const Outcome outcome = pound({"run", POUND_SOURCE_DIR "/models/three_span_bridge.json", "--out",
                                 path("out").string(), "--max-steps", "5"});
  const json summary = json::parse(read_text(path("out") / "summary.json"));
  const json& e = summary["excitations"][0];
  EXPECT_EQ(e["format"], "at2");
  EXPECT_EQ(e["scaling"], json({{"target_pga_g", 0.4}}));
  EXPECT_NEAR(e["pga_g"].get<double>(), 0.4, 1e-15);
  EXPECT_FALSE(e.contains("replaced_by"));
  EXPECT_FALSE(summary.contains("model_title"));
  // Issue 16 item 5: the model's units block, named (its mass unit gives the force unit).
  EXPECT_EQ(summary["units"], json({{"length", "m"},
                                    {"time", "s"},
                                    {"acceleration", "m/s^2"},
                                    {"mass", "kg"},
                                    {"force", "N"},
                                    {"moment", "N*m"}}));
  EXPECT_EQ(e["sha1"], pound::io::sha1_hex(read_text(fs::path(POUND_SOURCE_DIR) / "ground_motions" /
                                                     "synthetic_firm_01.AT2")));
  // ... and so do the CSV headers: histories per column, envelopes per row (column "unit").
  EXPECT_TRUE(
      read_lines(path("out") / "joints.csv")
          .front()
          .starts_with("time [s],bridge.a0.joint.force [N],bridge.a0.joint.penetration [m],"));
  const std::vector<std::string> forces = read_lines(path("out") / "pier_base_forces.csv");
  ASSERT_GE(forces.size(), 4u);
  EXPECT_EQ(forces[0], "quantity,unit,max,time_of_max [s],min,time_of_min [s],abs_max");
  EXPECT_TRUE(forces[2].starts_with("bridge.p1.e1.V_i,N,")) << forces[2];
  EXPECT_TRUE(forces[3].starts_with("bridge.p1.e1.M_i,N*m,")) << forces[3];
}

TEST_F(Cli, MotionOptionsNeedMotionAndSensibleValues) {
  const std::string record = POUND_SOURCE_DIR "/ground_motions/synthetic_firm_01.AT2";
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--pga", "0.3"}, "--pga says how to read the record of --motion"},
      {{"--units", "m/s2"}, "--units says how to read the record of --motion"},
      {{"--motion", record, "--pga", "0"}, "--pga must be a positive number"},
      {{"--motion", record, "--scale", "-2"}, "--scale must be a positive number"},
      {{"--motion", record, "--scale", "nan"}, "--scale must be a finite number"},
      {{"--motion", record, "--scale", "2", "--pga", "0.3"}, "give --scale or --pga, not both"},
      {{"--motion", record, "--units", "furlongs"}, "--units: unknown acceleration unit"},
      {{"--motion", record, "--column", "0"}, "--column must be 1 or more"},
  };
  for (const auto& [options, message] : cases) {
    std::vector<std::string> arguments = {"run", kRodModel, "--out", path("out").string()};
    arguments.insert(arguments.end(), options.begin(), options.end());
    const Outcome outcome = pound(arguments);
    EXPECT_EQ(outcome.exit_code, 1) << outcome.err;
    EXPECT_TRUE(contains(outcome.err, message)) << outcome.err;
    EXPECT_FALSE(fs::exists(path("out")));
  }
}

// At the longest period asked (1000 s) every column is finite; beyond, omega^2 underflows (at
// 1e308 s Sd was 0 / 0 = NaN in a completed result): refused.
TEST_F(Cli, SpectrumIsFiniteAtItsLongestPeriodAndRefusesLonger) {
  const std::string record = POUND_SOURCE_DIR "/ground_motions/synthetic_firm_01.AT2";
  const Outcome longest = pound({"spectrum", record, "--periods", "0,1000", "--json"});
  ASSERT_EQ(longest.exit_code, 0) << longest.err;
  const json spectrum = json::parse(longest.out);
  for (const char* column : {"sa_g", "sv_m_per_s", "sd_m"})
    for (const json& value : spectrum[column]) EXPECT_TRUE(value.is_number()) << longest.out;
  std::cout << "Sd at 1000 s: " << spectrum["sd_m"][1] << " m\n";
  EXPECT_GT(spectrum["sd_m"][1].get<double>(), 0.0);
  for (const char* periods : {"0,1e308", "1000.5"}) {
    const Outcome refused = pound({"spectrum", record, "--periods", periods});
    EXPECT_EQ(refused.exit_code, 1) << refused.err;
    EXPECT_TRUE(contains(refused.err, "beyond any structure's period (at most 1000 s)"))
        << refused.err;
  }
}

TEST_F(Cli, SpectrumScalesTheRecordAsAskedAndSaysBy) {
  const std::string record = POUND_SOURCE_DIR "/ground_motions/synthetic_firm_01.AT2";
  const Outcome scaled = pound({"spectrum", record, "--pga", "0.25", "--periods", "0,1", "--json"});
  ASSERT_EQ(scaled.exit_code, 0) << scaled.err;
  const Outcome doubled = pound({"spectrum", record, "--scale", "2", "--periods", "0,1", "--json"});
  const Outcome plain = pound({"spectrum", record, "--periods", "0,1", "--json"});
  const json a = json::parse(scaled.out), b = json::parse(doubled.out), c = json::parse(plain.out);
  EXPECT_NEAR(a["pga_g"].get<double>(), 0.25, 1e-15);
  EXPECT_NEAR(a["sa_g"][0].get<double>(), 0.25, 1e-15);  // period 0: the PGA
  EXPECT_EQ(b["scale_factor"], 2.0);
  EXPECT_EQ(b["sa_g"][1].get<double>(), 2.0 * c["sa_g"][1].get<double>());
  EXPECT_NEAR(a["sa_g"][1].get<double>() / c["sa_g"][1].get<double>(),
              a["scale_factor"].get<double>(), 1e-14);
  const Outcome both = pound({"spectrum", record, "--pga", "0.25", "--scale", "2"});
  EXPECT_EQ(both.exit_code, 1);
  EXPECT_TRUE(contains(both.err, "give --scale or --pga, not both")) << both.err;
}

// A factor that makes the record, or its spectral accelerations, overflow is a usage error naming
// the option, not "an unexpected failure" or inf in a completed spectrum (tools/mutate.py
// --options found both).
TEST_F(Cli, SpectrumRefusesAFactorThatOverflowsTheRecord) {
  const std::string record = POUND_SOURCE_DIR "/ground_motions/synthetic_firm_01.AT2";
  for (const std::vector<std::string>& factor : std::vector<std::vector<std::string>>{
           {"--pga", "1e308"}, {"--scale", "1e308"}, {"--scale", "3e307"}}) {
    std::vector<std::string> arguments = {"spectrum", record};
    arguments.insert(arguments.end(), factor.begin(), factor.end());
    const Outcome refused = pound(arguments);
    EXPECT_EQ(refused.exit_code, 1) << factor[0] << " " << factor[1] << ": " << refused.err;
    EXPECT_TRUE(contains(refused.err, "overflows the number range")) << refused.err;
    EXPECT_TRUE(contains(refused.err, "the factor of " + factor[0])) << refused.err;
    EXPECT_TRUE(refused.out.empty()) << refused.out;
  }
  const Outcome pair = pound({"spectrum", record, "--pair", record, "--scale", "1e308"});
  EXPECT_EQ(pair.exit_code, 1) << pair.err;
  EXPECT_TRUE(contains(pair.err, "the pair overflows the number range")) << pair.err;
  const Outcome units = pound({"spectrum", record, "--units", "0.5"});
  EXPECT_EQ(units.exit_code, 1);
  EXPECT_TRUE(contains(units.err, "--units: unknown acceleration unit '0.5'")) << units.err;
}

// ---- Issue 18 item 3: the intensity measures of a record's two horizontal components ----

TEST_F(Cli, SpectrumOfAPairGivesRotD50AndRotD100AsAnIndependentSolutionDoes) {
  POUND_SKIP_WITHOUT_SHARED_RECORDS();
  // Kobe 1995, JMA: NS and EW in the two columns of one file, cm/s^2. The references are RotD50,
  // RotD100 [m/s^2] and the direction of RotD100 from SciPy's lsim (first-order hold, the same
  // piecewise-linear record) projected on the same 180 directions, computed once.
  const std::string kobe = pound::testing::shared_record("Kobe1995_JMA_NS-EW_cms2_dt0.005.txt");
  const Outcome outcome =
      pound({"spectrum", kobe, "--units", "cm/s2", "--pair-column", "2", "--periods", "0.3,1,2",
             "--json", "--csv", path("pair.csv").string()});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const json pair = json::parse(outcome.out);
  const double references[3][3] = {{17.55932495, 20.19825054, 156},
                                   {13.56160027, 18.66582395, 142},
                                   {3.053893402, 4.222294952, 152}};
  for (int k = 0; k < 3; ++k) {
    const double rot_d50 = pair["rotd50_g"][k].get<double>() * 9.80665;
    const double rot_d100 = pair["rotd100_g"][k].get<double>() * 9.80665;
    const double d50 = std::abs(rot_d50 / references[k][0] - 1.0);
    const double d100 = std::abs(rot_d100 / references[k][1] - 1.0);
    std::cout << "T = " << pair["periods"][k] << " s: RotD50 " << d50 << ", RotD100 " << d100
              << " from SciPy's; GM / RotD50 "
              << pair["geometric_mean_g"][k].get<double>() / pair["rotd50_g"][k].get<double>()
              << "\n";
    EXPECT_LT(d50, 1e-8);  // the references' 10 digits
    EXPECT_LT(d100, 1e-8);
    EXPECT_EQ(pair["rotd100_angle_deg"][k].get<double>(), references[k][2]);
    EXPECT_GE(pair["rotd100_g"][k].get<double>(),
              std::max(pair["sa1_g"][k].get<double>(), pair["sa2_g"][k].get<double>()));
  }
  const std::vector<std::string> csv = read_lines(path("pair.csv"));
  ASSERT_EQ(csv.size(), 4u);
  EXPECT_EQ(csv[0], "period,sa1_g,sa2_g,geometric_mean_g,rotd50_g,rotd100_g,rotd100_angle_deg");
  // Turning the sensors changes the components' Sa, not RotD50.
  const json turned = json::parse(pound({"spectrum", kobe, "--units", "cm/s2", "--pair-column", "2",
                                         "--periods", "0.3,1,2", "--json", "--rotation", "40"})
                                      .out);
  EXPECT_NE(turned["sa1_g"][1], pair["sa1_g"][1]);
  EXPECT_NEAR(turned["rotd50_g"][1].get<double>() / pair["rotd50_g"][1].get<double>(), 1.0, 1e-12);
  EXPECT_EQ(turned["rotation_deg"], 40.0);
}

TEST_F(Cli, SpectrumRefusesPairsOnDifferentGridsAndOptionsThatDoNotFitAPair) {
  const std::string firm = POUND_SOURCE_DIR "/ground_motions/synthetic_firm_01.AT2";
  // Two records of different lengths or steps are no pair: exit 2, the second file named.
  const std::string north = path("north.txt").string(), short_east = path("east.txt").string(),
                    coarse_east = path("coarse.txt").string();
  std::ofstream(north) << "0 0.1\n0.01 0.2\n0.02 -0.1\n0.03 0.05\n";
  std::ofstream(short_east) << "0 0.1\n0.01 0.2\n0.02 -0.1\n";
  std::ofstream(coarse_east) << "0 0.1\n0.02 0.2\n0.04 -0.1\n0.06 0.05\n";
  for (const auto& [east, message] : {std::pair{short_east, "as many samples (4 and 3)"},
                                      std::pair{coarse_east, "one time step (0.01 and 0.02)"}}) {
    const Outcome mismatched = pound({"spectrum", north, "--time-column", "--pair", east});
    std::cout << mismatched.err;
    EXPECT_EQ(mismatched.exit_code, 2) << mismatched.err;
    EXPECT_TRUE(contains(mismatched.err, east)) << mismatched.err;
    EXPECT_TRUE(contains(mismatched.err, message)) << mismatched.err;
  }
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--rotation", "30"}, "--rotation turns a pair"},
      {{"--pair", firm, "--pga", "0.3"}, "scale a pair by one factor with --scale"},
      {{"--pair", firm, "--pair-column", "2"}, "give --pair or --pair-column, not both"},
      {{"--pair-column", "1"}, "--pair-column must be 1 or more and not the record's --column"},
      {{"--pair", firm, "--rotation", "inf"}, "--rotation must be a finite number"},
  };
  for (const auto& [options, message] : cases) {
    std::vector<std::string> arguments = {"spectrum", firm};
    arguments.insert(arguments.end(), options.begin(), options.end());
    const Outcome outcome = pound(arguments);
    EXPECT_EQ(outcome.exit_code, 1) << outcome.err;
    EXPECT_TRUE(contains(outcome.err, message)) << outcome.err;
  }
  // An .AT2 file has one component: a column of it (the pair's, or the record's) would read that
  // component again, a pair of a record with itself taken for two.
  for (const std::vector<std::string>& options :
       {std::vector<std::string>{"--pair-column", "2"}, {"--column", "2"}, {"--time-column"}}) {
    std::vector<std::string> arguments = {"spectrum", firm};
    arguments.insert(arguments.end(), options.begin(), options.end());
    const Outcome outcome = pound(arguments);
    EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
    EXPECT_TRUE(contains(outcome.err, "a PEER .AT2 file holds one component")) << outcome.err;
    EXPECT_TRUE(outcome.out.empty()) << outcome.out;
  }
  // A record paired with itself: RotD50 is its Sa, RotD100 sqrt(2) times it, at 45 degrees.
  const json self = json::parse(
      pound({"spectrum", firm, "--pair", firm, "--scale", "2", "--periods", "0.5", "--json"}).out);
  EXPECT_NEAR(self["rotd50_g"][0].get<double>() / self["sa1_g"][0].get<double>(), 1.0, 1e-14);
  EXPECT_NEAR(self["rotd100_g"][0].get<double>() / self["sa1_g"][0].get<double>(), std::sqrt(2.0),
              1e-14);
  EXPECT_EQ(self["rotd100_angle_deg"][0], 45.0);
  EXPECT_EQ(self["scale_factor"], 2.0);
}

// ---- Issue 16 item 8: `pound modes` shows the directions the scene has, and writes shapes ----

TEST_F(Cli, ModesListOnlyTheDirectionsTheSceneMovesInAndWriteTheShapes) {
  const std::string buildings = POUND_SOURCE_DIR "/models/adjacent_buildings.json";
  const Outcome listed = pound({"modes", buildings, "--count", "3"});
  ASSERT_EQ(listed.exit_code, 0) << listed.err;
  EXPECT_TRUE(contains(listed.out, "mass x")) << listed.out;
  EXPECT_FALSE(contains(listed.out, "mass y")) << listed.out;  // floors sway along x only
  const json modes = json::parse(pound({"modes", buildings, "--count", "3", "--json"}).out);
  EXPECT_EQ(modes["units"]["time"], "s");  // the periods' unit
  EXPECT_FALSE(modes["modes"][0].contains("mass_ratio_y"));
  const json bridge = json::parse(
      pound({"modes", POUND_SOURCE_DIR "/models/three_span_bridge.json", "--count", "2", "--json"})
          .out);
  EXPECT_TRUE(bridge["modes"][0].contains("mass_ratio_y"));  // its girders and piers move in y

  const Outcome written =
      pound({"modes", buildings, "--count", "3", "--shapes", path("shapes.csv").string()});
  ASSERT_EQ(written.exit_code, 0) << written.err;
  const std::vector<std::string> lines = read_lines(path("shapes.csv"));
  ASSERT_EQ(lines.size(), 1u + modes["dofs"].get<std::size_t>());  // a row per free DOF
  EXPECT_EQ(lines[0], "dof,mode_1,mode_2,mode_3");
  std::set<std::string> labels;
  std::vector<double> largest(3, 0.0);
  for (std::size_t r = 1; r < lines.size(); ++r) {
    std::stringstream row(lines[r]);
    std::string label, cell;
    std::getline(row, label, ',');
    labels.insert(label);
    for (std::size_t m = 0; std::getline(row, cell, ','); ++m)
      largest[m] = std::max(largest[m], std::stod(cell));
  }
  EXPECT_EQ(labels.size(), lines.size() - 1);
  EXPECT_TRUE(labels.count("pair.right.f8.u_x"));
  EXPECT_EQ(largest, (std::vector<double>{1.0, 1.0, 1.0}));  // each scaled to +1

  const Outcome refused = pound({"modes", buildings, "--shapes", path("shapes.txt").string()});
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_TRUE(contains(refused.err, "--shapes: a file name ending in .csv or .npy")) << refused.err;
  const Outcome over = pound({"modes", buildings, "--shapes", buildings});
  EXPECT_NE(over.exit_code, 0);
}

// Effective modal mass along every axis the scene's mass moves: the skewed 3-D bridge lists z too,
// and all its modes hold the whole mass along x, y and z (sum of (phi^T M iota)^2 over an
// M-orthonormal basis = iota^T M iota). The listed modes' sums are printed; where they hold less
// than the codes' 90 % along an axis a record shakes (the plane bridge's first mode alone, x),
// the listing says so, and not for an axis no record shakes (its y).
// A model copied away from its records still has periods and a capacity curve: modes and pushover
// read no record (they were refused, naming the record file they did not need).
TEST_F(Cli, ModesAndPushoverOfAModelAwayFromItsRecordsNeedNone) {
  const fs::path original = fs::path(POUND_SOURCE_DIR) / "models" / "eccentric_storey_3d.json";
  const fs::path copy = path("storey.json");
  fs::copy_file(original, copy);
  const Outcome here = pound({"modes", copy.string(), "--json"});
  ASSERT_EQ(here.exit_code, 0) << here.err;
  const Outcome there = pound({"modes", original.string(), "--json"});
  ASSERT_EQ(there.exit_code, 0) << there.err;
  EXPECT_EQ(json::parse(here.out)["modes"], json::parse(there.out)["modes"]);
  const Outcome push = pound({"pushover", copy.string(), "--node", "floor", "--direction", "x",
                              "--to", "0.01", "--out", path("push").string()});
  EXPECT_EQ(push.exit_code, 0) << push.err;
  // A run needs its records, and says which.
  const Outcome run = pound({"run", copy.string(), "--out", path("run").string()});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(contains(run.err, "synthetic_firm_01.AT2")) << run.err;
  // Unread, a record is still an input: shapes written over it are refused, the file kept.
  json model = json::parse(read_text(copy));
  model["excitations"][0]["record"] = "ground.csv";
  model["excitations"][0].erase("pair");
  std::ofstream(copy) << model.dump(2);
  std::ofstream(path("ground.csv")) << "0.0\n0.1\n";
  const Outcome over = pound({"modes", copy.string(), "--shapes", path("ground.csv").string()});
  EXPECT_EQ(over.exit_code, 2) << over.err;
  EXPECT_EQ(read_text(path("ground.csv")), "0.0\n0.1\n");
}

TEST_F(Cli, ModesSumTheirEffectiveMassAlongEachAxisAgainstTheCodes90Percent) {
  const std::string skewed = POUND_SOURCE_DIR "/models/skewed_bridge_3d.json";
  const Outcome listed = pound({"modes", skewed});
  ASSERT_EQ(listed.exit_code, 0) << listed.err;
  EXPECT_TRUE(contains(listed.out, "mass z")) << listed.out;
  EXPECT_TRUE(contains(listed.out, "  sum ")) << listed.out;
  EXPECT_FALSE(contains(listed.out, "less than 90 %")) << listed.out;  // x 0.937, y 0.967
  const json all = json::parse(pound({"modes", skewed, "--count", "300", "--json"}).out);
  for (const char* axis : {"x", "y", "z"}) {
    const double sum = all["mass_ratio_sum"][axis].get<double>();
    std::cout << "skewed bridge, all " << all["modes"].size() << " modes: mass along " << axis
              << " " << sum << "\n";
    EXPECT_NEAR(sum, 1.0, 1e-12) << axis;
  }
  EXPECT_TRUE(all["modes"][0].contains("mass_ratio_z"));
  const Outcome first =
      pound({"modes", POUND_SOURCE_DIR "/models/three_span_bridge.json", "--count", "1"});
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_TRUE(contains(first.out,
                       "the one mode listed holds less than 90 % of the mass along x (58.7 %), "
                       "which the records shake"))
      << first.out;
  EXPECT_FALSE(contains(first.out, "along x (58.7 %), y")) << first.out;
}

// `pound modes --count 12` on two girders lists their 2 modes and says why not 12; a free body's
// rigid-body mode is left out and said so; as many modes as asked: no such line.
TEST_F(Cli, ModesFewerThanAskedSayWhy) {
  const std::string girders = POUND_SOURCE_DIR "/models/two_sdof_girders.json";
  const Outcome listed = pound({"modes", girders, "--count", "12"});
  ASSERT_EQ(listed.exit_code, 0) << listed.err;
  // The header gives the units: the model's time unit, Hz where it is seconds.
  EXPECT_TRUE(contains(listed.out, " mode   period [s]   freq. [Hz]     mass x\n")) << listed.out;
  EXPECT_TRUE(contains(listed.out,
                       "\n2 of the 12 modes asked for: the model has 2 DOFs with "
                       "mass, hence 2 modes\n"))
      << listed.out;
  const json document = json::parse(pound({"modes", girders, "--count", "12", "--json"}).out);
  EXPECT_EQ(document["asked"], 12);
  EXPECT_EQ(document["modes"].size(), 2u);
  EXPECT_EQ(document["fewer"], "the model has 2 DOFs with mass, hence 2 modes");
  const json enough = json::parse(pound({"modes", girders, "--count", "2", "--json"}).out);
  EXPECT_FALSE(enough.contains("fewer"));
  EXPECT_FALSE(contains(pound({"modes", girders, "--count", "2"}).out, "asked for"));

  // Three masses joined by two trusses, free, beside a mass on a spring from the ground.
  const std::string free_body = path("free.json").string();
  std::ofstream(free_body) << R"({"dimension": 1,
    "nodes": [{"id": "a", "x": 0}, {"id": "b", "x": 1}, {"id": "c", "x": 2},
              {"id": "ground", "x": 5}, {"id": "d", "x": 6}],
    "materials": [{"id": "steel", "youngs_modulus": 2e11, "density": 0}],
    "elements": [
      {"id": "ab", "type": "truss", "nodes": ["a", "b"], "material": "steel", "area": 0.01},
      {"id": "bc", "type": "truss", "nodes": ["b", "c"], "material": "steel", "area": 0.01},
      {"id": "gd", "type": "truss", "nodes": ["ground", "d"], "material": "steel", "area": 0.01}],
    "masses": [{"node": "a", "mass": 1000}, {"node": "b", "mass": 1000},
               {"node": "c", "mass": 1000}, {"node": "d", "mass": 1000}],
    "supports": [{"node": "ground", "fix": ["x"]}],
    "initial_velocities": [{"node": "a", "x": 1}],
    "analysis": {"time_step": 0.0001, "duration": 0.01}})";
  const Outcome rigid = pound({"modes", free_body, "--count", "5"});
  ASSERT_EQ(rigid.exit_code, 0) << rigid.err;
  EXPECT_TRUE(contains(rigid.out,
                       "3 of the 5 modes asked for: 1 of the model's 4 modes (one per "
                       "DOF with mass) stores no strain energy"))
      << rigid.out;
  std::cout << listed.out << rigid.out;
}

// A floor tied by a rigid diaphragm: its corners have shape rows too, the floor node's motion
// there (top3 stands at (6, 4) from it: u_x - 4 theta, u_y + 6 theta); `check` counts them.
TEST_F(Cli, ModesOfATiedFloorGiveItsCornersShapesAndCheckCountsTheTiedDofs) {
  const std::string storey = POUND_SOURCE_DIR "/models/diaphragm_storey_3d.json";
  const Outcome written = pound({"modes", storey, "--shapes", path("tied.csv").string()});
  ASSERT_EQ(written.exit_code, 0) << written.err;
  std::map<std::string, std::vector<double>> rows;
  const std::vector<std::string> lines = read_lines(path("tied.csv"));
  for (std::size_t r = 1; r < lines.size(); ++r) {
    std::stringstream row(lines[r]);
    std::string label, cell;
    std::getline(row, label, ',');
    while (std::getline(row, cell, ',')) rows[label].push_back(std::stod(cell));
  }
  EXPECT_EQ(rows.size(), 15u);  // the floor's 3, and x, y, rz of each of the four tops
  double worst = 0.0;
  for (std::size_t m = 0; m < 3; ++m) {
    const double x = rows["floor.u_x"][m], y = rows["floor.u_y"][m], turn = rows["floor.u_rz"][m];
    worst = std::max({worst, std::abs(rows["top3.u_x"][m] - (x - 4.0 * turn)),
                      std::abs(rows["top3.u_y"][m] - (y + 6.0 * turn)),
                      std::abs(rows["top3.u_rz"][m] - turn)});
  }
  std::printf("  tied corner's shape against the floor's rigid motion: %.1e\n", worst);
  EXPECT_LT(worst, 1e-14);
  const json check = json::parse(pound({"check", storey, "--json"}).out);
  EXPECT_EQ(check["dofs"], 3);
  EXPECT_EQ(check["tied_dofs"], 12);
}

// Issue 16 item 7: `pound check` counts the DOFs along the directions the scene moves in.
TEST_F(Cli, CheckCountsTheDofsOfEachDirectionTheSceneHas) {
  const Outcome buildings = pound({"check", POUND_SOURCE_DIR "/models/adjacent_buildings.json"});
  EXPECT_TRUE(contains(buildings.out, ": 33 DOFs (23 x, 10 rotation), 10 links")) << buildings.out;
  const json bridge = json::parse(
      pound({"check", POUND_SOURCE_DIR "/models/three_span_bridge.json", "--json"}).out);
  EXPECT_EQ(bridge["dofs_x"].get<long>() + bridge["dofs_y"].get<long>() +
                bridge["dofs_rotation"].get<long>(),
            bridge["dofs"].get<long>());
  EXPECT_GT(bridge["dofs_y"].get<long>(), 0);
  const json girders =
      json::parse(pound({"check", POUND_SOURCE_DIR "/models/two_sdof_girders.json", "--json"}).out);
  EXPECT_EQ(girders["dofs_x"], 2);
  EXPECT_EQ(girders["dofs_y"], 0);
}

// ---- Issue 14: every input ends in a clear answer, and no output overwrites an input ----

TEST_F(Cli, DeviceOrFifoAsModelIsRefusedAtOnce) {
  const Outcome zero = pound({"check", "/dev/zero"});
  EXPECT_EQ(zero.exit_code, 2) << zero.err;
  EXPECT_TRUE(contains(zero.err, "/dev/zero: not a regular file (a character device)")) << zero.err;
  const std::string fifo = path("model.json").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const Outcome waiting = pound({"run", fifo, "--out", path("out").string()});
  EXPECT_EQ(waiting.exit_code, 2) << waiting.err;
  EXPECT_TRUE(contains(waiting.err, "not a regular file (a FIFO)")) << waiting.err;
  EXPECT_FALSE(fs::exists(path("out")));
}

TEST_F(Cli, MissingRecordNamesTheModelAndItsField) {
  const std::string model = write_model(
      "x.json", R"([{"op": "add", "path": "/excitations", "value": [{"record": "zzz"}]}])");
  const Outcome outcome = run_refused(model);
  EXPECT_TRUE(contains(
      outcome.err, model + ": /excitations/0/record: no such file: '" + path("zzz").string() + "'"))
      << outcome.err;
}

TEST_F(Cli, RunOutputsMayNotOverwriteTheModelOrItsRecords) {
  // A record named like the recorder's file, in the folder given as --out.
  fs::copy_file(fs::path(POUND_SOURCE_DIR) / "ground_motions" / "synthetic_firm_01.AT2",
                path("links.csv"));
  const std::string before = read_text(path("links.csv"));
  const std::string model =
      write_model("summary.json",
                  R"([{"op": "add", "path": "/excitations", "value": [{"record": "links.csv",
           "format": "at2"}]}, {"op": "remove", "path": "/analysis/duration"}])");
  const std::string model_text = read_text(model);
  const Outcome outcome = pound({"run", model, "--out", folder_.string()});
  EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
  EXPECT_TRUE(contains(outcome.err, "--out: the output")) << outcome.err;
  EXPECT_EQ(read_text(path("links.csv")), before);
  EXPECT_EQ(read_text(model), model_text);
  // The model alone in the folder: its summary would replace it.
  const std::string plain = write_model("summary.json", "[]");
  const Outcome own = pound({"run", plain, "--out", folder_.string()});
  EXPECT_EQ(own.exit_code, 2) << own.err;
  EXPECT_TRUE(contains(own.err, "would overwrite the input")) << own.err;
  EXPECT_TRUE(json::parse(read_text(plain)).contains("nodes"));
}

TEST_F(Cli, ModelNameThatCannotNameAFolderNeedsOut) {
  const std::string model = write_model("...json", "[]");
  const Outcome outcome = pound({"run", model});
  EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
  EXPECT_TRUE(contains(outcome.err, "--out: no output folder can be named after")) << outcome.err;
}

TEST_F(Cli, SpectrumAndExpandMayNotOverwriteTheirInput) {
  const fs::path record = path("r.AT2");
  fs::copy_file(fs::path(POUND_SOURCE_DIR) / "ground_motions" / "synthetic_firm_01.AT2", record);
  const std::string text = read_text(record);
  const Outcome spectrum = pound({"spectrum", record.string(), "--csv", record.string()});
  EXPECT_EQ(spectrum.exit_code, 2) << spectrum.err;
  EXPECT_TRUE(contains(spectrum.err, "--csv: the output")) << spectrum.err;
  EXPECT_EQ(read_text(record), text);
  const std::string model = write_model("m.json", "[]");
  const std::string model_text = read_text(model);
  const Outcome expand = pound({"expand", model, "--out", model});
  EXPECT_EQ(expand.exit_code, 2) << expand.err;
  EXPECT_TRUE(contains(expand.err, "--out: the output")) << expand.err;
  EXPECT_EQ(read_text(model), model_text);
}

TEST_F(Cli, NumericOptionsMustBeFiniteAndInRange) {
  for (const std::vector<std::string>& arguments :
       {std::vector<std::string>{"verify", "rod-impact", "--eta", "-1"},
        {"verify", "rod-impact", "--eta", "nan"},
        {"verify", "rod-impact", "--k-ratio", "inf"},
        {"spectrum", POUND_SOURCE_DIR "/ground_motions/synthetic_firm_01.AT2", "--dt", "nan"},
        {"spectrum", POUND_SOURCE_DIR "/ground_motions/synthetic_firm_01.AT2", "--column", "0"},
        {"run", kGirderModel, "--time-limit", "nan"},
        {"modes", kGirderModel, "--count", "0"}}) {
    const Outcome outcome = pound(arguments);
    EXPECT_EQ(outcome.exit_code, 1) << arguments[0] << " " << arguments[2] << "\n" << outcome.err;
    EXPECT_TRUE(contains(outcome.err, "--")) << outcome.err;
  }
  const Outcome nan = pound({"verify", "rod-impact", "--eta", "nan"});
  EXPECT_TRUE(contains(nan.err, "--eta must be a finite number")) << nan.err;
}

// Issue 16: a Hertz-damp contact at about 5 steps per impact passed with "no warnings" while
// its peak force was 5 % low. Hertz-type laws now get the elastic Hertz impact's closed-form
// duration (2.943 delta_max / v0) at an approach velocity of twice the record's peak ground
// velocity, and the same steps-per-contact warnings; what does not apply is null in --json.
TEST_F(Cli, CheckResolvesHertzTypeContactsAtAnEstimatedApproachVelocity) {
  json model =
      json::parse(read_text(fs::path(POUND_SOURCE_DIR) / "models" / "two_sdof_girders.json"));
  model["links"][0]["law"] = {{"type", "hertz_damp"}, {"stiffness", 1e10}, {"restitution", 0.65}};
  model["excitations"][0]["record"] =
      (fs::path(POUND_SOURCE_DIR) / "ground_motions" / "synthetic_firm_02.AT2").string();
  auto check = [&](double time_step) {
    model["analysis"]["time_step"] = time_step;
    const fs::path file = path("hertz.json");
    std::ofstream(file) << model.dump();
    const Outcome outcome = pound({"check", file.string(), "--json"});
    EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
    return json::parse(outcome.out);
  };
  const json fine = check(0.001);
  const json& link = fine["links"][0];
  const double velocity = link["approach_velocity"].get<double>();
  const double duration = link["contact_duration"].get<double>();
  // m_eff of the 4e5 and 2e5 kg girders, k_h = 1e10.
  const pound::links::HertzImpact closed =
      pound::links::hertz_impact(1e10, 4e5 * 2e5 / 6e5, velocity);
  std::cout << "approach velocity " << velocity << ", contact " << duration << " (closed form "
            << closed.duration << ")\n";
  EXPECT_GT(velocity, 0.3);  // twice the record's peak ground velocity (0.3 m/s)
  EXPECT_LT(velocity, 1.0);
  EXPECT_DOUBLE_EQ(duration, closed.duration);
  EXPECT_TRUE(fine["warnings"].empty()) << fine.dump();
  EXPECT_TRUE(link["stiffness"].is_null());
  EXPECT_TRUE(link["automatic_alpha0"].is_null());  // not an extended-penalty link

  const json coarse = check(duration / 5.0);
  std::string all;
  for (const json& w : coarse["warnings"]) all += w["warning"].get<std::string>() + "\n";
  EXPECT_TRUE(contains(all, "gives fewer than 20 steps per contact")) << all;
  EXPECT_TRUE(contains(all, "a Hertz-type contact at an approach velocity")) << all;
}

TEST_F(Cli, StepLongerThanTheRecordIsWarned) {
  const std::string model = write_model(
      "long_step.json", R"([{"op": "replace", "path": "/analysis/time_step", "value": 0.05}])");
  const Outcome outcome = pound({"check", model, "--json"});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_TRUE(contains(outcome.out, "more than a tenth of the duration")) << outcome.out;
}

TEST_F(Cli, TerminatedRunLeavesNoTemporaryAndNoSummary) {
  // Long enough to be stopped in the step loop; nothing recorded, so nothing is large.
  const std::string model =
      write_model("long.json", R"([{"op": "replace", "path": "/analysis/duration", "value": 1.0e5},
                       {"op": "add", "path": "/recorders", "value": []}])");
  const fs::path out = path("out");
  fs::create_directories(out);
  std::ofstream(out / "links.csv.tmp.999999999") << "left by a killed run";
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::execl(POUND_BINARY, POUND_BINARY, "run", model.c_str(), "--out", out.c_str(), "--quiet",
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::sleep(2);
  ASSERT_EQ(::kill(child, SIGTERM), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 143);
  EXPECT_FALSE(fs::exists(out / "summary.json"));
  std::set<std::string> left;
  for (const fs::directory_entry& entry : fs::directory_iterator(out))
    left.insert(entry.path().filename().string());
  EXPECT_EQ(left, std::set<std::string>{"links.csv.tmp.999999999"});  // only the stale one
  // The next run into the folder removes what a run killed with SIGKILL left.
  const Outcome next = pound({"run", write_model("short.json", "[]"), "--out", out.string()});
  ASSERT_EQ(next.exit_code, 0) << next.err;
  EXPECT_FALSE(fs::exists(out / "links.csv.tmp.999999999"));
  EXPECT_TRUE(fs::exists(out / "summary.json"));
}

}  // namespace
