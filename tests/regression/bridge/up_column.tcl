# u-p test input for fem2mpm --pore-pressure (issue 36): a saturated column 1 m x 4 m of 2 x 8 u-p elements
# (kN-m-kPa; `set ele quadUP` before sourcing this file for FourNodeQuadUP, default SSPquadUP), loose PM4Sand
# (Dr 0.4, G0 from the usual 167 sqrt(46 Dr^2 + 2.5), hpo 0.5, Den 1.9 Mg/m3) on a PM4Sand of Dr 0.75 in the
# bottom 1 m, water table at the surface (top nodes drained), base fixed and impervious, sides tied (equalDOF 1 2: a
# free-field column). Gravity in the elastic stage as a transient with large steps (10 x 500 s), the plastic
# stage (FirstCall), `setTime 0.0`, then `steps` (default 300) steps of 5 ms of a 0.1 g, 0.4 s sine at the base
# (UniformExcitation): the loose sand builds excess pore pressure (r_u about 0.9 at 2 m depth by 1.5 s). With
# `set drained 1` every node is drained (p = 0: no pore pressure at all) and the material is elastic
# (ElasticIsotropic). Recorders (with -time, -precision `precision`, default 6): disp, vel, pp (-dof 3 vel),
# stress, strain; print -JSON writes the model.
if {![info exists ele]} { set ele SSPquadUP }
if {![info exists drained]} { set drained 0 }
if {![info exists steps]} { set steps 300 }
if {![info exists precision]} { set precision 6 }
wipe
model basic -ndm 2 -ndf 3
set W 1.0; set H 4.0; set nx 2; set ny 8
set g 9.81
for {set j 0} {$j <= $ny} {incr j} {
  for {set i 0} {$i <= $nx} {incr i} { node [expr {$j*($nx+1)+$i+1}] [expr {$i*$W/$nx}] [expr {$j*$H/$ny}] }
}
set nN [expr {($nx+1)*($ny+1)}]
for {set i 1} {$i <= $nx + 1} {incr i} { fix $i 1 1 0 }
for {set j 1} {$j <= $ny} {incr j} { equalDOF [expr {$j*($nx+1)+1}] [expr {$j*($nx+1)+$nx+1}] 1 2 }
if {$drained} {
  for {set j 1} {$j <= $ny} {incr j} { for {set i 1} {$i <= $nx + 1} {incr i} { fix [expr {$j*($nx+1)+$i}] 0 0 1 } }
  for {set i 1} {$i <= $nx + 1} {incr i} { fix $i 0 0 1 }
  nDMaterial ElasticIsotropic 1 60.0e3 0.3 1.9
  nDMaterial ElasticIsotropic 2 60.0e3 0.3 1.9
} else {
  for {set i 1} {$i <= $nx + 1} {incr i} { fix [expr {$ny*($nx+1)+$i}] 0 0 1 }
  foreach {tag Dr} {1 0.75 2 0.4} {
    nDMaterial PM4Sand $tag $Dr [expr {167.0 * sqrt(46.0 * $Dr * $Dr + 2.5)}] 0.5 1.9 101.3 -1 0.8 0.5 0.5 0.1 -1 -1 250.0 -1 32.0 0.3
  }
}
set e 0
for {set j 0} {$j < $ny} {incr j} {
  for {set i 0} {$i < $nx} {incr i} {
    incr e
    set n1 [expr {$j*($nx+1)+$i+1}]
    set m [expr {$j < 2 ? 1 : 2}]
    set nodes [list $n1 [expr {$n1+1}] [expr {$n1+$nx+2}] [expr {$n1+$nx+1}]]
    if {$ele eq "SSPquadUP"} {
      element SSPquadUP $e {*}$nodes $m 1.0 2.2e6 1.0 [expr {1.0e-4 / $g}] [expr {1.0e-4 / $g}] 0.7 1.0e-5 0.0 [expr {-$g}]
    } else {
      element quadUP $e {*}$nodes 1.0 $m [expr {2.2e6 / 0.41}] 1.0 [expr {1.0e-4 / $g}] [expr {1.0e-4 / $g}] 0.0 [expr {-$g}]
    }
  }
}
recorder Node -file pp.out -time -precision $precision -nodeRange 1 $nN -dof 3 vel
recorder Node -file disp.out -time -precision $precision -nodeRange 1 $nN -dof 1 2 disp
recorder Node -file vel.out -time -precision $precision -nodeRange 1 $nN -dof 1 2 vel
recorder Element -file stress.out -time -precision $precision -eleRange 1 $e stress
recorder Element -file strain.out -time -precision $precision -eleRange 1 $e strain
if {!$drained} {
  updateMaterialStage -material 1 -stage 0
  updateMaterialStage -material 2 -stage 0
}
constraints Transformation
test NormDispIncr 1.0e-5 50 0
algorithm Newton
numberer RCM
system UmfPack
integrator Newmark 0.8333333333333334 0.4444444444444444
analysis Transient
puts stdout "gravity: [analyze 10 500.0]"
if {!$drained} {
  updateMaterialStage -material 1 -stage 1
  updateMaterialStage -material 2 -stage 1
  setParameter -val 0 -eleRange 1 $e FirstCall 1
  setParameter -val 0 -eleRange 1 $e FirstCall 2
}
analyze 2 500.0
setTime 0.0
wipeAnalysis
timeSeries Sine 10 0.0 1.5 0.4 -factor [expr {0.1 * $g}]
pattern UniformExcitation 10 1 -accel 10
constraints Transformation
test NormDispIncr 1.0e-5 50 0
algorithm Newton
numberer RCM
system UmfPack
integrator Newmark 0.8333333333333334 0.4444444444444444
analysis Transient
puts stdout "shaking: [analyze $steps 0.005]"
print -JSON -file model.json
wipe
