// SPDX-License-Identifier: MIT
// LoadData, Control and Step sections: load curves, time control and analysis steps.
#include "trifem/feb/reader.hpp"

#include <algorithm>
#include <cctype>
#include <fmt/format.h>

namespace trifem::feb::detail {
namespace {

std::string lower(std::string s) {
  for (char& c : s)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

/// The points of a load curve: <points><pt>t,v</pt>...</points> (4.0) or <point>t,v</point>
/// children (3.0).
std::vector<std::pair<Real, Real>> curve_points(const Reader& r, pugi::xml_node lc) {
  std::vector<std::pair<Real, Real>> points;
  const pugi::xml_node list = lc.child("points") ? lc.child("points") : lc;
  for (pugi::xml_node p : elements(list)) {
    if (std::string_view(p.name()) != "pt" && std::string_view(p.name()) != "point")
      continue;
    const std::vector<Real> v = r.doc.numbers(p, 2);
    if (!points.empty() && v[0] <= points.back().first)
      r.doc.fail(p, "the times of the points must increase");
    points.emplace_back(v[0], v[1]);
  }
  if (points.empty())
    r.doc.fail(lc, "the load curve has no points");
  return points;
}

/// The interpolation of a load curve; FEBio's SMOOTH is a blend of quadratics through
/// neighbouring points (trifem's "quadratic-blend"; linear through two points), and its STEP
/// takes the value of the next point: trifem's "next".
dofs::Interpolation interpolation(const Reader& r, pugi::xml_node node, const std::string& kind,
                                  std::size_t points) {
  const std::string k = lower(kind);
  if (k == "linear" || (k == "smooth" && points == 2))
    return dofs::Interpolation::Linear;
  if (k == "smooth")
    return dofs::Interpolation::QuadraticBlend;
  if (k == "step")
    return dofs::Interpolation::Next;
  r.doc.fail(node, fmt::format("interpolation '{}' is not supported: trifem reproduces FEBio's "
                               "LINEAR, STEP and SMOOTH exactly; write the curve with LINEAR "
                               "segments",
                               kind));
}

/// The extension of a load curve: CONSTANT, REPEAT and REPEAT OFFSET as FEBio's; EXTRAPOLATE
/// as CONSTANT, marked in `extent` (checked to cover the run once the steps are known).
dofs::Extension extension(const Reader& r, pugi::xml_node node, CurveExtent& extent) {
  const std::string mode = lower(r.doc.text(node));
  if (mode == "constant")
    return dofs::Extension::Constant;
  if (mode == "repeat")
    return dofs::Extension::Repeat;
  if (mode == "repeat offset")
    return dofs::Extension::RepeatOffset;
  if (mode != "extrapolate")
    r.doc.fail(node, fmt::format("extend '{}' is not supported (expected CONSTANT, REPEAT, "
                                 "REPEAT OFFSET, or EXTRAPOLATE inside the points)",
                                 r.doc.text(node)));
  extent.extrapolate = true;
  return dofs::Extension::Constant;
}

void read_curve(Reader& r, pugi::xml_node lc) {
  const std::string id = r.doc.attribute(lc, "id");
  const std::string type = lc.attribute("type").value();
  if (r.version == Version::V4 && type != "loadcurve")
    r.doc.fail(lc, "type",
               fmt::format("load controller type '{}' is not supported (expected "
                           "loadcurve)",
                           type));
  std::string name = lc.attribute("name").value();
  if (name.empty())
    name = "lc" + id;
  if (r.spec.curves.contains(name) || r.curve_by_id.contains(id))
    r.doc.fail(lc, fmt::format("a second load controller with id {} or name '{}'", id, name));
  io::CurveSpec curve;
  curve.points = curve_points(r, lc);
  CurveExtent extent{lc, false, curve.points.front().first, curve.points.back().first};
  for (pugi::xml_node c : elements(lc)) {
    const std::string_view key = c.name();
    if (key == "interpolate") {
      curve.interpolation = interpolation(r, c, r.doc.text(c), curve.points.size());
    } else if (key == "extend") {
      curve.extension = extension(r, c, extent);
    } else if (key != "points" && key != "point")
      r.doc.fail(c, fmt::format("unknown parameter '{}' of a load curve", key));
  }
  if (r.version == Version::V3 && !type.empty() && type != "loadcurve") // 3.0: type="smooth"
    curve.interpolation = interpolation(r, lc, type, curve.points.size());
  r.spec.curves[name] = curve;
  r.curve_by_id[id] = name;
  r.curve_extents.push_back(extent);
}

/// The generalized-α parameters of a dynamic Control (FEBio's <solver> rhoi, or Newmark's beta
/// and gamma of the trapezoidal rule, FEBio's default) into r.spec.dynamics.
void read_dynamic_parameters(const Reader& r, pugi::xml_node control) {
  const pugi::xml_node solver = control.child("solver");
  Real rho_inf = 1.0;
  if (const pugi::xml_node rhoi = solver.child("rhoi")) {
    const Real value = r.doc.number(rhoi);
    if (value >= 0.0 && value <= 1.0)
      rho_inf = value;
    else if (value != -2.0)
      r.doc.fail(rhoi, fmt::format("rhoi = {} is not supported (expected a spectral radius in "
                                   "[0, 1], or -2: Newmark's trapezoidal rule)",
                                   value));
  }
  for (const auto& [key, trapezoidal] : {std::pair{"beta", 0.25}, {"gamma", 0.5}})
    if (const pugi::xml_node n = solver.child(key); n && r.doc.number(n) != trapezoidal)
      r.doc.fail(n, fmt::format("{} = {} is not supported (trifem's dynamic steps are the "
                                "generalized-alpha family of rhoi; Newmark's {} = {} with rhoi = "
                                "-2 or 1)",
                                key, r.doc.number(n), key, trapezoidal));
  r.spec.dynamics.rho_inf = rho_inf;
}

/// The analysis of a Control: static or dynamic solids, transient, dynamic or steady-state
/// mixtures.
FebAnalysis read_analysis(const Reader& r, pugi::xml_node control) {
  const pugi::xml_node node = control.child("analysis");
  const std::string type = node ? lower(r.doc.text(node)) : std::string();
  if (type == "dynamic") {
    read_dynamic_parameters(r, control);
    return FebAnalysis::Dynamic;
  }
  if (r.biphasic_module) {
    if (type.empty() || type == "steady-state") // FEBio's default for mixtures
      return FebAnalysis::SteadyState;
    if (type != "transient")
      r.doc.fail(node, fmt::format("a {} analysis of a mixture is not supported (expected "
                                   "TRANSIENT, STEADY-STATE or DYNAMIC)",
                                   type));
    return FebAnalysis::Transient;
  }
  if (!type.empty() && type != "static")
    r.doc.fail(node, fmt::format("analysis '{}' is not supported (expected STATIC or DYNAMIC)",
                                 r.doc.text(node)));
  return FebAnalysis::Static;
}

/// The time stepper of a Control (FEBio's auto time stepper -> trifem's step control).
void read_time_stepper(Reader& r, pugi::xml_node stepper, io::TimeSpec& t) {
  t.growth = 1.5;
  for (pugi::xml_node c : elements(stepper)) {
    const std::string_view key = c.name();
    if (key == "dtmin") {
      t.dt_min = std::max(0.0, r.doc.number(c));
    } else if (key == "dtmax") {
      const std::string curve = r.curve_of(c);
      Real dtmax = r.doc.number(c);
      if (!curve.empty()) // must points: the curve's points; its values are the largest step
        for (const auto& p : r.spec.curves.at(curve).points)
          dtmax = std::max(dtmax, p.second);
      t.dt_max = dtmax;
    } else if (key == "opt_iter") {
      t.target_iterations = static_cast<int>(std::max(1L, r.doc.integer(c)));
    } else if (key == "cutback") {
      const Real f = r.doc.number(c);
      if (f > 0.0 && f < 1.0)
        t.cutback = f;
    } else if (key != "max_retries" && key != "aggressiveness" && key != "dtforce") {
      r.doc.fail(c, fmt::format("unknown parameter '{}' of the time stepper", key));
    }
  }
}

/// Control parameters that only concern FEBio's own output or solver.
bool ignored_control(std::string_view key) {
  for (std::string_view k : {"plot_zero_state",
                             "plot_range",
                             "plot_level",
                             "output_level",
                             "plot_stride",
                             "output_stride",
                             "adaptor_re_solve",
                             "title",
                             "solver",
                             "max_refs",
                             "max_ups",
                             "dtol",
                             "etol",
                             "rtol",
                             "ptol",
                             "lstol",
                             "min_residual",
                             "qnmethod",
                             "symmetric_biphasic",
                             "reform_each_time_step",
                             "diverge_reform",
                             "integration",
                             "output_stride",
                             "must_point_plot"})
    if (key == k)
      return true;
  return false;
}

/// The span of a step: time_steps * step_size, checked.
void check_time(const Reader& r, pugi::xml_node control, io::TimeSpec& t, Real start) {
  const Real span = t.end_time - start;
  if (!(span >= 1e-8) || !(t.dt > 0.0))
    r.doc.fail(control, fmt::format("time_steps x step_size = {}: the step must last at least "
                                    "1e-8 s with step_size > 0",
                                    span));
  if (span / t.dt > io::kMaxSteps)
    r.doc.fail(control, "more than 1e8 time steps");
  t.dt = std::min(t.dt, span);
  if (t.dt_max > 0.0)
    t.dt_max = std::max(t.dt_max, t.dt);
  if (t.dt_min > t.dt)
    t.dt_min = t.dt;
}

/// A name trifem accepts for a step ([A-Za-z0-9_-]+).
std::string step_name(std::string name, std::size_t k) {
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-')
      c = '_';
  return name.empty() ? fmt::format("step{}", k) : name;
}

} // namespace

void read_load_data(Reader& r, pugi::xml_node section) {
  for (pugi::xml_node lc : elements(section)) {
    const std::string_view kind = lc.name();
    if (kind != "load_controller" && kind != "loadcurve")
      r.doc.fail(lc, fmt::format("<{}> is not supported in <LoadData>", kind));
    read_curve(r, lc);
  }
}

io::TimeSpec read_control(Reader& r, pugi::xml_node control, Real start, FebAnalysis* analysis) {
  const FebAnalysis kind = read_analysis(r, control);
  if (analysis)
    *analysis = kind;
  io::TimeSpec t;
  long steps = 0;
  t.growth = 1.0; // without a time stepper FEBio keeps step_size
  for (pugi::xml_node c : elements(control)) {
    const std::string_view key = c.name();
    if (key == "time_steps")
      steps = r.doc.integer(c);
    else if (key == "step_size")
      t.dt = r.doc.number(c);
    else if (key == "time_stepper")
      read_time_stepper(r, c, t);
    else if (key != "analysis" && !ignored_control(key))
      r.doc.fail(c, fmt::format("unknown or unsupported control parameter '{}'", key));
  }
  if (steps <= 0)
    r.doc.fail(control, "<time_steps> must be given and positive");
  t.end_time = start + static_cast<Real>(steps) * t.dt;
  if (!control.child("time_stepper"))
    t.dt_max = t.dt;
  check_time(r, control, t, start);
  return t;
}

pugi::xml_node only_step(pugi::xml_node root) {
  const pugi::xml_node steps = root.child("Step");
  const pugi::xml_node first = steps.child("step");
  return first && !first.next_sibling("step") ? first : pugi::xml_node();
}

void read_steps(Reader& r, pugi::xml_node root) {
  const pugi::xml_node single = only_step(root);
  const pugi::xml_node steps = root.child("Step");
  const pugi::xml_node control = root.child("Control");
  if (!steps) {
    if (!control)
      r.doc.fail(root, "the element <Control> is required");
    FebAnalysis analysis = FebAnalysis::Static;
    r.spec.time = read_control(r, control, 0.0, &analysis);
    if (analysis == FebAnalysis::Dynamic)
      r.spec.analysis.type = io::AnalysisType::Dynamic;
    if (analysis == FebAnalysis::SteadyState) { // a steady-state run: one steady step
      io::StepSpec step;
      step.name = "step1";
      step.key = "step[1]";
      step.time = r.spec.time;
      step.steady = true;
      r.spec.steps.push_back(step);
    }
    return;
  }
  Real start = 0.0;
  for (pugi::xml_node s : elements(steps)) {
    if (std::string_view(s.name()) != "step")
      r.doc.fail(s, "expected <step> elements");
    const std::size_t k = r.spec.steps.size() + 1;
    io::StepSpec step;
    step.name = step_name(s.attribute("name").value(), k);
    step.key = fmt::format("step[{}]", k);
    const pugi::xml_node c = s.child("Control") ? s.child("Control") : control;
    if (!c)
      r.doc.fail(s, "the step has no <Control> (and there is no top-level one)");
    FebAnalysis analysis = FebAnalysis::Static;
    step.time = read_control(r, c, start, &analysis);
    step.steady = analysis == FebAnalysis::SteadyState;
    if (analysis == FebAnalysis::Dynamic)
      step.analysis = io::AnalysisType::Dynamic;
    start = step.time.end_time;
    for (pugi::xml_node part : elements(s)) {
      const std::string_view kind = part.name();
      if (kind == "Boundary")
        read_boundary(r, part, step.fixed, step.prescribed, true);
      else if (kind == "Loads")
        read_loads(r, part, step.pressures, step.tractions, step.prescribed, true);
      else if (s == single && (kind == "Rigid" || kind == "Contact" || kind == "Constraints"))
        continue; // read with the file's own sections (feb_reader.cpp)
      else if (kind != "Control")
        r.doc.fail(part, fmt::format("<{}> in a step is not supported", kind));
    }
    r.spec.steps.push_back(std::move(step));
  }
  if (r.spec.steps.empty())
    r.doc.fail(steps, "the <Step> section has no <step>");
  r.spec.time = r.spec.steps.front().time;
  r.spec.time.end_time = start;
}

void map_densities(Reader& r) {
  if (!r.spec.has_dynamic_step() && r.spec.body_forces.empty())
    return;
  for (auto& [name, m] : r.spec.materials)
    if (const auto it = r.densities.find(name); it != r.densities.end())
      m.density = it->second;
}

} // namespace trifem::feb::detail
