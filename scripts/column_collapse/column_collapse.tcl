# The FEM-only reference scene: collapse of the paper's granular column (Sordo, Rathje & Kumar, hybrid FEM-MPM
# column collapse; ../shared/DESIGN.md "reference scene") with SSPquads (McGann et al. 2012) and Mohr-Coulomb.
#
# Usage: fem_tcl column_collapse.tcl <outdir> ?-width 50? ?-height 40? ?-cell 1.0? ?-tend 5.0? ?-dt 1e-3?
#            ?-record 0.05? ?-phi 22.2? ?-cohesion 0.1? ?-friction-base fixed? ?-tol 1e-6? ?-max-cuts 8?
#            ?-on-inversion stop?
#
# Units kN, m, s, kPa, Mg/m3: E = 172e3 kPa, nu = 0.23, rho = 1.925 Mg/m3, g = 9.81 m/s2, plane strain.
# Mesh: width/cell x height/cell SSPquads; node tags 1..N row by row from the bottom-left (node (i, j) at
# x = i cell, y = j cell has tag j (nx + 1) + i + 1), element tags likewise (element (i, j): j nx + i + 1).
# Supports: base fixed (ux, uy: a rough base, the only `-friction-base` this FEM model has), left face on
# rollers (ux = 0), right face and top free (the gate that opens).
#
# Stage 1 (elastic, `MohrCoulomb` in stage 0): gravity through the SSPquad body force, one static step (linear).
# Stage 2: `loadConst -time 0`, `updateMaterialStage -stage 1` (phi, cohesion, psi = 0), then Newmark average
# acceleration (gamma 1/2, beta 1/4: unconditionally stable, no numerical dissipation; the energy the collapse
# loses goes into plastic work, so no Rayleigh damping is added) to t = tend. Equilibrium iterations:
# KrylovNewton (Carlson & Miller 1998) on the initial (elastic) effective stiffness K0 + 4 M / dt^2, factored
# once while dt is unchanged. With 1 m elements and dt = 1e-3 s the mass term is ~45 times the elastic
# stiffness (4 rho h^2 / (E dt^2)), so K0 is a close preconditioner of the plastic effective tangent and the
# Krylov acceleration converges in ~3-4 iterations; full Newton on the consistent tangent needs a numeric LU
# factorization per iteration (non-symmetric, psi != phi) and is ~10 times slower per step for the same
# converged result (NormDispIncr -tol on the displacement increment, default 1e-6 m).
# Cohesion default 0.1 kPa: "minimal" (the paper gives no value): c / (rho g H) = 1.3e-4, i.e. it matters only
# in the top few centimetres, and keeps the top elements (near-zero stress) off a zero-strength apex.
#
# The elastic K0 = nu / (1 - nu) = 0.30 lies below the Mohr-Coulomb active ratio (1 - sin phi) / (1 + sin phi)
# = 0.45, so at the switch the whole column is outside the yield surface: the first plastic step returns every
# element to it and the column starts to fail at once ("opening the gate").
#
# Step cutting: when `analyze 1 dt` fails the step is halved and retried (up to -max-cuts times); after two
# converged steps at a cut level the step doubles again. Every record time (k * record, and 0.5, 1, 2, 3 s) is
# landed on exactly. The run stops cleanly when a step fails at the deepest cut, and by default (-on-inversion
# stop) when the mesh inverts (minimum corner det J <= 0); the files are then complete up to the last converged
# step. `-on-inversion continue` goes on to tend past inverted corners (the paper's FEM run went on to 5 s; an
# SSPquad is still integrable while the det J at its centre, its one integration point, stays positive).
#
# Output in <outdir>:
#   model.json     print -JSON after the model is built
#   disp.out       -time, all nodes in tag order, dofs 1 2, every -record s from t = 0 (after the switch)
#   vel.out        the same for velocities
#   stress.out     -time, all elements in tag order, stress3D (sxx syy szz sxy syz sxz), every -record s
#   mesh_quality.out  every step: time minDetJ elementTag minRatio elementTag (recorder MeshQuality)
#   steps.csv      every converged step: time,dt,iterations,cut_level
# and a summary line on stdout.

proc usage {} {
    return "usage: fem_tcl column_collapse.tcl <outdir> ?-width 50? ?-height 40? ?-cell 1.0? ?-tend 5.0? ?-dt 1e-3? ?-record 0.05? ?-phi 22.2? ?-cohesion 0.1? ?-friction-base fixed? ?-tol 1e-6? ?-max-cuts 8? ?-on-inversion stop|continue?"
}

