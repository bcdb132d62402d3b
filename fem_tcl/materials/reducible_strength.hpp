#pragma once
// The strength a factor-of-safety analysis reduces (`strengthReduction`, fem_tcl/analysis/strength_reduction.hpp).
// Shear strength reduction (Zienkiewicz, Humpheson & Lewis 1975, Geotechnique 25(4):671-689; Griffiths & Lane
// 1999, Geotechnique 49(3):387-403, eqs. 1-2; Dawson, Roth & Drescher 1999, Geotechnique 49(6):835-840):
//   c_F = c / F,   phi_F = atan(tan(phi) / F),   psi_F = atan(tan(psi) / F)   (dilation likewise)
// applied to the strength the material was defined with; F = 1 is that strength.
namespace fem::materials {

class ReducibleStrength {
 public:
  virtual ~ReducibleStrength() = default;
  /// Sets the trial strength to the defined strength reduced by `factor` (> 0); the next trial state uses it.
  virtual void set_strength_reduction(double factor) = 0;
  /// The factor in force (1 after creation).
  virtual double strength_reduction() const = 0;
};

}  // namespace fem::materials
