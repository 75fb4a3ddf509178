// Writing a model spec back as a model file: parse_model(model_to_json(spec)) gives back the
// spec, and `pound expand` writes a model that runs exactly like the one with generators.
#include "io/model_writer.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "builder/generators.hpp"
#include "io/model_reader.hpp"
#include "support/process.hpp"
#include "support/sanitizers.hpp"

namespace pound::io {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A model that uses every field the reader reads, each at a value other than its default, written
// the way model_to_json writes it (defaults it always writes included, choices at their defaults
// left out), so that parse + write must give back exactly this JSON. Not a model that builds
// (rod pairs need 1-D), only one that reads.
constexpr const char* kRichModel = R"({
  "title": "every field",
  "dimension": 2,
  "nodes": [{"id": "a", "x": 0.0, "y": 0.0}, {"id": "b", "x": 1.0, "y": 0.5},
            {"id": "c", "x": 1.0, "y": 0.5}, {"id": "d", "x": 2.0, "y": -0.25}],
  "materials": [{"id": "steel", "youngs_modulus": 2.0e11, "density": 7850.0},
                {"id": "light", "youngs_modulus": 1.0e6, "density": 0.0}],
  "elements": [
    {"id": "e0", "type": "truss", "nodes": ["a", "b"], "material": "light", "area": 0.01},
    {"id": "e1", "type": "beam", "nodes": ["b", "d"], "material": "steel", "area": 0.2,
     "inertia": 0.003, "extra_mass": 1200.0, "mass": "consistent"},
    {"id": "e2", "type": "beam", "nodes": ["c", "d"], "material": "steel", "area": 0.1,
     "inertia": 0.001, "damping": {"mass_coefficient": 0.3, "stiffness_coefficient": 0.004}}
  ],
  "masses": [{"node": "b", "mass": 2.5, "rotary_inertia": 0.75},
             {"node": "c", "mass": 3.0, "mass_damping": 0.2}],
  "supports": [{"node": "a", "fix": ["x", "y", "rz"]}, {"node": "d", "fix": ["y"]}],
  "initial_velocities": [{"node": "b", "x": 0.1, "y": -0.2}],
  "loads": [{"node": "c", "x": 5.0, "y": -98.1}],
  "links": [
    {"id": "pound", "nodes": ["b", "c"], "gap": 0.02, "axis": [0.6, 0.8],
     "law": {"type": "kelvin_voigt", "stiffness": 1.0e8, "restitution": 0.7, "mass": 12.5,
             "tension": "allow", "calibration": "published"},
     "friction": {"coefficient": 0.4, "stick_stiffness": 1.0e7, "stick_damping": 100.0,
                  "stick_mass": 0.5}},
    {"id": "hinge", "nodes": ["b", "c"], "gap": 0.0, "dof": "rotation",
     "law": {"type": "bilinear_spring", "stiffness": 5.0e6, "yield_force": 1.0e4,
             "hardening_ratio": 0.05}},
    {"id": "impact", "nodes": ["c", "d"], "gap": 0.125,
     "law": {"type": "bilinear_impact", "k1": 3.0e9, "k2": 1.0e9, "yield_penetration": 0.001},
     "friction": {"coefficient": 0.3}},
    {"id": "penalty", "nodes": ["a", "d"], "gap": 0.0,
     "law": {"type": "extended_penalty", "alpha0": 1.0e9, "alpha1": 10.0, "alpha2": 2.0,
             "tolerance": 0.002, "eta": 0.5}},
    {"id": "cable", "nodes": ["a", "c"], "gap": 0.0,
     "law": {"type": "restrainer", "stiffness": 2.0e7, "slack": 0.08, "yield_force": 1.5e6,
             "hardening_ratio": 0.02}}
  ],
  "generators": [
    {"type": "rod_pair", "id": "rods",
     "left": {"youngs_modulus": 100.0, "density": 0.1, "area": 1.0, "length": 10.0,
              "elements": 10, "initial_velocity": 0.1, "far_end": "free"},
     "right": {"youngs_modulus": 200.0, "density": 0.2, "area": 2.0, "length": 5.0,
               "elements": 4, "initial_velocity": 0.0, "far_end": "fixed"},
     "gap": 0.5, "law": {"type": "gap_spring", "stiffness_ratio": 1.5}},
    {"type": "adjacent_buildings", "id": "pair",
     "left": {"damping_ratio": 0.05,
              "storeys": [{"height": 3.5, "mass": 3.0e5, "stiffness": 4.0e8},
                          {"height": 3.0, "mass": 2.5e5, "stiffness": 3.0e8}]},
     "right": {"damping_ratio": 0.0,
               "storeys": [{"height": 3.0, "mass": 2.0e5, "stiffness": 2.0e8}]},
     "separation": 0.03, "law": {"type": "hertz", "stiffness": 2.75e9}},
    {"type": "rod_pair", "id": "more",
     "left": {"youngs_modulus": 1.0, "density": 1.0, "area": 1.0, "length": 1.0, "elements": 1,
              "initial_velocity": -0.3, "far_end": "fixed"},
     "right": {"youngs_modulus": 1.0, "density": 1.0, "area": 1.0, "length": 1.0, "elements": 2,
               "initial_velocity": 0.0, "far_end": "free"},
     "gap": 0.0,
     "law": {"type": "jankowski", "stiffness": 2.75e9, "restitution": 0.65,
             "calibration": "published"}},
    {"type": "girder_bridge", "id": "bridge", "spans": [30.0, 40.0, 30.0],
     "girder": {"youngs_modulus": 3.0e10, "area": 4.0, "inertia": 2.5, "density": 0.0,
                "extra_mass": 25000.0, "elements": 3},
     "pier": {"youngs_modulus": 3.0e10, "area": 3.0, "inertia": 0.8, "density": 2500.0,
              "extra_mass": 0.0, "elements": 2},
     "pier_height": 8.0, "pier_yield_displacement": 0.04,
     "bearing": {"type": "bilinear_spring", "stiffness": 2.0e7, "yield_force": 3.0e5},
     "bearing_vertical_stiffness": 1.0e10, "expansion_joints": [2],
     "joint": {"gap": 0.05, "seat_width": 0.6,
               "law": {"type": "hertz_damp", "stiffness": 1.0e10, "restitution": 0.6},
               "restrainer": {"type": "hook", "stiffness": 3.0e7, "slack": 0.03}},
     "abutment": {"gap": 0.04, "seat_width": 0.0,
                  "law": {"type": "gap_spring", "stiffness": 1.0e9}},
     "backfill": {"type": "backfill", "initial_stiffness": 5.0e8, "ultimate_force": 1.05e7,
                  "ultimate_deformation": 0.125},
     "backwall_mass": 5.0e4}
  ],
  "monitors": {
    "drifts": [{"id": "storey", "kind": "storey", "group": "frame", "bottom": "a", "top": "b",
                "height": 3.0, "yield_displacement": 0.03},
               {"id": "column", "kind": "pier", "bottom": "c", "top": "d", "height": 8.0}],
    "joints": [{"id": "seat", "link": "impact", "girder": "c", "seat": "d", "seat_width": 0.4}]
  },
  "units": {"length": "mm", "time": "ms"},
  "damping": {"type": "rayleigh", "ratio": 0.05, "periods": [0.2, 1.5]},
  "excitations": [
    {"record": "records/a.AT2", "format": "auto", "units": "g", "scale": {"factor": 1.25}},
    {"record": "b.txt", "format": "columns", "column": 3, "time_step": 0.005,
     "units": "cm/s2", "direction": [0.0, 1.0], "scale": {"pga": 0.4}},
    {"record": "c.txt", "format": "columns", "time_column": true, "column": 2, "units": "m/s2",
     "direction": [-1.0, 0.0], "scale": {"sa": 0.8, "period": 1.2, "damping": 0.02}},
    {"record": "d.at2", "format": "at2", "units": "model"}
  ],
  "analysis": {"integrator": {"type": "newmark", "beta": 0.3, "gamma": 0.6},
               "time_step": 6.32456e-4, "duration": 1.5,
               "convergence": {"relative_tolerance": 1e-8, "absolute_tolerance": 1e-12,
                               "max_iterations": 30},
               "max_step_cuts": 5, "max_steps": 100000},
  "recorders": [{"type": "link", "links": ["pound", "rods.contact"], "file": "pounding.csv"},
                {"type": "link", "file": "link_1.csv"},
                {"type": "node", "nodes": ["b", "c"], "file": "nodes.csv"}]
})";

