// SPDX-License-Identifier: MIT
// Shared set-up of the explicit verification tests: laws and models in μ = ρ = 1 units, built
// as every case is (io::CaseSpec → model::build_model), with the explicit view of the model.
#pragma once

#include "trifem/explicit/explicit_solver.hpp"
#include "trifem/explicit/explicit_view.hpp"
#include "trifem/io/case_spec.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/model/model.hpp"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace trifem::test {

/// The explicit part of the multiplier formulation: W = μ/2 (I1 − 3) − μ ln J, i.e. the
/// registry's neo-Hookean with ν = 0 (E = 2μ); the bulk response comes from λ Ψ(C).
inline io::MaterialSpec deviatoric_material(Real mu, Real density) {
  io::MaterialSpec m;
  m.type = "neo-hookean";
  m.parameters = {{"E", 2.0 * mu}, {"nu", 0.0}};
  m.density = density;
  return m;
}

/// Compressible neo-Hookean with shear modulus μ and small-strain bulk modulus κ
/// (ν = (3κ − 2μ) / (2(3κ + μ))): the pure-displacement Q1 comparison.
inline io::MaterialSpec compressible_material(Real mu, Real kappa, Real density) {
  const Real nu = (3.0 * kappa - 2.0 * mu) / (2.0 * (3.0 * kappa + mu));
  io::MaterialSpec m = deviatoric_material(mu, density);
  m.parameters = {{"E", 2.0 * mu * (1.0 + nu)}, {"nu", nu}};
  return m;
}

/// The law of a material above.
inline std::shared_ptr<const material::ElasticLaw> law_of(const io::MaterialSpec& m) {
  return material::create_law(m.solid_law(), "test");
}

/// The case of an explicit test model: one mesh whose cell blocks take materials, fixed
/// displacement components on node sets, surface loads with their load curves.
class ExplicitTestCase {
public:
  /// `mesh` with every cell block of `material`.
  ExplicitTestCase(mesh::Mesh mesh, const io::MaterialSpec& material) {
    spec_.analysis.type = io::AnalysisType::DynamicExplicit;
    spec_.materials["solid"] = material;
    io::InlineMeshSpec inline_mesh{std::move(mesh), {}};
    for (const auto& [block, cells] : inline_mesh.mesh.cell_blocks())
      inline_mesh.materials[block] = "solid";
    spec_.meshes.push_back(std::move(inline_mesh));
  }
  /// Cell block `block` of `material` instead.
  ExplicitTestCase& block(const std::string& block, const io::MaterialSpec& material) {
    spec_.materials[block] = material;
    spec_.meshes[0].materials[block] = block;
    return *this;
  }
  /// u_k = 0 on node set `set` for each k of `components`.
  ExplicitTestCase& fix(const std::string& set, std::vector<int> components) {
    spec_.fixed.push_back({"boundary.fixed", set, std::move(components)});
    return *this;
  }
  /// u_component = `value` * curve(t) on node set `set`.
  ExplicitTestCase& prescribe(const std::string& set, int component, Real value,
                              const io::CurveSpec& curve) {
    io::PrescribedSpec p;
    p.set = set;
    p.component = component;
    p.value = value;
    p.curve = add_curve(curve);
    spec_.prescribed.push_back(p);
    return *this;
  }
  /// Dead traction `value` * curve(t) per reference area on `surface`.
  ExplicitTestCase& traction(const std::string& surface, const Vec3& value,
                             const io::CurveSpec& curve) {
    spec_.tractions.push_back({surface, value, add_curve(curve)});
    return *this;
  }
  /// Follower pressure `value` * curve(t) on `surface`.
  ExplicitTestCase& pressure(const std::string& surface, Real value, const io::CurveSpec& curve) {
    spec_.pressures.push_back({surface, value, add_curve(curve)});
    return *this;
  }
  std::unique_ptr<model::Model> build() const { return model::build_model(spec_); }
  /// The case (e.g. to run it as another analysis).
  io::CaseSpec& spec() { return spec_; }

private:
  std::string add_curve(const io::CurveSpec& curve) {
    const std::string name = "curve" + std::to_string(spec_.curves.size() + 1);
    spec_.curves[name] = curve;
    return name;
  }
  io::CaseSpec spec_;
};

/// The load curves of the tests.
inline io::CurveSpec step_curve() {
  return {dofs::Interpolation::Step, {{0.0, 1.0}}};
}
/// 0 at t = 0 to 1 at `t1`, smooth (zero slope at both ends).
inline io::CurveSpec smooth_ramp(Real t1) {
  return {dofs::Interpolation::Smooth, {{0.0, 0.0}, {t1, 1.0}}};
}

/// The owner of a shared model, first base of TestModel (built before the view).
struct SharedModel {
  std::unique_ptr<model::Model> shared;
};

/// A model built from a test case with its explicit view (the view refers to the model it owns).
struct TestModel : SharedModel, explicit_dynamics::ExplicitView {
  explicit TestModel(std::unique_ptr<model::Model> model)
      : SharedModel{std::move(model)}, explicit_dynamics::ExplicitView(*shared) {}
  explicit TestModel(const ExplicitTestCase& c) : TestModel(c.build()) {}
};

} // namespace trifem::test
