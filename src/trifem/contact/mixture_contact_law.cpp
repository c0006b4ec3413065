// SPDX-License-Identifier: MIT
#include "trifem/contact/mixture_contact_law.hpp"

namespace trifem::contact {

MixtureContactLaw::MixtureContactLaw(MixtureContactFields fields) : f_(fields), normal_(fields.u) {
  TRIFEM_CHECK(f_.u.valid() && f_.w.valid(),
               "mixture contact: the displacement and fluid flux fields are required");
  TRIFEM_CHECK(f_.j_plus.valid() == f_.j_minus.valid(),
               "mixture contact: give both ion flux fields (triphasic) or neither (biphasic)");
}

dofs::FieldId MixtureContactLaw::paired_field(int c) const {
  switch (c) {
  case 0:
    return f_.u;
  case 1:
    return f_.w;
  case 2:
    return f_.j_plus;
  default:
    return f_.j_minus;
  }
}

std::vector<dofs::FieldId> MixtureContactLaw::constraint_fields() const {
  if (triphasic())
    return {f_.w, f_.j_plus, f_.j_minus};
  return {f_.w};
}

Real MixtureContactLaw::indicator(const SlaveNodeRows& node) const {
  return normal_.indicator(node);
}

void MixtureContactLaw::flux_row(const SlaveNodeRows& node, int c, dofs::FieldId F,
                                 LocalSystem& out) const {
  const Projection& pr = *node.projection;
  const ProjectionDerivatives& d = *node.derivatives;
  const Vector& x = node.state->x;
  const auto dof = [&](int j, int i) { return node.dofs->dof(F, node.nodes[j], i); };
  const int n = node.nodes.size - 1; // master facet nodes
  FacetNodeValues<3> fm(n, 3);       // nodal values on the master facet
  Vec3 fs;
  for (int i = 0; i < 3; ++i) {
    fs[i] = x[dof(0, i)];
    for (int a = 0; a < n; ++a)
      fm(a, i) = x[dof(1 + a, i)];
  }
  // the fluxes are linear from the corners (quadratic facets: zero weight at mid-edge nodes)
  const fe::FacetShapeValues N = corner_shape(node.facet_type, pr.xi);
  const Vec3 jump = fm.transpose() * N - fs;
  const Real weight = node.dt * node.weight;
  const Index row = node.lambda_at + c;
  out.r()[row] += weight * jump.dot(pr.normal);
  if (!out.with_jacobian())
    return;
  for (int i = 0; i < 3; ++i) {
    out.K()(row, out.at(dof(0, i))) -= weight * pr.normal[i];
    for (int a = 0; a < n; ++a)
      out.K()(row, out.at(dof(1 + a, i))) += weight * N[a] * pr.normal[i];
  }
  // through ξ and n: n·(Σ_a f_a N_{a,α}) ∂ξ^α/∂x + (f^m - f_s)·∂n/∂x
  const StencilRows<1> dx =
      pr.normal.transpose() * (fm.transpose() * corner_shape_grad(node.facet_type, pr.xi) * d.dxi) +
      jump.transpose() * d.dnormal;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i < 3; ++i)
      out.K()(row, node.x_at[j] + i) += weight * dx(3 * j + i);
}

void MixtureContactLaw::active_rows(const SlaveNodeRows& node, LocalSystem& out) const {
  normal_.active_rows(node, out);
  if (node.wetted || node.mid_edge) { // (no flux unknowns at a mid-edge node: λ = 0 there)
    bath_rows(node, 1, out);
    return;
  }
  flux_row(node, 1, f_.w, out);
  if (triphasic()) {
    flux_row(node, 2, f_.j_plus, out);
    flux_row(node, 3, f_.j_minus, out);
  }
}

void MixtureContactLaw::inactive_rows(const SlaveNodeRows& node, LocalSystem& out) const {
  bath_rows(node, 0, out);
}

void MixtureContactLaw::bath_rows(const SlaveNodeRows& node, int first, LocalSystem& out) const {
  const Real w = node.weight / node.scale;
  for (int c = first; c < num_components(); ++c) {
    const Index row = node.lambda_at + c;
    out.r()[row] += w * node.multiplier[c];
    if (out.with_jacobian())
      out.K()(row, row) += w;
  }
}

} // namespace trifem::contact
