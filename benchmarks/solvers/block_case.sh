#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Writes the case file of the 3-D triphasic block benchmark (docs/performance.md, "PETSc
# backends on 3-D triphasic blocks") to standard output:
#   block_case.sh CELLS SOLVER [PETSC_OPTIONS] [REUSE] [PRECONDITIONER] [INITIAL_STATE] [DT] [STEPS]
#                 [PRECISION] [SCHUR] [FLUX_MASS]
# A 1 mm cube of CELLS^3 hex8 cells of the paper's cartilage, bottom fixed and impermeable, the
# top compressed by 0.05 mm ramped over 50 s, STEPS steps (default 1) of DT s (default 2.5);
# SOLVER is any linear_solver, REUSE "true" sets reuse_factorization, PRECONDITIONER the krylov
# preconditioner (lu, amg), INITIAL_STATE the [analysis] initial_state (donnan,
# donnan-prestressed), PRECISION the factorization_precision of reused factorizations (single,
# double), SCHUR the krylov schur_approximation (selfp, drained), FLUX_MASS the [analysis]
# flux_mass (consistent, lumped).
set -euo pipefail
cells=${1:?usage: block_case.sh CELLS SOLVER [PETSC_OPTIONS] [REUSE]}
solver=${2:?usage: block_case.sh CELLS SOLVER [PETSC_OPTIONS] [REUSE]}
options=${3:-}
reuse=${4:-false}
preconditioner=${5:-lu}
initial_state=${6:-donnan}
dt=${7:-2.5}
steps=${8:-1}
precision=${9:-single}
schur=${10:-selfp}
flux_mass=${11:-consistent}
end_time=$(awk -v dt="$dt" -v n="$steps" 'BEGIN { print dt * n }')
cat <<CASE
title = "triphasic block ${cells}^3, ${solver}"

[[mesh.box]]
name = "b"
size = [1.0, 1.0, 1.0]
divisions = [${cells}, ${cells}, ${cells}]
material = "cartilage"

[materials.cartilage]
type = "triphasic"
phi_s0 = 0.25
permeability = 1.07e-3
fixed_charge = 2.0e-4
d_plus = 5.0e-4
d_minus = 8.0e-4

[materials.cartilage.solid]
type = "saint-venant-kirchhoff"
E = 0.3
nu = 0.0

[electrochemistry]
T = 298.0
bath_concentration = 1.5e-4

[curves.ramp]
points = [[0.0, 0.0], [50.0, 1.0]]

[[boundary.fixed]]
set = "b.zmin"

[[boundary.impermeable]]
set = "b.zmin"
normal = "z"

[[boundary.prescribed]]
set = "b.zmax"
component = "z"
value = -0.05
curve = "ramp"

[analysis]
initial_state = "${initial_state}"
flux_mass = "${flux_mass}"

[time]
end_time = ${end_time}
dt = ${dt}

[output]
vtu = false

[solver]
linear_solver = "${solver}"
CASE
[ -n "$options" ] && echo "petsc_options = \"${options}\""
[ "$reuse" = true ] && echo "reuse_factorization = true"
[ "$preconditioner" != lu ] && echo "preconditioner = \"${preconditioner}\""
[ "$precision" != single ] && echo "factorization_precision = \"${precision}\""
[ "$schur" != selfp ] && echo "schur_approximation = \"${schur}\""
exit 0
