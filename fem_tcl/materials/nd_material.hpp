#pragma once
// The 2D continuum material interface (OpenSees' NDMaterial protocol, in this project's style):
// trial / commit / revert-to-last-commit / revert-to-start, value types, std::unique_ptr copies.
//
// Component order (Voigt), tension positive:
//   strain  (exx, eyy, gxy)  with engineering shear gxy = 2 exy
//   stress  (sxx, syy, sxy)
//   full stress tensor (sxx, syy, szz, sxy, syz, sxz)
#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "fem_tcl/materials/reducible_strength.hpp"

namespace fem::materials {

using Vector3 = Eigen::Vector3d;
using Matrix3 = Eigen::Matrix3d;
using Vector6 = Eigen::Matrix<double, 6, 1>;

/// The plane-strain elastic matrix for (exx, eyy, gxy) of bulk modulus K and shear modulus G:
/// [[l + 2G, l, 0], [l, l + 2G, 0], [0, 0, G]] with Lame's l = K - 2G/3.
inline Matrix3 plane_strain_elastic_matrix(double K, double G) {
  const double lambda = K - 2.0 * G / 3.0;
  Matrix3 d;
  d << lambda + 2.0 * G, lambda, 0.0, lambda, lambda + 2.0 * G, 0.0, 0.0, 0.0, G;
  return d;
}

/// The 2D formulation an element asks its material for (OpenSees' "PlaneStrain" / "PlaneStress").
enum class PlaneType { PlaneStrain, PlaneStress };

class NDMaterial {
 public:
  explicit NDMaterial(int tag) : tag_(tag) {}
  virtual ~NDMaterial() = default;

  int tag() const { return tag_; }
  /// OpenSees type name, e.g. "ElasticIsotropic", "DruckerPrager", "MohrCoulomb".
  virtual std::string type_name() const = 0;

  /// A fresh copy for one integration point, in the start state, for `plane` (OpenSees getCopy(type)).
  /// Throws common::InputError when the material does not support `plane`.
  virtual std::unique_ptr<NDMaterial> copy_for(PlaneType plane) const = 0;
  /// A copy in this material's current state (trial and committed), for analyses that try and undo
  /// (`strengthReduction` restores every integration point from such copies).
  virtual std::unique_ptr<NDMaterial> clone() const = 0;
  /// The strength a factor-of-safety analysis can reduce, or null when the material has none (elastic).
  virtual ReducibleStrength* reducible_strength() { return nullptr; }

  // --- state protocol -----------------------------------------------------------------------
  /// Sets the total trial strain (exx, eyy, gxy) and computes the trial stress and tangent.
  virtual void set_trial_strain(const Vector3& strain) = 0;
  virtual const Vector3& strain() const = 0;
  virtual const Vector3& stress() const = 0;
  /// Algorithmic (consistent where the model has one) tangent d stress / d strain at the trial state.
  virtual const Matrix3& tangent() const = 0;
  virtual Matrix3 initial_tangent() const = 0;
  /// Whether initial_tangent() depends on the parameters alone (not on the state), so that only a command
  /// (setParameter, updateMaterialStage) can change it; false unless a material says so.
  virtual bool initial_tangent_fixed() const { return false; }
  virtual void commit_state() = 0;
  virtual void revert_to_last_commit() = 0;
  virtual void revert_to_start() = 0;

  // --- properties and responses -------------------------------------------------------------
  /// Mass density (mass per unit volume); 0 when the material was given none.
  virtual double density() const = 0;
  /// Full trial stress tensor (sxx, syy, szz, sxy, syz, sxz); plane strain tracks szz.
  virtual Vector6 stress_3d() const = 0;

  /// `setParameter -val v ... name`: returns false when the material has no parameter `name`.
  virtual bool set_parameter(std::string_view name, double value) { (void)name; (void)value; return false; }
  /// `updateMaterialStage -stage s`: returns false when the material has no stages (OpenSees warns).
  virtual bool update_stage(int stage) { (void)stage; return false; }
  /// Values of a response forwarded by an element ("stress", "strain", "state", ...), or nullopt
  /// when the material does not know `name`. Default: stress/stresses, strain/strains, stress3D.
  virtual std::optional<std::vector<double>> response(std::string_view name) const {
    if (name == "stress" || name == "stresses") { const auto& s = stress(); return std::vector<double>{s[0], s[1], s[2]}; }
    if (name == "strain" || name == "strains") { const auto& e = strain(); return std::vector<double>{e[0], e[1], e[2]}; }
    if (name == "stress3D" || name == "fullStress") { const auto s = stress_3d(); return std::vector<double>(s.data(), s.data() + 6); }
    return std::nullopt;
  }
  /// The material's entry in `print -JSON` ("ndMaterials" list); keys as OpenSees where it has them.
  virtual nlohmann::json to_json() const = 0;

 private:
  int tag_;
};

}  // namespace fem::materials
