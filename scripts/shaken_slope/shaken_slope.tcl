# A shaken embankment on a foundation layer, built the way OpenSees site-response scripts are, carried to
# MPM when the shaking ends (scripts/hybrid_run.py; docs/study/shaken_slope.md has the study).
#
# Geometry (m), units kN, m, s, kPa, Mg/m3: a foundation layer 0 <= x <= 72, 0 <= y <= 6 (block2D) and on it
# an embankment 8 m high, slopes 1.5H:1V (33.7 deg), crest 16 m wide: corners (16, 6), (56, 6), (44, 14),
# (28, 14) (a second block2D block, its base nodes tied to the foundation's top nodes with equalDOF).
# -cell must divide 2, 6, 8 and 16 (0.5, 1 or 2) so that the blocks' nodes coincide.
# Soil: embankment MohrCoulomb E = 50 MPa (Vs = 100 m/s), nu = 0.3, rho = 1.9, phi = 30, c = 4 kPa, psi = 0;
# foundation E = 150 MPa (Vs = 174 m/s), nu = 0.3, rho = 1.9, phi = 38, c = 30 kPa.
#
# Boundaries (what an OpenSees site-response user builds, carried to 2D):
# - free-field sides by periodic ties: each foundation row's left and right end nodes are tied with
#   equalDOF 1 2 (the sides then move like the 1D column under a vertically incident wave, as in the
#   1D site-response scripts). The two ends are equally high (both at the foundation level, the embankment
#   stands in the middle): that is why the model is a whole embankment and not a slope with a crest side.
#   The toes are 16 m = 2 H from the ties, so that the embankment's scattered waves are small there.
# - compliant base: the base nodes fixed vertically and tied horizontally to base node 1 (equalDOF 1), a
#   Lysmer & Kuhlemeyer (1969) dashpot (zeroLength + uniaxialMaterial Viscous, C = rho_r Vs_r A, A = 72 m x
#   1 m) between a fixed dummy node and node 1, and the Joyner & Chen (1975) force F(t) = rho_r Vs_r A
#   v_outcrop(t) at node 1 (pattern Plain with a -dt Path series on the outcrop velocity file); rock
#   rho_r = 2.4, Vs_r = 760 m/s.
# Motion: the synthetic outcrop record scripts/shaken_slope/motion/vel.txt (dt 0.01 s, 12 s, PGA 0.40 g;
# provenance in motion/motion.json, made by scripts/shaken_slope/ground_motion.py), times -scale (0: the
# unshaken case, the same run without input).
# Stages: (1) elastic gravity (MohrCoulomb stage 0), one static step, base node 1 held horizontally by an sp
# in a pattern removed afterwards; (2) MohrCoulomb (stage 1), the dashpot and the input added, Newmark
# average acceleration (0.5, 0.25), KrylovNewton -elasticTangent, 2 % mass-proportional Rayleigh damping at
# 2 Hz (no stiffness-proportional term: it would follow the plastic tangent and refactor every iteration),
# from t = 0 to -tend (steps of -dt halved where one fails).
#
# Sample run (the study's shaken case, about 30 s; figures, summary.md in results/shaken_slope/shaken):
#   scripts/hybrid_run.py scripts/shaken_slope/shaken_slope.tcl --transfer 12 --duration 3 --out results/shaken_slope/shaken --ppd 2 --units kN --left-wall roller --right-wall roller --base friction --base-friction 0.58 --base-y 0 --cell-size 1 --extent 0 72 -1 18 -- -cell 1 -dt 0.005 -tend 12 -scale 1
# (the periodic sides have no CB-Geo counterpart: fem2mpm warns, and roller walls are put at x = 0 and 72;
# the base nodes are y-fixed, a roller line, and the MPM base is made frictional, mu = tan 30 deg). The
# whole study (shaken, unshaken, elastic, Newmark): scripts/shaken_slope/study.py, docs/study/shaken_slope.md.
#
# Usage: fem_tcl shaken_slope.tcl <outdir> ?-cell 1? ?-tend 12? ?-dt 0.005? ?-record 0.05? ?-scale 1?
#        ?-plastic 1? ?-motion FILE? ?-motion-dt 0.01?
# -motion FILE -motion-dt DT: the outcrop velocity (m/s, one value a line, sample k at t = k DT; default the
# synthetic record above, DT 0.01 s): the velocity contract of scripts/motion_suite.py.
# Files in <outdir>: the hybrid_run.py contract (model.json, disp.out, vel.out, stress.out, mesh_quality.out,
# every -record s) and crest.out (`-time`, every step: ux uy of the left shoulder (28, 14), the crest centre
# (36, 14) and the right shoulder (44, 14)), crest_accel.out (the same nodes' ux accelerations, absolute:
# the base is compliant, so nodal accelerations are absolute), base.out and base_accel.out (ux and ax of base node 1),
# embankment_accel.out (ax of every embankment node, every step: the sliding mass's mean acceleration for
# the decoupled Newmark analysis), points.txt (the node tags of those points).
source [file join [file dirname [info script]] .. examples hybrid_stages.tcl]
set usage "usage: fem_tcl shaken_slope.tcl <outdir> ?-cell 1? ?-tend 12? ?-dt 0.005? ?-record 0.05? ?-scale 1? ?-plastic 1? ?-motion FILE? ?-motion-dt 0.01?"
if {$argc < 1 || [string index [lindex $argv 0] 0] eq "-"} { error "shaken_slope.tcl: missing <outdir>; $usage" }
set outdir [lindex $argv 0]
# -scale (>= 0), -plastic (0: the materials stay elastic while shaken, for the decoupled Newmark analysis's
# seismic coefficient), -motion (a file) and -motion-dt (its sample interval, s) are read here; the numbers > 0
# by parse_options
set scale 1.0
set plastic 1
set motion [file join [file dirname [info script]] motion vel.txt]
set motion_dt 0.01
set rest {}
foreach {key value} [lrange $argv 1 end] {
    if {$key eq "-scale"} {
        if {![string is double -strict $value] || !($value >= 0)} { error "shaken_slope.tcl: expected a number >= 0 after '-scale', got '$value'" }
        set scale $value
    } elseif {$key eq "-plastic"} {
        if {$value ni {0 1}} { error "shaken_slope.tcl: expected 0 or 1 after '-plastic', got '$value'" }
        set plastic $value
    } elseif {$key eq "-motion"} {
        if {![file readable $value]} { error "shaken_slope.tcl: -motion '$value': no such readable file" }
        set motion $value
    } elseif {$key eq "-motion-dt"} {
        if {![string is double -strict $value] || !($value > 0)} { error "shaken_slope.tcl: expected a time > 0 s after '-motion-dt', got '$value'" }
        set motion_dt $value
    } elseif {$key in {-cell -tend -dt -record}} {
        lappend rest $key $value
    } else {
        error "shaken_slope.tcl: unknown option '$key' (known: -cell -dt -motion -motion-dt -plastic -record -scale -tend); $usage"
    }
}
array set opt {-cell 1.0 -tend 12.0 -dt 0.005 -record 0.05}
parse_options shaken_slope.tcl opt $rest
file mkdir $outdir
set h $opt(-cell)
set g 9.81
set rho 1.9
set L 72.0

