# A 2:1 slope of height H = 10 m (Griffiths & Lane 1999, Geotechnique 49(3), example 1 when the foundation
# depth is 0), its factor of safety by strength reduction.
# Sample run: build/bin/fem_tcl tests/verification/fem/data/slope_fos.tcl 10 SSPquad 0 10
# Arguments: ny (elements over H; element size about H / ny) elementType (SSPquad | quad) foundationDepth (m)
#            cohesion (kPa, of the slope soil; 10 in G&L's example) then any strengthReduction options
#            (e.g. -criterion convergence -tol 0.01). Prints "FoS F elements n wall_ms t" on stdout.
# Units kN, m, kPa. Soil (G&L example 1): gamma = 20 kN/m3, E = 1e5 kPa, nu = 0.3, c = 10 kPa
# (c / (gamma H) = 0.05), phi = 20 deg, psi = 0. The foundation layer (material 2), when present, is a weaker
# clay: c = 20 kPa, phi = 10 deg (same gamma, E, nu). Base fixed, sides on rollers.
# Mesh (Tcl loops): the slope block is the trapezoid toe (0,0), (L,0), (L,H), crest (2H,H), nx x ny SSPquads
# with every row of nodes spread evenly from the face to the right side (nx = 2.2 ny: square elements on average);
# the foundation block below it continues those columns and extends 10 m to the left of the toe.
set ny [lindex $argv 0]
set eletype [lindex $argv 1]
set depth [lindex $argv 2]
set cohesion [lindex $argv 3]
set options [lrange $argv 4 end]
set H 10.0
set L 32.0
set gamma 20.0
set nx [expr {int(round(2.2 * $ny))}]
set dx [expr {$L / $nx}]
set nleft [expr {$depth > 0 ? int(round(10.0 / $dx)) : 0}]
set nfound [expr {int(round($depth * $ny / $H))}]
set cols [expr {$nleft + $nx + 1}]   ;# nodes per row

model basic -ndm 2 -ndf 2
nDMaterial MohrCoulomb 1 1.0e5 0.3 0.0 20.0 $cohesion 0.0
nDMaterial MohrCoulomb 2 1.0e5 0.3 0.0 10.0 20.0 0.0
# node (i, j): j = 0 at the base; rows 0..nfound-1 foundation, nfound..nfound+ny the slope block
set rows [expr {$nfound + $ny}]
for {set j 0} {$j <= $rows} {incr j} {
  for {set i 0} {$i < $cols} {incr i} {
    set tag [expr {$j * $cols + $i + 1}]
    if {$j <= $nfound} {
      set y [expr {-$depth + $depth * $j / double(max($nfound, 1))}]
      if {$i < $nleft} { node $tag [expr {($i - $nleft) * $dx}] $y; continue }
      node $tag [expr {($i - $nleft) * $dx}] $y
    } else {
      if {$i < $nleft} continue   ;# no soil left of the face above the toe level
      set y [expr {$H * ($j - $nfound) / double($ny)}]
      set xf [expr {2.0 * $y}]
      node $tag [expr {$xf + ($L - $xf) * ($i - $nleft) / double($nx)}] $y
    }
  }
}
set e 0
for {set j 0} {$j < $rows} {incr j} {
  for {set i 0} {$i < $cols - 1} {incr i} {
    if {$j >= $nfound && $i < $nleft} continue
    set n1 [expr {$j * $cols + $i + 1}]
    set n2 [expr {$n1 + 1}]
    set n3 [expr {$n2 + $cols}]
    set n4 [expr {$n1 + $cols}]
    set mat [expr {$j < $nfound ? 2 : 1}]
    incr e
    if {$eletype eq "quad"} {
      element quad $e $n1 $n2 $n3 $n4 1.0 PlaneStrain $mat 0.0 0.0 0.0 -$gamma
    } else {
      element SSPquad $e $n1 $n2 $n3 $n4 $mat PlaneStrain 1.0 0.0 -$gamma
    }
  }
}
# supports: base fixed, left (foundation only) and right sides on rollers
for {set i 0} {$i < $cols} {incr i} { fix [expr {$i + 1}] 1 1 }
for {set j 1} {$j <= $rows} {incr j} {
  fix [expr {$j * $cols + $cols}] 1 0
  if {$nleft > 0 && $j <= $nfound} { fix [expr {$j * $cols + 1}] 1 0 }
}

# gravity, elastic (MohrCoulomb stage 0)
constraints Plain
numberer RCM
system UmfPack
test NormDispIncr 1.0e-6 100
algorithm NewtonLineSearch
integrator LoadControl 1.0
analysis Static
if {[analyze 1] != 0} { error "gravity stage failed" }
loadConst -time 0.0
updateMaterialStage -material 1 -stage 1
updateMaterialStage -material 2 -stage 1
set materials [expr {$depth > 0 ? {1 2} : {1}}]
set t0 [clock milliseconds]
set F [strengthReduction -materials $materials {*}$options]
puts stdout "FoS $F elements $e wall_ms [expr {[clock milliseconds] - $t0}]"
