# An upstream-raised tailings dam of the kind of Mochikoshi No. 1 (Izu-Oshima-Kinkai earthquake, 14 January
# 1978, M 7.0: a 28 m high dam raised upstream over its own tailings; the pond's saturated silty-sand tailings
# liquefied and some 80,000 m3 flowed down the valley; Ishihara, Yasuda & Yokota 1981, Soils and Foundations
# 21(1); Ishihara 1984, Proc. Int. Conf. Case Histories in Geotech. Eng.), idealised for this chain (the
# dimensions and properties are round values of that kind, not a back-analysis of the case):
#   - a stiff foundation (8 m, elastic, Vs ~ 400 m/s), 0 <= x <= 232 m;
#   - the dam and its pond, 28 m high on the foundation, with the crest at x = 104 m, the downstream face at
#     1V:2.4H down to the toe at x = 172 m, the pond's tailings extending upstream to x = 0;
#   - the dikes: a shell of compacted tailings 8 m wide (horizontally) along the downstream face (PM4Sand,
#     Dr -Drd), the loose silty-sand tailings behind it (PM4Sand, Dr -Drt; PM4Silt, which tailings of finer
#     grading call for, does not get through this model's plastic-stage consolidation yet: 381 of its steps
#     fail at 1 s in 100 s, so the example keeps to PM4Sand);
#   - saturated to the surface (an upper bound of the phreatic level, as the pond's tailings were): drained
#     (p = 0) along the pond surface, the downstream face and the ground downstream of the toe; the base and
#     the upstream side impermeable; u-p elements (SSPquadUP) everywhere;
#   - gravity in the materials' elastic stage with the permeabilities raised 1000 times (consolidated in a few
#     large steps, as OpenSees modellers do), the plastic stage with FirstCall, the real permeabilities, then
#     seeded synthetic outcrop record (scripts/shaken_slope/motion, PGA 0.40 g) times -scale (0.5; a record
#     given with -accel or -motion is applied as given, -scale 1, unless -scale says otherwise): -base rigid
#     (default: the base fixed and shaken with the acceleration -accel, UniformExcitation, the sides on rollers)
#     or -base compliant (a Lysmer dashpot and the Joyner-Chen force of the velocity -motion; the sides tied
#     horizontally to the base). -motion-dt is the records' time step (scripts/motion_suite.py passes its own).
# The recorders of scripts/hybrid_run.py's contract (with pp.out: the pore pressures) every -record s from the
# start of the shaking, so that the chain carries the liquefied dam into MPM with a residual strength
# (fem2mpm --residual-ratio: Sr = 0.06 sigma'v0, the lower part of Olson & Stark's range) and the rest with its
# friction on the effective stress of the transfer (--effective-friction; without it the dam body holds the
# liquefied pond: bridge/README.md).
#
# The elastic foundation (FEM material 1) does not flow: the sample run leaves it out of MPM, whose base takes its
# place at its top (fem2mpm --exclude-material 1 --base-y 8; bridge/README.md, "Layers and materials").
#
# Sample run (the transfer window: one FEM run, transfers at 4, 8 and 12 s, each run 10 s in MPM; minutes):
#   scripts/hybrid_run.py scripts/examples/tailings_dam.tcl --transfer 4,8,12 --duration 10 --jobs 2 --out results/tailings_dam --units kN --ppd 8 --cell-size 1 --cfl 0.4 --base-friction 0.6 --residual-ratio 0.06 --effective-friction --exclude-material 1 --base-y 8
#
# Test run (tests/regression/study/examples_sample_runs_test.py: these values replace the sample run's):
#   --transfer 2 --duration 1.5 --jobs 1 --ppd 2 --cell-size 4 -- -tend 2
#
# Factor of safety: none (PM4Sand has no strength for strengthReduction to reduce; the dam is built to liquefy)
#
# Usage: fem_tcl tailings_dam.tcl <outdir> ?-cell 4? ?-tend 12? ?-dt 0.00125? ?-record 0.1? ?-scale 0.5 (1 with -accel or -motion)? ?-Drt 0.3?
#        ?-Drd 0.6? ?-base rigid|compliant? ?-accel FILE? ?-motion FILE? ?-motion-dt 0.01?
# -dt 0.00125 s (the shaking stage's step, KrylovNewton to 1e-5): converged in the step and the cheapest measured
# (synthetic record, seed 1, 0.3 g, 4 s: crest ux 0.889 / 0.867 / 0.837 / 0.840 m at dt 0.005 / 0.0025 /
# 0.00125 / 0.000625 s, 212 / 24 / 25 / 27 s of CPU: at 0.005 s the liquefying tailings fail 500 Newton steps
# of 30 iterations each). 12 s at 0.1 / 0.2 / 0.3 / 0.4 / 0.5 g: 37 / 52 / 72 / 85 / 95 s of CPU, no failed step.
# -cell must divide 4 (4 or 2 m: the dam's base nodes then fall on the foundation's top nodes; 2 m takes about
# four times as long).
source [file join [file dirname [info script]] hybrid_stages.tcl]
set usage "usage: fem_tcl tailings_dam.tcl <outdir> ?-cell 4? ?-tend 12? ?-dt 0.00125? ?-record 0.1? ?-scale 0.5 (1 with -accel or -motion)? ?-Drt 0.3? ?-Drd 0.6? ?-base rigid|compliant? ?-accel FILE? ?-motion FILE? ?-motion-dt 0.01?"
set motion_dir [file normalize [file join [file dirname [info script]] .. shaken_slope motion]]
if {$argc < 1 || [string index [lindex $argv 0] 0] eq "-"} { error "tailings_dam.tcl: missing <outdir>; $usage" }
set outdir [lindex $argv 0]
array set opt [list -cell 4.0 -tend 12.0 -dt 0.00125 -record 0.1 -scale default -Drt 0.3 -Drd 0.6 \
    -base rigid -accel [file join $motion_dir accel.txt] -motion [file join $motion_dir vel.txt] -motion-dt 0.01]