builder::ModelSpec parse(const std::string& text) { return parse_model(text, "x.json"); }

// The JSON `text` with a JSON patch (RFC 6902) applied.
std::string patched(const std::string& text, const std::string& json_patch) {
  return json::parse(text).patch(json::parse(json_patch)).dump();
}

// Writes `spec`, reads it back and writes it again: the two texts must be the same, so nothing
// the writer wrote was read differently. Returns the spec read back.
builder::ModelSpec round_trip(const builder::ModelSpec& spec) {
  const std::string text = model_to_json(spec);
  builder::ModelSpec again = parse(text);
  EXPECT_EQ(model_to_json(again), text);
  return again;
}

// `model` read and written must give back `model` itself (objects compare regardless of key
// order, 1 equals 1.0); the difference is printed as a JSON patch.
void expect_written_as_given(const std::string& model) {
  const json given = json::parse(model);
  const json written = json::parse(model_to_json(round_trip(parse(model))));
  EXPECT_EQ(written, given) << "difference (given -> written): "
                            << json::diff(given, written).dump(2);
}

TEST(ModelWriter, WritesBackEveryFieldOfARichModel) { expect_written_as_given(kRichModel); }

// Every field of a 3-D scene, as the writer writes it: z components, the six fixed directions,
// a 3-D beam's section, orientation and offsets, rotary inertia about three axes, a rotational
// link's axis, gravity along -z.
constexpr const char* kRichSpaceModel = R"({
  "title": "every 3-D field",
  "dimension": 3,
  "nodes": [
    {"id": "a", "x": 0.0, "y": 0.0, "z": 0.0},
    {"id": "b", "x": 1.0, "y": 0.5, "z": 2.0},
    {"id": "c", "x": 1.0, "y": 0.5, "z": 2.5}
  ],
  "materials": [
    {
      "id": "steel",
      "youngs_modulus": 200000000000.0,
      "density": 7850.0,
      "shear_modulus": 80000000000.0
    }
  ],
  "elements": [
    {
      "id": "col",
      "type": "beam",
      "nodes": ["a", "b"],
      "material": "steel",
      "area": 0.02,
      "inertia_y": 0.0001,
      "inertia_z": 0.0002,
      "torsion": 5e-05,
      "orientation": [1.0, 0.0, 0.0],
      "rigid_offsets": [[0.0, 0.0, 0.25], [0.0, 0.0, -0.25]],
      "mass": "consistent"
    },
    {"id": "bar", "type": "truss", "nodes": ["b", "c"], "material": "steel", "area": 0.001}
  ],
  "masses": [{"node": "b", "mass": 10.0, "rotary_inertia": [1.0, 2.0, 3.0]}],
  "supports": [{"node": "a", "fix": ["x", "y", "z", "rx", "ry", "rz"]}],
  "initial_velocities": [{"node": "c", "x": 0.1, "y": 0.0, "z": -0.2}],
  "loads": [{"node": "b", "x": 1.0, "y": 2.0, "z": -3.0}],
  "links": [
    {
      "id": "hinge",
      "nodes": ["a", "b"],
      "gap": 0.0,
      "axis": [0.0, 1.0, 0.0],
      "dof": "rotation",
      "law": {"type": "elastic_spring", "stiffness": 1000000.0}
    },
    {
      "id": "hit",
      "nodes": ["b", "c"],
      "gap": 0.01,
      "axis": [0.0, 0.0, 1.0],
      "law": {"type": "gap_spring", "stiffness": 1000000000.0}
    }
  ],
  "gravity": {"direction": [0.0, 0.0, -1.0], "p_delta": "chord"},
  "excitations": [
    {
      "record": "ns.txt",
      "format": "columns",
      "time_step": 0.01,
      "units": "g",
      "pair": {"record": "ew.txt", "column": 2, "angle": 15.0}
    }
  ],
  "analysis": {
    "integrator": {"type": "newmark", "beta": 0.25, "gamma": 0.5},
    "time_step": 0.001,
    "duration": 1.0,
    "convergence": {"relative_tolerance": 1e-10, "absolute_tolerance": 0.0, "max_iterations": 25},
    "max_step_cuts": 10
  }
})";

