#include "constitutive/mohr_coulomb.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>

#include "common/cpu_variants.hpp"

namespace constitutive {
namespace {

// Yield planes in sorted principal space (s1 >= s2 >= s3), each  m . s <= r, with plastic flow along n
// ([SPO] sec. 8.2; [CDA]):
//   0 main  (s1, s3)   m = (1+sin phi, 0, -(1-sin phi)),  r = 2 c cos phi
//   1 TC    (s2, s3)   m = (0, 1+sin phi, -(1-sin phi))   -- coincides with main on s1 = s2
//   2 TE    (s1, s2)   m = (1+sin phi, -(1-sin phi), 0)   -- coincides with main on s2 = s3
//   3..5 Rankine       m = n = e_i,                 r = T
constexpr int kMain = 0, kTC = 1, kTE = 2, kT1 = 3, kT2 = 4, kT3 = 5;

struct Planes {
  std::array<Eigen::Vector3d, 6> m;
  std::array<Eigen::Vector3d, 6> dn;  ///< D n (stress correction per unit multiplier)
  std::array<double, 6> r;
  bool tension = false;  ///< Rankine planes active (T below the apex)
  bool apex = false;     ///< the pyramid has an apex (phi > 0)
  double apex_stress = 0.0;
};

Eigen::Matrix3d principal_elasticity(const IsotropicElasticity& el) {
  const double lambda = el.bulk_modulus - 2.0 * el.shear_modulus / 3.0;
  Eigen::Matrix3d d = Eigen::Matrix3d::Constant(lambda);
  d.diagonal().array() += 2.0 * el.shear_modulus;
  return d;
}

bool tension_active(double sin_phi, double cos_phi, const MohrCoulombStrength& st);

Planes make_planes(const IsotropicElasticity& el, const MohrCoulombSurface& surface) {
  Planes p;
  const Eigen::Matrix3d d = principal_elasticity(el);
  const MohrCoulombStrength& st = surface.strength;
  const double sf = surface.sin_phi, cf = surface.cos_phi, sd = surface.sin_psi;
  const double r_shear = 2.0 * st.cohesion * cf;
  p.m[kMain] = {1.0 + sf, 0.0, -(1.0 - sf)};
  p.m[kTC] = {0.0, 1.0 + sf, -(1.0 - sf)};
  p.m[kTE] = {1.0 + sf, -(1.0 - sf), 0.0};
  const Eigen::Vector3d n_main(1.0 + sd, 0.0, -(1.0 - sd));
  const Eigen::Vector3d n_tc(0.0, 1.0 + sd, -(1.0 - sd));
  const Eigen::Vector3d n_te(1.0 + sd, -(1.0 - sd), 0.0);
  p.dn[kMain] = d * n_main;
  p.dn[kTC] = d * n_tc;
  p.dn[kTE] = d * n_te;
  p.r[kMain] = p.r[kTC] = p.r[kTE] = r_shear;
  p.apex = sf > 0.0;
  p.apex_stress = p.apex ? st.cohesion * cf / sf : std::numeric_limits<double>::infinity();
  // Rankine cutoff clamped at the apex: at or above it the pyramid already bounds s1 ([CDA]).
  const double t = st.tension_cutoff;
  p.tension = tension_active(sf, cf, st);
  for (int i = 0; i < 3; ++i) {
    p.m[kT1 + i] = Eigen::Vector3d::Unit(i);
    p.dn[kT1 + i] = d.col(i);
    p.r[kT1 + i] = p.tension ? t : std::numeric_limits<double>::infinity();
  }
  return p;
}

/// The sorted principal values of a plane-strain stress and how to put them back.
struct Spectral {
  Eigen::Vector3d sorted;  ///< s1 >= s2 >= s3
  std::array<int, 3> slot; ///< slot[i]: 0 = in-plane major (a), 1 = in-plane minor (b), 2 = szz, for sorted i
  double radius;           ///< in-plane Mohr circle radius R = (a - b) / 2
  double cos2, sin2;       ///< direction of the in-plane major axis, cos 2 alpha and sin 2 alpha
};

Spectral decompose(const PlaneStrainStress& s) {
  Spectral sp;
  const double center = 0.5 * (s[0] + s[1]);
  const double half = 0.5 * (s[0] - s[1]);
  sp.radius = std::sqrt(half * half + s[3] * s[3]);
  if (sp.radius > 0.0) {
    sp.cos2 = half / sp.radius;
    sp.sin2 = s[3] / sp.radius;
  } else {
    sp.cos2 = 1.0;
    sp.sin2 = 0.0;
  }
  const double a = center + sp.radius, b = center - sp.radius, z = s[2];
  if (z >= a) {
    sp.sorted = {z, a, b};
    sp.slot = {2, 0, 1};
  } else if (z >= b) {
    sp.sorted = {a, z, b};
    sp.slot = {0, 2, 1};
  } else {
    sp.sorted = {a, b, z};
    sp.slot = {0, 1, 2};
  }
  return sp;
}

PlaneStrainStress recompose(const Spectral& sp, const Eigen::Vector3d& sorted) {
  Eigen::Vector3d abz;
  for (int i = 0; i < 3; ++i) abz[sp.slot[i]] = sorted[i];
  const double center = 0.5 * (abz[0] + abz[1]);
  const double radius = 0.5 * (abz[0] - abz[1]);
  return {center + radius * sp.cos2, center - radius * sp.cos2, abz[2], radius * sp.sin2};
}

struct PrincipalResult {
  Eigen::Vector3d stress;
  ReturnRegion region;
  std::array<int, 3> active;  ///< active plane ids (first `count`)
  int count;                  ///< 0 = elastic; -1 = a vertex reached through a 3-plane set or the apex
};

/// The active-set candidates in the order they are tried: from the most frequent; the first admissible
/// one is the return ([SPO] Box 8.5 tries the face, then the edge on the trial's side, then the apex; the
/// Rankine sets follow [CDA]).
struct Candidate {
  std::array<int, 3> ids;
  int k;
  ReturnRegion region;
};
constexpr std::array<Candidate, 12> kCandidates{{
    {{kMain, 0, 0}, 1, ReturnRegion::Face},
    {{kMain, kTC, 0}, 2, ReturnRegion::EdgeTriaxialCompression},
    {{kMain, kTE, 0}, 2, ReturnRegion::EdgeTriaxialExtension},
    {{kT1, 0, 0}, 1, ReturnRegion::TensionCutoff},
    {{kT1, kMain, 0}, 2, ReturnRegion::TensionShearEdge},
    {{kT1, kT2, 0}, 2, ReturnRegion::TensionCutoffEdge},
    {{kT1, kMain, kTE}, 3, ReturnRegion::TensionCorner},
    {{kT1, kT2, kMain}, 3, ReturnRegion::TensionCorner},
    {{kT1, kT2, kTC}, 3, ReturnRegion::TensionCorner},
    {{kT1, kMain, kTC}, 3, ReturnRegion::TensionCorner},
    {{kT2, kMain, kTC}, 3, ReturnRegion::TensionCorner},
    {{kT1, kT2, kT3}, 3, ReturnRegion::TensionCorner},
}};

/// What one candidate's solve needs that depends on the planes alone (not on the trial stress): the
/// matrix a_jl = m_j . D n_l of its active planes, whether it is (near-)singular, its inverse for 3
/// planes, and the inactive planes it is checked against (ascending).
struct CandidateSolve {
  Eigen::Matrix3d a = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d inverse = Eigen::Matrix3d::Identity();
  double det = 1.0;
  bool singular = false;
  std::array<int, 6> others{};
  int other_count = 0;
  int shear_other_count = 0;  ///< the pyramid's planes among the others (they come first)
};

CandidateSolve solve_of(const Planes& p, const int* ids, int k) {
  CandidateSolve cs;
  double amax = 0.0;
  for (int j = 0; j < k; ++j)
    for (int l = 0; l < k; ++l) {
      cs.a(j, l) = p.m[ids[j]].dot(p.dn[ids[l]]);
      amax = std::max(amax, std::abs(cs.a(j, l)));
    }
  // Closed-form solves by size (1, 2 or 3 active planes); a (near-)singular set is not a candidate.
  if (k == 1) {
    cs.singular = !(std::abs(cs.a(0, 0)) > 1e-12 * amax);
  } else if (k == 2) {
    cs.det = cs.a(0, 0) * cs.a(1, 1) - cs.a(0, 1) * cs.a(1, 0);
    cs.singular = !(std::abs(cs.det) > 1e-12 * amax * amax);
  } else {
    cs.det = cs.a.determinant();
    cs.singular = !(std::abs(cs.det) > 1e-12 * amax * amax * amax);
    if (!cs.singular) cs.inverse = cs.a.inverse();
  }
  for (int j = 0; j < 6; ++j) {
    if (j >= kT1 && !p.tension) break;
    if (std::find(ids, ids + k, j) != ids + k) continue;
    cs.others[static_cast<std::size_t>(cs.other_count++)] = j;
    if (j < kT1) cs.shear_other_count = cs.other_count;
  }
  return cs;
}

/// One active-set candidate: solve sum_l (m_j . D n_l) dgamma_l = m_j . s_trial - r_j ([SPO] sec. 8.2,
/// [CDA]), then check dgamma >= 0, the principal order and every other plane.
/// Returns the violation measure (<= 0 when admissible); the stress in `out`.
template <int k>
double try_active_set(const Planes& p, const CandidateSolve& cs, const Eigen::Vector3d& trial, const int* ids,
                      double tol, double gamma_scale, Eigen::Vector3d& out) {
  if (cs.singular) return std::numeric_limits<double>::infinity();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (int j = 0; j < k; ++j) b[j] = p.m[ids[j]].dot(trial) - p.r[ids[j]];
  const Eigen::Matrix3d& a = cs.a;
  Eigen::Vector3d gamma = Eigen::Vector3d::Zero();
  if constexpr (k == 1) {
    gamma[0] = b[0] / a(0, 0);
  } else if constexpr (k == 2) {
    gamma[0] = (a(1, 1) * b[0] - a(0, 1) * b[1]) / cs.det;
    gamma[1] = (a(0, 0) * b[1] - a(1, 0) * b[0]) / cs.det;
  } else {
    gamma = cs.inverse * b;
  }
  out = trial;
  double violation = -std::numeric_limits<double>::infinity();
  for (int l = 0; l < k; ++l) {
    out -= gamma[l] * p.dn[ids[l]];
    violation = std::max(violation, -gamma[l] * gamma_scale);
  }
  violation = std::max(violation, out[1] - out[0]);
  violation = std::max(violation, out[2] - out[1]);
  for (int i = 0; i < cs.shear_other_count; ++i) {
    const int j = cs.others[static_cast<std::size_t>(i)];
    violation = std::max(violation, p.m[j].dot(out) - p.r[j]);
  }
  // A Rankine plane's m is the unit vector e_i: its dot product is out_i exactly.
  for (int i = cs.shear_other_count; i < cs.other_count; ++i) {
    const int j = cs.others[static_cast<std::size_t>(i)];
    violation = std::max(violation, out[j - kT1] - p.r[j]);
  }
  return violation - tol;
}
/// try_active_set<k> for a run-time count of active planes.
double try_active_set(const Planes& p, const CandidateSolve& cs, const Eigen::Vector3d& trial, const int* ids, int k,
                      double tol, double gamma_scale, Eigen::Vector3d& out) {
  if (k == 1) return try_active_set<1>(p, cs, trial, ids, tol, gamma_scale, out);
  if (k == 2) return try_active_set<2>(p, cs, trial, ids, tol, gamma_scale, out);
  return try_active_set<3>(p, cs, trial, ids, tol, gamma_scale, out);
}

/// Tension cutoff in force: finite and below the apex c cot(phi) ([CDA]).
bool tension_active(double sin_phi, double cos_phi, const MohrCoulombStrength& st) {
  const double t = st.tension_cutoff;
  if (!std::isfinite(t)) return false;
  return sin_phi > 0.0 ? t < st.cohesion * cos_phi / sin_phi : true;
}

/// The elastic test on sorted principal trial values, [SPO] Box 8.4 step (ii), with a round-off tolerance of
/// 1e-12 of the stress scale (so a state returned onto the surface stays elastic when reloaded with zero
/// increment). The one place this test is made, for the fast path and for the full return alike.
bool inside(const Eigen::Vector3d& t, double sin_phi, double cos_phi, const MohrCoulombStrength& st, bool tension) {
  const double two_c_cos = 2.0 * st.cohesion * cos_phi;
  // Strictly inside needs no tolerance (tol >= 0): the common case, without the stress scale.
  if (strictly_inside(t[0], t[2], sin_phi, two_c_cos, tension, st.tension_cutoff)) return true;
  const double f_main = (t[0] - t[2]) + (t[0] + t[2]) * sin_phi - two_c_cos;
  // Each test with the scale of what it compares: a cutoff far above the stresses (a Tresca material given
  // T = 1e30 for "none") must not widen the shear test (it made every state elastic).
  const double tol = 1e-12 * std::max({std::abs(t[0]), std::abs(t[2]), two_c_cos});
  const double tol_t = 1e-12 * std::max(std::abs(t[0]), std::abs(st.tension_cutoff));
  return f_main <= tol && (!tension || t[0] - st.tension_cutoff <= tol_t);
}
bool inside(const Eigen::Vector3d& t, double sin_phi, double cos_phi, const MohrCoulombStrength& st) {
  return inside(t, sin_phi, cos_phi, st, tension_active(sin_phi, cos_phi, st));
}

/// The return in sorted principal space for a trial OUTSIDE the surface (see inside()).
/// `solves`: the candidates' solves in kCandidates order, or nullptr to form each when it is tried.
PrincipalResult principal_return(const Planes& p, const Eigen::Vector3d& trial, double shear_modulus,
                                 const CandidateSolve* solves) {
  // The tension cutoff counts only where it is within the stresses' reach (see inside()).
  const double stresses = std::max({std::abs(trial[0]), std::abs(trial[2]), std::abs(p.r[kMain])});
  const double scale = std::max(stresses, p.tension ? std::min(std::abs(p.r[kT1]), 1e3 * stresses) : 0.0);
  PrincipalResult res{trial, ReturnRegion::Elastic, {0, 0, 0}, 0};

  const double tol = 1e-9 * scale;
  const double gamma_scale = 2.0 * shear_modulus;
  double best = std::numeric_limits<double>::infinity();
  Eigen::Vector3d out = trial;
  CandidateSolve formed;  // a candidate's solve formed when it is tried (no `solves`)
  for (std::size_t i = 0; i < kCandidates.size(); ++i) {
    const Candidate& c = kCandidates[i];
    if (!p.tension && c.ids[0] >= kT1) break;  // the Rankine sets come last
    const CandidateSolve* cs = solves != nullptr ? &solves[i] : &(formed = solve_of(p, c.ids.data(), c.k));
    const double v = try_active_set(p, *cs, trial, c.ids.data(), c.k, tol, gamma_scale, out);
    if (v < best) {
      best = v;
      res.stress = out;
      res.region = c.region;
      res.active = c.ids;
      res.count = c.k;
    }
    if (v <= 0.0) return res;
    // No tension: after face and both edges only the apex is left ([SPO] Box 8.5, step (iv)).
    if (!p.tension && c.region == ReturnRegion::EdgeTriaxialExtension && p.apex) {
      res.stress = Eigen::Vector3d::Constant(p.apex_stress);
      res.region = ReturnRegion::Apex;
      res.count = -1;
      return res;
    }
  }
  return res;  // nothing admissible within the tolerance (round-off at a corner): the least violating set
}

}  // namespace

const char* to_string(ReturnRegion region) {
  switch (region) {
    case ReturnRegion::Elastic: return "elastic";
    case ReturnRegion::Face: return "face";
    case ReturnRegion::EdgeTriaxialCompression: return "edge (triaxial compression)";
    case ReturnRegion::EdgeTriaxialExtension: return "edge (triaxial extension)";
    case ReturnRegion::Apex: return "apex";
    case ReturnRegion::TensionCutoff: return "tension cutoff";
    case ReturnRegion::TensionShearEdge: return "tension cutoff + shear edge";
    case ReturnRegion::TensionCutoffEdge: return "tension cutoff edge";
    case ReturnRegion::TensionCorner: return "tension corner";
  }
  return "unknown";
}

MohrCoulombSurface::MohrCoulombSurface(const MohrCoulombStrength& st)
    : strength(st), sin_phi(std::sin(st.friction)), cos_phi(std::cos(st.friction)), sin_psi(std::sin(st.dilation)) {}

MohrCoulombUpdate mohr_coulomb_return(const PlaneStrainStress& trial, const IsotropicElasticity& el,
                                      const MohrCoulombStrength& st) {
  return mohr_coulomb_return(trial, el, MohrCoulombSurface(st));
}

namespace {
/// The plastic part of the return (the trial is outside the surface): stress back from the principal
/// return and the plastic strain increment C (s_trial - s) (the total strain is fixed; [SPO] sec. 8.2).
MohrCoulombUpdate plastic_return(const PlaneStrainStress& trial, const Spectral& sp, const IsotropicElasticity& el,
                                 const Planes& planes, const CandidateSolve* solves) {
  const PrincipalResult pr = principal_return(planes, sp.sorted, el.shear_modulus, solves);
  // ds from the stress in registers (reading up.stress back would wait on its partial stores).
  const PlaneStrainStress stress = recompose(sp, pr.stress);
  const Eigen::Vector4d ds = trial - stress;
  MohrCoulombUpdate up;
  up.stress = stress;
  up.region = pr.region;
  const double p = (ds[0] + ds[1] + ds[2]) / 3.0;
  const double g2 = 2.0 * el.shear_modulus, k3 = 3.0 * el.bulk_modulus;
  up.plastic_strain_increment = {(ds[0] - p) / g2 + p / k3, (ds[1] - p) / g2 + p / k3, (ds[2] - p) / g2 + p / k3,
                                 ds[3] / el.shear_modulus};
  return up;
}
}  // namespace

MohrCoulombUpdate mohr_coulomb_return(const PlaneStrainStress& trial, const IsotropicElasticity& el,
                                      const MohrCoulombSurface& surface) {
  const Spectral sp = decompose(trial);
  if (inside(sp.sorted, surface.sin_phi, surface.cos_phi, surface.strength))
    return {trial, Eigen::Vector4d::Zero(), ReturnRegion::Elastic};
  return plastic_return(trial, sp, el, make_planes(el, surface), nullptr);
}

struct MohrCoulombReturnMap::Data {
  IsotropicElasticity elasticity;
  MohrCoulombSurface surface;
  Planes planes;
  std::array<CandidateSolve, kCandidates.size()> solves;
};

MohrCoulombReturnMap::MohrCoulombReturnMap(const IsotropicElasticity& el, const MohrCoulombSurface& surface) {
  auto d = std::make_shared<Data>();
  d->elasticity = el;
  d->surface = surface;
  d->planes = make_planes(el, surface);
  for (std::size_t i = 0; i < kCandidates.size(); ++i)
    d->solves[i] = solve_of(d->planes, kCandidates[i].ids.data(), kCandidates[i].k);
  sin_phi_ = surface.sin_phi;
  two_c_cos_phi_ = 2.0 * surface.strength.cohesion * surface.cos_phi;  // inside()'s expression
  tension_cutoff_ = surface.strength.tension_cutoff;
  tension_ = d->planes.tension;
  data_ = std::move(d);
}

const MohrCoulombSurface& MohrCoulombReturnMap::surface() const { return data_->surface; }
const IsotropicElasticity& MohrCoulombReturnMap::elasticity() const { return data_->elasticity; }

bool MohrCoulombReturnMap::admits_at_round_off(const PrincipalExtremes& t) const {
  const Data& d = *data_;
  return inside({t.s1, 0.0, t.s3}, d.surface.sin_phi, d.surface.cos_phi, d.surface.strength, d.planes.tension);
}

CPU_VARIANTS MohrCoulombUpdate MohrCoulombReturnMap::apply_plastic(const PlaneStrainStress& trial) const {
  const Data& d = *data_;
  return plastic_return(trial, decompose(trial), d.elasticity, d.planes, d.solves.data());
}

PrincipalUpdate MohrCoulombReturnMap::apply_principal(const Eigen::Vector3d& sorted_trial) const {
  const Data& d = *data_;
  if (inside(sorted_trial, d.surface.sin_phi, d.surface.cos_phi, d.surface.strength, d.planes.tension))
    return {sorted_trial, ReturnRegion::Elastic};
  const PrincipalResult pr = principal_return(d.planes, sorted_trial, d.elasticity.shear_modulus, d.solves.data());
  return {pr.stress, pr.region};
}

PrincipalUpdate mohr_coulomb_return_principal(const Eigen::Vector3d& sorted_trial, const IsotropicElasticity& el,
                                              const MohrCoulombSurface& surface) {
  const Planes planes = make_planes(el, surface);
  if (inside(sorted_trial, surface.sin_phi, surface.cos_phi, surface.strength, planes.tension))
    return {sorted_trial, ReturnRegion::Elastic};
  const PrincipalResult pr = principal_return(planes, sorted_trial, el.shear_modulus, nullptr);
  return {pr.stress, pr.region};
}

MohrCoulombUpdate MohrCoulombReturnMap::apply(const PlaneStrainStress& trial) const {
  if (admits(trial)) return {trial, Eigen::Vector4d::Zero(), ReturnRegion::Elastic};
  return apply_plastic(trial);
}

MohrCoulombUpdate mohr_coulomb_update(const PlaneStrainStress& stress, const PlaneStrainStrain& dstrain,
                                      const IsotropicElasticity& el, const MohrCoulombStrength& st) {
  return mohr_coulomb_return(elastic_trial(stress, dstrain, el), el, MohrCoulombSurface(st));
}

MohrCoulombUpdate mohr_coulomb_update(const PlaneStrainStress& stress, const PlaneStrainStrain& dstrain,
                                      const IsotropicElasticity& el, const MohrCoulombSurface& surface) {
  return mohr_coulomb_return(elastic_trial(stress, dstrain, el), el, surface);
}

Eigen::Matrix<double, 4, 3> mohr_coulomb_tangent_4x3(const PlaneStrainStress& trial, const IsotropicElasticity& el,
                                                     const MohrCoulombStrength& st) {
  const double g = el.shear_modulus;
  const double lambda = el.bulk_modulus - 2.0 * g / 3.0;
  Eigen::Matrix<double, 4, 3> d;  // d(sxx, syy, szz, sxy) / d(exx, eyy, gxy), plane strain
  d << lambda + 2.0 * g, lambda, 0.0,  //
      lambda, lambda + 2.0 * g, 0.0,   //
      lambda, lambda, 0.0,             //
      0.0, 0.0, g;
  const Spectral sp = decompose(trial);
  const MohrCoulombSurface surface(st);
  if (inside(sp.sorted, surface.sin_phi, surface.cos_phi, st)) return d;
  const Planes planes = make_planes(el, surface);
  const PrincipalResult pr = principal_return(planes, sp.sorted, g, nullptr);

  // Principal algorithmic tangent ds/ds_trial = I - D N A^-1 M^T over the active planes ([SPO] sec. 8.2);
  // zero at a vertex (the stress is a fixed point).
  Eigen::Matrix3d jp = Eigen::Matrix3d::Zero();
  if (pr.count > 0 && pr.count < 3) {
    const int k = pr.count;
    Eigen::Matrix3d a = Eigen::Matrix3d::Identity();
    for (int j = 0; j < k; ++j)
      for (int l = 0; l < k; ++l) a(j, l) = planes.m[pr.active[j]].dot(planes.dn[pr.active[l]]);
    const Eigen::Matrix3d ainv = a.inverse();
    jp = Eigen::Matrix3d::Identity();
    for (int j = 0; j < k; ++j)
      for (int l = 0; l < k; ++l) jp -= ainv(l, j) * planes.dn[pr.active[l]] * planes.m[pr.active[j]].transpose();
  }
  // In (a, b, z) coordinates: a, b the in-plane principal values, z = szz.
  Eigen::Matrix3d jabz;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) jabz(sp.slot[i], sp.slot[j]) = jp(i, j);
  // d(a, b, z) / d(sxx, syy, szz, sxy) of the trial.
  const double c2 = sp.cos2, s2 = sp.sin2;
  Eigen::Matrix<double, 3, 4> l;
  l << 0.5 * (1.0 + c2), 0.5 * (1.0 - c2), 0.0, s2,  //
      0.5 * (1.0 - c2), 0.5 * (1.0 + c2), 0.0, -s2,  //
      0.0, 0.0, 1.0, 0.0;
  const Eigen::Matrix<double, 3, 4> dabz = jabz * l;
  const Eigen::Matrix<double, 1, 4> dcenter = 0.5 * (dabz.row(0) + dabz.row(1));
  const Eigen::Matrix<double, 1, 4> dradius = 0.5 * (dabz.row(0) - dabz.row(1));
  // Spin term ([SPO] Appendix A, 2D case): q = r'/R, the returned over the trial circle radius; its limit
  // dr'/dR when the in-plane principal values of the trial coincide.
  double q;
  Eigen::Vector3d abz_new;
  for (int i = 0; i < 3; ++i) abz_new[sp.slot[i]] = pr.stress[i];
  const double r_new = 0.5 * (abz_new[0] - abz_new[1]);
  const double scale = std::max({std::abs(trial[0]), std::abs(trial[1]), std::abs(trial[2]), std::abs(trial[3])});
  if (sp.radius > 1e-10 * scale && sp.radius > 0.0)
    q = r_new / sp.radius;
  else
    q = 0.5 * (jabz(0, 0) - jabz(0, 1) - jabz(1, 0) + jabz(1, 1));
  Eigen::Matrix<double, 1, 4> w;  // sin2 dh - cos2 dsxy, h = (sxx - syy) / 2
  w << 0.5 * s2, -0.5 * s2, 0.0, -c2;
  Eigen::Matrix4d t;  // d(sxx, syy, szz, sxy) / d(trial)
  t.row(0) = dcenter + c2 * dradius + q * s2 * w;
  t.row(1) = dcenter - c2 * dradius - q * s2 * w;
  t.row(2) = dabz.row(2);
  t.row(3) = s2 * dradius - q * c2 * w;
  return t * d;
}

Eigen::Matrix3d mohr_coulomb_tangent(const PlaneStrainStress& trial, const IsotropicElasticity& el,
                                     const MohrCoulombStrength& st) {
  const Eigen::Matrix<double, 4, 3> t = mohr_coulomb_tangent_4x3(trial, el, st);
  Eigen::Matrix3d out;
  out.row(0) = t.row(0);
  out.row(1) = t.row(1);
  out.row(2) = t.row(3);
  return out;
}

double mohr_coulomb_yield(const PlaneStrainStress& stress, const MohrCoulombStrength& st) {
  const Spectral sp = decompose(stress);
  const double sf = std::sin(st.friction);
  return (sp.sorted[0] - sp.sorted[2]) + (sp.sorted[0] + sp.sorted[2]) * sf - 2.0 * st.cohesion * std::cos(st.friction);
}

}  // namespace constitutive
