#pragma once
// The model file format (docs/model_format.md) as field lists (io/schema.hpp), one per struct of
// builder/spec.hpp: what the reader reads, the writer writes and `pound docs` shows.
#include <vector>

#include "builder/spec.hpp"
#include "io/generated_docs.hpp"
#include "io/schema.hpp"

namespace pound::io {

const Fields<builder::ModelSpec>& model_fields();

// The fields of a record entry that say how to read and scale it (format, column, time_step,
// time_column, units, scale), shared by model excitations and batch sets.
const Fields<builder::ExcitationSpec>& record_fields();

// The field tables of docs/model_format.md, one section per struct.
std::vector<GeneratedSection> model_format_sections();
// Every row of those tables (for the vocabulary of the fuzz dictionary).
std::vector<FieldDoc> model_field_docs();

// A link law and an integrator are read and written whole, by the functions below
// (model_reader.cpp, model_writer.cpp), which check them against the law registry and the
// integrator catalog.

// Where a contact law is given: a stiffness_ratio refers to the elements next to the contact,
// which only a rod_pair generator knows.
// Where a law object is: a link's, a rod_pair generator's (which may scale the stiffness by its
// elements), a girder_bridge pier hinge's (the generator sets the elastic stiffness and the
// yield moment: kGeneratedHingeParameters must be left out) or an adjacent_buildings storey's
// (its stiffness is the storey's).
enum class LawPlace { link, rod_pair, pier_hinge, storey };
inline const std::vector<std::string> kGeneratedHingeParameters{"stiffness", "yield_force"};
inline const std::vector<std::string> kGeneratedStoreyParameters{"stiffness"};

builder::LawSpec read_law_in(const JsonValue& value, LawPlace place);
OrderedJson law_json(const builder::LawSpec& law);
builder::IntegratorSpec read_integrator(const JsonValue& value);
OrderedJson integrator_json(const builder::IntegratorSpec& integrator);

}  // namespace pound::io