TEST(ModelWriter, WritesBackEveryFieldOfASpaceModel) {
  expect_written_as_given(kRichSpaceModel);
  const builder::ModelSpec spec = round_trip(parse(kRichSpaceModel));
  EXPECT_EQ(spec.nodes.at(1).z, 2.0);
  EXPECT_EQ(spec.elements.at(0).offsets[1][2], -0.25);
  EXPECT_EQ(spec.masses.at(0).rotary_inertia, (std::array<double, 3>{1.0, 2.0, 3.0}));
  EXPECT_EQ(spec.supports.at(0).fixed, (std::array<bool, 6>{true, true, true, true, true, true}));
  EXPECT_EQ(spec.gravity->direction, (std::vector<double>{0.0, 0.0, -1.0}));
  EXPECT_EQ(spec.excitations.at(0).pair->record, "ew.txt");
  EXPECT_EQ(spec.excitations.at(0).pair->angle, 15.0);
}

TEST(ModelWriter, ReadsBackTheSameValues) {
  const builder::ModelSpec spec = round_trip(parse(kRichModel));
  EXPECT_EQ(spec.title, "every field");
  EXPECT_EQ(spec.dimension, 2);
  EXPECT_EQ(spec.nodes.at(3).y, -0.25);
  EXPECT_EQ(spec.elements.at(1).type, builder::ElementKind::beam);
  EXPECT_EQ(spec.elements.at(1).inertia, 0.003);
  EXPECT_EQ(spec.elements.at(1).extra_mass, 1200.0);
  EXPECT_TRUE(spec.elements.at(1).consistent_mass);
  EXPECT_FALSE(spec.elements.at(2).consistent_mass);
  EXPECT_EQ(spec.masses.at(0).rotary_inertia[2], 0.75);  // about z
  EXPECT_TRUE(spec.supports.at(0).fixed[0] && spec.supports.at(0).fixed[1] &&
              spec.supports.at(0).fixed[2]);
  EXPECT_TRUE(!spec.supports.at(1).fixed[0] && spec.supports.at(1).fixed[1]);
  EXPECT_EQ(spec.loads.at(0).y, -98.1);
  EXPECT_EQ(spec.initial_velocities.at(0).y, -0.2);

  const builder::LinkSpec& pound = spec.links.at(0);
  EXPECT_EQ(pound.axis, (std::vector<double>{0.6, 0.8}));
  EXPECT_EQ(pound.law.number("restitution"), 0.7);
  EXPECT_EQ(pound.law.choice("tension", ""), "allow");
  EXPECT_EQ(pound.law.choice("calibration", ""), "published");
  ASSERT_TRUE(pound.friction);
  EXPECT_EQ(pound.friction->stick_mass, 0.5);
  EXPECT_TRUE(spec.links.at(1).rotational);
  EXPECT_FALSE(spec.links.at(1).axis);
  EXPECT_FALSE(spec.links.at(2).friction->stick_stiffness);
  EXPECT_EQ(spec.links.at(3).law.number("eta"), 0.5);

  EXPECT_EQ(spec.elements.at(2).rayleigh, (std::array<double, 2>{0.3, 0.004}));
  EXPECT_FALSE(spec.elements.at(1).rayleigh);
  EXPECT_EQ(spec.masses.at(1).mass_damping, 0.2);
  EXPECT_FALSE(spec.masses.at(0).mass_damping);

  ASSERT_EQ(spec.rod_pairs.size(), 2u);
  EXPECT_EQ(spec.rod_pair_generator_index, (std::vector<int>{0, 2}));
  EXPECT_EQ(spec.rod_pairs[0].law.number("stiffness_ratio"), 1.5);
  EXPECT_TRUE(spec.rod_pairs[0].right.far_end_fixed);
  EXPECT_EQ(spec.rod_pairs[1].left.initial_velocity, -0.3);
  EXPECT_EQ(spec.rod_pairs[1].right.elements, 2);
  ASSERT_EQ(spec.building_pairs.size(), 1u);
  EXPECT_EQ(spec.building_pairs[0].generator_index, 1);
  EXPECT_EQ(spec.building_pairs[0].left.storeys.at(1).stiffness, 3.0e8);
  EXPECT_EQ(spec.building_pairs[0].separation, 0.03);
  ASSERT_EQ(spec.bridges.size(), 1u);
  const builder::GirderBridgeSpec& bridge = spec.bridges[0];
  EXPECT_EQ(bridge.generator_index, 3);
  EXPECT_EQ(bridge.spans, (std::vector<double>{30.0, 40.0, 30.0}));
  EXPECT_EQ(bridge.girder.elements, 3);
  EXPECT_EQ(bridge.pier.density, 2500.0);
  EXPECT_EQ(bridge.pier_yield_drift, 0.04);
  EXPECT_EQ(bridge.expansion_joints, (std::vector<int>{2}));
  ASSERT_TRUE(bridge.joint.restrainer);
  EXPECT_EQ(bridge.joint.restrainer->number("slack"), 0.03);
  ASSERT_TRUE(bridge.backfill);
  EXPECT_EQ(bridge.backwall_mass, 5.0e4);
  ASSERT_EQ(spec.drift_monitors.size(), 2u);
  EXPECT_EQ(spec.drift_monitors[0].group, "frame");
  EXPECT_EQ(spec.drift_monitors[1].kind, builder::DriftKind::pier);
  EXPECT_FALSE(spec.drift_monitors[1].yield_drift);
  ASSERT_EQ(spec.joint_monitors.size(), 1u);
  EXPECT_EQ(spec.joint_monitors[0].seat_width, 0.4);

  EXPECT_EQ(spec.units.length, "mm");
  EXPECT_EQ(spec.units.time, "ms");
  ASSERT_TRUE(spec.damping && spec.damping->periods);
  EXPECT_EQ((*spec.damping->periods)[1], 1.5);

  ASSERT_EQ(spec.excitations.size(), 4u);
  EXPECT_EQ(spec.excitations[0].scale_factor, 1.25);
  EXPECT_EQ(spec.excitations[1].column, 3);
  EXPECT_EQ(spec.excitations[1].time_step, 0.005);
  EXPECT_EQ(spec.excitations[1].direction, (std::vector<double>{0.0, 1.0}));
  EXPECT_EQ(spec.excitations[1].target_pga, 0.4);
  EXPECT_TRUE(spec.excitations[2].time_column);
  EXPECT_EQ(spec.excitations[2].target_sa, 0.8);
  EXPECT_EQ(spec.excitations[2].sa_period, 1.2);
  EXPECT_EQ(spec.excitations[2].sa_damping, 0.02);
  EXPECT_EQ(spec.excitations[3].units, "model");

  EXPECT_EQ(spec.analysis.integrator.parameter("beta"), 0.3);
  EXPECT_EQ(spec.analysis.integrator.parameter("gamma"), 0.6);
  EXPECT_EQ(spec.analysis.time_step, 6.32456e-4);
  EXPECT_EQ(spec.analysis.absolute_tolerance, 1e-12);
  EXPECT_EQ(spec.analysis.max_iterations, 30);
  EXPECT_EQ(spec.analysis.max_step_cuts, 5);
  EXPECT_EQ(spec.analysis.max_steps, 100000);

  EXPECT_TRUE(spec.recorders_given);
  ASSERT_EQ(spec.recorders.size(), 3u);
  EXPECT_EQ(spec.recorders[0].ids, (std::vector<std::string>{"pound", "rods.contact"}));
  EXPECT_TRUE(spec.recorders[1].ids.empty());
  EXPECT_EQ(spec.recorders[2].file, "nodes.csv");
}

