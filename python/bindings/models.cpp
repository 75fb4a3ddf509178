#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <tuple>

#include "app/model_loading.hpp"
#include "app/model_queries.hpp"
#include "app/pushover.hpp"
#include "bindings/bindings.hpp"
#include "builder/generators.hpp"
#include "io/model_reader.hpp"
#include "io/model_writer.hpp"

namespace py = pybind11;

namespace pound::python {
namespace {

// The model of a pound.Model: its JSON text when it came from a dict, else the file at `path`.
app::LoadedModel load(const std::optional<std::string>& text, const std::string& path) {
  return text ? app::load_model_text(*text, path) : app::load_model(path);
}

void validate(const std::optional<std::string>& text, const std::string& path) {
  const py::gil_scoped_release unlocked;
  (void)load(text, path);
}

std::string expand(const std::optional<std::string>& text, const std::string& path) {
  const py::gil_scoped_release unlocked;
  return io::model_to_json(
      builder::expand(text ? io::parse_model(*text, path) : io::read_model_file(path)));
}

std::string check(const std::optional<std::string>& text, const std::string& path) {
  const py::gil_scoped_release unlocked;
  return app::check_findings(load(text, path), path).document.dump();
}

// The modes' document, their shapes (a row per free or tied DOF, a column per mode) and the DOFs'
// labels.
std::tuple<std::string, py::array_t<double>, std::vector<std::string>> modes(
    const std::optional<std::string>& text, const std::string& path, int count) {
  if (count < 1) throw std::invalid_argument("count must be 1 or more");
  app::ModalFindings findings;
  {
    const py::gil_scoped_release unlocked;
    findings = app::modal_findings(load(text, path), path, count);
  }
  const Table& shapes = findings.shapes;
  const std::size_t rows = shapes.text_columns.empty() ? 0 : shapes.text_columns[0].values.size();
  py::array_t<double> array({rows, shapes.values.size()});
  auto view = array.mutable_unchecked<2>();
  for (std::size_t mode = 0; mode < shapes.values.size(); ++mode)
    for (std::size_t row = 0; row < rows; ++row)
      view(static_cast<py::ssize_t>(row), static_cast<py::ssize_t>(mode)) =
          shapes.values[mode][row];
  return {findings.document.dump(), array,
          shapes.text_columns.empty() ? std::vector<std::string>() : shapes.text_columns[0].values};
}

// pound.Model.pushover: the curve's columns and their arrays, pushover.json's text, the summary's
// lines and why it stopped short (empty when it reached the target).
std::tuple<std::vector<std::string>, std::vector<py::array_t<double>>, std::string, std::string,
           std::string>
pushover(const std::optional<std::string>& text, const std::string& path, const std::string& node,
         double target, const std::string& direction, const std::string& pattern, int increments,
         const std::optional<std::string>& out) {
  app::PushoverRequest request{node, direction, pattern, target, increments, ""};
  app::PushoverFindings push;
  {
    const InterruptGuard guard;
    const py::gil_scoped_release unlocked;
    if (out) app::check_pushover_outputs(*out, path, "out");
    push = app::pushover_findings(load(text, path), path, request);
    if (out) app::write_pushover_outputs(*out, push);
  }
  std::vector<py::array_t<double>> arrays;
  for (const std::vector<double>& column : push.curve.values)
    arrays.emplace_back(static_cast<py::ssize_t>(column.size()), column.data());
  return {push.curve.columns, arrays, push.document.dump(), push.text, push.stopped};
}

}  // namespace

void bind_models(py::module_& module) {
  module.def("validate_model", &validate, py::arg("text"), py::arg("path"),
             "Reads, checks and builds the model (with its records); raises on any input error.");
  module.def("expand_model", &expand, py::arg("text"), py::arg("path"),
             "The model with its generators expanded, as JSON text (`pound expand`).");
  module.def("check_model", &check, py::arg("text"), py::arg("path"),
             "The checks before a run as JSON text (`pound check --json`).");
  module.def("model_pushover", &pushover, py::arg("text"), py::arg("path"), py::arg("node"),
             py::arg("target"), py::arg("direction"), py::arg("pattern"), py::arg("increments"),
             py::arg("out"),
             "A static pushover (`pound pushover`): the curve, pushover.json, the summary text and "
             "why it stopped short.");
  module.def("model_modes", &modes, py::arg("text"), py::arg("path"), py::arg("count"),
             "The first modes as JSON text, their shapes and the DOF labels (`pound modes`).");
}

}  // namespace pound::python
