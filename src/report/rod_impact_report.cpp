#include "report/rod_impact_report.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace pound::report {

std::vector<std::string> rod_impact_case_names() { return {"kawashima", "fixed-end", "area-ratio-3"}; }

std::vector<std::string> rod_impact_law_names() { return {"gap_spring", "extended_penalty"}; }

builder::RodPairSpec rod_impact_case(const std::string& name, int elements, double stiffness_ratio,
                                     const std::string& law, double eta) {
  builder::RodPairSpec pair = kawashima_rod_pair(elements, stiffness_ratio);
  if (law == "extended_penalty") {
    pair.law = {.type = "extended_penalty", .parameters = {{"eta", eta}}};
  } else if (law != "gap_spring") {
    throw std::invalid_argument(fmt::format("unknown law '{}' for the rod pair (expected one of: {})",
                                            law, fmt::join(rod_impact_law_names(), ", ")));
  }
  if (name == "kawashima") return pair;
  pair.right.initial_velocity = 0.0;
  pair.right.far_end_fixed = true;
  if (name == "fixed-end") return pair;
  if (name == "area-ratio-3") {
    pair.left.area = 3.0 * pair.right.area;
    return pair;
  }
  throw std::invalid_argument(fmt::format("unknown rod-impact case '{}' (expected one of: {})", name,
                                          fmt::join(rod_impact_case_names(), ", ")));
}

io::Document to_document(const RodImpactMetrics& m) {
  io::Document doc;
  doc.set("force_l2_error", m.force_l2_error)
      .set("duration_error", m.duration_error)
      .set("separation_velocity_error", m.separation_velocity_error)
      .set("peak_force_ratio", m.peak_force_ratio)
      .set("max_penetration", m.max_penetration)
      .set("min_force", m.min_force)
      .set("run_time_s", m.run_time_s)
      .set("steps", m.steps)
      .set("newton_iterations", m.newton_iterations)
      .set("contact_duration", m.duration)
      .set("exact_contact_duration", m.exact_duration)
      .set("exact_peak_force", m.exact_peak_force)
      .set("contact_episodes", m.contact_episodes)
      .set("exact_contact_episodes", m.exact_contact_episodes)
      .set("separation_velocity", m.separation_velocity)
      .set("exact_separation_velocity", m.exact_separation_velocity);
  return doc;
}

io::Table force_history_table(const RodImpactResult& r) {
  return {{"time", "force", "exact_force", "penetration"},
          {r.time, r.force, r.exact_force, r.penetration}};
}

io::Table profile_table(const RodImpactResult& r) {
  io::Table table{{"time_over_T", "time", "rod", "x", "velocity", "exact_velocity", "stress",
                   "exact_stress"},
                  std::vector<std::vector<double>>(8)};
  for (const RodProfile& profile : r.profiles)
    for (const RodProfile::Point& p : profile.points) {
      const double row[] = {profile.label, profile.time, static_cast<double>(p.rod), p.x,
                            p.velocity, p.exact_velocity, p.stress, p.exact_stress};
      for (std::size_t c = 0; c < 8; ++c) table.values[c].push_back(row[c]);
    }
  return table;
}

std::vector<Study> kawashima_study() {
  std::vector<Study> studies;
  auto run = [](int elements, double stiffness_ratio, double dt_ratio) {
    RodImpactOptions options;
    options.pair = kawashima_rod_pair(elements, stiffness_ratio);
    options.dt_ratio = dt_ratio;
    return run_rod_impact(options).metrics;
  };
  // Kawashima's k_I is absolute; with n = 10, E A / h = 100, so k-ratio = k_I / 100.
  Study stiffness{"link stiffness k_I (n = 10, dt = T_I/1000)", {}};
  for (double k : {10.0, 100.0, 1e3, 1e4, 1e5})
    stiffness.rows.push_back({fmt::format("k_I = {:g} (k-ratio {:g})", k, k / 100.0), run(10, k / 100.0, 1e-3)});
  studies.push_back(std::move(stiffness));
  Study mesh{"elements per rod n (k-ratio 1, dt = T_I/100)", {}};
  for (int n : {2, 10, 40}) mesh.rows.push_back({fmt::format("n = {}", n), run(n, 1.0, 1e-2)});
  studies.push_back(std::move(mesh));
  Study step{"time step dt (n = 10, k-ratio 1)", {}};
  for (double ratio : {0.5, 0.05, 0.01}) step.rows.push_back({fmt::format("dt = {:g} T_I", ratio), run(10, 1.0, ratio)});
  studies.push_back(std::move(step));
  return studies;
}

std::string format_metrics(const RodImpactMetrics& m) {
  return fmt::format(
      "  force_l2_error             {:>12.4e}\n"
      "  duration_error             {:>12.4e}   (contact {:.6g}, exact {:.6g})\n"
      "  separation_velocity_error  {:>12.4e}   (relative v_cm {:.6g}, exact {:.6g})\n"
      "  peak_force_ratio           {:>12.4f}   (exact peak {:.6g})\n"
      "  max_penetration            {:>12.4e}\n"
      "  min_force                  {:>12.4e}\n"
      "  contact episodes           {:>12}   (exact {})\n"
      "  steps                      {:>12}\n"
      "  newton_iterations          {:>12}\n"
      "  run_time_s                 {:>12.4e}\n",
      m.force_l2_error, m.duration_error, m.duration, m.exact_duration, m.separation_velocity_error,
      m.separation_velocity, m.exact_separation_velocity, m.peak_force_ratio, m.exact_peak_force,
      m.max_penetration, m.min_force, m.contact_episodes, m.exact_contact_episodes, m.steps,
      m.newton_iterations, m.run_time_s);
}

std::string format_study(const Study& study) {
  std::string text = fmt::format("{}\n{:<26} {:>10} {:>10} {:>10} {:>8} {:>11} {:>8} {:>7}\n",
                                 study.title, "case", "force_L2", "duration", "sep_vel", "peak",
                                 "penetration", "contacts", "steps");
  for (const StudyRow& row : study.rows) {
    const RodImpactMetrics& m = row.metrics;
    text += fmt::format("{:<26} {:>10.4f} {:>+10.4f} {:>+10.4f} {:>8.3f} {:>11.3e} {:>8} {:>7}\n",
                        row.label, m.force_l2_error, m.duration_error, m.separation_velocity_error,
                        m.peak_force_ratio, m.max_penetration, m.contact_episodes, m.steps);
  }
  return text;
}

io::Document to_document(const std::vector<Study>& studies) {
  std::vector<io::Document> items;
  for (const Study& study : studies) {
    std::vector<io::Document> rows;
    for (const StudyRow& row : study.rows) {
      io::Document doc;
      doc.set("case", row.label).set("metrics", to_document(row.metrics));
      rows.push_back(std::move(doc));
    }
    io::Document doc;
    doc.set("study", study.title).set("rows", rows);
    items.push_back(std::move(doc));
  }
  io::Document root;
  root.set("studies", items);
  return root;
}

}  // namespace pound::report
