# Procs the examples share (sourced, not run): tying blocks together, the recorders of the hybrid_run.py
# contract, and the two stages of a slope analysis (elastic gravity, then the Mohr-Coulomb collapse in time).

# Ties every node to the first node found at the same position (within tol) with `equalDOF first node 1 2`
# (and 3, the pore pressure, when both are u-p nodes): block2D always makes new nodes, so two blocks that share
# an edge are joined this way (as in OpenSees). Returns the number of ties.
proc tie_coincident_nodes {{tol 1e-6}} {
    set first [dict create]
    set ties 0
    foreach n [getNodeTags] {
        set key [format "%.0f,%.0f" [expr {[nodeCoord $n 1] / $tol}] [expr {[nodeCoord $n 2] / $tol}]]
        if {[dict exists $first $key]} {
            set m [dict get $first $key]
            if {[getNDF $m] == 3 && [getNDF $n] == 3} { equalDOF $m $n 1 2 3 } else { equalDOF $m $n 1 2 }
            incr ties
        } else {
            dict set first $key $n
        }
    }
    return $ties
}

# The files scripts/hybrid_run.py expects in outdir (its contract): model.json, and every drec seconds the
# nodal displacements and velocities, the full element stresses and, for the u-p (3-dof) nodes, the pore
# pressures (pp.out, tag order); plus the mesh quality every step.
# soil_elements: the elements with stresses (default all; a model with zeroLength dashpots gives its soil
# elements, which fem2mpm transfers: their tags must be a contiguous range).
proc record_for_hybrid {outdir drec {soil_elements {}}} {
    set nodes [lsort -integer [getNodeTags]]
    set eles [lsort -integer [expr {[llength $soil_elements] ? $soil_elements : [getEleTags]}]]
    print -JSON -file [file join $outdir model.json]
    recorder Node -file [file join $outdir disp.out] -time -dT $drec -nodeRange [lindex $nodes 0] [lindex $nodes end] -dof 1 2 disp
    recorder Node -file [file join $outdir vel.out] -time -dT $drec -nodeRange [lindex $nodes 0] [lindex $nodes end] -dof 1 2 vel
    recorder Element -file [file join $outdir stress.out] -time -dT $drec -eleRange [lindex $eles 0] [lindex $eles end] stress3D
    set up {}
    foreach n $nodes { if {[getNDF $n] == 3} { lappend up $n } }
    if {[llength $up]} { recorder Node -file [file join $outdir pp.out] -time -dT $drec -node {*}$up -dof 3 vel }
    recorder MeshQuality -file [file join $outdir mesh_quality.out] -time
}

# Stage 1: gravity on the elastic materials (MohrCoulomb stage 0), one linear static step.
proc gravity_stage {} {
    constraints Transformation
    numberer RCM
    system UmfPack
    test NormDispIncr 1.0e-10 10
    algorithm Newton
    integrator LoadControl 1.0
    analysis Static
    if {[analyze 1] != 0} { error "gravity stage: the static step failed" }
}

# The transient analysis of the plastic stages: Newmark average acceleration, KrylovNewton on the elastic
# tangent (factored once per dt), NormDispIncr 1e-6.
proc transient_analysis {} {
    constraints Transformation
    numberer RCM
    system UmfPack
    test NormDispIncr 1.0e-6 25
    algorithm KrylovNewton -elasticTangent -maxDim 6
    integrator Newmark 0.5 0.25
    analysis Transient
}

# Stage 2: MohrCoulomb (stage 1) for the materials given, Newmark average acceleration from t = 0 to tend in
# steps of dt (halved up to 6 times where a step fails). The recorders are made here, at t = 0.
proc collapse_stage {materials outdir tend dt drec} {
    loadConst -time 0.0
    wipeAnalysis
    foreach m $materials { updateMaterialStage -material $m -stage 1 }
    transient_analysis
    record_for_hybrid $outdir $drec
    record
    set t [advance_to $tend $dt "collapse stage"]
    remove recorders
    set mj [minJacobian]
    puts stdout [format "collapse stage: t = %.4g s reached, min corner det J %.4g (element %d)" $t [lindex $mj 0] [lindex $mj 1]]
}

