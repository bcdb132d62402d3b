# Benchmark model (not a test): a 2D slope on a foundation shaken through a compliant base, the
# construction of an OpenSees site-response script carried to 2D. kN-m-s units (kPa, Mg/m3).
#   foundation 100 m wide x 20 m deep; slope 20 m high above it, crest from x = 0 to 60 m, toe at x = 100 m
#   (2H:1V); nx x ny SSPquads (default 125 x 40 = 5000), every row's nodes evenly spaced between its edges;
#   MohrCoulomb (E = 100 MPa, nu = 0.3, rho = 2.0, phi = 32, c = 15 kPa), elastic gravity stage, plastic shaking;
#   free-field sides: equalDOF between the left and right node of every foundation row; the boundary behind
#   the crest (x = 0 above the foundation) tied horizontally to the free-field column below;
#   base: all base nodes tied horizontally (equalDOF dof 1 to base node 1) and fixed vertically, one
#   Lysmer-Kuhlemeyer dashpot (zeroLength + Viscous, C = rho_r Vs_r W) on a fixed dummy node, and the
#   Joyner-Chen force F(t) = rho_r Vs_r W v_outcrop(t) from a synthetic velocity record (sum of four sines
#   under a 2 s rise / 10 s plateau / exponential decay envelope; peak about 0.3 m/s);
#   Newmark (0.5, 0.25), KrylovNewton -elasticTangent, 2 % mass-proportional Rayleigh damping at 2 Hz (a
#   stiffness-proportional term would follow the plastic tangent and refactor the matrix every iteration).
# Usage (from the benchmark): set nx, ny, dt and tend before sourcing; the driver times `analyze`.
if {![info exists nx]} { set nx 125 }
if {![info exists ny]} { set ny 40 }
if {![info exists dt]} { set dt 0.005 }
if {![info exists tend]} { set tend 20.0 }
set W 100.0; set D 20.0; set Hs 20.0; set crest 60.0
set nyf [expr {$ny/2}]
set pi [expr {acos(-1.0)}]
model basic -ndm 2 -ndf 2
for {set j 0} {$j <= $ny} {incr j} {
  if {$j <= $nyf} {
    set y [expr {$D*$j/double($nyf)}]; set xr $W
  } else {
    set y [expr {$D + $Hs*($j - $nyf)/double($ny - $nyf)}]
    set xr [expr {$W - ($W - $crest)*($y - $D)/$Hs}]
  }
  for {set i 0} {$i <= $nx} {incr i} { node [expr {$j*($nx + 1) + $i + 1}] [expr {$xr*$i/double($nx)}] $y }
}
nDMaterial MohrCoulomb 1 100000.0 0.3 2.0 32.0 15.0 0.0
set e 0
for {set j 0} {$j < $ny} {incr j} {
  for {set i 0} {$i < $nx} {incr i} {
    incr e
    set n1 [expr {$j*($nx + 1) + $i + 1}]
    element SSPquad $e $n1 [expr {$n1 + 1}] [expr {$n1 + $nx + 2}] [expr {$n1 + $nx + 1}] 1 PlaneStrain 1.0 0.0 [expr {-2.0*9.81}]
  }
}
# free-field sides (foundation rows above the base) and the horizontally rigid, vertically fixed base
for {set j 1} {$j <= $nyf} {incr j} { equalDOF [expr {$j*($nx + 1) + 1}] [expr {$j*($nx + 1) + $nx + 1}] 1 2 }
# behind the crest (x = 0 above the foundation): moves horizontally with the free-field column below
for {set j [expr {$nyf + 1}]} {$j <= $ny} {incr j} { equalDOF [expr {$nyf*($nx + 1) + 1}] [expr {$j*($nx + 1) + 1}] 1 }
for {set i 0} {$i <= $nx} {incr i} { fix [expr {$i + 1}] 0 1 }
for {set i 2} {$i <= $nx + 1} {incr i} { equalDOF 1 $i 1 }

# gravity: base node 1 held horizontally by an sp that is removed with its pattern afterwards
timeSeries Constant 1
pattern Plain 1 1 { sp 1 1 0.0 }
constraints Transformation; numberer RCM; system UmfPack; test NormDispIncr 1e-8 30; algorithm Newton
integrator LoadControl 1.0; analysis Static
if {[analyze 1] != 0} { error "gravity failed" }
loadConst -time 0.0
remove loadPattern 1
wipeAnalysis
updateMaterialStage -material 1 -stage 1

# compliant base: rock rho_r = 2.4, Vs_r = 800 m/s
set C [expr {2.4*800.0*$W}]
node 900001 0.0 0.0
fix 900001 1 1
uniaxialMaterial Viscous 900001 $C 1.0
element zeroLength 900001 900001 1 -mat 900001 -dir 1
set nsteps [expr {int(round($tend/$dt))}]
set v {}
# one sample past tend: a -dt Path series returns 0 at its last sample's own time (OpenSees PathSeries)
for {set k 0} {$k <= $nsteps + 1} {incr k} {
  set t [expr {$k*$dt}]
  set envelope [expr {$t < 2.0 ? $t/2.0 : ($t < 12.0 ? 1.0 : exp(-($t - 12.0)/2.0))}]
  lappend v [expr {$envelope*(0.12*sin(2*$pi*0.8*$t) + 0.10*sin(2*$pi*1.7*$t + 1.0) + 0.06*sin(2*$pi*3.1*$t + 2.0) + 0.03*sin(2*$pi*5.3*$t + 0.5))}]
}
timeSeries Path 2 -dt $dt -values $v
pattern Plain 2 2 -fact $C { load 1 1.0 0.0 }
rayleigh [expr {2.0*0.02*2*$pi*2.0}] 0.0 0.0 0.0
constraints Transformation; numberer RCM; system UmfPack; test NormDispIncr 1e-6 30
algorithm KrylovNewton -elasticTangent -maxDim 6
integrator Newmark 0.5 0.25; analysis Transient