if {$argc < 1 || [string index [lindex $argv 0] 0] eq "-"} { error "column_collapse.tcl: missing <outdir>; [usage]" }
set outdir [lindex $argv 0]
array set opt {-width 50.0 -height 40.0 -cell 1.0 -tend 5.0 -dt 1e-3 -record 0.05 -phi 22.2 -cohesion 0.1
               -friction-base fixed -tol 1e-6 -max-cuts 8 -on-inversion stop}
foreach {key value} [lrange $argv 1 end] {
    if {![info exists opt($key)]} { error "column_collapse.tcl: unknown option '$key'; [usage]" }
    if {$value eq ""} { error "column_collapse.tcl: missing value after '$key'; [usage]" }
    if {$key ne "-friction-base" && $key ne "-on-inversion" && ![string is double -strict $value]} {
        error "column_collapse.tcl: expected a number after '$key', got '$value'"
    }
    set opt($key) $value
}
if {[llength [lrange $argv 1 end]] % 2 != 0} { error "column_collapse.tcl: option '[lindex $argv end]' has no value; [usage]" }
if {$opt(-friction-base) ne "fixed"} {
    error "column_collapse.tcl: -friction-base '$opt(-friction-base)' is not supported (only 'fixed': ux = uy = 0 on the base)"
}
if {$opt(-on-inversion) ni {stop continue}} {
    error "column_collapse.tcl: expected -on-inversion stop or continue, got '$opt(-on-inversion)'"
}
foreach key {-width -height -cell -tend -dt -record} {
    if {!($opt($key) > 0.0)} { error "column_collapse.tcl: expected $key > 0, got $opt($key)" }
}
set W $opt(-width)
set H $opt(-height)
set cell $opt(-cell)
set tend $opt(-tend)
set dt0 $opt(-dt)
set drec $opt(-record)
set maxCuts [expr {int($opt(-max-cuts))}]
set nx [expr {int(round($W / $cell))}]
set ny [expr {int(round($H / $cell))}]
if {abs($nx * $cell - $W) > 1e-9 * $W || abs($ny * $cell - $H) > 1e-9 * $H} {
    error "column_collapse.tcl: -cell $cell does not divide -width $W and -height $H"
}
file mkdir $outdir

set E 172.0e3     ;# kPa
set nu 0.23
set rho 1.925     ;# Mg/m3
set g 9.81        ;# m/s2
set psi 0.0

# ---- model ----
wipe
model basic -ndm 2 -ndf 2
for {set j 0} {$j <= $ny} {incr j} {
    for {set i 0} {$i <= $nx} {incr i} {
        node [expr {$j * ($nx + 1) + $i + 1}] [expr {$i * $cell}] [expr {$j * $cell}]
    }
}
set tol [expr {1e-6 * $cell}]
fixY 0.0 1 1 -tol $tol
fixX 0.0 1 0 -tol $tol
nDMaterial MohrCoulomb 1 $E $nu $rho $opt(-phi) $opt(-cohesion) $psi
set e 0
for {set j 0} {$j < $ny} {incr j} {
    for {set i 0} {$i < $nx} {incr i} {
        incr e
        set n1 [expr {$j * ($nx + 1) + $i + 1}]
        element SSPquad $e $n1 [expr {$n1 + 1}] [expr {$n1 + $nx + 2}] [expr {$n1 + $nx + 1}] 1 PlaneStrain 1.0 0.0 [expr {-$rho * $g}]
    }
}
set nNodes [expr {($nx + 1) * ($ny + 1)}]
set nEle $e
print -JSON -file [file join $outdir model.json]

# ---- stage 1: elastic gravity (stage 0 of MohrCoulomb is linear: one step reaches equilibrium) ----
constraints Transformation
numberer RCM
system UmfPack
test NormDispIncr 1.0e-10 10
algorithm Newton
integrator LoadControl 1.0
analysis Static
set ok [analyze 1]
if {$ok != 0} { error "column_collapse.tcl: the elastic gravity stage failed ($ok)" }

# ---- stage 2: Mohr-Coulomb, transient ----
loadConst -time 0.0
wipeAnalysis
updateMaterialStage -material 1 -stage 1
constraints Transformation
numberer RCM
system UmfPack
test NormDispIncr $opt(-tol) 25
algorithm KrylovNewton -elasticTangent -maxDim 6
integrator Newmark 0.5 0.25
analysis Transient

