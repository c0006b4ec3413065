// SPDX-License-Identifier: MIT
#include "trifem/model/averages.hpp"

#include "trifem/core/error.hpp"
#include "trifem/model/conditions.hpp"

namespace trifem::model {
namespace {

/// The cells of the block of `a` (the i-th average).
std::vector<Index> block_cells(const io::AverageSpec& a, std::size_t i, const Model& model) {
  const std::string key = fmt::format("output.average[{}].block", i + 1);
  std::vector<Index> cells = with_context(key, [&] { return model.mesh.cell_block(a.block); });
  TRIFEM_CHECK(!cells.empty(), "{} = '{}': the cell block has no cells", key, a.block);
  return cells;
}

/// Fails naming the first cell of `cells` whose material lacks the quantity `q`.
void check_materials(const io::ProbeQuantity& q, const io::AverageSpec& a, std::size_t i,
                     const std::vector<Index>& cells, const Model& model) {
  for (Index c : cells) {
    const auto& mixture = model.materials[c].mixture;
    TRIFEM_CHECK(io::material_has(q, mixture != nullptr, mixture && mixture->charged),
                 "output.average[{}].quantity = '{}': the material of {} of the cell block "
                 "'{}' has no {} (it needs a {} material)",
                 i + 1, q.name, model.mesh.describe(c), a.block, q.name, io::required_material(q));
  }
}

} // namespace

std::vector<Average> make_averages(const io::CaseSpec& spec, const Model& model) {
  std::vector<Average> averages;
  for (std::size_t i = 0; i < spec.output.averages.size(); ++i) {
    const io::AverageSpec& a = spec.output.averages[i];
    const io::ProbeQuantity* q = io::find_probe_quantity(a.quantity);
    TRIFEM_VERIFY(q, "unknown probe quantity {}", a.quantity); // the reader checked it
    std::vector<Index> cells = block_cells(a, i, model);
    check_materials(*q, a, i, cells, model);
    averages.push_back({a.name, q, a.block, std::move(cells)});
  }
  return averages;
}

} // namespace trifem::model
