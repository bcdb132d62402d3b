# Effective-stress 1D site response of a liquefiable deposit, built the way OpenSees liquefaction modellers
# write it (McGann & Arduino's effective-stress free-field pattern; the PM4Sand manual's examples), in fem_tcl:
#   - a column one SSPquadUP wide (u-p: each node carries ux, uy and the pore pressure p), kN-m-s units;
#   - a loose sand layer (PM4Sand, Dr -Drl) over a dense one (Dr -Drd), the water table at the surface
#     (the top nodes drained, p = 0), the base impermeable;
#   - periodic sides: equalDOF between the left and right node of every row (dofs 1 2, the pressures free);
#   - compliant base (default): a Lysmer-Kuhlemeyer dashpot, zeroLength + Viscous with C = rho_r Vs_r A,
#     between a fixed node and the base, driven by the Joyner & Chen (1975) force rho_r Vs_r A v_outcrop(t);
#     -base rigid fixes the base and shakes it with the outcrop acceleration (UniformExcitation);
#   - gravity in PM4Sand's elastic stage (large steps: consolidated, hydrostatic pressures), then the plastic
#     stage with FirstCall (PM4Sand's initialisation at the consolidated stress), setTime 0, shaking.
# PM4Sand per layer as the calibration examples of Boulanger & Ziotopoulou (2017): G0 = 167 sqrt(46 Dr^2 + 2.5)
# (their eq. for G0 from (N1)60 = 46 Dr^2), hpo 0.5, Den 1.9 Mg/m3, phicv 32 deg, nu 0.3; void ratio
# e = 0.8 - 0.3 Dr; hydraulic conductivity -k m/s (k / gamma_w in OpenSees' units).
# Motion: the seeded synthetic outcrop record scripts/shaken_slope/motion/ (dt 0.01 s, 12 s, PGA 0.40 g;
# provenance in motion/motion.json), times -scale.
# Sample run: build/bin/fem_tcl scripts/site_response/liquefiable_column.tcl /tmp/liq -tend 2
# Then: /usr/bin/python3 scripts/site_response/liquefaction.py /tmp/liq (figures, the simplified-procedure check)
# Files in <outdir>: pp.out (the pore pressure of the left nodes, base to top), stress.out (each element's
# effective stress sxx syy sxy, base to top), disp.out (ux of the left nodes), surface_accel.out (the top's
# relative acceleration), each with a first row at t = 0 holding the consolidated state, every -record s after;
# column.txt (the layers and the node heights, for liquefaction.py); model.json.
set usage "usage: fem_tcl liquefiable_column.tcl <outdir> ?-Hl 6? ?-Hd 10? ?-Drl 0.4? ?-Drd 0.75? ?-h 0.5? ?-k 1e-4? ?-base compliant|rigid? ?-scale 0.6? ?-tend 12? ?-dt 0.005? ?-record 0.01?"
set outdir [lindex $argv 0]
if {$outdir eq "" || [string index $outdir 0] eq "-"} { error $usage }
array set opt {-Hl 6.0 -Hd 10.0 -Drl 0.4 -Drd 0.75 -h 0.5 -k 1.0e-4 -base compliant -scale 0.6 -tend 12.0 -dt 0.005 -record 0.01}
foreach {key value} [lrange $argv 1 end] {
    if {![info exists opt($key)]} { error "liquefiable_column.tcl: unknown option '$key'; $usage" }
    if {$key ne "-base" && (![string is double -strict $value] || ($value <= 0.0 && $key ne "-scale"))} {
        error "liquefiable_column.tcl: $key expects a positive number, got '$value'"
    }
    set opt($key) $value
}
if {$opt(-base) ni {compliant rigid}} { error "liquefiable_column.tcl: -base must be compliant or rigid, got '$opt(-base)'" }
file mkdir $outdir
set g 9.81
set h $opt(-h)
set nl [expr {int(round($opt(-Hl) / $h))}]; set nd [expr {int(round($opt(-Hd) / $h))}]; set ne [expr {$nl + $nd}]
set k [expr {$opt(-k) / $g}]                     ;# OpenSees' permeability: hydraulic conductivity / gamma_w
set rho 1.9; set rhof 1.0; set Kf 2.2e6          ;# Mg/m3, kPa
set rock_rho 2.4; set rock_vs 760.0              ;# the base rock (site class B/C boundary)

wipe
model basic -ndm 2 -ndf 3
# node (i, j): left i = 0, right i = 1, row j from the base; tags 2 j + i + 1
for {set j 0} {$j <= $ne} {incr j} {
    node [expr {2 * $j + 1}] 0.0 [expr {$j * $h}]
    node [expr {2 * $j + 2}] 1.0 [expr {$j * $h}]
}
if {$opt(-base) eq "rigid"} { fix 1 1 1 0; fix 2 1 1 0 } else { fix 1 0 1 0; fix 2 0 1 0; equalDOF 1 2 1 }
for {set j 1} {$j <= $ne} {incr j} { equalDOF [expr {2 * $j + 1}] [expr {2 * $j + 2}] 1 2 }
fix [expr {2 * $ne + 1}] 0 0 1; fix [expr {2 * $ne + 2}] 0 0 1     ;# the water table at the surface