parse_options tailings_dam.tcl opt [lrange $argv 1 end]
# -scale: 0.5 on the project's record (0.40 g -> 0.20 g), 1 on a record given with -accel or -motion (a record
# is applied as given: scripts/motion_suite.py hands over the motion it has scaled itself)
if {$opt(-scale) eq "default"} {
    set own [expr {[lsearch -exact [lrange $argv 1 end] -accel] >= 0 || [lsearch -exact [lrange $argv 1 end] -motion] >= 0}]
    set opt(-scale) [expr {$own ? 1.0 : 0.5}]
}
if {![string is double -strict $opt(-scale)] || $opt(-scale) < 0} { error "tailings_dam.tcl: -scale must be a number >= 0, got '$opt(-scale)'" }
if {$opt(-base) ni {rigid compliant}} { error "tailings_dam.tcl: -base must be rigid or compliant, got '$opt(-base)'" }
foreach key {-accel -motion} {
    if {![file readable $opt($key)]} { error "tailings_dam.tcl: $key '$opt($key)': no such readable file" }
}
foreach key {-Drt -Drd} { if {$opt($key) >= 1.0} { error "tailings_dam.tcl: $key is a relative density below 1, got $opt($key)" } }
file mkdir $outdir
set h $opt(-cell)
if {abs(4.0 / $h - round(4.0 / $h)) > 1e-9} { error "tailings_dam.tcl: -cell must divide 4 (2 or 4 m), got $h" }
set g 9.81
set rhof 1.0; set Kf 2.2e6                         ;# water (Mg/m3, kPa)
set x_crest 104.0; set x_toe 172.0; set L 232.0     ;# m
set yF 8.0; set yT 36.0                            ;# foundation top, pond surface (m)
set shell 8.0                                      ;# dike shell width along the downstream face (m)
# materials: 1 foundation, 2 dikes, 3 tailings (Mg/m3, kPa); hydraulic conductivities (m/s)
set rho(1) 2.0; set rho(2) 1.95; set rho(3) 1.85
set void(1) 0.5; set void(2) [expr {0.8 - 0.3 * $opt(-Drd)}]; set void(3) 0.9
set kh(1) 1.0e-6; set kh(2) 1.0e-4; set kh(3) 1.0e-5
set speedup 1000.0                                 ;# permeabilities raised during the gravity stage

