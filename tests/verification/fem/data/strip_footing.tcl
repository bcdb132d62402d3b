# Strip footing on weightless undrained clay (Tresca: MohrCoulomb with phi = 0, psi = 0), plane strain, half
# model by symmetry. Prandtl (1920) / Hill (1950): collapse pressure q_u = (2 + pi) c for a rigid footing,
# smooth or rough (Chen 1975, Limit Analysis and Soil Plasticity, sec. 5; de Souza Neto et al. 2008, sec. 8.3.2).
# Usage: fem_tcl strip_footing.tcl ?n? ?element? ?footing? ?steps? ?algorithm? ?printFlag?
#   n        elements across the footing half-width b = 1 m (default 4); the domain is 5 b wide and 5 b deep
#   element  SSPquad (default) or quad
#   footing  smooth (rigid, uy prescribed, ux free: default), rough (rigid, ux = 0 too), flexible
#            (uniform pressure, load control; stops at the last converged load) or flexible-dc (uniform pressure,
#            `integrator DisplacementControl` on the centre node: its settlement grows by 0.05 b / steps a step)
#   steps    load / displacement steps (default 40)
#   algorithm NewtonLineSearch (default) or any other `algorithm` type; printFlag: the test's (default 0)
# Prints "q/c <value>" for each step (footing pressure over c, positive in compression) and "limit q/c <value>"
# (the last converged step) at the end. Equilibrium: NewtonLineSearch (plain Newton diverges on the first plastic
# step under the footing edge on meshes of 8 elements per half-width and finer).
wipe
model basic -ndm 2 -ndf 2
set n [expr {$argc >= 1 ? [lindex $argv 0] : 4}]
set eleType [expr {$argc >= 2 ? [lindex $argv 1] : "SSPquad"}]
set footing [expr {$argc >= 3 ? [lindex $argv 2] : "smooth"}]
set nsteps [expr {$argc >= 4 ? [lindex $argv 3] : 40}]
set alg [expr {$argc >= 5 ? [lindex $argv 4] : "NewtonLineSearch"}]
set printFlag [expr {$argc >= 6 ? [lindex $argv 5] : 0}]
set b 1.0
set L [expr {5.0 * $b}]
set h [expr {$b / $n}]
set nx [expr {int(round($L / $h))}]
set ny $nx
set c 100.0
set E 1.0e5
set nu 0.3
for {set j 0} {$j <= $ny} {incr j} {
    for {set i 0} {$i <= $nx} {incr i} {
        node [expr {$j * ($nx + 1) + $i + 1}] [expr {$i * $h}] [expr {$j * $h - $L}]
    }
}
set tol [expr {1e-6 * $h}]
fixY [expr {-$L}] 1 1 -tol $tol
fixX 0.0 1 0 -tol $tol
fixX $L 1 0 -tol $tol
nDMaterial MohrCoulomb 1 $E $nu 0.0 0.0 $c 0.0
updateMaterialStage -material 1 -stage 1
set e 0
for {set j 0} {$j < $ny} {incr j} {
    for {set i 0} {$i < $nx} {incr i} {
        incr e
        set n1 [expr {$j * ($nx + 1) + $i + 1}]
        if {$eleType eq "quad"} {
            element quad $e $n1 [expr {$n1 + 1}] [expr {$n1 + $nx + 2}] [expr {$n1 + $nx + 1}] 1.0 PlaneStrain 1
        } else {
            element SSPquad $e $n1 [expr {$n1 + 1}] [expr {$n1 + $nx + 2}] [expr {$n1 + $nx + 1}] 1 PlaneStrain 1.0
        }
    }
}
# footing nodes: top row, x <= b
set top [expr {$ny * ($nx + 1)}]
set fnodes {}
for {set i 0} {$i <= $n} {incr i} { lappend fnodes [expr {$top + $i + 1}] }
timeSeries Linear 1
set flexible [expr {$footing eq "flexible" || $footing eq "flexible-dc"}]
if {$flexible} {
    # uniform pressure q = lambda * 6 c (beyond the limit), consistent nodal loads
    set q [expr {6.0 * $c}]
    pattern Plain 1 1 {
        foreach nd $fnodes {
            set w [expr {($nd == [lindex $fnodes 0] || $nd == [lindex $fnodes end]) ? 0.5 : 1.0}]
            load $nd 0.0 [expr {-$w * $q * $h}]
        }
    }
} else {
    # rigid footing: uy = -lambda * delta on every footing node (delta = 0.05 b)
    set delta [expr {0.05 * $b}]
    pattern Plain 1 1 {
        foreach nd $fnodes {
            sp $nd 2 [expr {-$delta}]
            if {$footing eq "rough" && $nd != [lindex $fnodes 0]} { sp $nd 1 0.0 }  ;# the first is on the symmetry roller
        }
    }
}
constraints Transformation
numberer RCM
system UmfPack
test NormUnbalance 1.0e-8 30 $printFlag
algorithm $alg
if {$footing eq "flexible-dc"} {
    integrator DisplacementControl [lindex $fnodes 0] 2 [expr {-0.05 * $b / $nsteps}]
} else {
    integrator LoadControl [expr {1.0 / $nsteps}]
}
analysis Static
set qLast 0.0
for {set s 1} {$s <= $nsteps} {incr s} {
    set ok [analyze 1]
    if {$ok != 0} { puts stdout "step $s failed"; break }
    if {$flexible} {
        set qc [expr {[getLoadFactor 1] * 6.0}]
    } else {
        reactions
        set F 0.0
        foreach nd $fnodes { set F [expr {$F + [nodeReaction $nd 2]}] }
        set qc [expr {-$F / ($b * $c)}]
    }
    set qLast $qc
    puts stdout "step $s iterations [testIter] q/c $qc centre uy [nodeDisp [lindex $fnodes 0] 2]"
}
puts stdout "limit q/c $qLast"
