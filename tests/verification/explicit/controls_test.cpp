// SPDX-License-Identifier: MIT
// Step control of the explicit solver: lumped mass, stability estimates, reduction of a too
// large requested step, reading-A iteration limit Δt < 1/ω (docs/theory/explicit.md §3, §5), and
// the stop on a non-finite value with the output written so far kept.
#include "fixtures.hpp"

#include "solver_history.hpp"
#include "trifem/explicit/stable_step.hpp"
#include "trifem/mesh/box.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

using namespace trifem;
using namespace trifem::explicit_dynamics;
using namespace trifem::test;

namespace {

/// The 4 x 2 x 2 bar of 1 x 0.5 x 0.5 cells, clamped at x = 0, dead traction on x = 4.
test::ExplicitTestCase bar_case(const io::MaterialSpec& material, Real traction) {
  mesh::BoxSpec box;
  box.name = "bar";
  box.size = Vec3(4.0, 1.0, 1.0);
  box.divisions = {4, 2, 2};
  test::ExplicitTestCase c(mesh::make_box(box), material);
  c.fix("bar.xmin", {0, 1, 2}).traction("bar.xmax", Vec3(0.0, traction, 0.0), test::step_curve());
  return c;
}

/// The bar of μ = 1, ρ = 2 under a sudden traction.
test::TestModel bar(Real traction = 0.05) {
  return test::TestModel(bar_case(test::deviatoric_material(1.0, 2.0), traction));
}

} // namespace

TEST(ExplicitControls, LumpedMassIsRowSumAndConservesTotalMass) {
  const test::TestModel model = bar();
  // relative to each exact value: sums of positive quadrature terms, a few ulp each
  const Real volume = 4.0, density = 2.0, corner = density * 0.25 / 8.0;
  EXPECT_NEAR(model.mass().sum() / 3.0, density * volume, 1e-13 * density * volume); // ρ V
  EXPECT_NEAR(model.volumes().sum(), volume, 2.5e-13 * volume);
  // Corner node of the box: one cell, mass ρ V_cell / 8.
  EXPECT_NEAR(model.mass()[0], corner, 1e-13 * corner);
  EXPECT_EQ(model.inverse_mass()[0], 0.0); // x = 0 is clamped
}

TEST(ExplicitControls, PowerIterationIsBelowTheElementBound) {
  const test::TestModel model = bar();
  const Vector U = Vector::Zero(model.num_dofs());
  const FrequencyEstimate iso =
      power_iteration_omega(model, Constraint::JMinusOne, U, {}, true, 200, 1e-6);
  const FrequencyEstimate all =
      power_iteration_omega(model, Constraint::JMinusOne, U, {}, false, 200, 1e-6);
  const FrequencyEstimate bound = element_bound_omega(model, Constraint::JMinusOne, U, {});
  std::printf("omega: isochoric %.5f (%d it), unprojected %.5f (%d it), element bound %.5f\n",
              iso.omega, iso.iterations, all.omega, all.iterations, bound.omega);
  EXPECT_LE(iso.omega, all.omega * (1.0 + 1e-6));
  EXPECT_LE(all.omega, bound.omega * (1.0 + 1e-9));
  EXPECT_GT(iso.omega, 0.5 * bound.omega);
}

TEST(ExplicitControls, RequestedStepAboveTheEstimateIsReduced) {
  const test::TestModel model = bar();
  ExplicitSettings s;
  s.time_step = 10.0;
  ExplicitSolver solver(model, s);
  const TimeStepInfo& info = solver.time_step_info();
  EXPECT_TRUE(info.reduced);
  EXPECT_DOUBLE_EQ(info.used, info.stable);
  EXPECT_NEAR(info.stable, 0.8 * 2.0 / info.omega, 1e-12);
  EXPECT_TRUE(solver.run(20 * info.used).ok());
  // A request below the estimate is kept.
  s.time_step = 0.5 * info.stable;
  ExplicitSolver slower(model, s);
  EXPECT_FALSE(slower.time_step_info().reduced);
  EXPECT_DOUBLE_EQ(slower.time_step(), 0.5 * info.stable);
}

