# Chain test input for fem2mpm --loads: a laterally confined elastic column (4 m x 4 m, 4 x 4 SSPquads,
# kN-m-kPa: E = 10 MPa, nu = 0.3, rho = 2 Mg/m3), base fixed, both sides on rollers, under its weight and
# a surcharge q = 50 kPa on the top (nodal loads q x tributary width, pattern Plain), one static step.
# Recorders (with -time): displacements, the applied nodal loads (unbalance) and the stresses; print -JSON.
wipe
model basic -ndm 2 -ndf 2
set W 4.0; set H 4.0; set nx 4; set ny 4; set q 50.0
set dx [expr {$W/$nx}]; set dy [expr {$H/$ny}]
set rho 2.0; set g 9.81
for {set j 0} {$j <= $ny} {incr j} {
  for {set i 0} {$i <= $nx} {incr i} { node [expr {$j*($nx+1)+$i+1}] [expr {$i*$dx}] [expr {$j*$dy}] }
}
fixY 0.0 1 1
fixX 0.0 1 0
fixX $W 1 0
nDMaterial ElasticIsotropic 1 10.0e3 0.3 $rho
set e 0
for {set j 0} {$j < $ny} {incr j} {
  for {set i 0} {$i < $nx} {incr i} {
    incr e
    set n1 [expr {$j*($nx+1)+$i+1}]
    element SSPquad $e $n1 [expr {$n1+1}] [expr {$n1+$nx+2}] [expr {$n1+$nx+1}] 1 PlaneStrain 1.0 0.0 [expr {-$rho*$g}]
  }
}
timeSeries Linear 1
pattern Plain 1 1 {
  for {set i 0} {$i <= $nx} {incr i} {
    set w [expr {($i == 0 || $i == $nx) ? 0.5*$dx : $dx}]
    load [expr {$ny*($nx+1)+$i+1}] 0.0 [expr {-$q*$w}]
  }
}
set nN [expr {($nx+1)*($ny+1)}]
recorder Node -file disp.out -time -nodeRange 1 $nN -dof 1 2 disp
recorder Node -file loads.out -time -nodeRange 1 $nN -dof 1 2 unbalance
recorder Element -file stress.out -time -eleRange 1 $e stress3D
constraints Transformation
numberer RCM
system UmfPack
test NormDispIncr 1.0e-10 20
algorithm Newton
integrator LoadControl 1.0
analysis Static
puts stdout "static: [analyze 1]"
print -JSON -file model.json
wipe
