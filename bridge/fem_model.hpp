#pragma once
// The FEM model as OpenSees' `print -JSON` describes it (FORMATS.md section 3): nodes (with their dof
// count: 3 for the pore-pressure nodes of a u-p model), four-node elements (SSPquad, quad, Tri31 and the u-p
// SSPquadUP and FourNodeQuadUP) and nD materials. OpenSees 3.8 writes invalid JSON for DruckerPrager,
// PM4Sand, PM4Silt, the multi-yield materials and FourNodeQuadUP (text blocks); the reader then takes nodes
// and elements line by line (FourNodeQuadUP from its text block), lists what it skipped, and leaves the
// materials to command-line options.
#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace bridge {

enum class ElementKind { SSPquad /* 1 Gauss point */, Quad /* 4 Gauss points */, Tri31 /* 3 nodes, 1 Gauss point */ };

/// Number of Gauss points OpenSees records for the element kind (SSPquad 1, quad 4, Tri31 1).
inline int gauss_point_count(ElementKind kind) { return kind == ElementKind::Quad ? 4 : 1; }
/// Number of nodes of the element kind (the first ones of FemElement::nodes are used).
inline int node_count(ElementKind kind) { return kind == ElementKind::Tri31 ? 3 : 4; }

struct FemNode {
  long tag = 0;
  int ndf = 2;                                    ///< dofs per node ("ndf"; 3: u-p, dof 3 the pore pressure)
  Eigen::Vector2d crd = Eigen::Vector2d::Zero();  ///< reference coordinates, model units
};

struct FemElement {
  long tag = 0;
  ElementKind kind = ElementKind::SSPquad;
  std::array<long, 4> node_tags{};   ///< as in the file (the first node_count(kind))
  std::array<int, 4> nodes{};        ///< indices into FemModel::nodes (the first node_count(kind))
  double thickness = 1;
  std::string material;              ///< material name ("" when the element names none)
  double mass_per_volume = 0;        ///< quad's `masspervolume` (replaces the material rho when > 0)
  /// Force per unit volume (b1, b2); for a u-p element (SSPquadUP, FourNodeQuadUP) an acceleration (OpenSees
  /// multiplies it by the material density).
  Eigen::Vector2d body_force = Eigen::Vector2d::Zero();
  /// A u-p element (SSPquadUP: 1 Gauss point like SSPquad; FourNodeQuadUP: 4 like quad): its nodes carry the
  /// pore pressure as dof 3 and its stress recorder gives the effective stress.
  bool pore_pressure = false;
};

/// What the bridge needs of an nD material; model units (stress, density) until converted.
struct FemMaterial {
  std::string name;
  std::string type;                  ///< OpenSees type word ("ElasticIsotropicMaterial", "MohrCoulomb", ...)
  std::optional<double> E, nu, rho;  ///< elastic constants and density when the JSON gives them
  std::optional<double> phi_deg, cohesion, psi_deg, tension;  ///< MohrCoulomb only
  /// DruckerPrager only, OpenSees' parameters: cone f = ||s|| + rho I1 - sqrt(2/3) sigma_y, plastic potential
  /// with rho_bar (E and nu are derived from its K and G, the density from "density").
  std::optional<double> dp_sigma_y, dp_rho, dp_rho_bar;
  /// PressureIndependMultiYield only: cohesi and frictionAng (E and nu from refShearModul, refBulkModul).
  std::optional<double> multi_yield_cohesion, multi_yield_friction_deg;
  /// PM4Sand / PM4Silt (fem_tcl's entries): G0 (dimensionless; G = G0 P_atm in the elastic stage), P_atm and
  /// phi_cv (degrees); nu and rho (from "Den") in E/nu/rho above.
  std::optional<double> pm4_G0, pm4_P_atm, phi_cv_deg;
};

/// A homogeneous single-point constraint (`fix node fx fy <fp>`), from fem_tcl's "constraints.fix" list.
struct FemFix {
  long node = 0;
  bool x = false, y = false;
  bool pore_pressure = false;  ///< a u-p node's dof 3 fixed (a drained node)
};

/// An `equalDOF retained constrained dofs...` tie (dofs 1-based), from "constraints.equalDOF".
struct FemTie {
  long retained = 0, constrained = 0;
  std::vector<int> dofs;
};

struct FemModel {
  std::filesystem::path source;
  std::vector<FemNode> nodes;        ///< in file order
  std::vector<FemElement> elements;  ///< in file order
  std::map<std::string, FemMaterial> materials;
  bool materials_readable = true;    ///< false when the JSON was invalid and only geometry was read
  /// The supports: true when the file has fem_tcl's "constraints" block (OpenSees 3.8 writes none).
  bool has_constraints = false;
  std::vector<FemFix> fixes;
  std::vector<FemTie> ties;
  /// Tags of zeroLength elements (springs and dashpots of a compliant base or free-field sides): boundary
  /// devices of the FEM model, not soil, so they are not transferred.
  std::vector<long> boundary_devices;
  /// What could not be read (OpenSees 3.8's text blocks in place of JSON), one line each, for the report.
  std::vector<std::string> skipped;

  /// Index of the node with `tag`, or -1.
  int node_index(long tag) const;
  /// Index of the element with `tag`, or -1.
  int element_index(long tag) const;

  std::map<long, int> node_by_tag;
  std::map<long, int> element_by_tag;
};

/// Reads `print -JSON` output. Throws common::InputError "<file>:<line>: <what>" for a missing
/// file, an element type other than SSPquad/quad/Tri31/SSPquadUP/FourNodeQuadUP, an unknown node tag, no
/// nodes/elements, or a malformed "constraints" entry (naming the key).
FemModel read_fem_model(const std::filesystem::path& file);

/// Parses the JSON text (exposed for tests); `file` names it in errors.
FemModel parse_fem_model(const std::string& text, const std::filesystem::path& file);

}  // namespace bridge
