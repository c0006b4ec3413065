// SPDX-License-Identifier: MIT
// The tissue materials of the case-file tests that run the same check on a solid, a biphasic
// and a triphasic (Donnan-prestressed) body: each a [materials.tissue] table.
#pragma once

namespace trifem::test {

constexpr const char* kSolid = R"(
[materials.tissue]
type = "neo-hookean"
E = 1.0
nu = 0.3
)";

constexpr const char* kBiphasic = R"(
[materials.tissue]
type = "biphasic"
phi_s0 = 0.25
permeability = 1.07e-3
[materials.tissue.solid]
type = "neo-hookean"
E = 0.3
nu = 0.2
)";

constexpr const char* kTriphasic = R"(
[materials.tissue]
type = "triphasic"
phi_s0 = 0.25
permeability = 1.07e-3
fixed_charge = 2.0e-4
d_plus = 5.0e-4
d_minus = 8.0e-4
[materials.tissue.solid]
type = "neo-hookean"
E = 0.3
nu = 0.2
[analysis]
initial_state = "donnan-prestressed"
)";

} // namespace trifem::test
