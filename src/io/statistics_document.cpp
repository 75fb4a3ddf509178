#include "io/statistics_document.hpp"

namespace pound::io {
namespace {

// What each response quantity is, so that readers (tools/plot_batch.py) need no list of their own.
Document quantities_document() {
  Document quantities;
  for (const results::BatchQuantity& q : results::batch_quantities())
    quantities.set(std::string(q.name), Document()
                                            .set("meaning", std::string(q.meaning))
                                            .set("axis_label", std::string(q.axis_label))
                                            .set("response", q.response)
                                            .set("running_peak", q.running_peak));
  return quantities;
}

Document intensity_document(const builder::IntensityMeasure& measure) {
  Document intensity;
  intensity.set("type", builder::intensity_name(measure.type)).set("units", "g");
  if (measure.type == builder::IntensityKind::sa)
    intensity.set("period", measure.period).set("damping", measure.damping);
  intensity.set("pair", builder::pair_measure_name(measure.pair));
  return intensity;
}

// One model at one scale: its response statistics and how often each limit was exceeded.
Document group_document(const results::ScaleGroup& g) {
  Document group;
  group.set("model", g.model)
      .set("scale", g.scale)
      .set("cases", static_cast<long>(g.cases))
      .set("completed", static_cast<long>(g.completed));
  Document responses;
  for (const results::ResponseStatistics& r : g.responses)
    responses.set(r.quantity, Document()
                                  .set("count", static_cast<long>(r.count))
                                  .set("median", r.median)
                                  .set("p84", r.p84)
                                  .set("max", r.max));
  group.set("responses", responses);
  if (!g.exceedances.empty()) {
    Document exceedances;
    for (const results::Exceedance& e : g.exceedances)
      exceedances.set(e.quantity, Document()
                                      .set("limit", e.limit)
                                      .set("count", static_cast<long>(e.count))
                                      .set("exceeded", static_cast<long>(e.exceeded))
                                      .set("fraction", e.fraction));
    group.set("exceedance", exceedances);
  }
  return group;
}

Document fragility_document(const results::FragilityFit& f) {
  Document fit;
  fit.set("model", f.model)
      .set("quantity", f.quantity)
      .set("limit", f.limit)
      .set("observations", static_cast<long>(f.observations))
      .set("left_out", static_cast<long>(f.left_out))
      .set("exceeded", static_cast<long>(f.exceeded))
      .set("fitted", f.fitted);
  if (f.fitted)
    fit.set("median", f.median)
        .set("dispersion", f.dispersion)
        .set("log_likelihood", f.log_likelihood);
  else
    fit.set("reason", f.reason);
  return fit;
}

}  // namespace

Document to_document(const results::BatchStatistics& statistics, const builder::SetSpec& set) {
  Document doc;
  doc.set("set", set.source)
      .set("title", set.title)
      .set("cases", static_cast<long>(statistics.cases))
      .set("completed", static_cast<long>(statistics.completed))
      .set("failed", static_cast<long>(statistics.failed))
      .set("input_errors", static_cast<long>(statistics.input_errors))
      .set("statistics",
           "per model and scale over the completed cases: median and 84th percentile "
           "interpolated between order statistics (type 7), maximum");
  doc.set("intensity_measure", intensity_document(set.intensity));
  doc.set("quantities", quantities_document());
  doc.set("groups", documents(statistics.groups, group_document));
  doc.set("fragility", documents(statistics.fragilities, fragility_document));
  return doc;
}

}  // namespace pound::io
