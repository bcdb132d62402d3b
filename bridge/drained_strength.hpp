#pragma once
// The drained strength of the liquefiable FEM materials, as the Mohr-Coulomb material (CB-Geo MohrCoulomb2D)
// of their particles that are not liquefied at the transfer (issue 36, item 2):
// - PM4Sand (Boulanger & Ziotopoulou 2017, "PM4Sand (Version 3.1)", Report UCD/CGM-17/01, UC Davis) and PM4Silt
//   (Boulanger & Ziotopoulou 2018, "PM4Silt (Version 1)", Report UCD/CGM-18/01): the critical-state friction
//   angle phi_cv, no cohesion, no dilation (steady shearing at critical state); the elastic constants of the
//   model's elastic stage: G = G0 P_atm (OpenSees PM4Sand.cpp / PM4Silt.cpp GetElasticModuli with
//   m_FirstCall's stage 0; fem_tcl/materials/pm4sand.cpp, pm4silt.cpp), E = 2 G (1 + nu). The plastic stage's
//   G = G0 P_atm sqrt(p/P_atm) differs from particle to particle; one MPM material has one modulus, and the
//   elastic stage's is the one the FEM's gravity state was built with (and the stiffest: the MPM time step
//   it sets is safe for the rest).
// - PressureDependMultiYield02 (Yang, Elgamal & Parra 2003, J. Geotech. Geoenviron. Eng. 129(12) 1119-1127;
//   OpenSees' nDMaterial PressureDependMultiYield02): its friction angle frictionAng and its cohesion c (the
//   shift of its cone, OpenSees' default 0.3 kPa), no dilation; E, nu from refShearModul and refBulkModul
//   (the moduli at refPress, those of its elastic stage).
// Units: those of the model file (stress and moduli; angles in degrees).
#include <optional>
#include <string>

#include "bridge/fem_model.hpp"

namespace bridge {

struct DrainedStrength {
  double E = 0, nu = 0;          ///< model stress units, -
  std::optional<double> rho;     ///< model density units, when the material gives it
  double phi_deg = 0, cohesion = 0, psi_deg = 0;
  std::string note;              ///< what was chosen, for the report
};

/// The drained strength of `m` when it is PM4Sand, PM4Silt or PressureDependMultiYield02 with the values it
/// needs (fem_tcl's print -JSON entries); nullopt otherwise (e.g. OpenSees 3.8's text blocks: options then).
std::optional<DrainedStrength> drained_strength(const FemMaterial& m);

}  // namespace bridge
