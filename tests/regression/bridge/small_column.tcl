# Whole-chain test input (fem_tcl -> fem2mpm -> mpm): an 8 m x 6 m Mohr-Coulomb column of 8 x 6 SSPquads
# (plane strain, kN-m-kPa units: E = 20 MPa, nu = 0.3, rho = 1.925 Mg/m3, phi = 25 deg, c = 1 kPa, psi = 0),
# base fixed, left face on rollers, right face free. Stage 1: elastic gravity (MohrCoulomb stage 0, one
# static step). Stage 2: loadConst -time 0, plastic (stage 1), 20 Newmark steps of 5 ms: the free face
# starts to slump. Recorders (with -time) hold the nodal displacements and velocities and the full
# stress tensor (stress3D); print -JSON writes the model description.
wipe
model basic -ndm 2 -ndf 2
set W 8.0; set H 6.0; set nx 8; set ny 6
set dx [expr {$W/$nx}]; set dy [expr {$H/$ny}]
set rho 1.925; set g 9.81
for {set j 0} {$j <= $ny} {incr j} {
  for {set i 0} {$i <= $nx} {incr i} { node [expr {$j*($nx+1)+$i+1}] [expr {$i*$dx}] [expr {$j*$dy}] }
}
fixY 0.0 1 1
fixX 0.0 1 0
nDMaterial MohrCoulomb 1 20.0e3 0.3 $rho 25.0 1.0 0.0
set e 0
for {set j 0} {$j < $ny} {incr j} {
  for {set i 0} {$i < $nx} {incr i} {
    incr e
    set n1 [expr {$j*($nx+1)+$i+1}]
    element SSPquad $e $n1 [expr {$n1+1}] [expr {$n1+$nx+2}] [expr {$n1+$nx+1}] 1 PlaneStrain 1.0 0.0 [expr {-$rho*$g}]
  }
}
set nN [expr {($nx+1)*($ny+1)}]
recorder Node -file disp.out -time -nodeRange 1 $nN -dof 1 2 disp
recorder Node -file vel.out -time -nodeRange 1 $nN -dof 1 2 vel
recorder Element -file stress.out -time -eleRange 1 $e stress3D
constraints Transformation
numberer RCM
system UmfPack
test NormDispIncr 1.0e-10 20
algorithm Newton
integrator LoadControl 1.0
analysis Static
puts stdout "gravity: [analyze 1]"
loadConst -time 0.0
wipeAnalysis
updateMaterialStage -material 1 -stage 1
constraints Transformation
numberer RCM
system UmfPack
test NormDispIncr 1.0e-8 50
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
puts stdout "collapse: [analyze 20 0.005]"
print -JSON -file model.json
wipe
