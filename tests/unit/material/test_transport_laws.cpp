// SPDX-License-Identifier: MIT
// Tests of the permeability and diffusivity laws of a mixture: derivatives by central
// differences, closed-form values, the registries' messages, and the laws in make_mixture.
#include "trifem/core/error.hpp"
#include "trifem/material/mixture.hpp"
#include "trifem/material/registry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace trifem;
using namespace trifem::material;

namespace {

constexpr Real kPhiS0 = 0.25;

/// The message of the InputError that `f` throws ("" if none).
template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// Every permeability law with strain dependence switched on (cartilage-like values).
std::vector<std::pair<std::string, std::unique_ptr<PermeabilityLaw>>> permeabilities() {
  std::vector<std::pair<std::string, std::unique_ptr<PermeabilityLaw>>> out;
  out.emplace_back("constant", create_permeability("constant", {{"k0", 1.07e-3}}, kPhiS0, "k"));
  out.emplace_back("holmes-mow",
                   create_permeability("holmes-mow", {{"k0", 1.07e-3}, {"M", 4.6}, {"alpha", 2.0}},
                                       kPhiS0, "k"));
  out.emplace_back(
      "holmes-mow (alpha only)",
      create_permeability("holmes-mow", {{"k0", 1.07e-3}, {"alpha", 1.5}}, kPhiS0, "k"));
  out.emplace_back("exponential",
                   create_permeability("exponential", {{"k0", 1.07e-3}, {"M", 3.0}}, kPhiS0, "k"));
  return out;
}

} // namespace

/// dkappa/dJ = central difference of kappa on J from near pore closure to strong swelling,
/// relative to |dkappa/dJ| + kappa/J (a scale that does not vanish).
TEST(PermeabilityLaw, DerivativeMatchesCentralDifferences) {
  ASSERT_EQ(permeability_laws().size(), 3u);
  for (const auto& [name, law] : permeabilities()) {
    for (Real J : {0.3, 0.5, 0.8, 1.0, 1.3, 2.0}) {
      const Real h = 1e-6 * (J - kPhiS0); // kappa is steep near pore closure
      const Real fd = (law->value(J + h) - law->value(J - h)) / (2 * h);
      const Real exact = law->derivative(J);
      EXPECT_LE(std::abs(fd - exact), 1e-8 * (std::abs(exact) + law->value(J) / J))
          << name << " at J = " << J << ": " << exact << " vs " << fd;
    }
  }
}

/// Values the formulas must give: k0 in the reference state, and points where the exponent or
/// the power law take round values.
TEST(PermeabilityLaw, ClosedFormValues) {
  const Real k0 = 1.07e-3, M = 4.6, mid = (1.0 + kPhiS0) / 2; // (J - phi_s0)/(1 - phi_s0) = 1/2
  const auto hm =
      create_permeability("holmes-mow", {{"k0", k0}, {"M", M}, {"alpha", 2.0}}, kPhiS0, "k");
  EXPECT_DOUBLE_EQ(hm->value(1.0), k0);
  EXPECT_NEAR(hm->value(mid), k0 * 0.25 * std::exp(M * (mid * mid - 1) / 2), 1e-15 * k0);
  EXPECT_LT(hm->value(kPhiS0 + 1e-6), 1e-11 * k0); // pores close at J = phi_s0
  const auto power = create_permeability("holmes-mow", {{"k0", k0}, {"alpha", 2.0}}, kPhiS0, "k");
  EXPECT_NEAR(power->value(mid), k0 / 4, 1e-16 * k0); // M defaults to 0
  const auto ex = create_permeability("exponential", {{"k0", k0}, {"M", M}}, kPhiS0, "k");
  EXPECT_DOUBLE_EQ(ex->value(1.0), k0);
  // (J - 1)/(J - phi_s0) = -1 at J = mid: kappa = k0 e^-M; small strain: k0 exp(M e/(1 - phi_s0))
  EXPECT_NEAR(ex->value(mid), k0 * std::exp(-M), 1e-15 * k0);
  const Real e = 1e-4;
  EXPECT_NEAR(std::log(ex->value(1 + e) / k0), M * e / (1 - kPhiS0), 1e-3 * M * e);
  EXPECT_LT(ex->value(kPhiS0 + 1e-6), 1e-100 * k0);
  // M = alpha = 0 is the constant law, bit for bit
  const auto flat = create_permeability("holmes-mow", {{"k0", k0}}, kPhiS0, "k");
  for (Real J : {0.4, 1.0, 1.7}) {
    EXPECT_EQ(flat->value(J), k0);
    EXPECT_EQ(flat->derivative(J), 0.0);
  }
  EXPECT_TRUE(create_permeability("constant", {{"k0", k0}}, kPhiS0, "k")->is_constant());
  EXPECT_FALSE(flat->is_constant());
}

