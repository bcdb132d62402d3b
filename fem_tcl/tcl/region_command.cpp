// `region regTag <-ele e..> <-eleOnly e..> <-eleRange a b> <-eleOnlyRange a b> <-node n..> <-nodeOnly n..>
// <-nodeRange a b> <-nodeOnlyRange a b> <-rayleigh alphaM betaK betaK0 betaKc>`: OpenSees 3.8's MeshRegion
// (OPS_MeshRegion and SRC/domain/region/MeshRegion.cpp), mostly used for Rayleigh damping that differs
// between parts of a model (an elastic base, a soil column) and for recorders of a part (`-region tag`).
// - Elements given: the region is those elements and every node they connect; nodes given: those nodes and
//   every element whose nodes are all among them. An -*Only flag anywhere keeps only what was listed.
//   Both elements and nodes: the elements win (OpenSees warns; so does fem_tcl). Tags not in the domain
//   are skipped, as OpenSees does; a range may be given high to low.
// - `-rayleigh`: each element of the region takes the four factors (zeroLength only with -doRayleigh) and
//   each node its alphaM, replacing what `rayleigh` set; like OpenSees, all-zero factors change nothing.
// Differences, errors where OpenSees goes on quietly: an unknown option (`-node all` included), a list
// flag without tags, and a region that selects nothing.
#include <iostream>
#include <set>
#include <utility>

#include "fem_tcl/tcl/commands.hpp"

namespace fem::tcl {

namespace {

/// The tags one list flag or range flag selected, in the order given: a range [a, b] stands for the
/// domain's tags in it (never expanded, so `-eleRange 1 2000000000` costs nothing).
struct TagSelection {
  std::vector<std::pair<int, int>> spans;  ///< [first, last]; a single tag is [t, t]
  bool given = false;
};

struct RegionRequest {
  TagSelection elements, nodes;
  bool only = false;
  domain::RayleighFactors rayleigh;
};

void read_list(common::CommandArgs& args, const std::string& flag, TagSelection& into) {
  std::size_t read = 0;
  while (auto v = args.optional_integer()) {
    into.spans.emplace_back(*v, *v);
    ++read;
  }
  if (read == 0) args.fail("missing tags after " + flag);
  into.given = true;
}

void read_range(common::CommandArgs& args, const std::string& flag, TagSelection& into) {
  int a = args.integer(flag + " start"), b = args.integer(flag + " end");
  if (a > b) std::swap(a, b);
  into.spans.emplace_back(a, b);
  into.given = true;
}

RegionRequest parse_request(common::CommandArgs& args) {
  RegionRequest r;
  while (!args.empty()) {
    const std::string flag = args.word("option");
    if (flag == "-ele" || flag == "-eleOnly") read_list(args, flag, r.elements);
    else if (flag == "-eleRange" || flag == "-eleOnlyRange") read_range(args, flag, r.elements);
    else if (flag == "-node" || flag == "-nodeOnly") read_list(args, flag, r.nodes);
    else if (flag == "-nodeRange" || flag == "-nodeOnlyRange") read_range(args, flag, r.nodes);
    else if (flag == "-rayleigh") {
      r.rayleigh.alpha_m = args.number("-rayleigh alphaM");
      r.rayleigh.beta_k = args.number("-rayleigh betaK");
      r.rayleigh.beta_k0 = args.number("-rayleigh betaK0");
      r.rayleigh.beta_kc = args.number("-rayleigh betaKc");
    } else {
      args.fail("unknown option '" + flag + "'");
    }
    if (flag == "-eleOnly" || flag == "-eleOnlyRange" || flag == "-nodeOnly" || flag == "-nodeOnlyRange") r.only = true;
  }
  return r;
}

/// The tags of `objects` (a domain map by tag) that `selection` names, in its order, each once.
template <class Map>
std::vector<int> resolve(const TagSelection& selection, const Map& objects) {
  std::vector<int> out;
  std::set<int> seen;
  for (const auto& [first, last] : selection.spans) {
    for (auto it = objects.lower_bound(first); it != objects.end() && it->first <= last; ++it)
      if (seen.insert(it->first).second) out.push_back(it->first);
  }
  return out;
}

}  // namespace

std::string cmd_region(Context& ctx, common::CommandArgs& args) {
  const int tag = args.integer("regTag");
  const RegionRequest r = parse_request(args);
  domain::Domain& d = ctx.domain;
  domain::MeshRegion region;
  if (r.elements.given) {
    if (r.nodes.given) std::cerr << "WARNING region - both elements & nodes set, ONLY set using elements\n";
    region.elements = resolve(r.elements, d.elements());
    if (!r.only) {
      std::set<int> seen;
      for (int e : region.elements) {
        const domain::Element& el = *d.find_element(e);
        for (int a = 0; a < el.num_nodes(); ++a)
          if (seen.insert(el.nodes()[a]->tag).second) region.nodes.push_back(el.nodes()[a]->tag);
      }
    }
  } else if (r.nodes.given) {
    region.nodes = resolve(r.nodes, d.nodes());
    if (!r.only) {
      const std::set<int> in_region(region.nodes.begin(), region.nodes.end());
      for (const auto& [e, el] : d.elements()) {
        bool all_in = true;
        for (int a = 0; a < el->num_nodes() && all_in; ++a) all_in = in_region.count(el->nodes()[a]->tag) > 0;
        if (all_in) region.elements.push_back(e);
      }
    }
  }
  if (region.elements.empty() && region.nodes.empty()) {
    args.fail("region " + std::to_string(tag) + " selects no node or element of the domain");
  }
  const domain::RayleighFactors& f = r.rayleigh;
  if (f.alpha_m != 0.0 || f.beta_k != 0.0 || f.beta_k0 != 0.0 || f.beta_kc != 0.0) {
    for (int e : region.elements) d.find_element(e)->set_rayleigh(f);
    for (int n : region.nodes) d.find_node(n)->rayleigh_alpha_m = f.alpha_m;
  }
  d.set_region(tag, std::move(region));
  return {};
}

}  // namespace fem::tcl
