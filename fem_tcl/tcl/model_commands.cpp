// Model-building commands: model, node, fix*, equalDOF, mass, nDMaterial, element, timeSeries, pattern,
// load, sp, eleLoad, rayleigh, setParameter, updateMaterialStage.
#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>

#include "fem_tcl/elements/element_registry.hpp"
#include "fem_tcl/materials/material_registry.hpp"
#include "fem_tcl/tcl/commands.hpp"

namespace fem::tcl {

namespace {

void require_model(const Context& ctx, common::CommandArgs& args) {
  if (!ctx.model_defined) args.fail("no model defined; start the script with 'model basic -ndm 2 -ndf 2' (or -ndf 3 for u-p)");
}

std::vector<std::string> remaining_words(common::CommandArgs& args) {
  std::vector<std::string> words;
  while (!args.empty()) words.push_back(args.word("argument"));
  return words;
}

domain::LoadPattern& current_pattern(Context& ctx, common::CommandArgs& args) {
  if (!ctx.current_pattern) args.fail("only allowed inside the body of 'pattern Plain tag tsTag {...}'");
  return *ctx.current_pattern;
}

/// A number that must be finite (coordinates, masses, loads); CommandArgs::number rejects "nan" and "inf"
/// for every command.
double finite(common::CommandArgs& args, std::string_view what) { return args.number(what); }

int fix_flag(common::CommandArgs& args, std::string_view what) {
  const int f = args.integer(what);
  if (f != 0 && f != 1) args.fail("expected " + std::string(what) + " to be 0 or 1, got " + std::to_string(f));
  return f;
}

/// "m1", "f3": an argument's name with its index (built by append: GCC 12 warns, wrongly, about
/// "m" + std::to_string(i), -Wrestrict).
std::string indexed(std::string_view name, std::size_t i) {
  std::string s(name);
  s += std::to_string(i);
  return s;
}

/// Runs a parser; an error of the constructor it calls (parameters, geometry) gets the usage line too.
template <class Parse>
auto with_usage(std::string_view usage, Parse&& parse) -> decltype(parse()) {
  try {
    return parse();
  } catch (const common::InputError& e) {
    const std::string what = e.what();
    if (what.find("usage:") != std::string::npos) throw;
    throw common::InputError(what + "; usage: " + std::string(usage));
  }
}

std::string_view material_usage(std::string_view type) {
  if (type == "ElasticIsotropic") return "nDMaterial ElasticIsotropic tag E nu <rho>";
  if (type == "DruckerPrager") {
    return "nDMaterial DruckerPrager tag K G sigma_y rho rho_bar Kinf Ko delta1 delta2 H theta <density> <atm>";
  }
  if (type == "MohrCoulomb") return "nDMaterial MohrCoulomb tag E nu rho phi c psi <-tension T>";
  if (type == "PressureIndependMultiYield") {
    return "nDMaterial PressureIndependMultiYield tag nd rho refShearModul refBulkModul cohesi peakShearStra "
           "<frictionAng=0 <refPress=100 <pressDependCoe=0 <noYieldSurf=20 <r1 Gs1 ...>>>>>";
  }
  if (type == "PressureDependMultiYield02") {
    return "nDMaterial PressureDependMultiYield02 tag nd rho refShearModul refBulkModul frictionAng peakShearStra "
           "refPress pressDependCoe PTAng contrac1 contrac3 dilat1 dilat3 <noYieldSurf=20 <r1 Gs1 ...> <contrac2=5 "
           "dilat2=3 liquefac1=1 liquefac2=0 e=0.6 cs1=0.9 cs2=0.02 cs3=0.7 pa=101 <c=0.1 <Hv=0 Pv=1>>>>>";
  }
  if (type == "PM4Sand") {
    return "nDMaterial PM4Sand tag Dr G0 hpo Den <P_atm h0 emax emin nb nd Ado z_max cz ce phicv nu Cgd Cdr Ckaf Q R m "
           "Fsed_min p_sedo IntScheme TanType TolF TolR>";
  }
  if (type == "PM4Silt") {
    return "nDMaterial PM4Silt tag S_u Su_Rat G_o h_po Den <Su_factor P_atm nu nG h0 eInit lambda phicv nb_wet nb_dry "
           "nd Ado ru_max z_max cz ce Cgd Ckaf m_m CG_consol IntScheme TanType TolF TolR>";
  }
  return "nDMaterial <type> tag ...";
}

}  // namespace

std::string cmd_model(Context& ctx, common::CommandArgs& args) {
  const std::string builder = args.word("builder (basic)");
  if (builder != "basic" && builder != "Basic" && builder != "BasicBuilder") {
    args.fail("unknown model builder '" + builder + "' (basic)");
  }
  int ndm = 0, ndf = 0;
  while (!args.empty()) {
    if (args.flag("-ndm")) ndm = args.integer("-ndm value");
    else if (args.flag("-ndf")) ndf = args.integer("-ndf value");
    else args.fail("unknown option '" + args.peek() + "'");
  }
  if (ndm != 2) args.fail("fem_tcl builds 2D models only: expected -ndm 2");
  if (ndf == 0) ndf = 3;  // OpenSees' default for ndm = 2
  if (ndf != 2 && ndf != 3) {
    args.fail("expected -ndf 2 (solids) or 3 (u-p: ux, uy and the pore pressure), got " + std::to_string(ndf));
  }
  // OpenSees (myCommands.cpp specifyModelBuilder): a new builder replaces the old one, whose destructor
  // clears the time series; the domain and the materials stay, so a script can add nodes of another ndf
  // (a 2-dof block beside a u-p one, tied with equalDOF on dofs 1 2).
  ctx.time_series.clear();
  ctx.ndf = ndf;
  ctx.model_defined = true;
  return {};
}

std::string cmd_node(Context& ctx, common::CommandArgs& args) {
  require_model(ctx, args);
  const int tag = args.integer("tag");
  const double x = finite(args, "x");
  const double y = finite(args, "y");
  domain::NodeVector mass = domain::NodeVector::Zero();
  bool has_mass = false;
  while (!args.empty()) {
    if (args.flag("-mass")) {
      for (int d = 0; d < ctx.ndf; ++d) mass[d] = finite(args, indexed("m", d + 1));
      has_mass = true;
    } else {
      args.fail("unexpected argument '" + args.peek() + "'");
    }
  }
  domain::Node& n = ctx.domain.add_node(tag, x, y, ctx.ndf, args.command());
  n.mass = mass;
  n.has_mass = has_mass;
  return {};
}

std::string cmd_fix(Context& ctx, common::CommandArgs& args) {
  require_model(ctx, args);
  const int tag = args.integer("nodeTag");
  domain::Node& n = ctx.domain.node(tag, args.command());
  // one flag per dof of the node (OpenSees: fewer is an error, more are ignored)
  const auto ndf = static_cast<std::size_t>(n.ndf);
  std::array<int, domain::kMaxNodeDofs> flags{};
  for (std::size_t d = 0; d < ndf; ++d) {
    if (args.empty()) {
      args.fail("node " + std::to_string(tag) + " has " + std::to_string(ndf) + " dofs: expected " +
                std::to_string(ndf) + " fix flags, got " + std::to_string(d));
    }
    flags[d] = fix_flag(args, indexed("f", d + 1));
  }
  args.expect_end();
  bool again = false;
  for (std::size_t d = 0; d < ndf; ++d) again = again || (flags[d] && n.fixed[d]);
  if (again) std::cerr << "WARNING fix " << tag << ": a dof is already fixed; the constraint is kept once\n";
  for (std::size_t d = 0; d < ndf; ++d) n.fixed[d] = n.fixed[d] || flags[d];
  ctx.domain.touch();
  return {};
}

namespace {
std::string fix_line(Context& ctx, common::CommandArgs& args, int axis) {
  require_model(ctx, args);
  const double coord = args.number(axis == 0 ? "x" : "y");
  // one flag per dof of the model builder (`model -ndf`); a node with fewer dofs takes the first ones
  std::array<int, domain::kMaxNodeDofs> flags{};
  for (int d = 0; d < ctx.ndf; ++d) flags[static_cast<std::size_t>(d)] = fix_flag(args, indexed("f", d + 1));
  double tol = 1e-10;
  if (args.flag("-tol")) tol = args.number("-tol value");
  args.expect_end();
  // OpenSees fixX/fixY skip dofs that are already fixed (no duplicate constraint).
  for (const auto& [tag, n] : ctx.domain.nodes()) {
    if (std::abs(n->crd[axis] - coord) <= tol) {
      for (int d = 0; d < std::min(n->ndf, ctx.ndf); ++d) {
        const auto k = static_cast<std::size_t>(d);
        n->fixed[k] = n->fixed[k] || flags[k];
      }
    }
  }
  ctx.domain.touch();
  return {};
}
}  // namespace

std::string cmd_fix_x(Context& ctx, common::CommandArgs& args) { return fix_line(ctx, args, 0); }
std::string cmd_fix_y(Context& ctx, common::CommandArgs& args) { return fix_line(ctx, args, 1); }

std::string cmd_equal_dof(Context& ctx, common::CommandArgs& args) {
  require_model(ctx, args);
  domain::EqualDof c;
  c.retained = args.integer("retainedNode");
  c.constrained = args.integer("constrainedNode");
  if (c.retained == c.constrained) args.fail("retained and constrained node are the same");
  const int ndf = std::min(ctx.domain.node(c.retained, args.command()).ndf,
                           ctx.domain.node(c.constrained, args.command()).ndf);
  while (!args.empty()) {
    const int d = args.integer("dof");
    if (d < 1 || d > ndf) {
      args.fail("expected dof 1.." + std::to_string(ndf) + " (the dofs both nodes have), got " + std::to_string(d));
    }
    c.dofs.push_back(d - 1);
  }
  if (c.dofs.empty()) args.fail("missing dof");
  ctx.domain.add_equal_dof(std::move(c));
  return {};
}

std::string cmd_mass(Context& ctx, common::CommandArgs& args) {
  require_model(ctx, args);
  const int tag = args.integer("nodeTag");
  domain::Node& n = ctx.domain.node(tag, args.command());
  domain::NodeVector mass = domain::NodeVector::Zero();
  for (int d = 0; d < n.ndf; ++d) mass[d] = finite(args, indexed("m", d + 1));
  args.expect_end();
  n.mass = mass;
  n.has_mass = true;
  return {};
}

std::string cmd_nd_material(Context& ctx, common::CommandArgs& args) {
  require_model(ctx, args);
  const std::string type = args.word("type");
  const auto parse = materials::find_nd_material_parser(type);
  if (!parse) {
    std::string known;
    for (const auto& e : materials::nd_material_parsers()) known += (known.empty() ? "" : ", ") + std::string(e.type);
    args.fail("unknown material type '" + type + "' (known: " + known + ")");
  }
  const std::vector<std::string> words = remaining_words(args);
  common::CommandArgs sub("nDMaterial " + type + (words.empty() ? "" : " " + words[0]),
                          std::string(material_usage(type)), words);
  std::unique_ptr<materials::NDMaterial> material = with_usage(sub.usage(), [&] { return parse(sub); });
  const int tag = material->tag();
  if (ctx.materials.count(tag)) sub.fail("nDMaterial " + std::to_string(tag) + " already exists");
  ctx.materials.emplace(tag, std::move(material));
  return {};
}

std::string cmd_element(Context& ctx, common::CommandArgs& args) {
  require_model(ctx, args);
  const std::string type = args.word("type");
  const elements::ElementParserEntry* entry = elements::find_element_parser(type);
  if (!entry) {
    std::string known;
    for (const auto& e : elements::element_parsers()) known += (known.empty() ? "" : ", ") + std::string(e.type);
    args.fail("unknown element type '" + type + "' (known: " + known + ")");
  }
  const std::vector<std::string> words = remaining_words(args);
  common::CommandArgs sub("element " + type + (words.empty() ? "" : " " + words[0]), std::string(entry->usage), words);
  elements::ElementBuildContext build{ctx.domain, ctx.materials, &ctx.uniaxial_materials};
  std::unique_ptr<domain::Element> element = with_usage(entry->usage, [&] { return entry->parse(sub, build); });
  if (ctx.domain.find_element(element->tag())) sub.fail("element " + std::to_string(element->tag()) + " already exists");
  ctx.domain.add_element(std::move(element), sub.command());
  return {};
}

std::string cmd_time_series(Context& ctx, common::CommandArgs& args) {
  auto series = domain::parse_time_series(args);
  // OpenSees replaces a series with the same tag silently in some versions; an error is clearer.
  if (ctx.time_series.count(series->tag())) args.fail("timeSeries " + std::to_string(series->tag()) + " already exists");
  ctx.time_series.emplace(series->tag(), std::move(series));
  return {};
}

std::string cmd_pattern(Context& ctx, common::CommandArgs& args) {
  require_model(ctx, args);
  const std::string type = args.word("type (Plain or UniformExcitation)");
  if (type == "Plain") {
    const int tag = args.integer("tag");
    const std::string ts = args.word("tsTag or {inline series}");
    double fact = 1.0;
    if (args.flag("-fact") || args.flag("-factor")) fact = args.number("-fact value");
    const std::string body = args.word("body {...}");
    args.expect_end();
    auto pattern = std::make_unique<domain::PlainPattern>(tag, series_argument(ctx, args, ts), fact);
    domain::LoadPattern* raw = pattern.get();
    ctx.domain.add_pattern(std::move(pattern), args.command());
    struct Restore {
      Context& c;
      domain::LoadPattern* previous;
      ~Restore() { c.current_pattern = previous; }
    } restore{ctx, ctx.current_pattern};
    ctx.current_pattern = raw;
    ctx.eval(body);
    return {};
  }
  if (type == "UniformExcitation") {
    const int tag = args.integer("tag");
    const int dir = args.integer("dir");
    if (dir < 1 || dir > 2) args.fail("expected dir 1 or 2, got " + std::to_string(dir));
    std::shared_ptr<domain::TimeSeries> accel;
    double fact = 1.0, vel0 = 0.0;
    while (!args.empty()) {
      if (args.flag("-accel") || args.flag("-acceleration")) accel = series_argument(ctx, args, args.word("-accel tsTag"));
      else if (args.flag("-fact") || args.flag("-factor")) fact = finite(args, "-fact value");
      else if (args.flag("-vel0") || args.flag("-initialVel")) vel0 = finite(args, "-vel0 value");
      else if (args.peek() == "-vel" || args.peek() == "-disp" || args.peek() == "-int") {
        args.fail("option '" + args.peek() + "' is not supported (give the ground acceleration with -accel)");
      } else args.fail("unknown option '" + args.peek() + "'");
    }
    if (!accel) args.fail("missing -accel tsTag");
    ctx.domain.add_pattern(std::make_unique<domain::UniformExcitation>(tag, dir - 1, std::move(accel), fact),
                           args.command());
    // OpenSees UniformExcitation::setDomain: every node not fixed in `dir` starts with velocity vel0
    // (relative to the ground), set as its trial and committed velocity.
    if (vel0 != 0.0) {
      for (const auto& [ntag, n] : ctx.domain.nodes()) {
        if (n->fixed[dir - 1]) continue;
        n->vel[dir - 1] = vel0;
        n->committed_vel[dir - 1] = vel0;
      }
    }
    return {};
  }
  args.fail("unknown pattern type '" + type + "' (Plain or UniformExcitation)");
}

std::string cmd_load(Context& ctx, common::CommandArgs& args) {
  domain::LoadPattern& p = current_pattern(ctx, args);
  const int tag = args.integer("nodeTag");
  const domain::Node& n = ctx.domain.node(tag, args.command());
  domain::NodeVector force = domain::NodeVector::Zero();
  for (int d = 0; d < n.ndf; ++d) force[d] = finite(args, indexed("F", d + 1));
  args.expect_end();
  p.nodal_loads.push_back({tag, force});
  return {};
}

std::string cmd_sp(Context& ctx, common::CommandArgs& args) {
  domain::LoadPattern& p = current_pattern(ctx, args);
  const int tag = args.integer("nodeTag");
  const int dof = args.integer("dof");
  const double value = finite(args, "value");
  args.expect_end();
  const domain::Node& n = ctx.domain.node(tag, args.command());
  if (dof < 1 || dof > n.ndf) {
    args.fail("expected dof 1.." + std::to_string(n.ndf) + " (node " + std::to_string(tag) + " has " +
              std::to_string(n.ndf) + "), got " + std::to_string(dof));
  }
  if (n.fixed[dof - 1]) args.fail("node " + std::to_string(tag) + " dof " + std::to_string(dof) + " is already fixed");
  p.prescribed.push_back({tag, dof - 1, value});
  ctx.domain.touch();
  return {};
}

std::string cmd_ele_load(Context& ctx, common::CommandArgs& args) {
  domain::LoadPattern& p = current_pattern(ctx, args);
  domain::SelfWeightLoad load{{}, 1.0, 1.0};
  bool have_type = false;
  while (!args.empty()) {
    if (args.flag("-ele")) {
      while (auto t = args.optional_integer()) load.elements.push_back(*t);
    } else if (args.flag("-range")) {
      const int a = args.integer("-range start"), b = args.integer("-range end");
      for (const auto& [tag, e] : ctx.domain.elements()) if (tag >= a && tag <= b) load.elements.push_back(tag);
    } else if (args.flag("-type")) {
      const std::string t = args.word("load type");
      if (t != "-selfWeight") args.fail("only -type -selfWeight is supported for 2D solids, got '" + t + "'");
      have_type = true;
      if (auto xf = args.optional_number()) load.xf = *xf;
      if (auto yf = args.optional_number()) load.yf = *yf;
      if (auto zf = args.optional_number()) (void)zf;
    } else {
      args.fail("unknown option '" + args.peek() + "'");
    }
  }
  if (!have_type) args.fail("missing -type -selfWeight");
  for (int t : load.elements) ctx.domain.element(t, args.command());
  p.self_weight.push_back(std::move(load));
  return {};
}

std::string cmd_rayleigh(Context& ctx, common::CommandArgs& args) {
  domain::RayleighFactors f;
  f.alpha_m = finite(args, "alphaM");
  f.beta_k = finite(args, "betaK");
  f.beta_k0 = finite(args, "betaK0");
  f.beta_kc = finite(args, "betaKc");
  args.expect_end();
  ctx.domain.set_rayleigh(f);
  return {};
}

std::string cmd_set_parameter(Context& ctx, common::CommandArgs& args) {
  double value = 0.0;
  bool have_value = false;
  std::vector<domain::Element*> targets;
  bool have_targets = false;
  std::string name;
  std::optional<int> material_tag;
  while (!args.empty()) {
    if (args.flag("-val")) { value = args.number("-val value"); have_value = true; }
    else if (args.flag("-ele")) {
      have_targets = true;
      while (auto t = args.optional_integer()) targets.push_back(&ctx.domain.element(*t, args.command()));
    } else if (args.flag("-eleRange")) {
      have_targets = true;
      const int a = args.integer("-eleRange start"), b = args.integer("-eleRange end");
      for (const auto& [tag, e] : ctx.domain.elements()) if (tag >= a && tag <= b) targets.push_back(e.get());
    } else {
      // OpenSees passes the words after the options to the element: the parameter's name, then its
      // arguments. `material k name` (a quad's Gauss point k) names the parameter last; otherwise a trailing
      // integer is the material tag the parameter is meant for (PM4Sand, PM4Silt, the multi-yield models:
      // `setParameter -val 0 -ele 1 FirstCall 1`), and only elements of that material take it.
      name = args.word("parameter name");
      if (name == "material" || name == "integrPoint") {
        while (!args.empty()) name = args.word("parameter name");
      } else if (!args.empty()) {
        material_tag = args.integer("material tag (after the parameter name)");
        args.expect_end();
      }
    }
  }
  if (!have_value) args.fail("missing -val value");
  if (name.empty()) args.fail("missing parameter name (e.g. E, nu, rho, materialState)");
  if (!have_targets) for (const auto& [tag, e] : ctx.domain.elements()) targets.push_back(e.get());
  int accepted = 0;
  for (domain::Element* e : targets) {
    if (material_tag && e->material_tag() != *material_tag) continue;
    accepted += e->set_parameter(name, value) ? 1 : 0;
  }
  if (accepted == 0 && !targets.empty()) {
    std::cerr << "WARNING setParameter: no element" << (material_tag ? " of material " + std::to_string(*material_tag) : "")
              << " has a parameter '" << name << "'\n";
  }
  return {};
}

std::string cmd_update_material_stage(Context& ctx, common::CommandArgs& args) {
  int tag = 0, stage = 0;
  bool have_tag = false, have_stage = false;
  while (!args.empty()) {
    if (args.flag("-material")) { tag = args.integer("-material tag"); have_tag = true; }
    else if (args.flag("-stage")) { stage = args.integer("-stage value"); have_stage = true; }
    else if (args.flag("-parameter")) args.integer("-parameter tag");
    else args.fail("unknown option '" + args.peek() + "'");
  }
  if (!have_tag || !have_stage) args.fail("missing -material tag or -stage value");
  auto it = ctx.materials.find(tag);
  if (it == ctx.materials.end()) args.fail("nDMaterial " + std::to_string(tag) + " does not exist");
  bool any = it->second->update_stage(stage);
  for (const auto& [etag, e] : ctx.domain.elements()) {
    if (e->material_tag() == tag) any = e->update_material_stage(stage) || any;
  }
  if (!any) std::cerr << "WARNING updateMaterialStage: nDMaterial " << tag << " has no stages\n";
  return {};
}

}  // namespace fem::tcl