TEST(ExplicitControls, ReadingAIterationConvergesOnlyBelowOneOverOmega) {
  const test::TestModel model = bar(0.2);
  ExplicitSettings probe;
  probe.reading = Reading::A;
  const Real omega = ExplicitSolver(model, probe).time_step_info().omega;
  for (const Real factor : {0.5, 1.3}) {
    ExplicitSettings s;
    s.reading = Reading::A;
    s.stable_step = StableStepMethod::None;
    s.time_step = factor / omega;
    s.max_halvings = 0;
    ExplicitSolver solver(model, s);
    const StepReport r = solver.run(10.0 * s.time_step);
    if (factor < 1.0)
      EXPECT_TRUE(r.ok()) << r.message;
    else
      EXPECT_EQ(r.status, StepStatus::TooManyHalvings) << "dt = 1.3/omega must not converge";
  }
}

TEST(ExplicitControls, NonConvergedStepIsRepeatedWithHalfTheStep) {
  const test::TestModel model = bar(0.2);
  ExplicitSettings probe;
  probe.reading = Reading::A;
  const Real omega = ExplicitSolver(model, probe).time_step_info().omega;
  ExplicitSettings s;
  s.reading = Reading::A;
  s.stable_step = StableStepMethod::None;
  s.time_step = 1.3 / omega;
  ExplicitSolver solver(model, s);
  const StepReport r = solver.step(s.time_step); // the target is one full step away
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_GE(r.halvings, 1);
  EXPECT_NEAR(r.dt, s.time_step / std::pow(2.0, r.halvings), 1e-14 * r.dt); // halving is exact
}

namespace {

/// A neo-Hookean law that fails (NaN stress) once I1 − 3 exceeds a threshold: a stand-in for a
/// law evaluated outside its range, to provoke a non-finite value mid-run.
class FailingLaw final : public material::ElasticLaw {
public:
  explicit FailingLaw(Real threshold)
      : base_(test::law_of(test::deviatoric_material(1.0, 1.0))), threshold_(threshold) {}
  Real energy(const Mat3& C) const override { return base_->energy(C); }
  Mat3 stress(const Mat3& C) const override {
    return C.trace() - 3.0 > threshold_ ? Mat3::Constant(std::nan("")) : base_->stress(C);
  }
  material::StressTangent stress_tangent(const Mat3& C) const override {
    return base_->stress_tangent(C);
  }
  Real p_wave_modulus() const override { return base_->p_wave_modulus(); }
  Real shear_modulus() const override { return base_->shear_modulus(); }
  std::string type() const override { return "failing"; }

private:
  std::shared_ptr<const material::ElasticLaw> base_;
  Real threshold_;
};

} // namespace

TEST(ExplicitControls, NonFiniteValueStopsTheRunNamingStepCellAndQuantityKeepingHistory) {
  std::unique_ptr<model::Model> shared = bar_case(test::deviatoric_material(1.0, 2.0), 0.2).build();
  for (model::CellMaterial& m : shared->materials)
    m.solid = std::make_shared<FailingLaw>(0.01);
  const test::TestModel model(std::move(shared));
  ExplicitSolver solver(model, ExplicitSettings{});
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / "trifem_explicit_nonfinite_history.csv";
  long accepted = 0;
  {
    HistoryWriter history(file, {});
    history.record_initial(solver);
    const StepReport r = solver.run(50.0, [&](const ExplicitSolver& sv, const StepReport& rep) {
      history.record(sv, rep);
      ++accepted;
    });
    std::printf("stopped: %s\n", r.message.c_str());
    EXPECT_EQ(r.status, StepStatus::NonFinite);
    EXPECT_NE(r.message.find(fmt::format("step {} ", accepted + 1)), std::string::npos);
    EXPECT_NE(r.message.find("non-finite internal force Q_V in cell "), std::string::npos);
    EXPECT_GT(accepted, 1);
  }
  std::ifstream in(file);
  long lines = 0;
  for (std::string line; std::getline(in, line);)
    ++lines;
  EXPECT_EQ(lines, accepted + 2); // header, initial row, every accepted step
  std::filesystem::remove(file);
}
