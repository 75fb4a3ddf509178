#include "verification/rod_impact_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace pound::verification {

std::vector<std::string> rod_impact_case_names() {
  return {"kawashima", "fixed-end", "area-ratio-3", "unequal-lengths", "rigid-wall"};
}

std::vector<std::string> rod_impact_law_names() {
  return {"gap_spring", "extended_penalty", "hard_contact"};
}

builder::RodPairSpec rod_impact_case(const std::string& name, int elements, double stiffness_ratio,
                                     const std::string& law, double eta) {
  builder::RodPairSpec pair = kawashima_rod_pair(elements, stiffness_ratio);
  if (law == "extended_penalty") {
    pair.law = {.type = "extended_penalty", .parameters = {{"eta", eta}}};
  } else if (law == "hard_contact") {
    // Between meshes: the rods' elasticity makes the bounce.
    pair.law = {.type = "hard_contact", .parameters = {{"restitution", 0.0}}};
  } else if (law != "gap_spring") {
    throw std::invalid_argument(
        fmt::format("unknown law '{}' for the rod pair (expected one of: {})", law,
                    fmt::join(rod_impact_law_names(), ", ")));
  }
  if (name == "kawashima") return pair;
  if (name == "rigid-wall") {
    // The striking rod against a fixed rigid wall across a gap of L / 200: contact from gap / V0
    // for 2 L / c at the force rho c V0 A, then the rod leaves at -V0 unstrained.
    pair.right_wall = true;
    pair.right = {};
    pair.gap = pair.left.length / 200.0;
    return pair;
  }
  pair.right.initial_velocity = 0.0;
  if (name == "unequal-lengths") {
    // One material, the struck rod at rest and twice as long (same element size): the contact
    // lasts 2 L_short / c, after which the short rod is at rest and the long one moves at
    // V0 L_short / L_long on average (apparent restitution L_short / L_long).
    pair.right.length = 2.0 * pair.left.length;
    pair.right.elements = 2 * pair.left.elements;
    return pair;
  }
  pair.right.far_end_fixed = true;
  if (name == "fixed-end") return pair;
  if (name == "area-ratio-3") {
    pair.left.area = 3.0 * pair.right.area;
    return pair;
  }
  throw std::invalid_argument(fmt::format("unknown rod-impact case '{}' (expected one of: {})",
                                          name, fmt::join(rod_impact_case_names(), ", ")));
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
      .set("exact_separation_velocity", m.exact_separation_velocity)
      .set("energy_ratio", m.energy_ratio)
      .set("time_step", m.time_step);
  if (m.stable_time_step) doc.set("stable_time_step", *m.stable_time_step);
  return doc;
}

io::Table force_history_table(const RodImpactResult& r) {
  return {{"time", "force", "exact_force", "penetration"},
          {r.time, r.force, r.exact_force, r.penetration}};
}

io::Table profile_table(const RodImpactResult& r) {
  io::Table table = table_with_columns(
      {"time_over_T", "time", "rod", "x", "velocity", "exact_velocity", "stress", "exact_stress"});
  for (const RodProfile& profile : r.profiles)
    for (const RodProfile::Point& p : profile.points)
      append_row(table, {profile.label, profile.time, static_cast<double>(p.rod), p.x, p.velocity,
                         p.exact_velocity, p.stress, p.exact_stress});
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
    stiffness.rows.push_back(
        {fmt::format("k_I = {:g} (k-ratio {:g})", k, k / 100.0), run(10, k / 100.0, 1e-3)});
  studies.push_back(std::move(stiffness));
  Study mesh{"elements per rod n (k-ratio 1, dt = T_I/100)", {}};
  for (int n : {2, 10, 40}) mesh.rows.push_back({fmt::format("n = {}", n), run(n, 1.0, 1e-2)});
  studies.push_back(std::move(mesh));
  Study step{"time step dt (n = 10, k-ratio 1)", {}};
  for (double ratio : {0.5, 0.05, 0.01})
    step.rows.push_back({fmt::format("dt = {:g} T_I", ratio), run(10, 1.0, ratio)});
  studies.push_back(std::move(step));
  return studies;
}

