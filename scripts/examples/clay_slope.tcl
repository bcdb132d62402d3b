# An 8 m cut in soft clay, 1:1.5 (33.7 degrees), on a 6 m layer of stiffer clay: undrained, total stress,
# the OpenSees way (nDMaterial PressureIndependMultiYield, frictionAng 0), one material per layer, sides on
# rollers, base fixed. The cut cannot stand: its plane-strain strength is 2 c / sqrt(3) = 10.4 kPa (cohesi
# c = 9 kPa; the foundation's 40.4 kPa), and strength reduction (fem_tcl strengthReduction, 1 m cells, -fos yes)
# gives a factor of safety of 0.57 (0.59 for MohrCoulomb phi = 0 of the same strengths, -soil tresca). fem2mpm maps each
# layer to Tresca with its plane-strain strength (bridge/multi_yield_match.hpp) and MPM carries the runout
# (sample run: 2.8 m of travel, 28 % of the mass moving, nearly at rest at 3.5 s; transferred at 0 s instead
# 2.64 m, at 1 s (with -- -tend 1) 2.82 m).
#
# Sample run (figures and summary.md in results/clay_slope):
#   scripts/hybrid_run.py scripts/examples/clay_slope.tcl --transfer 0.5 --duration 3 --out results/clay_slope --units kN --ppd 2 --cfl 0.4 --base-friction 0.4
#
# Walls, base, grid and cell size come from the FEM supports (fem2mpm defaults).
#
# Test run (tests/regression/study/examples_sample_runs_test.py: these values replace the sample run's):
#   --duration 1 --ppd 1 -- -cell 2
#
# Usage: fem_tcl clay_slope.tcl <outdir> ?-cell 1? ?-tend 0.5? ?-dt 0.005? ?-record 0.05? ?-soil multiyield|tresca?
#        ?-fos no|yes?
# -fos yes: the factor of safety instead of the collapse (strengthReduction after the gravity stage, KrylovNewton,
# NormDispIncr 1e-6 100), printed as "FoS F". -soil tresca: MohrCoulomb phi = 0 with each layer's plane-strain
# strength 2 c / sqrt(3) and the same E and nu, the model fem2mpm hands to MPM.
# Units kN, m, s, kPa, Mg/m3. Geometry (m): foundation 0 <= x <= 60, 0 <= y <= 6; the cut on top with
# corners (0, 6), (32, 6), (20, 14), (0, 14): crest at x = 20, toe at x = 32. -cell must divide 6, 8 and 32
# (1 or 2), so that the cut's base nodes fall on the foundation's top nodes.
# Soils (PressureIndependMultiYield, G = 10 MPa, K = 46.7 MPa (nu 0.4), rho 1.8, peakShearStra 0.1, 20
# surfaces): the cut (material 1) cohesi 9 kPa, the foundation (material 2) cohesi 35 kPa.
# Stages: elastic gravity (static, stage 0), then plastic (stage 1: the surfaces set around the gravity
# stress, OpenSees' elast2Plast) and Newmark to -tend; the recorders of the hybrid_run.py contract every
# -record s.
source [file join [file dirname [info script]] hybrid_stages.tcl]
if {$argc < 1 || [string index [lindex $argv 0] 0] eq "-"} {
    error "clay_slope.tcl: missing <outdir>; usage: fem_tcl clay_slope.tcl <outdir> ?-cell 1? ?-tend 0.5? ?-dt 0.005? ?-record 0.05? ?-soil multiyield|tresca? ?-fos no|yes?"
}
set outdir [lindex $argv 0]
array set opt {-cell 1.0 -tend 0.5 -dt 0.005 -record 0.05 -soil multiyield -fos no}
parse_options clay_slope.tcl opt [lrange $argv 1 end]
file mkdir $outdir
set h $opt(-cell)
set rho 1.8
set g 9.81
set G 1.0e4
set K 4.667e4

wipe
model basic -ndm 2 -ndf 2
if {$opt(-soil) eq "multiyield"} {
    nDMaterial PressureIndependMultiYield 1 2 $rho $G $K 9.0 0.1
    nDMaterial PressureIndependMultiYield 2 2 $rho $G $K 35.0 0.1
} elseif {$opt(-soil) eq "tresca"} {
    set E [expr {9.0 * $K * $G / (3.0 * $K + $G)}]
    set nu [expr {(3.0 * $K - 2.0 * $G) / (2.0 * (3.0 * $K + $G))}]
    nDMaterial MohrCoulomb 1 $E $nu $rho 0.0 [expr {2.0 * 9.0 / sqrt(3.0)}] 0.0
    nDMaterial MohrCoulomb 2 $E $nu $rho 0.0 [expr {2.0 * 35.0 / sqrt(3.0)}] 0.0
} else {
    error "clay_slope.tcl: -soil must be multiyield or tresca, got '$opt(-soil)'"
}
set nxF [expr {int(round(60.0 / $h))}]
set nyF [expr {int(round(6.0 / $h))}]
block2D $nxF $nyF 1 1 SSPquad "2 PlaneStrain 1.0 0.0 [expr {-$rho * $g}]" {1 0 0 2 60 0 3 60 6 4 0 6}
set nxS [expr {int(round(32.0 / $h))}]
set nyS [expr {int(round(8.0 / $h))}]
set n0 [expr {($nxF + 1) * ($nyF + 1) + 1}]
set e0 [expr {$nxF * $nyF + 1}]
block2D $nxS $nyS $n0 $e0 SSPquad "1 PlaneStrain 1.0 0.0 [expr {-$rho * $g}]" {1 0 6 2 32 6 3 20 14 4 0 14}
set ties [tie_coincident_nodes [expr {1e-6 * $h}]]
if {$ties != $nxS + 1} { error "clay_slope.tcl: -cell $h: $ties of the cut's [expr {$nxS + 1}] base nodes lie on foundation nodes (-cell must divide 6, 8 and 32)" }

set tol [expr {1e-6 * $h}]
fixY 0.0 1 1 -tol $tol     ;# base fixed
fixX 0.0 1 0 -tol $tol     ;# left side on rollers
fixX 60.0 1 0 -tol $tol    ;# right side on rollers

gravity_stage
if {[fos_asked clay_slope.tcl $opt(-fos)]} {
    fos_stage {1 2}
} else {
    collapse_stage {1 2} $outdir $opt(-tend) $opt(-dt) $opt(-record)
}
puts stdout "clay_slope: [llength [getNodeTags]] nodes, [llength [getEleTags]] SSPquads, $ties tied node pairs"