recorder Node -file [file join $outdir disp.out] -time -dT $drec -nodeRange 1 $nNodes -dof 1 2 disp
recorder Node -file [file join $outdir vel.out] -time -dT $drec -nodeRange 1 $nNodes -dof 1 2 vel
recorder Element -file [file join $outdir stress.out] -time -dT $drec -eleRange 1 $nEle stress3D
recorder MeshQuality -file [file join $outdir mesh_quality.out] -time
record   ;# the t = 0 rows: the elastic state after the switch

# the times to land on: k * record up to tend, and the paper's transfer times
set targets {}
set nrec [expr {int(floor($tend / $drec + 1e-9))}]
for {set k 1} {$k <= $nrec} {incr k} { lappend targets [expr {$k * $drec}] }
foreach t {0.5 1.0 2.0 3.0} {
    if {$t < $tend} {
        lappend targets $t
        if {abs($t / $drec - round($t / $drec)) > 1e-9} {
            puts stderr "column_collapse.tcl: warning: $t s is not a multiple of -record $drec: the steps land on it, the -dT recorders may not write a row there"
        }
    }
}
lappend targets $tend
set targets [lsort -real -unique $targets]

set steps [open [file join $outdir steps.csv] w]
puts $steps "time,dt,iterations,cut_level"
set nSteps 0
set nCutSteps 0     ;# steps taken at a cut dt (cut level > 0): the "cut steps" of the summary
set nFailed 0       ;# analyze calls that failed (each followed by a cut, or the stop)
set totalIter 0
set level 0         ;# current cut level: dt = dt0 / 2^level
set goodAtLevel 0
set stopReason ""
set firstInverted ""
set wall0 [clock microseconds]
set t 0.0
foreach target $targets {
    while {$target - $t > 1e-9 * $dt0} {
        set h [expr {$dt0 / pow(2, $level)}]
        # land exactly on the target; absorb a sliver below 1 % of a step into the last step
        if {$target - $t < 1.01 * $h} { set h [expr {$target - $t}] }
        while {[set ok [analyze 1 $h]] != 0} {
            incr nFailed
            if {$level >= $maxCuts} { break }
            incr level
            set goodAtLevel 0
            set h [expr {$h / 2.0}]
        }
        if {$ok != 0} {
            set stopReason "a step failed to converge at t = $t after $maxCuts cuts (dt = $h)"
            break
        }
        set t [getTime]
        set it [testIter]
        incr nSteps
        incr totalIter $it
        if {$level > 0} { incr nCutSteps }
        puts $steps [format "%.10g,%.6g,%d,%d" $t $h $it $level]
        if {$level > 0} {
            incr goodAtLevel
            if {$goodAtLevel >= 2} { incr level -1; set goodAtLevel 0 }
        }
        set mj [minJacobian]
        if {[lindex $mj 0] <= 0.0 && $firstInverted eq ""} {
            set firstInverted [format "%.6g s (element %d)" $t [lindex $mj 1]]
        }
        if {[lindex $mj 0] <= 0.0 && $opt(-on-inversion) eq "stop"} {
            set stopReason [format "the mesh inverted at t = %.6g s (element %d, corner det J = %.4g)" $t [lindex $mj 1] [lindex $mj 0]]
            break
        }
    }
    if {$stopReason ne ""} { break }
    # snap the committed time onto the target (round-off of the step sum)
    if {abs($t - $target) < 1e-9 * $dt0} { setTime $target; set t $target }
}
close $steps
set wall [expr {([clock microseconds] - $wall0) * 1e-6}]
remove recorders

set mj [minJacobian]
if {$stopReason eq ""} {
    set stopReason "reached t = $tend s"
    if {$firstInverted ne ""} { append stopReason " (the mesh first inverted at $firstInverted)" }
}
puts stdout [format "column_collapse: %s; %dx%d SSPquads, %d steps (%d cut, %d failed attempts), %.2f Newton iterations/step, wall %.2f s (%.2f ms/step), final min det J %.4g (element %d)" \
    $stopReason $nx $ny $nSteps $nCutSteps $nFailed [expr {$nSteps > 0 ? double($totalIter) / $nSteps : 0.0}] \
    $wall [expr {$nSteps > 0 ? 1e3 * $wall / $nSteps : 0.0}] [lindex $mj 0] [lindex $mj 1]]
