#include "mpm/core/velocity_transfer.hpp"

#include "common/input_error.hpp"
#include "common/number_text.hpp"

namespace mpm::core {

VelocityTransfer VelocityTransfer::from(const Analysis& an) {
  VelocityTransfer t;
  t.kind = an.velocity_update && an.transfer == Transfer::FLIP ? Transfer::PIC : an.transfer;
  if (an.velocity_update && t.kind != Transfer::PIC)
    throw common::InputError("analysis.transfer", "velocity_update true means PIC and contradicts the apic transfer");
  if (t.kind == Transfer::FLIP) {
    t.pic = an.pic_blend;
    if (!(t.pic >= 0.0 && t.pic <= 1.0))
      throw common::InputError("analysis.pic_blend",
                               "expected a number in [0, 1], got " + common::number_text(t.pic, 10));
  } else if (t.kind == Transfer::PIC) {
    t.pic = 1.0;
  } else if (an.pic_blend != 0.0) {
    throw common::InputError("analysis.pic_blend", "applies to the flip transfer only (the transfer is apic)");
  }
  return t;
}

}  // namespace mpm::core