TEST(DiffusivityLaw, DerivativeMatchesCentralDifferences) {
  ASSERT_EQ(diffusivity_laws().size(), 2u);
  for (const auto& law : {create_diffusivity("constant", {{"d", 5e-4}}, "d"),
                          create_diffusivity("mackie-meares", {{"d0", 1.33e-3}}, "d")}) {
    for (Real phi : {0.05, 0.3, 0.6, 0.75, 0.9, 0.99}) {
      const Real h = 1e-5 * phi;
      const Real fd = (law->value(phi + h) - law->value(phi - h)) / (2 * h);
      const Real exact = law->derivative(phi);
      EXPECT_LE(std::abs(fd - exact), 1e-8 * (std::abs(exact) + law->value(phi) / phi))
          << "phi_w = " << phi << ": " << exact << " vs " << fd;
    }
  }
}

TEST(DiffusivityLaw, MackieMearesClosedFormValues) {
  const Real d0 = 1.33e-3;
  const auto mm = create_diffusivity("mackie-meares", {{"d0", d0}}, "d");
  EXPECT_DOUBLE_EQ(mm->value(1.0), d0);             // free solution
  EXPECT_NEAR(mm->value(2.0 / 3.0), d0 / 4, 1e-18); // phi/(2 - phi) = 1/2
  EXPECT_NEAR(mm->value(0.75), d0 * 0.36, 1e-18);   // the paper's phi_w0: 4.79e-4 mm^2/s
  EXPECT_NEAR(mm->derivative(1.0), 4 * d0, 1e-17);
  EXPECT_FALSE(mm->is_constant());
  EXPECT_TRUE(create_diffusivity("constant", {{"d", 5e-4}}, "d")->is_constant());
}

TEST(TransportLaws, BadParametersNameTheKey) {
  EXPECT_EQ(error_of([] {
              create_permeability("holmes", {{"k0", 1e-3}}, kPhiS0, "m.permeability");
            }),
            "m.permeability.type = 'holmes': unknown permeability law (expected one of: constant, "
            "holmes-mow, exponential)");
  EXPECT_EQ(error_of([] {
              create_diffusivity("mackie", {{"d0", 1e-3}}, "m.d_plus");
            }),
            "m.d_plus.type = 'mackie': unknown diffusivity law (expected one of: constant, "
            "mackie-meares)");
  const std::string missing = error_of([] {
    create_permeability("holmes-mow", {{"M", 1.0}}, kPhiS0, "m.permeability");
  });
  EXPECT_NE(missing.find("m.permeability.k0: missing required parameter"), std::string::npos)
      << missing;
  const std::string negative = error_of([] {
    create_permeability("exponential", {{"k0", 1e-3}, {"M", -1.0}}, kPhiS0, "m.permeability");
  });
  EXPECT_NE(negative.find("m.permeability.M = -1: out of range, expected a value in [0, inf)"),
            std::string::npos)
      << negative;
  const std::string unknown = error_of([] {
    create_diffusivity("mackie-meares", {{"d", 1e-3}}, "m.d_minus");
  });
  EXPECT_NE(unknown.find("m.d_minus.d: unknown parameter (expected one of: d0)"), std::string::npos)
      << unknown;
}

namespace {

std::shared_ptr<const ElasticLaw> svk() {
  return create_law("saint-venant-kirchhoff", {{"E", 0.3}, {"nu", 0.0}}, "solid");
}

ParameterValues triphasic_values() {
  return {{"phi_s0", kPhiS0},
          {transport_law_key("permeability", "holmes-mow", "k0"), 1.07e-3},
          {transport_law_key("permeability", "holmes-mow", "M"), 4.6},
          {"fixed_charge", 2e-4},
          {transport_law_key("d_plus", "mackie-meares", "d0"), 1.33e-3},
          {"d_minus", 8e-4}};
}

} // namespace