wipe
model basic -ndm 2 -ndf 2
nDMaterial MohrCoulomb 1 150.0e3 0.3 $rho 38.0 30.0 0.0   ;# foundation
nDMaterial MohrCoulomb 2 50.0e3 0.3 $rho 30.0 4.0 0.0     ;# embankment
set nxF [expr {int(round($L / $h))}]
set nyF [expr {int(round(6.0 / $h))}]
block2D $nxF $nyF 1 1 SSPquad "1 PlaneStrain 1.0 0.0 [expr {-$rho * $g}]" {1 0 0 2 72 0 3 72 6 4 0 6}
set nxE [expr {int(round(40.0 / $h))}]
set nyE [expr {int(round(8.0 / $h))}]
set n0 [expr {($nxF + 1) * ($nyF + 1) + 1}]
set e0 [expr {$nxF * $nyF + 1}]
block2D $nxE $nyE $n0 $e0 SSPquad "2 PlaneStrain 1.0 0.0 [expr {-$rho * $g}]" {1 16 6 2 56 6 3 44 14 4 28 14}
set ties [tie_coincident_nodes [expr {1e-6 * $h}]]
if {$ties != $nxE + 1} { error "shaken_slope.tcl: -cell $h: $ties of the embankment's [expr {$nxE + 1}] base nodes lie on foundation nodes (-cell must divide 2, 6, 8 and 16)" }

