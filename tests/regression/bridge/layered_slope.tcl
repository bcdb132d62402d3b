# Whole-chain test input (issue 9): a 45-degree cut slope, 5 m high, on a 5 m foundation layer, 20 m wide
# (kN-m-kPa units, plane strain, SSPquads). Foundation 20 x 5 elements of 1 m (material 1: MohrCoulomb
# E = 50 MPa, nu = 0.3, rho = 2.0 Mg/m3, phi = 35, c = 50 kPa); slope 10 x 5 trapezoidal elements between x = 0
# and the face x = 10 - (y - 5) (material 2: E = 20 MPa, nu = 0.3, rho = 1.9, phi = 20, c = 2 kPa, psi = 0).
# Supports as an engineer sets them: both sides on rollers (the left over the full 10 m, the right over the
# foundation's 5 m), the base fixed. Stage 1: elastic gravity (one static step). Stage 2: loadConst -time 0,
# plastic, 20 Newmark steps of 5 ms: the slope starts to slide. print -JSON carries the supports.
wipe
model basic -ndm 2 -ndf 2
set g 9.81
# Foundation nodes: tag 1 + j*21 + i at (i, j), i = 0..20, j = 0..5.
for {set j 0} {$j <= 5} {incr j} {
  for {set i 0} {$i <= 20} {incr i} { node [expr {1 + $j*21 + $i}] [expr {double($i)}] [expr {double($j)}] }
}
# Slope nodes above y = 5: tag 127 + (j-1)*11 + i at x = i/10 * (10 - j), y = 5 + j, j = 1..5 (row j = 0 is
# the foundation's top row, tags 106 + i).
proc slope_node {i j} { if {$j == 0} { return [expr {106 + $i}] } else { return [expr {127 + ($j-1)*11 + $i}] } }
for {set j 1} {$j <= 5} {incr j} {
  for {set i 0} {$i <= 10} {incr i} { node [slope_node $i $j] [expr {$i/10.0*(10.0-$j)}] [expr {5.0+$j}] }
}
fixY 0.0 1 1
fixX 0.0 1 0
fixX 20.0 1 0
nDMaterial MohrCoulomb 1 50.0e3 0.3 2.0 35.0 50.0 0.0
nDMaterial MohrCoulomb 2 20.0e3 0.3 1.9 20.0 2.0 0.0
set e 0
for {set j 0} {$j < 5} {incr j} {
  for {set i 0} {$i < 20} {incr i} {
    incr e
    set n1 [expr {1 + $j*21 + $i}]
    element SSPquad $e $n1 [expr {$n1+1}] [expr {$n1+22}] [expr {$n1+21}] 1 PlaneStrain 1.0 0.0 [expr {-2.0*$g}]
  }
}
for {set j 0} {$j < 5} {incr j} {
  for {set i 0} {$i < 10} {incr i} {
    incr e
    element SSPquad $e [slope_node $i $j] [slope_node [expr {$i+1}] $j] [slope_node [expr {$i+1}] [expr {$j+1}]] \
        [slope_node $i [expr {$j+1}]] 2 PlaneStrain 1.0 0.0 [expr {-1.9*$g}]
  }
}
recorder Node -file disp.out -time -nodeRange 1 181 -dof 1 2 disp
recorder Node -file vel.out -time -nodeRange 1 181 -dof 1 2 vel
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
updateMaterialStage -material 2 -stage 1
constraints Transformation
numberer RCM
system UmfPack
test NormDispIncr 1.0e-8 50
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
puts stdout "slide: [analyze 20 0.005]"
print -JSON -file model.json
wipe