/// make_mixture builds the laws from case values: reference values, the laws themselves and the
/// defaults of the laws' parameters.
TEST(MixtureTransportLaws, MakeMixtureBuildsTheLaws) {
  EXPECT_EQ(transport_law_key("permeability", "holmes-mow", "k0"), "permeability.holmes-mow.k0");
  const MixtureProperties m = make_mixture(true, svk(), triphasic_values(), "m");
  EXPECT_DOUBLE_EQ(m.permeability, 1.07e-3);  // kappa(1)
  EXPECT_DOUBLE_EQ(m.d_plus, 1.33e-3 * 0.36); // d+(phi_w0 = 0.75)
  EXPECT_DOUBLE_EQ(m.d_minus, 8e-4);          // constant
  EXPECT_DOUBLE_EQ(m.permeability_law->value(1.2), 1.07e-3 * std::exp(4.6 * 0.44 / 2)); // alpha 0
  EXPECT_DOUBLE_EQ(m.d_plus_law->value(0.5), 1.33e-3 / 9);
  EXPECT_TRUE(m.d_minus_law->is_constant());
  const ParameterValues v = validate_mixture_parameters(true, triphasic_values(), "m");
  EXPECT_EQ(v.at("permeability.holmes-mow.alpha"), 0.0); // default filled in
  EXPECT_EQ(v.count("permeability"), 0u);
  EXPECT_EQ(v.at("osmotic"), 1.0);
  // the constant laws keep the plain numbers
  const MixtureProperties c =
      make_mixture(false, svk(), {{"phi_s0", kPhiS0}, {"permeability", 2e-3}}, "m");
  EXPECT_TRUE(c.permeability_law->is_constant());
  EXPECT_EQ(c.permeability_law->value(0.6), 2e-3);
}

TEST(MixtureTransportLaws, BadLawsNameTheKey) {
  auto with = [](const std::string& key, Real value) {
    ParameterValues v = triphasic_values();
    v[key] = value;
    return v;
  };
  EXPECT_EQ(error_of([&] { make_mixture(true, svk(), with("permeability", 1e-3), "m"); }),
            "m.permeability: given both as a number and as a law");
  EXPECT_EQ(
      error_of([&] { make_mixture(true, svk(), with("permeability.exponential.k0", 1e-3), "m"); }),
      "m.permeability: two laws given ('exponential' and 'holmes-mow')");
  EXPECT_EQ(error_of([&] { make_mixture(true, svk(), with("osmotic.constant.d", 1.0), "m"); }),
            "m.osmotic: only permeability, d_plus and d_minus take a law (a table with a type)");
  EXPECT_EQ(error_of([&] { make_mixture(true, svk(), with("d_minus.linear.d0", 1e-3), "m"); }),
            "m.d_minus: given both as a number and as a law");
  ParameterValues unknown_type = triphasic_values();
  unknown_type.erase("d_minus");
  unknown_type["d_minus.linear.d0"] = 1e-3;
  EXPECT_EQ(error_of([&] { make_mixture(true, svk(), unknown_type, "m"); }),
            "m.d_minus.type = 'linear': unknown diffusivity law (expected one of: constant, "
            "mackie-meares)");
  const std::string biphasic = error_of([] {
    make_mixture(false, svk(),
                 {{"phi_s0", kPhiS0}, {"permeability", 1e-3}, {"d_plus.constant.d", 1e-3}}, "m");
  });
  EXPECT_NE(biphasic.find("m.d_plus: unknown parameter (expected one of: phi_s0, permeability)"),
            std::string::npos)
      << biphasic;
  const std::string missing = error_of([&] {
    ParameterValues v = triphasic_values();
    v.erase("permeability.holmes-mow.k0");
    make_mixture(true, svk(), v, "m");
  });
  EXPECT_NE(missing.find("m.permeability.k0: missing required parameter"), std::string::npos)
      << missing;
}
