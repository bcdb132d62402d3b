#pragma once
// The particle materials of the engine, each a small value type with one stress-update function that
// the engine calls from a loop templated on the material type (no virtual call per particle).
// Stress (sxx, syy, szz, sxy), Pa, tension positive; strain increment (dexx, deyy, dgxy), engineering shear;
// plane strain (dezz = 0). State variables in CB-Geo's order (FORMATS.md section 4).
#include <array>
#include <cmath>
#include <cstddef>

#include "constitutive/mohr_coulomb.hpp"
#include "constitutive/stress_invariants.hpp"
#include "mpm/core/lanes.hpp"
#include "mpm/problem/deck.hpp"

namespace mpm::core {

/// Number of state variables stored per particle (the largest count of any material: Mohr-Coulomb's 7).
inline constexpr std::size_t kStateVariables = 7;

/// Isotropic linear elasticity in plane strain, hypoelastic rate form (CB-Geo LinearElastic2D):
/// dsigma = D : deps with D the isotropic stiffness, K bulk and G shear modulus,
/// dsxx = (K + 4G/3) dexx + (K - 2G/3) deyy, dszz = (K - 2G/3)(dexx + deyy), dsxy = G dgxy.
struct LinearElastic {
  double bulk = 0, shear = 0;
  static constexpr std::size_t kStateCount = 0;
  static LinearElastic from(const MaterialSpec& spec);
  void initial_state(double* /*svars*/) const {}
  /// An elastic solid never separates (see MohrCoulomb::separated).
  static constexpr bool separated(double /*mass*/, double /*volume*/) { return false; }
  void update(double* stress, const double* dstrain, double* /*svars*/) const {
    const double a1 = bulk + 4.0 / 3.0 * shear, a2 = bulk - 2.0 / 3.0 * shear;
    stress[0] += a1 * dstrain[0] + a2 * dstrain[1];
    stress[1] += a2 * dstrain[0] + a1 * dstrain[1];
    stress[2] += a2 * (dstrain[0] + dstrain[1]);
    stress[3] += shear * dstrain[2];
  }
};

/// CB-Geo's Mohr-Coulomb material (include/materials/mohr_coulomb.tcc) apart from the dimension: its
/// parameters resolved once, the peak and residual return maps, CB-Geo's linear softening and its 7 state
/// variables in its order:
///   svars = [phi, psi, cohesion, epsilon = sqrt(3) p, rho = sqrt(2 J2), theta (Lode, [0, pi/3]), pdstrain].
/// pdstrain accumulates the equivalent plastic deviatoric strain increment sqrt(2/3) |dev(deps_p)| (tensor
/// norm; CB-Geo's lambda * dP/dq with q = sqrt(3 J2)). As in CB-Geo, the strength used in a step is the one
/// reached at the start of the step (softening applied before the return). The plane-strain update is
/// MohrCoulomb (below), the 3D one MohrCoulomb3D (materials_3d.hpp).
struct MohrCoulombParameters {
  double bulk = 0, shear = 0;
  constitutive::PlaneStrainStiffness stiffness;  ///< of bulk and shear, for the elastic trial
  double phi_peak = 0, psi_peak = 0, c_peak = 0;
  double phi_residual = 0, psi_residual = 0, c_residual = 0;
  double pdstrain_peak = 0, pdstrain_residual = 0;
  double tension_cutoff = 0;
  bool softening = false;
  /// density / separation_volume_ratio, kg/m3 (0: never separates); see separated().
  double separation_density = 0;
  /// The peak and residual strengths with their sin / cos evaluated once (from()); update() uses them
  /// when the particle's (phi, psi) equal one of them, and evaluates its own only inside the
  /// softening range (or for other angles read from a resume file).
  constitutive::MohrCoulombSurface peak_surface, residual_surface;
  /// Their return maps (planes and active-set matrices formed once), used when the particle's whole
  /// strength (phi, psi, c) is the peak or the residual one: the same result bit for bit, less work.
  constitutive::MohrCoulombReturnMap peak_map, residual_map;
  static constexpr std::size_t kStateCount = 7;
  static MohrCoulombParameters from(const MaterialSpec& spec);
  void initial_state(double* svars) const;
  /// Whether update() takes the peak map: no softening this step and the particle at the peak strength.
  bool at_peak_strength(const double* svars) const {
    return !(softening && svars[6] > pdstrain_peak) && has_strength_of(peak_map, peak_surface, svars);
  }
  /// Whether the particle's strength (svars phi, psi, c) is the one `map` was built from.
  static bool has_strength_of(const constitutive::MohrCoulombReturnMap& map,
                              const constitutive::MohrCoulombSurface& built_from, const double* svars) {
    const constitutive::MohrCoulombStrength& c = built_from.strength;
    return map.valid() && svars[0] == c.friction && svars[1] == c.dilation && svars[2] == c.cohesion;
  }
  /// CB-Geo's linear softening of svars phi, psi, c over pdstrain (svars[6]) from peak_pdstrain to
  /// residual_pdstrain (mohr_coulomb.tcc, compute_stress, before the predictor); nothing below the peak.
  void soften(double* svars) const;
  /// The peak or residual map when the particle has that whole strength, else nullptr.
  const constitutive::MohrCoulombReturnMap* map_of(const double* svars) const {
    return has_strength_of(peak_map, peak_surface, svars)
               ? &peak_map
               : (has_strength_of(residual_map, residual_surface, svars) ? &residual_map : nullptr);
  }
  /// The particle's surface (svars phi, psi, c and the cutoff), the trigonometry of the peak or residual
  /// angles reused when they are the particle's.
  constitutive::MohrCoulombSurface surface_of(const double* svars) const;
  /// The equivalent plastic deviatoric strain increment sqrt(2/3 |dev(dp)|^2) of a plastic strain increment
  /// dp = (dexx, deyy, dezz, then kShears engineering shears), added to pdstrain by a return.
  template <int kShears>
  static double plastic_deviatoric_strain(const double* dp) {
    const double mean = (dp[0] + dp[1] + dp[2]) / 3.0;
    const double d0 = dp[0] - mean, d1 = dp[1] - mean, d2 = dp[2] - mean;
    double sum = d0 * d0 + d1 * d1 + d2 * d2;
    for (int i = 3; i < 3 + kShears; ++i) {
      const double h = 0.5 * dp[i];  // tensor shear component
      sum += 2.0 * h * h;
    }
    return std::sqrt(2.0 / 3.0 * sum);
  }
  /// CB-Geo's invariant state variables of a full stress (svars[3..5]: epsilon, rho, theta).
  static void set_invariants_of(const constitutive::Stress6& stress, double* svars);
  /// Stress-free separation (an extension; CB-Geo has none): a particle whose density mass / volume has
  /// fallen below separation_density is disconnected grains and carries no stress, the "disconnected"
  /// regime of Dunatunga & Kamrin (2015, J. Fluid Mech. 779, 483-513, section 2.2: sigma = 0 below the
  /// critical density). Without it a particle torn off at the apex of the yield surface keeps dilating
  /// with its neighbours' motion (V grew 100-2000x on the paper's column) and its nodal force V sigma grad N
  /// with it, until nearly empty cells run away. The engine zeroes the stress after the update; a particle
  /// that is compacted again reloads from zero stress.
  bool separated(double mass, double volume) const { return mass < separation_density * volume; }
};

/// CB-Geo's MohrCoulomb2D: the plane-strain Mohr-Coulomb return of constitutive::mohr_coulomb_update
/// (exact at face, edges and apex, with a Rankine tension cutoff) with MohrCoulombParameters' softening and
/// state variables.
struct MohrCoulomb : MohrCoulombParameters {
  static MohrCoulomb from(const MaterialSpec& spec) { return {MohrCoulombParameters::from(spec)}; }
  /// The stress update. Inline, the common case: no softening this step and the peak strength (the
  /// elastic trial for most particles, every step, without a call; the peak map's return for the rest);
  /// softening and any other strength in update_general() (which handles every case).
  void update(double* stress, const double* dstrain, double* svars) const {
    if (at_peak_strength(svars)) {
      const constitutive::PlaneStrainStress trial = constitutive::elastic_trial(
          Eigen::Map<const Eigen::Vector4d>(stress), Eigen::Map<const Eigen::Vector3d>(dstrain), stiffness);
      if (peak_map.admits(trial)) {  // the trial stands, the state is unchanged
        Eigen::Map<Eigen::Vector4d> out(stress);
        out = trial;
        return;
      }
      store(peak_map.apply_plastic(trial), stress, svars);
      return;
    }
    update_general(stress, dstrain, svars);
  }
  /// update() of four particles whose stress, dstrain and svars blocks (4, 3 and kStateVariables values)
  /// follow one another: at the peak strength the four trials and their elastic test in the lanes of a
  /// Double4, then the return of each trial it refuses. The same results as four update() calls, bit
  /// for bit (the same operations per lane; tests/unit/mpm/core_materials_test.cpp).
  void update4(double* stress, const double* dstrain, double* svars) const {
    for (int l = 0; l < 4; ++l)
      if (!at_peak_strength(svars + kStateVariables * l)) {
        for (int p = 0; p < 4; ++p) update(stress + 4 * p, dstrain + 3 * p, svars + kStateVariables * p);
        return;
      }
    Double4 s[4], de[3], trial[4];  // component c of particle l in lane l
    load_transposed4(stress, s);
    load_transposed4x3(dstrain, de);
    constitutive::elastic_trial_of(s, de, stiffness, trial);
    store_transposed4(trial, stress);
    const constitutive::Extremes<Double4> t = constitutive::principal_extremes(trial[0], trial[1], trial[2], trial[3]);
    const auto admitted = peak_map.strictly_admits(t);
    if (admitted[0] && admitted[1] && admitted[2] && admitted[3]) return;  // the common case
    for (int l = 0; l < 4; ++l) {
      double* sl = stress + 4 * l;
      if (admitted[l] || peak_map.admits_at_round_off({t.s1[l], t.s3[l]})) continue;
      store(peak_map.apply_plastic(Eigen::Map<const Eigen::Vector4d>(sl)), sl, svars + kStateVariables * l);
    }
  }
  void update_general(double* stress, const double* dstrain, double* svars) const;
  /// A return's stress, and its plastic strain increment added to pdstrain (svars[6]).
  static void store(const constitutive::MohrCoulombUpdate& r, double* stress, double* svars);
  /// CB-Geo's invariant state variables of `stress` (svars[3..5]: epsilon, rho, theta). They depend on
  /// the stress only, so the engine computes them when it writes the state (snapshot), not every step.
  static void set_invariants(const double* stress, double* svars);
};

/// A material of the deck, resolved: its type, its spec id and its model parameters, for the elastic
/// and Mohr-Coulomb models of one dimension (Material: plane strain; Material3D, materials_3d.hpp: 3D).
template <class Elastic, class Plastic>
struct MaterialOf {
  MaterialType type = MaterialType::LinearElastic2D;
  unsigned id = 0;
  double density = 0;
  double p_wave_modulus = 0;  ///< K + 4G/3, Pa (for the time-step limit)
  std::size_t state_count = 0;
  Elastic elastic;
  Plastic mohr_coulomb;
  static MaterialOf from(const MaterialSpec& spec) {
    MaterialOf m;
    m.type = spec.type;
    m.id = spec.id;
    m.density = spec.density;
    const LinearElastic moduli = LinearElastic::from(spec);
    m.p_wave_modulus = moduli.bulk + 4.0 / 3.0 * moduli.shear;
    if (spec.type == MaterialType::LinearElastic2D) {  // = LinearElastic3D
      m.elastic = Elastic::from(spec);
      m.state_count = Elastic::kStateCount;
    } else {
      m.mohr_coulomb = Plastic::from(spec);
      m.state_count = Plastic::kStateCount;
    }
    return m;
  }
};
using Material = MaterialOf<LinearElastic, MohrCoulomb>;

}  // namespace mpm::core