TEST(ModelWriter, WritesTheOtherFormsOfDampingAndDuration) {
  expect_written_as_given(patched(kRichModel, R"([{"op": "replace", "path": "/damping",
                       "value": {"type": "rayleigh", "ratio": 0.02, "modes": [1, 3]}}])"));
  expect_written_as_given(patched(kRichModel, R"([{"op": "replace", "path": "/damping",
                       "value": {"type": "rayleigh", "mass_coefficient": 0.1,
                                 "stiffness_coefficient": 0.002}}])"));
  // Without a duration the longest record's is taken: it stays left out.
  const std::string open_ended =
      patched(kRichModel, R"([{"op": "remove", "path": "/analysis/duration"}])");
  expect_written_as_given(open_ended);
  EXPECT_EQ(round_trip(parse(open_ended)).analysis.duration, 0.0);
}

TEST(ModelWriter, KeepsNoRecordersApartFromDefaultRecorders) {
  const builder::ModelSpec none =
      round_trip(parse(patched(kRichModel, R"([{"op": "replace", "path": "/recorders",
                                                "value": []}])")));
  EXPECT_TRUE(none.recorders_given);
  EXPECT_TRUE(none.recorders.empty());
  const builder::ModelSpec absent =
      round_trip(parse(patched(kRichModel, R"([{"op": "remove", "path": "/recorders"}])")));
  EXPECT_FALSE(absent.recorders_given);
  EXPECT_FALSE(json::parse(model_to_json(absent)).contains("recorders"));
}

