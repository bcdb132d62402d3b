#include <array>

#include "fem_tcl/tcl/commands.hpp"

namespace fem::tcl {

namespace {
constexpr std::array kCommands{
    CommandEntry{"model", "model basic -ndm 2 <-ndf 2|3>", 0, cmd_model},
    CommandEntry{"node", "node tag x y <-mass m1 m2 <m3>>", 1, cmd_node},
    CommandEntry{"fix", "fix nodeTag f1 f2 <f3>", 1, cmd_fix},
    CommandEntry{"fixX", "fixX x f1 f2 <f3> <-tol tol>", 1, cmd_fix_x},
    CommandEntry{"fixY", "fixY y f1 f2 <f3> <-tol tol>", 1, cmd_fix_y},
    CommandEntry{"equalDOF", "equalDOF retainedNode constrainedNode dof1 <dof2 <dof3>>", 2, cmd_equal_dof},
    CommandEntry{"mass", "mass nodeTag m1 m2 <m3>", 1, cmd_mass},
    CommandEntry{"nDMaterial", "nDMaterial type tag ...", 2, cmd_nd_material},
    CommandEntry{"uniaxialMaterial", "uniaxialMaterial Elastic tag E <eta> <Eneg> | Viscous tag C alpha <minVel>", 2, cmd_uniaxial_material},
    CommandEntry{"element", "element type tag ...", 2, cmd_element},
    CommandEntry{"block2D", "block2D numX numY startNode startEle eleType eleArgs <-numEleNodes 4> {1 x y 2 x y 3 x y 4 x y <5 x y .. 9 x y>}", 4, cmd_block2d},
    CommandEntry{"timeSeries", "timeSeries Constant|Linear tag <-factor f> | Path tag -dt dt -values {..}|-filePath f <-factor f> <-useLast> <-prependZero> <-startTime t> | Path tag -time {..} -values {..} | -fileTime ft -filePath fv | Trig|Sine tag tStart tEnd period <-phaseShift p> <-factor f> <-zeroShift z> | Rectangular tag tStart tEnd <-factor f> | Pulse tag tStart tEnd period <-width w> <-phaseShift p> <-factor f> <-zeroShift z>", 2, cmd_time_series},
    CommandEntry{"pattern", "pattern Plain tag tsTag|{series} <-fact f> {body} | pattern UniformExcitation tag dir -accel tsTag|{series} <-vel0 v> <-fact f>", 2, cmd_pattern},
    CommandEntry{"load", "load nodeTag F1 F2 <F3>", 1, cmd_load},
    CommandEntry{"sp", "sp nodeTag dof value", 1, cmd_sp},
    CommandEntry{"eleLoad", "eleLoad -ele t.. | -range a b -type -selfWeight xf yf", 0, cmd_ele_load},
    CommandEntry{"rayleigh", "rayleigh alphaM betaK betaK0 betaKc", 0, cmd_rayleigh},
    CommandEntry{"region", "region regTag (-ele e.. | -eleOnly e.. | -eleRange a b | -eleOnlyRange a b | -node n.. | -nodeOnly n.. | -nodeRange a b | -nodeOnlyRange a b) <-rayleigh alphaM betaK betaK0 betaKc>", 1, cmd_region},
    CommandEntry{"setParameter", "setParameter -val v <-ele t.. | -eleRange a b> name <materialTag> | material k name", 0, cmd_set_parameter},
    CommandEntry{"updateMaterialStage", "updateMaterialStage -material tag -stage s", 0, cmd_update_material_stage},
    CommandEntry{"constraints", "constraints Plain|Transformation|Penalty <alphaS alphaM>", 0, cmd_constraints},
    CommandEntry{"numberer", "numberer Plain|RCM|AMD|ParallelPlain|ParallelRCM", 0, cmd_numberer},
    CommandEntry{"system", "system BandGeneral|BandSPD|ProfileSPD|SparseGeneral|UmfPack|FullGeneral|SparseSYM", 0, cmd_system},
    CommandEntry{"test", "test NormDispIncr|NormUnbalance|EnergyIncr|RelativeNormDispIncr|RelativeNormUnbalance|RelativeEnergyIncr tol maxIter <printFlag> <normType> | FixedNumIter maxIter <printFlag> <normType>", 0, cmd_test},
    CommandEntry{"algorithm", "algorithm Linear|Newton|ModifiedNewton|KrylovNewton|NewtonLineSearch", 0, cmd_algorithm},
    CommandEntry{"integrator", "integrator LoadControl dLambda <Jd minLambda maxLambda> | DisplacementControl node dof dU <numIter dUmin dUmax> | Newmark gamma beta | HHT alpha <gamma beta> | CentralDifference", 0, cmd_integrator},
    CommandEntry{"analysis", "analysis Static|Transient|VariableTransient", 0, cmd_analysis},
    CommandEntry{"analyze", "analyze numSteps <dt> <dtMin dtMax Jd>", 0, cmd_analyze},
    CommandEntry{"eigen", "eigen <-genBandArpack|-symmBandLapack|-fullGenLapack> numModes", 1, cmd_eigen},
    CommandEntry{"nodeEigenvector", "nodeEigenvector nodeTag mode <dof>", 2, cmd_node_eigenvector},
    CommandEntry{"strengthReduction", "strengthReduction -materials {tags} <-bracket Flo Fhi> <-tol dF> <-criterion displacement|convergence> <-displacementRatio r> <-displacementLimit d> <-steps n> <-maxCuts m> <-maxTrials k>", 0, cmd_strength_reduction},
    CommandEntry{"loadConst", "loadConst <-time t>", 0, cmd_load_const},
    CommandEntry{"setTime", "setTime t", 0, cmd_set_time},
    CommandEntry{"getTime", "getTime <format>", 0, cmd_get_time},
    CommandEntry{"wipe", "wipe", 0, cmd_wipe},
    CommandEntry{"wipeAnalysis", "wipeAnalysis", 0, cmd_wipe_analysis},
    CommandEntry{"reset", "reset", 0, cmd_reset},
    CommandEntry{"remove", "remove recorders | recorder tag | loadPattern tag | timeSeries tag | element tag | node tag | sp nodeTag dofTag <patternTag>", 1, cmd_remove},
    CommandEntry{"nodeDisp", "nodeDisp nodeTag <dof>", 1, cmd_node_disp},
    CommandEntry{"nodeVel", "nodeVel nodeTag <dof>", 1, cmd_node_vel},
    CommandEntry{"nodeAccel", "nodeAccel nodeTag <dof>", 1, cmd_node_accel},
    CommandEntry{"nodeCoord", "nodeCoord nodeTag <dim>", 1, cmd_node_coord},
    CommandEntry{"eleResponse", "eleResponse eleTag response..", 1, cmd_ele_response},
    CommandEntry{"getNodeTags", "getNodeTags", 0, cmd_get_node_tags},
    CommandEntry{"getNDF", "getNDF <nodeTag>", 0, cmd_get_ndf},
    CommandEntry{"getEleTags", "getEleTags", 0, cmd_get_ele_tags},
    CommandEntry{"eleNodes", "eleNodes eleTag", 1, cmd_ele_nodes},
    CommandEntry{"reactions", "reactions", 0, cmd_reactions},
    CommandEntry{"nodeReaction", "nodeReaction nodeTag <dof>", 1, cmd_node_reaction},
    CommandEntry{"getLoadFactor", "getLoadFactor patternTag", 1, cmd_get_load_factor},
    CommandEntry{"testIter", "testIter", 0, cmd_test_iter},
    CommandEntry{"testNorm", "testNorm", 0, cmd_test_norm},
    CommandEntry{"record", "record", 0, cmd_record},
    CommandEntry{"minJacobian", "minJacobian <-ratio>", 0, cmd_min_jacobian},
    CommandEntry{"meshQuality", "meshQuality <-warn ratio>", 0, cmd_mesh_quality},
    CommandEntry{"recorder", "recorder Node|Element|EnvelopeNode|EnvelopeElement|MeshQuality -file f <-time> <-dT dt> <-timeSeries tags> <-precision n> <-closeOnWrite> (-node n.. | -nodeRange a b | -region r -dof d.. | -ele e.. | -eleRange a b | -region r) response..", 1, cmd_recorder},
    CommandEntry{"print", "print -JSON <-file f> | print <file> <-node <-flag f> tags..> <-ele <-flag f> tags..>", 0, cmd_print},
};
}  // namespace

std::span<const CommandEntry> command_table() { return kCommands; }

}  // namespace fem::tcl
