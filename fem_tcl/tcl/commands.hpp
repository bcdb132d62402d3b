#pragma once
// The explicit registration table of fem_tcl's Tcl commands: one parse function per command.
// Each returns the command's Tcl result (possibly empty) and throws common::InputError (or
// common::NumericalError) for bad input; the one place that turns exceptions into TCL_ERROR is
// interpreter.cpp.
#include <span>
#include <string>
#include <string_view>

#include "common/command_args.hpp"
#include "fem_tcl/tcl/context.hpp"

namespace fem::tcl {

using CommandFunction = std::string (*)(Context& ctx, common::CommandArgs& args);

struct CommandEntry {
  std::string_view name;
  std::string_view usage;
  int name_words;  ///< how many leading words name the object in error messages ("element SSPquad 3": 2)
  CommandFunction run;
};

std::span<const CommandEntry> command_table();

// model building (model_commands.cpp)
std::string cmd_model(Context&, common::CommandArgs&);
std::string cmd_node(Context&, common::CommandArgs&);
std::string cmd_fix(Context&, common::CommandArgs&);
std::string cmd_fix_x(Context&, common::CommandArgs&);
std::string cmd_fix_y(Context&, common::CommandArgs&);
std::string cmd_equal_dof(Context&, common::CommandArgs&);
std::string cmd_mass(Context&, common::CommandArgs&);
std::string cmd_nd_material(Context&, common::CommandArgs&);
// uniaxial materials (uniaxial_commands.cpp)
std::string cmd_uniaxial_material(Context&, common::CommandArgs&);
std::string cmd_element(Context&, common::CommandArgs&);
std::string cmd_time_series(Context&, common::CommandArgs&);
std::string cmd_pattern(Context&, common::CommandArgs&);
std::string cmd_load(Context&, common::CommandArgs&);
std::string cmd_sp(Context&, common::CommandArgs&);
std::string cmd_ele_load(Context&, common::CommandArgs&);
std::string cmd_rayleigh(Context&, common::CommandArgs&);
std::string cmd_set_parameter(Context&, common::CommandArgs&);
std::string cmd_update_material_stage(Context&, common::CommandArgs&);
// meshing (block2d_command.cpp)
std::string cmd_block2d(Context&, common::CommandArgs&);
// regions of nodes and elements (region_command.cpp)
std::string cmd_region(Context&, common::CommandArgs&);
// analysis (analysis_commands.cpp)
std::string cmd_constraints(Context&, common::CommandArgs&);
std::string cmd_numberer(Context&, common::CommandArgs&);
std::string cmd_system(Context&, common::CommandArgs&);
std::string cmd_test(Context&, common::CommandArgs&);
std::string cmd_algorithm(Context&, common::CommandArgs&);
std::string cmd_integrator(Context&, common::CommandArgs&);
std::string cmd_analysis(Context&, common::CommandArgs&);
std::string cmd_analyze(Context&, common::CommandArgs&);
std::string cmd_eigen(Context&, common::CommandArgs&);
std::string cmd_node_eigenvector(Context&, common::CommandArgs&);
std::string cmd_load_const(Context&, common::CommandArgs&);
std::string cmd_strength_reduction(Context&, common::CommandArgs&);
std::string cmd_set_time(Context&, common::CommandArgs&);
std::string cmd_get_time(Context&, common::CommandArgs&);
std::string cmd_wipe(Context&, common::CommandArgs&);
std::string cmd_wipe_analysis(Context&, common::CommandArgs&);
std::string cmd_reset(Context&, common::CommandArgs&);
std::string cmd_remove(Context&, common::CommandArgs&);
// queries and output (query_commands.cpp)
std::string cmd_node_disp(Context&, common::CommandArgs&);
std::string cmd_node_vel(Context&, common::CommandArgs&);
std::string cmd_node_accel(Context&, common::CommandArgs&);
std::string cmd_node_coord(Context&, common::CommandArgs&);
std::string cmd_ele_response(Context&, common::CommandArgs&);
std::string cmd_get_node_tags(Context&, common::CommandArgs&);
std::string cmd_get_ndf(Context&, common::CommandArgs&);
std::string cmd_get_ele_tags(Context&, common::CommandArgs&);
std::string cmd_ele_nodes(Context&, common::CommandArgs&);
std::string cmd_reactions(Context&, common::CommandArgs&);
std::string cmd_node_reaction(Context&, common::CommandArgs&);
std::string cmd_get_load_factor(Context&, common::CommandArgs&);
std::string cmd_test_iter(Context&, common::CommandArgs&);
std::string cmd_test_norm(Context&, common::CommandArgs&);
std::string cmd_record(Context&, common::CommandArgs&);
std::string cmd_recorder(Context&, common::CommandArgs&);
std::string cmd_print(Context&, common::CommandArgs&);
std::string cmd_min_jacobian(Context&, common::CommandArgs&);
std::string cmd_mesh_quality(Context&, common::CommandArgs&);

/// A pattern's series argument: a timeSeries tag or an inline {type <tag> options..} (series_argument.cpp).
std::shared_ptr<domain::TimeSeries> series_argument(Context& ctx, common::CommandArgs& args, const std::string& word);

/// OpenSees' query format: every value as "%35.20f", joined with no separator (quirk 9).
std::string format_values(const double* values, std::size_t n);

}  // namespace fem::tcl
