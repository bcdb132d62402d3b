#pragma once
// The uniaxial (1D) material interface (OpenSees UniaxialMaterial, in this project's style) for springs and
// dashpots (zeroLength): trial strain and strain rate in, stress, tangent d stress / d strain and damping
// tangent d stress / d strain rate out; trial / commit / revert-to-last-commit / revert-to-start.
// "Strain" of a zeroLength element is the deformation (jNode minus iNode displacement along a direction),
// "stress" its force.
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/command_args.hpp"

namespace fem::materials {

class UniaxialMaterial {
 public:
  explicit UniaxialMaterial(int tag) : tag_(tag) {}
  virtual ~UniaxialMaterial() = default;

  int tag() const { return tag_; }
  /// OpenSees type word, e.g. "Elastic", "Viscous".
  virtual std::string type_name() const = 0;
  /// A fresh copy in the start state (OpenSees getCopy, one per element).
  virtual std::unique_ptr<UniaxialMaterial> copy() const = 0;

  virtual void set_trial_strain(double strain, double strain_rate) = 0;
  virtual double strain() const = 0;
  virtual double strain_rate() const = 0;
  virtual double stress() const = 0;
  /// d stress / d strain at the trial state (OpenSees getTangent).
  virtual double tangent() const = 0;
  virtual double initial_tangent() const = 0;
  /// Whether initial_tangent() and damp_tangent() depend on the parameters alone (not on the state);
  /// false unless a material says so.
  virtual bool tangents_fixed() const { return false; }
  /// d stress / d strain rate at the trial state (OpenSees getDampTangent; 0 for rate-independent models).
  virtual double damp_tangent() const { return 0.0; }
  virtual void commit_state() = 0;
  virtual void revert_to_last_commit() = 0;
  virtual void revert_to_start() = 0;

  /// `material k <name>` responses (OpenSees UniaxialMaterial::setResponse): stress, strain, tangent,
  /// stressStrain, stressStrainTangent; nullopt when unknown.
  std::optional<std::vector<double>> response(std::string_view name) const {
    if (name == "stress") return std::vector<double>{stress()};
    if (name == "strain") return std::vector<double>{strain()};
    if (name == "tangent") return std::vector<double>{tangent()};
    if (name == "stressStrain" || name == "stressANDstrain") return std::vector<double>{stress(), strain()};
    if (name == "stressStrainTangent" || name == "stressANDstrainANDtangent") {
      return std::vector<double>{stress(), strain(), tangent()};
    }
    return std::nullopt;
  }
  /// The entry in `print -JSON`'s "uniaxialMaterials" list (OpenSees' keys where it writes JSON).
  virtual nlohmann::ordered_json to_json() const = 0;

 private:
  int tag_;
};

using UniaxialMaterialMap = std::map<int, std::unique_ptr<UniaxialMaterial>>;

/// Builds one material from `uniaxialMaterial <type> tag ...`; `args` start at the tag. Throws common::InputError.
using UniaxialParser = std::unique_ptr<UniaxialMaterial> (*)(common::CommandArgs& args);

struct UniaxialParserEntry {
  std::string_view type;   ///< the OpenSees type word
  std::string_view usage;  ///< the syntax line for errors
  UniaxialParser parse;
};

/// The table of known `uniaxialMaterial` types (uniaxial_registry.cpp).
std::span<const UniaxialParserEntry> uniaxial_material_parsers();
const UniaxialParserEntry* find_uniaxial_material_parser(std::string_view type);

}  // namespace fem::materials
