# A 45-degree cut slope, 10 m high, on a 4 m foundation layer: two block2D blocks tied along their shared
# edge, sides on rollers, base fixed; Mohr-Coulomb soil that cannot stand at 45 degrees (phi 25, c 2 kPa:
# the infinite-slope factor tan(phi) / tan(45) is 0.47; strength reduction, -fos yes: 0.68), so the slope fails
# as soon as the material turns plastic, and the runout is carried by MPM.
#
# Sample run (about 15 s; figures and summary.md in results/slope_on_foundation):
#   scripts/hybrid_run.py scripts/examples/slope_on_foundation.tcl --transfer 0.5 --duration 3 --out results/slope_on_foundation --units kN --ppd 2 --cfl 0.4 --base-friction 0.47
#
# Walls, base, grid and cell size come from the FEM supports (fem2mpm defaults).
#
# Test run (tests/regression/study/examples_sample_runs_test.py: these values replace the sample run's):
#   --duration 1 --ppd 1 -- -cell 2
#
# Usage: fem_tcl slope_on_foundation.tcl <outdir> ?-cell 1? ?-tend 0.5? ?-dt 0.005? ?-record 0.05? ?-fos no|yes?
#        ?-mesh quad|tri? (tri: each block2D SSPquad cut along its 1-3 diagonal into two tri31, tags 100001..)
# Units kN, m, s, kPa, Mg/m3. Geometry (m): foundation 0 <= x <= 44, 0 <= y <= 4; slope block on top with
# corners (0, 4), (24, 4), (14, 14), (0, 14): crest at x = 14, toe at x = 24, slope 1:1. -cell must divide
# 4, 10, 14 and 24 (1 or 2), so that the slope block's base nodes fall on the foundation's top nodes.
# Soil (both blocks one material): E = 20 MPa, nu = 0.3, rho = 1.9 Mg/m3, phi = 25, c = 2 kPa, psi = 0.
# Stages: elastic gravity (static), then MohrCoulomb and Newmark to -tend; the recorders of the
# hybrid_run.py contract every -record s. -fos yes: the factor of safety instead (hybrid_stages.tcl fos_stage).
source [file join [file dirname [info script]] hybrid_stages.tcl]
if {$argc < 1 || [string index [lindex $argv 0] 0] eq "-"} {
    error "slope_on_foundation.tcl: missing <outdir>; usage: fem_tcl slope_on_foundation.tcl <outdir> ?-cell 1? ?-tend 0.5? ?-dt 0.005? ?-record 0.05? ?-fos no|yes? ?-mesh quad|tri?"
}
set outdir [lindex $argv 0]
array set opt {-cell 1.0 -tend 0.5 -dt 0.005 -record 0.05 -fos no -mesh quad}
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
set nxF [expr {int(round(44.0 / $h))}]
set nyF [expr {int(round(4.0 / $h))}]
block2D $nxF $nyF 1 1 SSPquad $eleArgs {1 0 0 2 44 0 3 44 4 4 0 4}
# slope: numbered after the foundation; its base nodes coincide with the foundation's top nodes
set nxS [expr {int(round(24.0 / $h))}]
set nyS [expr {int(round(10.0 / $h))}]
set n0 [expr {($nxF + 1) * ($nyF + 1) + 1}]
set e0 [expr {$nxF * $nyF + 1}]
block2D $nxS $nyS $n0 $e0 SSPquad $eleArgs {1 0 4 2 24 4 3 14 14 4 0 14}
if {$opt(-mesh) eq "tri"} {
    # every SSPquad as two constant-strain triangles, cut from its node 1 to its node 3
    foreach e [getEleTags] {
        set n [eleNodes $e]
        remove element $e
        foreach {k a b c} [list 1 0 1 2 2 0 2 3] {
            element tri31 [expr {100000 + 2 * $e - 2 + $k}] [lindex $n $a] [lindex $n $b] [lindex $n $c] 1.0 PlaneStrain 1 0.0 0.0 0.0 [expr {-$rho * $g}]
        }
    }
} elseif {$opt(-mesh) ne "quad"} {
    error "slope_on_foundation.tcl: expected quad or tri after -mesh, got '$opt(-mesh)'"
}
set ties [tie_coincident_nodes [expr {1e-6 * $h}]]
if {$ties != $nxS + 1} { error "slope_on_foundation.tcl: -cell $h: $ties of the slope's [expr {$nxS + 1}] base nodes lie on foundation nodes (-cell must divide 4, 10, 14 and 24)" }

set tol [expr {1e-6 * $h}]
fixY 0.0 1 1 -tol $tol     ;# base fixed
fixX 0.0 1 0 -tol $tol     ;# left side on rollers
fixX 44.0 1 0 -tol $tol    ;# right side on rollers

gravity_stage
if {[fos_asked slope_on_foundation.tcl $opt(-fos)]} {
    fos_stage {1}
} else {
    collapse_stage {1} $outdir $opt(-tend) $opt(-dt) $opt(-record)
}
puts stdout "slope_on_foundation: [llength [getNodeTags]] nodes, [llength [getEleTags]] [expr {$opt(-mesh) eq "tri" ? "tri31 triangles" : "SSPquads"}], $ties tied node pairs"