TEST(ModelWriter, WritesAnIntegratorPresetAsItsParameters) {
  const builder::ModelSpec spec =
      round_trip(parse(patched(kRichModel, R"([{"op": "replace", "path": "/analysis/integrator",
                       "value": "newmark_linear_acceleration"}])")));
  EXPECT_EQ(spec.analysis.integrator.parameter("beta"), 1.0 / 6.0);  // bit for bit
  EXPECT_EQ(spec.analysis.integrator.parameter("gamma"), 0.5);
}

TEST(ModelWriter, WritesAdaptiveStepping) {
  expect_written_as_given(
      patched(kRichModel, R"([{"op": "add", "path": "/analysis/adaptive", "value": true}])"));
  expect_written_as_given(patched(kRichModel, R"([{"op": "add", "path": "/analysis/adaptive",
                       "value": {"tolerance": 1e-4, "max_time_step": 0.01}}])"));
  const builder::ModelSpec off = round_trip(parse(
      patched(kRichModel, R"([{"op": "add", "path": "/analysis/adaptive", "value": false}])")));
  EXPECT_FALSE(off.analysis.adaptive);
}

TEST(ModelWriter, NumbersReadBackBitForBit) {
  builder::ModelSpec spec = parse(kRichModel);
  const std::vector<double> awkward = {0.1 + 0.2, 1.0 / 3.0, -2.0 / 7.0,
                                       std::numeric_limits<double>::min(), 6.02214076e23};
  for (std::size_t k = 0; k < awkward.size(); ++k) spec.nodes.at(k % 4).x = awkward[k] * 1.000001;
  spec.analysis.time_step = std::nextafter(1e-3, 1.0);
  spec.materials.at(0).youngs_modulus = std::numeric_limits<double>::max();
  const builder::ModelSpec again = round_trip(spec);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(again.nodes[k].x, spec.nodes[k].x) << k;
  EXPECT_EQ(again.analysis.time_step, spec.analysis.time_step);
  EXPECT_EQ(again.materials[0].youngs_modulus, spec.materials[0].youngs_modulus);
}

