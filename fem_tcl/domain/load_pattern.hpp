#pragma once
// Load patterns (OpenSees LoadPattern / UniformExcitation): nodal loads, prescribed displacements (sp),
// element self-weight loads, and a uniform base acceleration applied as -M * ag (relative response).
#include <memory>
#include <vector>

#include "fem_tcl/domain/node.hpp"
#include "fem_tcl/domain/time_series.hpp"

namespace fem::domain {

class Domain;

struct NodalLoad { int node; NodeVector force; };  ///< force per dof (entries past the node's ndf zero)
struct PrescribedDisp { int node; int dof; double value; };  ///< dof 0-based
struct SelfWeightLoad { std::vector<int> elements; double xf; double yf; };

class LoadPattern {
 public:
  LoadPattern(int tag, std::shared_ptr<TimeSeries> series, double cfactor)
      : tag_(tag), series_(std::move(series)), cfactor_(cfactor) {}
  virtual ~LoadPattern() = default;
  int tag() const { return tag_; }

  /// The pattern's load factor at `time` (frozen after loadConst).
  double factor(double time) const { return is_const_ ? const_factor_ : cfactor_ * series_->factor(time); }
  /// Adds this pattern's loads at `time` to the domain's (already zeroed) nodal and element loads.
  virtual void apply(Domain& domain, double time) = 0;
  /// `loadConst`: keep the factor of the last apply().
  void set_load_const() { is_const_ = true; const_factor_ = last_factor_; }
  /// The factor used by the last apply() (OpenSees getLoadFactor).
  double last_factor() const { return last_factor_; }

  std::vector<NodalLoad> nodal_loads;
  std::vector<PrescribedDisp> prescribed;
  std::vector<SelfWeightLoad> self_weight;

 protected:
  double last_factor_ = 0.0;

 private:
  int tag_;
  std::shared_ptr<TimeSeries> series_;
  double cfactor_;
  bool is_const_ = false;
  double const_factor_ = 0.0;
};

/// `pattern Plain tag tsTag <-fact f> {body}`.
class PlainPattern final : public LoadPattern {
 public:
  using LoadPattern::LoadPattern;
  void apply(Domain& domain, double time) override;
};

/// `pattern UniformExcitation tag dir -accel tsTag <-fact f>`: ground acceleration ag(t) in direction `dof`.
class UniformExcitation final : public LoadPattern {
 public:
  UniformExcitation(int tag, int dof, std::shared_ptr<TimeSeries> accel, double cfactor)
      : LoadPattern(tag, std::move(accel), cfactor), dof_(dof) {}
  void apply(Domain& domain, double time) override;
  int dof() const { return dof_; }

 private:
  int dof_;
};

}  // namespace fem::domain
