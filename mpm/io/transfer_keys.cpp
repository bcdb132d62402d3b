#include "mpm/io/transfer_keys.hpp"

#include <algorithm>

#include "common/number_text.hpp"

namespace mpm::io {

const std::vector<std::string>& transfer_names() {
  static const std::vector<std::string> names = {"flip", "pic", "apic"};
  return names;
}

const std::string& transfer_name(Transfer t) { return transfer_names()[static_cast<std::size_t>(t)]; }

namespace {
Transfer named_transfer(StrictObject& a, const std::string& key, const std::string& name) {
  const auto& names = transfer_names();
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) a.fail(key, "unknown transfer \"" + name + "\" (expected flip, pic or apic)");
  return static_cast<Transfer>(it - names.begin());
}
}  // namespace

void read_velocity_transfer(StrictObject& a, Analysis& an) {
  const nlohmann::json* update = a.optional("velocity_update");
  const bool named = update != nullptr && update->is_string();  // newer CB-Geo decks: "flip", "pic", "apic"
  const bool has_velocity_update = update != nullptr && !named;  // CB-Geo's boolean: true means PIC
  const bool velocity_update = has_velocity_update && a.boolean("velocity_update");
  an.transfer = named ? named_transfer(a, "velocity_update", update->get<std::string>())
                      : (velocity_update ? Transfer::PIC : Transfer::FLIP);
  if (a.has("transfer")) {
    const auto chosen = named_transfer(a, "transfer", a.string("transfer"));
    if (named && chosen != an.transfer)
      a.fail("transfer", "\"" + transfer_name(chosen) + "\" contradicts velocity_update \"" +
                             transfer_name(an.transfer) + "\"; give one of the two keys");
    if (has_velocity_update && (chosen == Transfer::PIC) != velocity_update)
      a.fail("transfer", "\"" + transfer_name(chosen) + "\" contradicts velocity_update " + (velocity_update ? "true" : "false") +
                             " (true means pic, false flip or apic); give one of the two keys");
    an.transfer = chosen;
  }
  an.velocity_update = an.transfer == Transfer::PIC;
  an.pic_blend = an.transfer == Transfer::PIC ? 1.0 : 0.0;
  if (a.has("pic_blend")) {
    if (an.transfer != Transfer::FLIP)
      a.fail("pic_blend", "blends FLIP with PIC and applies to the flip transfer only (the transfer is " +
                              transfer_name(an.transfer) + ")");
    an.pic_blend = a.number("pic_blend");
    if (!(an.pic_blend >= 0 && an.pic_blend <= 1))
      a.fail("pic_blend", "expected a number in [0, 1], got " + common::number_text(an.pic_blend, 10));
  }
}

}  // namespace mpm::io