TEST(ModelWriter, OneDimensionalModelsGetNoYComponents) {
  const builder::ModelSpec spec =
      read_model_file(POUND_SOURCE_DIR "/models/girder_abutment_sdof.json");
  const std::string text = model_to_json(spec);
  EXPECT_EQ(text.find("\"y\""), std::string::npos) << text;
  round_trip(spec);
}

// Every bundled model, as it is and expanded, reads back as written.
TEST(ModelWriter, BundledModelsRoundTrip) {
  int models = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(POUND_SOURCE_DIR "/models")) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    ++models;
    const builder::ModelSpec spec = read_model_file(entry.path().string());
    const builder::ModelSpec again = round_trip(spec);
    EXPECT_EQ(again.nodes.size(), spec.nodes.size());
    EXPECT_EQ(again.links.size(), spec.links.size());
    EXPECT_EQ(again.rod_pairs.size(), spec.rod_pairs.size());
    EXPECT_EQ(again.analysis.time_step, spec.analysis.time_step);
    EXPECT_EQ(again.analysis.duration, spec.analysis.duration);
    const builder::ModelSpec expanded = round_trip(builder::expand(spec));
    EXPECT_TRUE(expanded.rod_pairs.empty());
  }
  EXPECT_GE(models, 4);
}

// ---- `pound expand` as a user runs it ----