std::vector<Study> penalty_study() {
  auto run = [](builder::LawSpec law) {
    RodImpactOptions options;
    options.pair = rod_impact_case("fixed-end", 50, 1.0);
    options.pair.law = std::move(law);
    options.courant = 1.0;
    return run_rod_impact(options).metrics;
  };
  const double adjacent = 100.0 * 1.0 / (10.0 / 50.0);  // E A / h of Kawashima's rod, n = 50
  Study spring_only{"alpha0 only (Suzuki & Toi Fig. 7), fixed-end rods, n = 50, dt = h/C0", {}};
  for (double xi : {1.0, 10.0, 1e3})
    spring_only.rows.push_back(
        {fmt::format("xi = alpha0/k = {:g}", xi),
         run({.type = "extended_penalty",
              .parameters = {{"alpha0", xi * adjacent}, {"alpha1", 0.0}, {"alpha2", 0.0}}})});
  Study extended{"extended penalty, e* = 1e-3 (Fig. 8), fixed-end rods, n = 50, dt = h/C0", {}};
  for (double eta : {0.0, 1.0, 10.0})
    extended.rows.push_back({fmt::format("eta = {:g}", eta),
                             run({.type = "extended_penalty", .parameters = {{"eta", eta}}})});
  extended.rows.push_back({"gap spring, k-ratio 1",
                           run({.type = "gap_spring", .parameters = {{"stiffness_ratio", 1.0}}})});
  return {spring_only, extended};
}

std::string format_two_element(const std::vector<TwoElementResult>& results) {
  std::string text =
      fmt::format("{:>6} {:>6} {:>9} {:>9} {:>13} {:>13} {:>10} {:>10}\n", "k2/k1", "m2/m1",
                  "alpha0/k1", "alpha2*", "w1/w_exact", "w2/w_exact", "error", "");
  double worst = 0.0;
  for (const TwoElementResult& r : results) {
    const TwoElementCase& c = r.input;
    const double reference_mass = c.alpha0 * (c.m1 + c.m2) / (c.k1 + c.k2);
    text += fmt::format("{:>6g} {:>6g} {:>9g} {:>9g} {:>13.6f} {:>13.6f} {:>10.2e}\n", c.k2 / c.k1,
                        c.m2 / c.m1, c.alpha0 / c.k1, c.alpha2 / reference_mass,
                        std::sqrt(r.omega1_squared / r.exact_omega_squared),
                        std::sqrt(r.omega2_squared / r.exact_omega_squared), r.relative_error);
    worst = std::max(worst, r.relative_error);
  }
  return text +
         fmt::format(
             "alpha2* = alpha2 / (alpha0 (m1 + m2) / (k1 + k2)), eq. 29 at 1; error: largest "
             "relative difference of w^2 from eq. 4 / eqs. 23-24\n{} cases, largest error {:.2e}\n",
             results.size(), worst);
}

io::Document to_document(const std::vector<TwoElementResult>& results) {
  double worst = 0.0;
  for (const TwoElementResult& r : results) worst = std::max(worst, r.relative_error);
  auto row = [](const TwoElementResult& r) {
    return io::Document()
        .set("k1", r.input.k1)
        .set("k2", r.input.k2)
        .set("m1", r.input.m1)
        .set("m2", r.input.m2)
        .set("alpha0", r.input.alpha0)
        .set("alpha2", r.input.alpha2)
        .set("omega1_squared", r.omega1_squared)
        .set("omega2_squared", r.omega2_squared)
        .set("closed_omega1_squared", r.closed_omega1_squared)
        .set("closed_omega2_squared", r.closed_omega2_squared)
        .set("exact_omega_squared", r.exact_omega_squared)
        .set("relative_error", r.relative_error);
  };
  io::Document doc;
  doc.set("cases", io::documents(results, row)).set("max_relative_error", worst);
  return doc;
}

std::string format_restitution(const std::vector<RestitutionRow>& rows) {
  std::string text = fmt::format("{:<32} {:>7} {:>9} {:>9} {:>12} {:>11} {:>12}\n", "law", "target",
                                 "achieved", "error", "peak force", "contact", "penetration");
  for (const RestitutionRow& r : rows)
    text += fmt::format(
        "{:<32} {:>7.3f} {:>9.5f} {:>+9.5f} {:>12.5g} {:>11.5g} {:>12.5g}{}\n", r.law, r.target,
        r.achieved, r.achieved - r.target, r.peak_force, r.contact_time, r.max_penetration,
        r.calibrated ? "" : (r.target == 1.0 ? "  (elastic)" : "  (published formula)"));
  return text;
}

