// SPDX-License-Identifier: MIT
// Case -> the [[output.average]] outputs of a model: each quantity with the cells of its block.
#pragma once

#include "trifem/model/model.hpp"

namespace trifem::model {

/// The averages of the case. InputError naming the key `output.average[i].block` if the block
/// is no cell block of the mesh or is empty, and `output.average[i].quantity` if a cell of the
/// block has a material without the quantity.
std::vector<Average> make_averages(const io::CaseSpec& spec, const Model& model);

} // namespace trifem::model
