// `eigen <-genBandArpack | -symmBandLapack | -fullGenLapack> numModes` and
// `nodeEigenvector nodeTag mode <dof>`: OpenSees' eigenvalue analysis of the model as it stands (its
// current tangent and lumped mass), returning lambda = omega^2 of the numModes lowest modes, as scripts use
// it for Rayleigh damping (omega_1 = sqrt(lambda_1), a0 = 2 xi w1 w2 / (w1 + w2), ...). The solver flag
// only names OpenSees' eigen solver: one subspace iteration serves all (analysis/eigen_analysis.cpp). The
// constraints are the analysis' handler when one was given (`constraints`), else Transformation.
#include <algorithm>
#include <cmath>
#include <string>

#include "fem_tcl/tcl/commands.hpp"

namespace fem::tcl {

std::string cmd_eigen(Context& ctx, common::CommandArgs& args) {
  while (!args.empty() && args.peek().rfind('-', 0) == 0 && !common::CommandArgs::parse_number(args.peek())) {
    const std::string flag = args.word("solver");
    if (flag == "-standard")
      args.fail("-standard (K phi = lambda phi without the mass) is not implemented; the generalized problem is");
    if (flag == "-findLargest") args.fail("-findLargest is not implemented (the lowest modes are)");
    if (flag != "-genBandArpack" && flag != "-symmBandLapack" && flag != "-fullGenLapack" && flag != "-UmfPack" &&
        flag != "-symmSparseArpack" && flag != "-generalized")
      args.fail("unknown option '" + flag + "' (-genBandArpack, -symmBandLapack, -fullGenLapack)");
  }
  const int modes = args.integer("numModes");
  args.expect_end();
  if (modes < 1) args.fail("expected numModes >= 1, got " + std::to_string(modes));
  if (ctx.domain.nodes().empty()) args.fail("the model has no nodes");
  analysis::AnalysisConfig config;
  config.handler = ctx.chain.handler.value_or(analysis::HandlerType::Transformation);
  config.penalty_sp = ctx.chain.penalty_sp;
  config.penalty_mp = ctx.chain.penalty_mp;
  config.numberer = ctx.chain.numberer.value_or("RCM");
  config.system = "UmfPack";  // K^-1 of the iteration: LU, whatever the tangent's symmetry
  analysis::Analysis eigen(ctx.domain, config);
  try {
    ctx.eigen = eigen.eigen_modes(modes);
  } catch (const common::NumericalError& e) {
    args.fail(e.what());
  }
  std::string out;
  for (double lambda : ctx.eigen.eigenvalues) out += (out.empty() ? "" : " ") + format_values(&lambda, 1);
  return out;
}

std::string cmd_node_eigenvector(Context& ctx, common::CommandArgs& args) {
  const int tag = args.integer("nodeTag");
  const int mode = args.integer("mode");
  int dof = 0;
  if (!args.empty()) dof = args.integer("dof");
  args.expect_end();
  const int ndf = ctx.domain.node(tag, args.command()).ndf;
  const auto& modes = ctx.eigen;
  if (modes.shapes.empty()) args.fail("no eigen analysis yet (run 'eigen numModes' first)");
  if (mode < 1 || mode > static_cast<int>(modes.shapes.size()))
    args.fail("expected mode 1.." + std::to_string(modes.shapes.size()) + ", got " + std::to_string(mode));
  if (dof < 0 || dof > ndf) args.fail("expected dof 1.." + std::to_string(ndf) + ", got " + std::to_string(dof));
  const auto it = std::lower_bound(modes.node_tags.begin(), modes.node_tags.end(), tag);
  if (it == modes.node_tags.end() || *it != tag) args.fail("node " + std::to_string(tag) + " was defined after 'eigen'");
  const double* phi =
      modes.shapes[static_cast<std::size_t>(mode - 1)].data() + modes.node_first_dof[it - modes.node_tags.begin()];
  return dof == 0 ? format_values(phi, ndf) : format_values(phi + dof - 1, 1);
}

}  // namespace fem::tcl
