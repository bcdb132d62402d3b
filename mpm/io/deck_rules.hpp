#pragma once
// The rules of a CB-Geo MPM deck that both its writer (fem2mpm) and its reader (mpm) apply, defined
// once so that fem2mpm never writes a deck that mpm rejects. Each rule is a common::NumberRange or a
// function returning what is wrong ("" when the value is fine); the caller names the option or key.
// Units: SI (Pa, kg/m3, s, m/s2); angles in degrees.
#include <string>

#include "common/finite_number.hpp"

namespace mpm::io {

/// Material parameters (materials[k] of mpm.json; fem2mpm's --E, --nu, --density, --phi, ...).
inline const common::NumberRange kDensityRange = common::NumberRange::positive();
inline const common::NumberRange kYoungsModulusRange = common::NumberRange::positive();
/// Poisson's ratio: (-1, 0.5) keeps the elastic tangent positive definite.
inline const common::NumberRange kPoissonRatioRange = common::NumberRange::open(-1, 0.5);
/// Mohr-Coulomb friction and dilation angles, degrees.
inline const common::NumberRange kFrictionAngleRange = common::NumberRange::closed_open(0, 90).named("an angle in degrees");
inline const common::NumberRange kCohesionRange = common::NumberRange::non_negative();
inline const common::NumberRange kTensionCutoffRange = common::NumberRange::non_negative();
inline const common::NumberRange kPdstrainRange = common::NumberRange::non_negative();
/// Cundall damping factor (analysis.damping.damping_factor): 1 would stop every motion.
inline const common::NumberRange kDampingFactorRange = common::NumberRange::closed_open(0, 1);
/// Coulomb friction coefficient of a friction constraint.
inline const common::NumberRange kFrictionCoefficientRange = common::NumberRange::non_negative();
/// analysis.dt.
inline const common::NumberRange kTimeStepRange = common::NumberRange::positive();
/// Gravity components and prescribed velocities: any finite number.
inline const common::NumberRange kFiniteRange = common::NumberRange::any();

/// "" when `ratio` is a usable separation_volume_ratio (0 = never, or a number > 1), else what is wrong.
std::string separation_volume_ratio_problem(double ratio);

/// "" when dilation <= friction (Mohr-Coulomb's flow rule: psi <= phi), else what is wrong.
std::string dilation_problem(double dilation_deg, double friction_deg);

/// "" when `uuid` is a run name usable as one folder name (letters, digits, '_', '-', '.', '+'; not
/// "." or ".."; at most 255 bytes), else what is wrong.
std::string run_name_problem(const std::string& uuid);

}  // namespace mpm::io