# free-field sides: periodic ties of the foundation rows above the base
for {set j 1} {$j <= $nyF} {incr j} { equalDOF [expr {$j * ($nxF + 1) + 1}] [expr {$j * ($nxF + 1) + $nxF + 1}] 1 2 }
# base: fixed vertically, moving horizontally as one with base node 1
for {set i 1} {$i <= $nxF + 1} {incr i} { fix $i 0 1 }
for {set i 2} {$i <= $nxF + 1} {incr i} { equalDOF 1 $i 1 }

# the points recorded every step: the shoulders and the crest centre (embankment top row), base node 1
set top [expr {$n0 + $nyE * ($nxE + 1)}]
set crest [list $top [expr {$top + $nxE / 2}] [expr {$top + $nxE}]]

# stage 1: elastic gravity, base node 1 held horizontally (the model has no horizontal support otherwise)
timeSeries Constant 1
pattern Plain 1 1 { sp 1 1 0.0 }
gravity_stage
loadConst -time 0.0
remove loadPattern 1
wipeAnalysis
if {$plastic} {
    updateMaterialStage -material 1 -stage 1
    updateMaterialStage -material 2 -stage 1
}

# compliant base: Lysmer-Kuhlemeyer dashpot on a fixed dummy node (the next tag after the mesh, so that the
# contract's -nodeRange covers it) and the Joyner-Chen force
set rhoR 2.4
set VsR 760.0
set C [expr {$rhoR * $VsR * $L}]
set soil [getEleTags]
set dummy [expr {[lindex [lsort -integer [getNodeTags]] end] + 1}]
node $dummy 0.0 0.0
fix $dummy 1 1
uniaxialMaterial Viscous 1 $C 1.0
element zeroLength [expr {[lindex [lsort -integer [getEleTags]] end] + 1}] $dummy 1 -mat 1 -dir 1
timeSeries Path 2 -dt $motion_dt -filePath $motion -factor $scale -useLast
pattern Plain 2 2 -fact $C { load 1 1.0 0.0 }
set pi [expr {acos(-1.0)}]
rayleigh [expr {2.0 * 0.02 * 2.0 * $pi * 2.0}] 0.0 0.0 0.0

# stage 2: plastic, shaken
transient_analysis
record_for_hybrid $outdir $opt(-record) $soil
recorder Node -file [file join $outdir crest.out] -time -node {*}$crest -dof 1 2 disp
recorder Node -file [file join $outdir crest_accel.out] -time -node {*}$crest -dof 1 accel
recorder Node -file [file join $outdir embankment_accel.out] -time -nodeRange $n0 [expr {$n0 + ($nxE + 1) * ($nyE + 1) - 1}] -dof 1 accel
recorder Node -file [file join $outdir base.out] -time -node 1 -dof 1 disp
recorder Node -file [file join $outdir base_accel.out] -time -node 1 -dof 1 accel
set f [open [file join $outdir points.txt] w]
puts $f "left_shoulder [lindex $crest 0]\ncrest_centre [lindex $crest 1]\nright_shoulder [lindex $crest 2]\nbase 1\ndummy $dummy"
close $f
record
set t [advance_to $opt(-tend) $opt(-dt) "shaking stage"]
remove recorders
set mj [minJacobian]
puts stdout [format "shaken_slope: %d nodes, %d elements (1 dashpot), scale %g, t = %.4g s, crest ux %.4g uy %.4g m (left shoulder), min det J %.4g" \
    [llength [getNodeTags]] [llength [getEleTags]] $scale $t [nodeDisp [lindex $crest 0] 1] [nodeDisp [lindex $crest 0] 2] [lindex $mj 0]]