wipe
model basic -ndm 2 -ndf 3
nDMaterial ElasticIsotropic 1 8.3e5 0.3 $rho(1)
set G0d [expr {167.0 * sqrt(46.0 * $opt(-Drd) * $opt(-Drd) + 2.5)}]
nDMaterial PM4Sand 2 $opt(-Drd) $G0d 0.5 $rho(2) 101.3 -1 0.8 0.5 0.5 0.1 -1 -1 250.0 -1 33.0 0.3
set G0t [expr {167.0 * sqrt(46.0 * $opt(-Drt) * $opt(-Drt) + 2.5)}]
nDMaterial PM4Sand 3 $opt(-Drt) $G0t 0.4 $rho(3) 101.3 -1 0.8 0.5 0.5 0.1 -1 -1 250.0 -1 32.0 0.3
# SSPquadUP: matTag t fBulk fDen k1 k2 e alpha b1 b2 (k: hydraulic conductivity / gamma_w; gravity stage: x1000)
proc up_args {m} {
    global Kf rhof void kh g speedup
    set k [expr {$speedup * $kh($m) / $g}]
    return "$m 1.0 $Kf $rhof $k $k $void($m) 1.0e-5 0.0 [expr {-$g}]"
}
# the foundation: nodes 1.., elements 1..
set nxF [expr {int(round($L / $h))}]
set nyF [expr {int(round($yF / $h))}]
block2D $nxF $nyF 1 1 SSPquadUP [up_args 1] [list 1 0 0 2 $L 0 3 $L $yF 4 0 $yF]
# the dam and its pond: numbered after the foundation, its base nodes on the foundation's top nodes
set nxD [expr {int(round($x_toe / $h))}]
set nyD [expr {int(round(($yT - $yF) / $h))}]
set n0 [expr {($nxF + 1) * ($nyF + 1) + 1}]
set e0 [expr {$nxF * $nyF + 1}]
block2D $nxD $nyD $n0 $e0 SSPquadUP [up_args 3] [list 1 0 $yF 2 $x_toe $yF 3 $x_crest $yT 4 0 $yT]
# the dike shell: the dam's elements whose centre lies within $shell (horizontally) of the downstream face
set slope [expr {($x_toe - $x_crest) / ($yT - $yF)}]   ;# horizontal per vertical
set shell_elements {}
foreach e [getEleTags] {
    if {$e < $e0} continue
    set nodes [eleNodes $e]
    set xc 0.0; set yc 0.0
    foreach n $nodes { set xc [expr {$xc + [nodeCoord $n 1] / 4.0}]; set yc [expr {$yc + [nodeCoord $n 2] / 4.0}] }
    set x_face [expr {$x_toe - $slope * ($yc - $yF)}]
    if {$x_face - $xc < $shell} {
        remove element $e
        element SSPquadUP $e {*}$nodes {*}[up_args 2]
        lappend shell_elements $e
    }
}
set ties [tie_coincident_nodes [expr {1e-6 * $h}]]
if {$ties != $nxD + 1} { error "tailings_dam.tcl: -cell $h: $ties of the dam's [expr {$nxD + 1}] base nodes lie on foundation nodes" }

set tol [expr {1e-6 * $h}]
if {$opt(-base) eq "rigid"} {
    # the base fixed (the shaking is the ground's: UniformExcitation), the sides on rollers
    for {set i 1} {$i <= $nxF + 1} {incr i} { fix $i 1 1 0 }
    foreach n [getNodeTags] {
        set x [nodeCoord $n 1]
        if {$n > $nxF + 1 && (abs($x) < $tol || abs($x - $L) < $tol)} { fix $n 1 0 0 }
    }
} else {
    # the base: vertical fixed, horizontal tied to base node 1 (which the dashpot holds); the sides move
    # horizontally with it (a rigid box, far from the dam)
    for {set i 1} {$i <= $nxF + 1} {incr i} { fix $i 0 1 0 }
    for {set i 2} {$i <= $nxF + 1} {incr i} { equalDOF 1 $i 1 }
    foreach n [getNodeTags] {
        set x [nodeCoord $n 1]
        if {$n > $nxF + 1 && (abs($x) < $tol || abs($x - $L) < $tol)} { equalDOF 1 $n 1 }
    }
}
# drainage: the pond surface and the downstream face (the dam's top row and right column) and the ground
# downstream of the toe
set top_row [expr {$n0 + $nyD * ($nxD + 1)}]
for {set i 0} {$i <= $nxD} {incr i} { fix [expr {$top_row + $i}] 0 0 1 }
for {set j 0} {$j < $nyD} {incr j} { fix [expr {$n0 + $j * ($nxD + 1) + $nxD}] 0 0 1 }
foreach n [getNodeTags] {
    if {$n < $n0 && abs([nodeCoord $n 2] - $yF) < $tol && [nodeCoord $n 1] > $x_toe - $tol} { fix $n 0 0 1 }
}
# the crest node (the dam's top row, x = x_crest) and the toe, for the summary line
set crest [expr {$top_row + $nxD}]

