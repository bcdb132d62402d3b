#include "mpm/io/transfer_keys.hpp"

#include <algorithm>

#include "common/number_text.hpp"

namespace mpm::io {

const std::vector<std::string>& transfer_names() {
  static const std::vector<std::string> names = {"flip", "pic", "apic"};
  return names;
}

const std::string& transfer_name(Transfer t) { return transfer_names()[static_cast<std::size_t>(t)]; }

void read_velocity_transfer(StrictObject& a, Analysis& an) {
  const bool has_velocity_update = a.has("velocity_update");
  const bool velocity_update = a.boolean_or("velocity_update", false);
  an.transfer = velocity_update ? Transfer::PIC : Transfer::FLIP;
  if (a.has("transfer")) {
    const std::string name = a.string("transfer");
    const auto& names = transfer_names();
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end())
      a.fail("transfer", "unknown transfer \"" + name + "\" (expected flip, pic or apic)");
    const auto chosen = static_cast<Transfer>(it - names.begin());
    if (has_velocity_update && (chosen == Transfer::PIC) != velocity_update)
      a.fail("transfer", "\"" + name + "\" contradicts velocity_update " + (velocity_update ? "true" : "false") +
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

void read_resume_affine(const std::filesystem::path& file, const std::string& shown, Deck& deck) {
  if (deck.analysis.transfer != Transfer::APIC) return;
  auto affine = read_affine_dataset(file, deck.particles.size());
  if (affine) {
    deck.particle_affine = std::move(*affine);
  } else {
    deck.particle_affine.clear();
    deck.warnings.push_back(shown + " has no /" + std::string(kAffineDataset) +
                            " dataset: the APIC transfer resumes from zero affine matrices (not bit for bit the run "
                            "that wrote it, if that run used APIC)");
  }
}

}  // namespace mpm::io
