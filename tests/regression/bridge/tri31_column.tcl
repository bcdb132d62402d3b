# A 2-cell-wide, 10 m elastic column of Tri31 triangles under self-weight (kN, m, kPa, Mg/m3), each cell
# cut along a diagonal, the two cells mirror images; lateral rollers, fixed base. For
# Fem2mpmRegression.TriangleMeshColumnThroughTheChain (the files are written into the working folder).
set out .
model basic -ndm 2 -ndf 2
set ny 10; set H 10.0; set dy [expr {$H/$ny}]
for {set j 0} {$j <= $ny} {incr j} {
  for {set i 0} {$i <= 2} {incr i} { node [expr {3*$j + $i + 1}] [expr {$i*0.5}] [expr {$j*$dy}] }
}
fixY 0.0 1 1
fixX 0.0 1 0
fixX 1.0 1 0
nDMaterial ElasticIsotropic 1 100.0e3 0.25 2.0
set e 0
for {set j 0} {$j < $ny} {incr j} {
  set a [expr {3*$j + 1}]
  element tri31 [incr e] $a [expr {$a+1}] [expr {$a+4}] 1.0 PlaneStrain 1 0.0 0.0 0.0 -19.62
  element tri31 [incr e] $a [expr {$a+4}] [expr {$a+3}] 1.0 PlaneStrain 1 0.0 0.0 0.0 -19.62
  element tri31 [incr e] [expr {$a+1}] [expr {$a+2}] [expr {$a+4}] 1.0 PlaneStrain 1 0.0 0.0 0.0 -19.62
  element tri31 [incr e] [expr {$a+2}] [expr {$a+5}] [expr {$a+4}] 1.0 PlaneStrain 1 0.0 0.0 0.0 -19.62
}
print -JSON -file [file join $out model.json]
recorder Node -file [file join $out disp.out] -time -nodeRange 1 33 -dof 1 2 disp
recorder Node -file [file join $out vel.out] -time -nodeRange 1 33 -dof 1 2 vel
recorder Element -file [file join $out stress.out] -time -eleRange 1 40 stresses
constraints Plain; numberer RCM; system BandSPD; test NormDispIncr 1e-12 5; algorithm Newton
integrator LoadControl 1.0; analysis Static
analyze 1
