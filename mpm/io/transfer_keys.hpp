#pragma once
// The velocity-transfer keys of a deck's analysis object: CB-Geo's velocity_update and this project's
// transfer and pic_blend (mpm/README.md, "Extensions"), read and checked together.
#include <string>
#include <vector>

#include "mpm/problem/deck.hpp"
#include "mpm/io/json_keys.hpp"

namespace mpm::io {

/// The names analysis.transfer accepts, in Transfer order: "flip", "pic", "apic".
const std::vector<std::string>& transfer_names();
/// The name of `t` in analysis.transfer ("flip", "pic", "apic").
const std::string& transfer_name(Transfer t);

/// Reads analysis.velocity_update (CB-Geo: true = PIC, false = FLIP), analysis.transfer ("flip", "pic",
/// "apic") and analysis.pic_blend into `an`. Either key alone decides the transfer (neither: FLIP);
/// both must agree (velocity_update true with "pic" only, false with "flip" or "apic"). pic_blend in
/// [0, 1] applies to FLIP only. Sets an.velocity_update = (transfer is PIC) and an.pic_blend = 1 for
/// PIC. A disagreement or a misplaced key is a common::InputError naming the key.
void read_velocity_transfer(StrictObject& analysis, Analysis& an);

}  // namespace mpm::io
