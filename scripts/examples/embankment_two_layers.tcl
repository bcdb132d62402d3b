# Half of a symmetric embankment, 8 m high, of two layers: a stiff, strong lower layer (0-4 m) under a weak
# upper layer (4-8 m), side slopes 1:1, on a rigid base. Two block2D blocks (one per layer) tied along the
# layer boundary; the centre line x = 0 on rollers, the base fixed. The upper layer (phi 20, c 1 kPa) cannot
# stand at 45 degrees on its own and slides off the lower one (phi 38, c 20 kPa), which stays in place
# (strength reduction of both layers, -fos yes: 0.59).
#
# Sample run (about 15 s; figures and summary.md in results/embankment_two_layers):
#   scripts/hybrid_run.py scripts/examples/embankment_two_layers.tcl --transfer 0.5 --duration 3 --out results/embankment_two_layers --units kN --ppd 2 --cfl 0.4 --base-friction 0.5
#
# Walls, base, grid and cell size come from the FEM supports (fem2mpm defaults).
#
# Test run (tests/regression/study/examples_sample_runs_test.py: these values replace the sample run's):
#   --duration 1 --ppd 1 -- -cell 1
#
# Usage: fem_tcl embankment_two_layers.tcl <outdir> ?-cell 0.5? ?-tend 0.5? ?-dt 0.005? ?-record 0.05? ?-fos no|yes?
# Units kN, m, s, kPa, Mg/m3. Lower layer: corners (0, 0), (14, 0), (10, 4), (0, 4), nodes and elements
# from 1; upper layer: (0, 4), (10, 4), (6, 8), (0, 8), numbered after it. Crest half-width 6 m. Both layers
# have 14 / cell elements across (-cell must divide 4, 6, 10 and 14), so the layer boundary's nodes coincide.
# Lower: E = 60 MPa, nu = 0.3, rho = 2.0, phi = 38, c = 20 kPa; upper: E = 15 MPa, nu = 0.3, rho = 1.8,
# phi = 20, c = 1 kPa; psi = 0. Stages as slope_on_foundation.tcl (hybrid_stages.tcl).
source [file join [file dirname [info script]] hybrid_stages.tcl]
if {$argc < 1 || [string index [lindex $argv 0] 0] eq "-"} {
    error "embankment_two_layers.tcl: missing <outdir>; usage: fem_tcl embankment_two_layers.tcl <outdir> ?-cell 0.5? ?-tend 0.5? ?-dt 0.005? ?-record 0.05? ?-fos no|yes?"
}
set outdir [lindex $argv 0]
array set opt {-cell 0.5 -tend 0.5 -dt 0.005 -record 0.05 -fos no}
parse_options embankment_two_layers.tcl opt [lrange $argv 1 end]
file mkdir $outdir
set h $opt(-cell)
set g 9.81

wipe
model basic -ndm 2 -ndf 2
nDMaterial MohrCoulomb 1 60.0e3 0.3 2.0 38.0 20.0 0.0
nDMaterial MohrCoulomb 2 15.0e3 0.3 1.8 20.0 1.0 0.0
# the layers have the same number of elements across, so the layer boundary's nodes coincide
set nx [expr {int(round(14.0 / $h))}]
set ny [expr {int(round(4.0 / $h))}]
block2D $nx $ny 1 1 SSPquad "1 PlaneStrain 1.0 0.0 [expr {-2.0 * $g}]" {1 0 0 2 14 0 3 10 4 4 0 4}
set n0 [expr {($nx + 1) * ($ny + 1) + 1}]
set e0 [expr {$nx * $ny + 1}]
block2D $nx $ny $n0 $e0 SSPquad "2 PlaneStrain 1.0 0.0 [expr {-1.8 * $g}]" {1 0 4 2 10 4 3 6 8 4 0 8}
set ties [tie_coincident_nodes [expr {1e-6 * $h}]]
if {$ties != $nx + 1} { error "embankment_two_layers.tcl: -cell $h: only $ties of the layer boundary's [expr {$nx + 1}] nodes are tied (-cell must divide 4, 6, 10 and 14)" }

set tol [expr {1e-6 * $h}]
fixY 0.0 1 1 -tol $tol     ;# rigid base
fixX 0.0 1 0 -tol $tol     ;# centre line: symmetry (rollers)

gravity_stage
if {[fos_asked embankment_two_layers.tcl $opt(-fos)]} {
    fos_stage {1 2}
} else {
    collapse_stage {1 2} $outdir $opt(-tend) $opt(-dt) $opt(-record)
}
puts stdout "embankment_two_layers: [llength [getNodeTags]] nodes, [llength [getEleTags]] SSPquads, $ties tied node pairs"