# 1. gravity: elastic stage, consolidated with large steps
constraints Transformation
numberer RCM
system UmfPack
test NormDispIncr 1.0e-5 50
algorithm Newton
integrator Newmark 0.8333333333333334 0.4444444444444444
analysis Transient
foreach m {2 3} { updateMaterialStage -material $m -stage 0 }
if {[analyze 10 1000.0] != 0} { error "tailings_dam.tcl: the gravity stage did not converge" }
# 2. plastic stage, initialised at the consolidated stress and consolidated again (the static shear stresses
# of the slope in the plastic model), then the real permeabilities
foreach m {2 3} { updateMaterialStage -material $m -stage 1 }
setParameter -val 0 FirstCall 2
setParameter -val 0 FirstCall 3
advance_to [expr {[getTime] + 100.0}] 10.0 "the plastic stage's consolidation"
advance_to [expr {[getTime] + 1.0e4}] 1000.0 "the plastic stage's consolidation"
foreach m {1 2 3} {
    setParameter -val [expr {$kh($m) / $g}] hPerm $m
    setParameter -val [expr {$kh($m) / $g}] vPerm $m
}
setTime 0.0
wipeAnalysis

# 3. the shaking: the ground's acceleration (rigid base), or the compliant base (a 2-dof dashpot node under
# base node 1, the Joyner-Chen force of the outcrop velocity)
set soil [lsort -integer [getEleTags]]
if {$opt(-base) eq "rigid"} {
    timeSeries Path 2 -dt $opt(-motion-dt) -filePath $opt(-accel) -factor $opt(-scale)
    pattern UniformExcitation 2 1 -accel 2
} else {
    set rhoR 2.4; set VsR 760.0
    set C [expr {$rhoR * $VsR * $L}]
    model basic -ndm 2 -ndf 2
    set dummy [expr {[lindex [lsort -integer [getNodeTags]] end] + 1}]
    node $dummy 0.0 0.0
    fix $dummy 1 1
    uniaxialMaterial Viscous 1 $C 1.0
    element zeroLength [expr {[lindex $soil end] + 1}] $dummy 1 -mat 1 -dir 1
    timeSeries Path 2 -dt $opt(-motion-dt) -filePath $opt(-motion) -factor $opt(-scale) -useLast
    pattern Plain 2 2 -fact $C { load 1 1.0 0.0 0.0 }
}
set pi [expr {acos(-1.0)}]
set w1 [expr {2.0 * $pi * 1.0}]; set w2 [expr {2.0 * $pi * 8.0}]; set xi 0.01
rayleigh [expr {2.0 * $xi * $w1 * $w2 / ($w1 + $w2)}] [expr {2.0 * $xi / ($w1 + $w2)}] 0.0 0.0
constraints Transformation
numberer RCM
system UmfPack
test NormDispIncr 1.0e-5 30
algorithm KrylovNewton
integrator Newmark 0.5 0.25
analysis Transient
record_for_hybrid $outdir $opt(-record) $soil
record
set t [advance_recorded $opt(-tend) $opt(-dt) $opt(-record) "shaking stage"]
remove recorders
set mj [minJacobian]
puts stdout [format "tailings_dam: %d nodes, %d SSPquadUP (%d in the dike shell), scale %g, t = %.4g s, crest ux %.4g uy %.4g m, min det J %.4g" \
    [llength [getNodeTags]] [llength $soil] [llength $shell_elements] $opt(-scale) $t [nodeDisp $crest 1] [nodeDisp $crest 2] [lindex $mj 0]]
