#pragma once
// `uniaxialMaterial Elastic tag E <eta> <Eneg>` (OpenSees 3.8 SRC/material/uniaxial/ElasticMaterial.cpp):
//   stress = E+ strain + eta rate   (strain >= 0)
//   stress = E- strain + eta rate   (strain < 0),   tangent E+ or E-, damping tangent eta, initial tangent E+.
// With two numbers (E eta) Eneg = E; with one, eta = 0 too.
#include "fem_tcl/materials/uniaxial_material.hpp"

namespace fem::materials {

class UniaxialElastic final : public UniaxialMaterial {
 public:
  UniaxialElastic(int tag, double e_pos, double eta, double e_neg)
      : UniaxialMaterial(tag), e_pos_(e_pos), e_neg_(e_neg), eta_(eta) {}
  std::string type_name() const override { return "Elastic"; }
  std::unique_ptr<UniaxialMaterial> copy() const override {
    return std::make_unique<UniaxialElastic>(tag(), e_pos_, eta_, e_neg_);
  }
  void set_trial_strain(double strain, double rate) override { strain_ = strain; rate_ = rate; }
  double strain() const override { return strain_; }
  double strain_rate() const override { return rate_; }
  double stress() const override { return tangent() * strain_ + eta_ * rate_; }
  double tangent() const override { return strain_ >= 0.0 ? e_pos_ : e_neg_; }
  double initial_tangent() const override { return e_pos_; }
  double damp_tangent() const override { return eta_; }
  bool tangents_fixed() const override { return true; }
  // OpenSees' ElasticMaterial keeps no committed state: reverting keeps the trial strain.
  void commit_state() override {}
  void revert_to_last_commit() override {}
  void revert_to_start() override { strain_ = rate_ = 0.0; }
  nlohmann::ordered_json to_json() const override;

 private:
  double e_pos_, e_neg_, eta_;
  double strain_ = 0.0, rate_ = 0.0;
};

std::unique_ptr<UniaxialMaterial> parse_uniaxial_elastic(common::CommandArgs& args);

}  // namespace fem::materials
