# Whole-chain input for a transfer during shaking (fem2mpm --ground-motion): an elastic soil column
# 2 m x 10 m of 2 x 10 SSPquads (kN-m-kPa: E = 20 MPa, nu = 0.3, rho = 2.0 Mg/m3), base fixed, both sides
# on rollers (1D constrained compression, P-wave speed sqrt(M / rho) = 116 m/s). Gravity (one static
# step), then the base shaken vertically by UniformExcitation: a Path -dt 0.01 record in g (motion.txt),
# Newmark steps of 5 ms to t = 1 s. Recorders (with -time) every step; print -JSON writes the model.
wipe
model basic -ndm 2 -ndf 2
set W 2.0; set H 10.0; set nx 2; set ny 10
set rho 2.0; set g 9.81
for {set j 0} {$j <= $ny} {incr j} {
  for {set i 0} {$i <= $nx} {incr i} { node [expr {$j*($nx+1)+$i+1}] [expr {$i*$W/$nx}] [expr {$j*$H/$ny}] }
}
fixY 0.0 1 1
fixX 0.0 1 0
fixX $W 1 0
nDMaterial ElasticIsotropic 1 20.0e3 0.3 $rho
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
timeSeries Path 2 -dt 0.01 -filePath motion.txt -factor $g
pattern UniformExcitation 2 2 -accel 2
constraints Transformation
numberer RCM
system UmfPack
test NormDispIncr 1.0e-10 20
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
puts stdout "shaking: [analyze 200 0.005]"
print -JSON -file model.json
wipe
