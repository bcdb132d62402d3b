# A 45-degree cut slope, 10 m high, on a 5 m foundation layer: two block2D blocks tied along their shared
# edge, sides on rollers, base fixed; Mohr-Coulomb soil that cannot stand at 45 degrees (phi 25, c 2 kPa:
# the infinite-slope factor tan(phi) / tan(45) is 0.47), so the slope fails as soon as the material turns
# plastic, and the runout is carried by MPM.
#
# Sample run (about 15 s; figures and summary.md in results/slope_on_foundation):
#   scripts/hybrid_run.py scripts/examples/slope_on_foundation.tcl --transfer 0.5 --duration 3 --out results/slope_on_foundation --units kN --ppd 2 --cfl 0.4 --cell-size 1 --extent 0 45 -1 20 --base-y 0 --left-wall roller --right-wall roller --base friction --base-friction 0.47
#
# Usage: fem_tcl slope_on_foundation.tcl <outdir> ?-cell 1? ?-tend 0.5? ?-dt 0.005? ?-record 0.05?
# Units kN, m, s, kPa, Mg/m3. Geometry (m): foundation 0 <= x <= 45, 0 <= y <= 5; slope block on top with
# corners (0, 5), (25, 5), (15, 15), (0, 15): crest at x = 15, toe at x = 25, slope 1:1.
# Soil (both blocks one material): E = 20 MPa, nu = 0.3, rho = 1.9 Mg/m3, phi = 25, c = 2 kPa, psi = 0.
# Stages: elastic gravity (static), then MohrCoulomb and Newmark to -tend; the recorders of the
# hybrid_run.py contract every -record s.
source [file join [file dirname [info script]] hybrid_stages.tcl]
if {$argc < 1 || [string index [lindex $argv 0] 0] eq "-"} {
    error "slope_on_foundation.tcl: missing <outdir>; usage: fem_tcl slope_on_foundation.tcl <outdir> ?-cell 1? ?-tend 0.5? ?-dt 0.005? ?-record 0.05?"
}
set outdir [lindex $argv 0]
array set opt {-cell 1.0 -tend 0.5 -dt 0.005 -record 0.05}
parse_options slope_on_foundation.tcl opt [lrange $argv 1 end]
file mkdir $outdir
set h $opt(-cell)
set rho 1.9
set g 9.81

wipe
model basic -ndm 2 -ndf 2
nDMaterial MohrCoulomb 1 20.0e3 0.3 $rho 25.0 2.0 0.0
set eleArgs "1 PlaneStrain 1.0 0.0 [expr {-$rho * $g}]"   ;# SSPquad: matTag type thick b1 b2
# foundation: nodes 1.., elements 1..
set nxF [expr {int(round(45.0 / $h))}]
set nyF [expr {int(round(5.0 / $h))}]
block2D $nxF $nyF 1 1 SSPquad $eleArgs {1 0 0 2 45 0 3 45 5 4 0 5}
# slope: numbered after the foundation; its base nodes coincide with the foundation's top nodes
set nxS [expr {int(round(25.0 / $h))}]
set nyS [expr {int(round(10.0 / $h))}]
set n0 [expr {($nxF + 1) * ($nyF + 1) + 1}]
set e0 [expr {$nxF * $nyF + 1}]
block2D $nxS $nyS $n0 $e0 SSPquad $eleArgs {1 0 5 2 25 5 3 15 15 4 0 15}
set ties [tie_coincident_nodes [expr {1e-6 * $h}]]

set tol [expr {1e-6 * $h}]
fixY 0.0 1 1 -tol $tol     ;# base fixed
fixX 0.0 1 0 -tol $tol     ;# left side on rollers
fixX 45.0 1 0 -tol $tol    ;# right side on rollers

gravity_stage
collapse_stage {1} $outdir $opt(-tend) $opt(-dt) $opt(-record)
puts stdout "slope_on_foundation: [llength [getNodeTags]] nodes, [llength [getEleTags]] SSPquads, $ties tied node pairs"