using pound::testing::read_text;

class ModelWriterCli : public pound::testing::PoundProcess {
 protected:
  // Runs `pound <arguments>`; returns the exit code, stdout in `out_`, stderr in `err_`.
  int pound(const std::vector<std::string>& arguments) {
    const pound::testing::Outcome outcome = PoundProcess::pound(arguments);
    out_ = outcome.out;
    err_ = outcome.err;
    return outcome.exit_code;
  }

  // `pound run` on a model: its summary.json and the folder its histories are in.
  json run(const std::string& model, const std::string& out_name) {
    EXPECT_EQ(pound({"run", model, "--quiet", "--out", path(out_name).string()}), 0) << err_;
    return json::parse(read_text(path(out_name) / "summary.json"));
  }

  std::string out_, err_;
};

TEST_F(ModelWriterCli, ExpandedRodImpactRunsLikeTheOriginal) {
  const std::string original = POUND_SOURCE_DIR "/models/rod_impact.json";
  const fs::path expanded = path("expanded.json");
  ASSERT_EQ(pound({"expand", original, "--out", expanded.string()}), 0) << err_;
  EXPECT_TRUE(out_.empty()) << out_;
  const json model = json::parse(read_text(expanded));
  EXPECT_FALSE(model.contains("generators"));
  EXPECT_EQ(model["nodes"].size(), 202u);
  EXPECT_EQ(model["links"][0]["id"], "rods.contact");

  const json before = run(original, "before");
  const json after = run(expanded.string(), "after");
  EXPECT_EQ(after["status"], "completed");
  EXPECT_EQ(after["steps"], before["steps"]);
  EXPECT_EQ(after["dofs"], before["dofs"]);
  EXPECT_EQ(after["links"][0]["impacts"], before["links"][0]["impacts"]);
  EXPECT_EQ(after["links"][0]["peak_force"].get<double>(),
            before["links"][0]["peak_force"].get<double>());
  EXPECT_EQ(read_text(path("after") / "link_force.csv"),
            read_text(path("before") / "link_force.csv"));

  // Standard output gets the same text.
  ASSERT_EQ(pound({"expand", original}), 0) << err_;
  EXPECT_EQ(out_, read_text(expanded));
}

