# A small Mohr-Coulomb soil column (10 m wide x 8 m high, 10 x 8 SSPquads, plane strain, kN-m-s), the paper's
# workflow in miniature: elastic gravity with MohrCoulomb in stage 0, then `updateMaterialStage -stage 1`
# (phi = 22.2 deg, c = 1 kPa, psi = 0) and a transient collapse with full Newton on the consistent tangent.
# The test driver reads the "iteration: k current Norm: r" lines (printFlag 1) to check quadratic convergence.
wipe
model basic -ndm 2 -ndf 2
set nx 10
set ny 8
set E 172.0e3
set nu 0.23
set rho 1.925
for {set j 0} {$j <= $ny} {incr j} {
    for {set i 0} {$i <= $nx} {incr i} {
        node [expr {$j*($nx+1) + $i + 1}] [expr {1.0*$i}] [expr {1.0*$j}]
    }
}
fixY 0.0 1 1
fixX 0.0 1 0
nDMaterial MohrCoulomb 1 $E $nu $rho 22.2 1.0 0.0
set e 0
for {set j 0} {$j < $ny} {incr j} {
    for {set i 0} {$i < $nx} {incr i} {
        incr e
        set n1 [expr {$j*($nx+1) + $i + 1}]
        element SSPquad $e $n1 [expr {$n1 + 1}] [expr {$n1 + $nx + 2}] [expr {$n1 + $nx + 1}] 1 PlaneStrain 1.0 0.0 [expr {-$rho*9.81}]
    }
}
constraints Transformation
numberer RCM
system UmfPack
test NormDispIncr 1.0e-10 10 0
algorithm Newton
integrator LoadControl 1.0
analysis Static
set ok [analyze 1]
puts stdout "gravity: analyze returned $ok"
puts stdout "stress3D element 1: [eleResponse 1 stress3D]"
loadConst -time 0.0
wipeAnalysis
updateMaterialStage -material 1 -stage 1
constraints Transformation
numberer RCM
system UmfPack
test NormDispIncr 1.0e-12 30 1
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
set ok [analyze 20 0.01]
puts stdout "collapse: analyze returned $ok, time [getTime]"
puts stdout "top right corner: [nodeDisp [expr {($ny+1)*($nx+1)}] 1] [nodeDisp [expr {($ny+1)*($nx+1)}] 2]"