io::Document to_document(const std::vector<RestitutionRow>& rows) {
  auto row = [](const RestitutionRow& r) {
    return io::Document()
        .set("law", r.law)
        .set("target", r.target)
        .set("achieved", r.achieved)
        .set("peak_force", r.peak_force)
        .set("contact_time", r.contact_time)
        .set("max_penetration", r.max_penetration)
        .set("calibrated", r.calibrated);
  };
  io::Document doc;
  doc.set("rows", io::documents(rows, row));
  return doc;
}

// Above this the rods end with more energy than they started with by more than round-off of the
// energy measure at integer steps.
constexpr double kEnergyMadeNote = 1.001;
// From this fraction of central difference's stable step with the contact closed, a penalty
// contact's closing and opening inside steps chatters (measured: 1,000 elements a rod, Kawashima's
// case: 4 contact episodes and an energy ratio of 1.0007 at 0.89, 368 and 1.002 at 0.91, 626 and
// 8.9 at 0.95).
constexpr double kChatterFraction = 0.9;

// Words of `text` in lines of at most `width` characters after `indent`, each line begun on a new
// line.
std::string indented_lines(const std::string& text, std::size_t indent, std::size_t width) {
  std::string lines, line;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(start, end - start);
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      lines += "\n" + std::string(indent, ' ') + line;
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
    start = end + 1;
  }
  if (!line.empty()) lines += "\n" + std::string(indent, ' ') + line;
  return lines;
}

// Why the rods made energy, from what the run knows: its step against the explicit stable step,
// and the kind of contact.
std::string energy_made_reason(const RodImpactMetrics& m) {
  const std::string penalty =
      "a penalty contact that closes or opens inside a step gives back more than it took";
  if (!m.stable_time_step) return penalty + "; reduce the step";
  const double fraction = m.time_step / *m.stable_time_step;
  const std::string step =
      fmt::format("the step is {:.3g} of central difference's stable step ({:.4g}{})", fraction,
                  *m.stable_time_step, m.hard_contact ? "" : " with the contact closed");
  if (fraction >= 0.999)
    return step +
           ", where its highest mode grows linearly; take a step below it (\"auto\" "
           "takes 0.8 of it)";
  if (m.hard_contact) return step + "; reduce the step";
  if (fraction >= kChatterFraction)
    return step + fmt::format(
                      ": from about {:g} of it the contact chatters ({} contact episodes, "
                      "exact {}) and {}; take 0.8 of it or less (\"auto\")",
                      kChatterFraction, m.contact_episodes, m.exact_contact_episodes, penalty);
  return step + ": " + penalty + "; reduce the step";
}

std::string format_metrics(const RodImpactMetrics& m) {
  const std::string energy = fmt::format(
      "  energy_ratio               {:>12.6f}   (rods' energy at the end / at the start){}\n",
      m.energy_ratio,
      m.energy_ratio > kEnergyMadeNote
          ? indented_lines("the integration made energy after the window of the errors below: " +
                               energy_made_reason(m),
                           4, 92)
          : "");
  return energy +
         fmt::format(
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
             m.force_l2_error, m.duration_error, m.duration, m.exact_duration,
             m.separation_velocity_error, m.separation_velocity, m.exact_separation_velocity,
             m.peak_force_ratio, m.exact_peak_force, m.max_penetration, m.min_force,
             m.contact_episodes, m.exact_contact_episodes, m.steps, m.newton_iterations,
             m.run_time_s);
}

std::string format_study(const Study& study) {
  std::string text =
      fmt::format("{}\n{:<26} {:>10} {:>10} {:>10} {:>8} {:>11} {:>8} {:>7}\n", study.title, "case",
                  "force_L2", "duration", "sep_vel", "peak", "penetration", "contacts", "steps");
  for (const StudyRow& row : study.rows) {
    const RodImpactMetrics& m = row.metrics;
    text += fmt::format("{:<26} {:>10.4f} {:>+10.4f} {:>+10.4f} {:>8.3f} {:>11.3e} {:>8} {:>7}\n",
                        row.label, m.force_l2_error, m.duration_error, m.separation_velocity_error,
                        m.peak_force_ratio, m.max_penetration, m.contact_episodes, m.steps);
  }
  return text;
}

io::Document to_document(const std::vector<Study>& studies) {
  auto row = [](const StudyRow& r) {
    return io::Document().set("case", r.label).set("metrics", to_document(r.metrics));
  };
  auto study = [&](const Study& s) {
    return io::Document().set("study", s.title).set("rows", io::documents(s.rows, row));
  };
  io::Document root;
  root.set("studies", io::documents(studies, study));
  return root;
}

}  // namespace pound::verification
