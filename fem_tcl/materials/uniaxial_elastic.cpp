#include "fem_tcl/materials/uniaxial_elastic.hpp"

#include <cmath>

namespace fem::materials {

nlohmann::ordered_json UniaxialElastic::to_json() const {
  nlohmann::ordered_json j;
  j["name"] = std::to_string(tag());
  j["type"] = "ElasticMaterial";
  j["Epos"] = e_pos_;
  j["Eneg"] = e_neg_;
  j["eta"] = eta_;
  return j;
}

std::unique_ptr<UniaxialMaterial> parse_uniaxial_elastic(common::CommandArgs& args) {
  const int tag = args.integer("tag");
  const double e = args.number("E");
  double eta = 0.0, e_neg = e;
  if (!args.empty()) eta = args.number("eta");
  if (!args.empty()) e_neg = args.number("Eneg");
  args.expect_end();
  if (!std::isfinite(e) || !std::isfinite(eta) || !std::isfinite(e_neg)) args.fail("expected finite E, eta and Eneg");
  return std::make_unique<UniaxialElastic>(tag, e, eta, e_neg);
}

}  // namespace fem::materials