# PM4Sand: Dr G0 hpo Den P_atm h0 emax emin nb nd Ado z_max cz ce phicv nu
foreach {tag Dr} [list 1 $opt(-Drd) 2 $opt(-Drl)] {
    set G0 [expr {167.0 * sqrt(46.0 * $Dr * $Dr + 2.5)}]
    nDMaterial PM4Sand $tag $Dr $G0 0.5 $rho 101.3 -1 0.8 0.5 0.5 0.1 -1 -1 250.0 -1 32.0 0.3
}
set f [open [file join $outdir column.txt] w]
puts $f "# liquefiable_column.tcl: element j (base = 1): material Dr void_ratio; node heights; rho rhof g"
puts $f "rho $rho rhof $rhof g $g h $h elements $ne loose_from [expr {$nd + 1}] Drl $opt(-Drl) Drd $opt(-Drd) scale $opt(-scale) base $opt(-base)"
close $f
for {set j 0} {$j < $ne} {incr j} {
    set n1 [expr {2 * $j + 1}]
    if {$j < $nd} { set m 1; set Dr $opt(-Drd) } else { set m 2; set Dr $opt(-Drl) }
    set e [expr {0.8 - 0.3 * $Dr}]
    element SSPquadUP [expr {$j + 1}] $n1 [expr {$n1 + 1}] [expr {$n1 + 3}] [expr {$n1 + 2}] $m 1.0 $Kf $rhof $k $k $e 1.0e-5 0.0 [expr {-$g}]
}

# the compliant base: a dashpot to a fixed node, tied to the base in x (dof 1)
if {$opt(-base) eq "compliant"} {
    node 5001 0.0 0.0; node 5002 0.0 0.0
    fix 5001 1 1 1; fix 5002 0 1 1
    equalDOF 1 5002 1
    uniaxialMaterial Viscous 5000 [expr {$rock_rho * $rock_vs * 1.0}] 1.0
    element zeroLength 5000 5001 5002 -mat 5000 -dir 1
}
print -JSON -file [file join $outdir model.json]

# 1. gravity, elastic stage, consolidated with large steps (hydrostatic pressures at the end)
updateMaterialStage -material 1 -stage 0
updateMaterialStage -material 2 -stage 0
constraints Transformation
test NormDispIncr 1.0e-5 50 0
algorithm Newton
numberer RCM
system UmfPack
integrator Newmark 0.8333333333333334 0.4444444444444444
analysis Transient
if {[analyze 10 500.0] != 0} { error "liquefiable_column.tcl: the gravity stage did not converge" }
# 2. the plastic stage, PM4Sand initialised at the consolidated stress
updateMaterialStage -material 1 -stage 1
updateMaterialStage -material 2 -stage 1
setParameter -val 0 -eleRange 1 $ne FirstCall 1
setParameter -val 0 -eleRange 1 $ne FirstCall 2
if {[analyze 5 500.0] != 0} { error "liquefiable_column.tcl: the plastic stage's consolidation did not converge" }
setTime 0.0
wipeAnalysis

# 3. shaking, the recorders from t = 0 (their first row: the consolidated state)
set left {}; for {set j 0} {$j <= $ne} {incr j} { lappend left [expr {2 * $j + 1}] }
recorder Node -file [file join $outdir pp.out] -time -dT $opt(-record) -node {*}$left -dof 3 vel
recorder Node -file [file join $outdir disp.out] -time -dT $opt(-record) -node {*}$left -dof 1 disp
recorder Node -file [file join $outdir surface_accel.out] -time -dT $opt(-record) -node [expr {2 * $ne + 1}] -dof 1 accel
recorder Element -file [file join $outdir stress.out] -time -dT $opt(-record) -eleRange 1 $ne stress
record
set motion_dir [file join [file dirname [info script]] .. shaken_slope motion]
if {$opt(-base) eq "compliant"} {
    timeSeries Path 10 -dt 0.01 -filePath [file join $motion_dir vel.txt] -factor [expr {$opt(-scale) * $rock_rho * $rock_vs}] -useLast
    pattern Plain 10 10 { load 1 1.0 0.0 0.0 }
} else {
    timeSeries Path 10 -dt 0.01 -filePath [file join $motion_dir accel.txt] -factor [expr {$opt(-scale) * $g}]
    pattern UniformExcitation 10 1 -accel 10
}
# 1 % Rayleigh damping at 1 and 10 Hz on the current tangent of the skeleton (small-strain damping)
set w1 [expr {2.0 * acos(-1.0) * 1.0}]; set w2 [expr {2.0 * acos(-1.0) * 10.0}]; set xi 0.01
rayleigh [expr {2.0 * $xi * $w1 * $w2 / ($w1 + $w2)}] [expr {2.0 * $xi / ($w1 + $w2)}] 0.0 0.0
constraints Transformation
test NormDispIncr 1.0e-5 50 0
algorithm Newton
numberer RCM
system UmfPack
integrator Newmark 0.5 0.25
analysis Transient
# steps of -dt, halved (down to -dt / 16) where one fails
set t 0.0
while {$t < $opt(-tend) - 1.0e-9} {
    set dt $opt(-dt)
    while {[analyze 1 $dt] != 0} {
        set dt [expr {$dt / 2.0}]
        if {$dt < $opt(-dt) / 16.0} { error "liquefiable_column.tcl: no convergence at t = $t even with dt = [expr {2.0 * $dt}]" }
    }
    set t [getTime]
}
puts stdout "liquefiable_column: shaken to t = [format %.3f $t] s ($ne elements, base $opt(-base), scale $opt(-scale))"