// Every bundled model (frames, bridges, buildings from their generators) expanded gives the same
// histories and summary, but for what names the file or cannot repeat (the run time; the
// comparison with the exact solution, which needs a rod_pair; the records' paths, written
// relative to the new file, whose contents (SHA-1) must be the same).
TEST_F(ModelWriterCli, EveryExpandedBundledModelRunsLikeTheOriginal) {
  for (const fs::directory_entry& entry : fs::directory_iterator(POUND_SOURCE_DIR "/models")) {
    if (entry.path().extension() != ".json") continue;
    const std::string name = entry.path().stem().string();
    SCOPED_TRACE(name);
    // In another folder than the original: its records must be found from there.
    const fs::path expanded = path(name + ".json");
    ASSERT_EQ(pound({"expand", entry.path().string(), "--out", expanded.string()}), 0) << err_;
    if (pound::testing::kUnderAddressSanitizer) {
      // Cli.EveryBundledModelRuns runs every model under the sanitizers; the runs' equality is
      // the release build's to check (here they would double the sanitizer tests' longest one).
      EXPECT_EQ(pound({"check", expanded.string()}), 0) << err_;
      continue;
    }
    json before = run(entry.path().string(), name + ".before");
    json after = run(expanded.string(), name + ".after");
    for (json* summary : {&before, &after}) {
      for (const char* key : {"model", "run_time_s", "verification"}) summary->erase(key);
      if (summary->contains("excitations"))
        for (json& excitation : (*summary)["excitations"]) {
          excitation.erase("record");  // paths differ; the SHA-1s must not
          if (excitation.contains("pair")) excitation["pair"].erase("record");
        }
    }
    EXPECT_EQ(after, before) << json::diff(before, after).dump(2);
    for (const fs::directory_entry& csv : fs::directory_iterator(path(name + ".before"))) {
      if (csv.path().extension() != ".csv") continue;
      EXPECT_EQ(read_text(path(name + ".after") / csv.path().filename()), read_text(csv.path()))
          << csv.path().filename();
    }
  }
}

// Records are found from the expanded model's folder, so a seismic model runs the same there.
TEST_F(ModelWriterCli, ExpandedModelFindsItsRecordsFromAnotherFolder) {
  fs::create_directories(path("in"));
  std::ofstream(path("in") / "motion.txt") << "0.0\n0.1\n-0.2\n0.15\n0.0\n-0.05\n";
  json model = json::parse(read_text(POUND_SOURCE_DIR "/models/girder_abutment_sdof.json"));
  model["excitations"] = {{{"record", "motion.txt"}, {"format", "columns"}, {"time_step", 0.01}}};
  std::ofstream(path("in") / "model.json") << model.dump(2);

  const fs::path expanded = path("elsewhere") / "expanded.json";
  fs::create_directories(expanded.parent_path());
  ASSERT_EQ(pound({"expand", (path("in") / "model.json").string(), "--out", expanded.string()}), 0)
      << err_;
  EXPECT_EQ(json::parse(read_text(expanded))["excitations"][0]["record"], "../in/motion.txt");
  const json before = run((path("in") / "model.json").string(), "before");
  const json after = run(expanded.string(), "after");
  EXPECT_EQ(after["steps"], before["steps"]);
  EXPECT_EQ(read_text(path("after") / "joint.csv"), read_text(path("before") / "joint.csv"));
}

TEST_F(ModelWriterCli, BadModelIsRefusedAndNothingIsWritten) {
  const fs::path model = path("bad.json");
  std::ofstream(model) << R"({"nodes": [{"id": "a", "x": 0}], "analysis": {"time_step": -1}})";
  const fs::path expanded = path("expanded.json");
  EXPECT_EQ(pound({"expand", model.string(), "--out", expanded.string()}), 2);
  EXPECT_NE(err_.find("time_step"), std::string::npos) << err_;
  EXPECT_FALSE(fs::exists(expanded));
}

TEST_F(ModelWriterCli, HelpExplainsTheCommand) {
  EXPECT_EQ(pound({"expand", "--help"}), 0);
  EXPECT_NE(out_.find("generator"), std::string::npos) << out_;
  EXPECT_NE(out_.find("--out"), std::string::npos) << out_;
  EXPECT_EQ(pound({"expand"}), 1);
}

}  // namespace
}  // namespace pound::io