# Instead of the collapse (the script's -fos yes): the factor of safety of the materials given by strength
# reduction from the gravity state (fem_tcl strengthReduction, the materials plastic, KrylovNewton and
# NormDispIncr 1e-6 100, a tolerance every material here can meet), printed as "FoS F" and returned.
proc fos_stage {materials} {
    loadConst -time 0.0
    foreach m $materials { updateMaterialStage -material $m -stage 1 }
    test NormDispIncr 1.0e-6 100
    algorithm KrylovNewton
    set F [strengthReduction -materials $materials]
    puts stdout "FoS $F"
    return $F
}

# Whether the script's -fos option (no or yes) asks for the factor of safety.
proc fos_asked {script value} {
    if {$value ni {no yes}} { error "$script: -fos must be no or yes, got '$value'" }
    return [expr {$value eq "yes"}]
}

# Transient steps of dt from the current time to tend (the last one shortened to land on tend), halved where
# one fails, down to dt / 64; an error naming the stage (label) and the time where it fails for good.
# Returns the time reached. After a cut the step stays halved for kStepsBeforeGrowth converged steps before it
# is doubled again (up to dt), across calls with the same dt: where the full step failed once (a liquefying
# layer, a yielding slope), it tends to fail again, and a failed step costs the test's whole iteration limit.
# Measured on the tailings dam at 0.3 g, 4 s of shaking, dt 0.005: 503 failed steps and 219 s of CPU going
# back to dt after every cut, 16 and 29 s keeping the halved step for 50 steps.
namespace eval hybrid_stages {
    variable kStepsBeforeGrowth 50
    variable step_dt ""       ;# the dt of the last call
    variable step_now 0.0     ;# the step in use (dt, or dt halved after cuts)
    variable converged 0      ;# converged steps since the last cut or doubling
}
proc advance_to {tend dt label} {
    upvar #0 hybrid_stages::step_dt step_dt hybrid_stages::step_now h_now hybrid_stages::converged converged
    if {$step_dt != $dt} { set step_dt $dt; set h_now $dt; set converged 0 }
    set t [getTime]
    while {$tend - $t > 1e-9} {
        set h [expr {min($h_now, $tend - $t)}]
        while {[analyze 1 $h] != 0} {
            if {$h < $dt / 64.0 * 1.5} { error [format "%s: no convergence at t = %.6g s" $label $t] }
            set h [expr {$h / 2.0}]
            set h_now $h
            set converged 0
        }
        if {$h_now < $dt && [incr converged] >= $hybrid_stages::kStepsBeforeGrowth} {
            set h_now [expr {min(2.0 * $h_now, $dt)}]
            set converged 0
        }
        set t [getTime]
    }
    return $t
}

# advance_to in chunks that end on the multiples of drec (the recorders' -dT), so that the rows of a `-dT drec`
# recorder land on those times even where steps are halved (hybrid_run.py transfers at a recorded time).
proc advance_recorded {tend dt drec label} {
    set k [expr {int(floor([getTime] / $drec + 1e-9)) + 1}]
    while {[getTime] < $tend - 1e-9} {
        set t [advance_to [expr {min($k * $drec, $tend)}] $dt $label]
        incr k
    }
    return [getTime]
}

# `-key value` options into the array named arr (whose defaults it holds); errors name the script.
proc parse_options {script arr words} {
    upvar $arr opt
    if {[llength $words] % 2 != 0} { error "$script: option '[lindex $words end]' has no value" }
    foreach {key value} $words {
        if {![info exists opt($key)]} { error "$script: unknown option '$key' (known: [lsort [array names opt]])" }
        # a numeric option takes a number > 0; a word option (its default a word) any word, which the script checks
        if {[string is double -strict $opt($key)] && (![string is double -strict $value] || !($value > 0))} {
            error "$script: expected a number > 0 after '$key', got '$value'"
        }
        set opt($key) $value
    }
}
